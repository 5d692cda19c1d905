#!/usr/bin/env python3
"""Writes period/m68k/profiles/sun3-60.json and sun3-260.json: one rule list, two machines.

Why one file of ~470 lines: it is the cycle table itself, one rule (and its source) a line,
in the manuals' order; splitting it would scatter one table.

Edit the rules here and run `python3 period/m68k/profiles/generate.py`; the JSON
files are what fb89 embeds and reads (docs/HOST_COST_MODEL.md).

Every figure carries a source tag:
  UM020  MC68020 User's Manual, section 8 (cache case), as transcribed by
         benletchford/m68k-rs src/core/timing_020.rs (T020a) and mras0/acycles
         cpu_model_020.cpp (T020b)
  UM881  MC68881/MC68882 User's Manual, section 8, Tables 8-1/8-2, as transcribed by
         twvd/snow core/src/cpu_m68k/fpu/timings.rs (T881)
  EST    our derivation, reasoning in the string
"""
import json
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else __import__("os").path.dirname(__import__("os").path.abspath(__file__))

rules = []


def rule(mn, ops, cpu, src, fpu=None, fetch=None, calc=None, acc=None):
    # ';' separates whole operand shapes (the evaluator's '|' alternates within one operand)
    if ops is not None and ";" in ops:
        for shape in ops.split(";"):
            rule(mn, shape, cpu, src, fpu, fetch, calc, acc)
        return
    r = {"mnemonic": mn}
    if ops is not None:
        r["operands"] = ops
    r["cpu"] = cpu
    if fpu is not None:
        r["fpu"] = fpu
    if fetch:
        r["fetch"] = fetch
    if calc:
        r["calc"] = calc
    if acc is not None:
        r["accesses"] = acc
    r["source"] = src
    rules.append(r)


# ---------------------------------------------------------------- EA tables (UM020 cache case)
FETCH = {"dreg": 0, "areg": 0, "fpreg": 0, "ind": 4, "postinc": 4, "predec": 5, "disp": 5,
         "index": 7, "abs": 4, "pcrel": 5, "imm.b": 2, "imm.w": 2, "imm.l": 4, "imm.s": 4,
         "imm.d": 8, "imm.x": 12, "target": 0, "reglist": 0, "fpcr": 0, "other": 0}
CALC = {"dreg": 0, "areg": 0, "fpreg": 0, "ind": 2, "postinc": 2, "predec": 2, "disp": 2,
        "index": 4, "abs": 4, "pcrel": 2, "imm": 0, "target": 0, "reglist": 0, "fpcr": 0,
        "other": 0}
EA_SOURCE = ("UM020 section 8, Fetch Effective Address and Calculate Effective Address "
             "tables, cache case (T020a fetch_ea/calculate_ea; fetch agrees with T020b): fetch "
             "(An) 4, (An)+ 4, -(An) 5, (d16,An) 5, (d8,An,Xn) 7, abs 4, (d16,PC) 5, #<data> "
             "B/W 2, L 4; calculate (An)/(An)+/-(An)/(d16,An)/(d16,PC) 2, (d8,An,Xn) 4, "
             "abs.L 4. 'index' uses the brief-format row (memory-indirect forms cost more); "
             "'abs' the abs.L row. EST: FPU immediates imm.s/imm.d/imm.x = 2 clocks per "
             "instruction-stream word (4/8/12), as #<data>.W 2 and .L 4.")

MEMS = ["ind", "postinc", "predec", "disp", "index", "abs", "pcrel"]

# ---------------------------------------------------------------- MOVE (UM020 MOVE table)
# rows: source class -> [Rn, (An), (An)+, -(An), (d16,An), abs.W, abs.L, (d8,An,Xn)]
MOVE = {
    "reg": [2, 4, 4, 5, 5, 4, 6, 7],
    "immw": [4, 6, 6, 7, 7, 6, 8, 7],
    "imml": [6, 8, 8, 9, 9, 8, 10, 9],
    "ind": [6, 7, 7, 7, 7, 7, 9, 9],
    "postinc": [6, 7, 7, 7, 7, 7, 9, 9],
    "predec": [7, 8, 8, 8, 8, 8, 10, 10],
    "disp": [7, 8, 8, 8, 8, 8, 10, 10],
    "absw": [6, 7, 7, 7, 7, 7, 9, 9],
    "abs": [6, 7, 7, 7, 7, 7, 9, 9],
    "index": [9, 10, 10, 10, 10, 10, 12, 12],
}
MOVE["pcrel"] = MOVE["disp"]
DCOL = {"reg": 0, "ind": 1, "postinc": 2, "predec": 3, "disp": 4, "abs": 6, "index": 7}
MSRC = "UM020 MOVE instruction table, cache case (T020a MOVE_CACHE; T020b agrees)"

rule("^moveq$", "imm,dreg", 2, "UM020 MOVEQ, cache case (T020a group 7; T020b)")
# group sources / destinations with identical rows/columns to keep the list short
src_groups = [("reg", "reg"), ("ind|postinc|abs", "ind"), ("predec|disp|pcrel", "disp"),
              ("index", "index")]
dst_groups = [("reg", "reg"), ("ind|postinc", "ind"), ("predec|disp", "disp"), ("abs", "abs"),
              ("index", "index")]
for sg, srow in src_groups:
    for dg, dcol in dst_groups:
        cyc = MOVE[srow][DCOL[dcol]]
        rule("^move[bwl]$|^movea[wl]$", f"{sg},{dg}", cyc,
             f"{MSRC}: {srow} source to {dcol} destination = {cyc} (EA included)")
for imm_mn, srow, what in [("^move[bw]$|^moveaw$", "immw", "#<data>.B/.W"),
                           ("^movel$|^moveal$", "imml", "#<data>.L")]:
    for dg, dcol in dst_groups:
        cyc = MOVE[srow][DCOL[dcol]]
        rule(imm_mn, f"imm,{dg}", cyc, f"{MSRC}: {what} source to {dcol} destination = {cyc}")

# ---------------------------------------------------------------- arithmetic / logic
ARITH = "UM020 Arithmetic/Logical Instructions table, cache case (T020a dyadic; T020b arit_cost_020)"
rule("^(add|sub|and|or|cmp)[bwl]$", "*,dreg", 2, ARITH + ": <ea>,Dn 2 + fetch-EA", fetch=[0])
rule("^eor[bwl]$", "dreg,dreg", 2, ARITH + ": EOR Dn,Dn 2")
rule("^(add|sub)a[wl]$", "*,areg", 2, ARITH + ": ADDA/SUBA <ea>,An 2 + fetch-EA", fetch=[0])
rule("^cmpa[wl]$", "*,areg", 4, ARITH + ": CMPA <ea>,An 4 + fetch-EA", fetch=[0])
rule("^(add|sub|and|or|eor)[bwl]$", "dreg,mem", 4,
     ARITH + ": Dn,<ea> 4 + fetch-EA; operand read and written (2 accesses)", fetch=[1], acc=2)
rule("^(add|sub)x[bwl]$", "dreg,dreg", 2, "UM020 Extended instructions, ADDX/SUBX Dn,Dn 2 (T020a)")
rule("^(add|sub)x[bwl]$", "predec,predec", 12,
     "UM020 Extended instructions, ADDX/SUBX -(Ay),-(Ax) 12 (T020a); 2 reads + 1 write", acc=3)
rule("^(add|sub)q[bwl]$", "imm,reg", 2, "UM020 ADDQ/SUBQ #,Rn 2, cache case (T020a group 5)")
rule("^(add|sub)q[bwl]$", "imm,mem", 4,
     "UM020 ADDQ/SUBQ #,<ea> 4 + fetch-EA (T020a group 5); read and written", fetch=[1], acc=2)

IMMA = "UM020 Immediate Arithmetic/Logical table, cache case (T020a group_0, fetch_immediate_ea; T020b)"
rule("^(add|sub|and|or|eor|cmp)i[bwl]$", "imm,dreg", 2,
     IMMA + ": #,Dn 2 + fetch-immediate-EA(Dn) = #<data> fetch 2 (B/W) or 4 (L)", fetch=[0])
# fetch immediate EA, cache case: (B/W, L)
FIMM_GROUPS = [("ind", (4, 4)), ("postinc|abs", (6, 8)), ("predec|disp|pcrel", (5, 7)),
               ("index", (9, 11))]
for grp, vals in FIMM_GROUPS:
    for sz, k in (("bw", 0), ("l", 1)):
        mn_mod = "^(add|sub|and|or|eor)i[bw]$" if sz == "bw" else "^(add|sub|and|or|eor)il$"
        mn_cmp = "^cmpi[bw]$" if sz == "bw" else "^cmpil$"
        f = vals[k]
        note = " (abs: the abs.L row; (d16,PC) as (d16,An))"
        rule(mn_mod, f"imm,{grp}", 4 + f,
             f"{IMMA}: #,<ea> 4 + fetch-immediate-EA {grp} {sz.upper()} {f}{note}; read and written",
             acc=2)
        rule(mn_cmp, f"imm,{grp}", 2 + f,
             f"{IMMA}: CMPI #,<ea> 2 + fetch-immediate-EA {grp} {sz.upper()} {f}{note}")

# ---------------------------------------------------------------- multiply / divide (long)
# base + fetch-immediate-EA(source, .W) per UM020 note; #<data> as .L (T020b)
FIMMW = {"dreg": 2, "ind": 4, "postinc|abs": 6, "predec|disp|pcrel": 5, "index": 9, "imm": 8}
for mn, base, name in (("^mul[su]l$", 43, "MULS.L/MULU.L"), ("^divs(l|ll)$", 90, "DIVS.L/DIVSL.L"),
                       ("^divu(l|ll)$", 78, "DIVU.L/DIVUL.L")):
    for cls, f in FIMMW.items():
        c = base + f
        src = (f"UM020 {name} {base} + fetch-immediate-EA({cls}) {f}, cache case "
               f"(T020a group_4 / T020b cost_020)")
        if cls == "imm":
            src += "; #<data> priced with the .L immediate row as T020b does"
        rule(mn, f"{cls},dreg", c, src)
        rule(mn, f"{cls},dreg,dreg", c, src + "; 64-bit/remainder form same table entry")
rule("^mul[su]w$", "*,dreg", 27, "UM020 MULS.W/MULU.W 27 + fetch-EA (T020a; T020b)", fetch=[0])
rule("^divuw$", "*,dreg", 44, "UM020 DIVU.W 44 + fetch-EA (T020a; T020b)", fetch=[0])
rule("^divsw$", "*,dreg", 56, "UM020 DIVS.W 56 + fetch-EA (T020a; T020b)", fetch=[0])

# ---------------------------------------------------------------- shifts / rotates
SH = "UM020 Shift/Rotate table, cache case (T020a group_e; T020b)"
rule("^ls[lr][bwl]$", "imm,dreg", 4, SH + ": LSL/LSR #,Dn 4")
rule("^ls[lr][bwl]$", "dreg,dreg", 6, SH + ": LSL/LSR Dn,Dn 6")
rule("^asl[bwl]$", "imm|dreg,dreg", 8, SH + ": ASL Dn 8")
rule("^asr[bwl]$", "imm|dreg,dreg", 6, SH + ": ASR Dn 6")
rule("^ro[lr][bwl]$", "imm|dreg,dreg", 8, SH + ": ROL/ROR Dn 8")
rule("^rox[lr][bwl]$", "imm|dreg,dreg", 12, SH + ": ROXL/ROXR Dn 12")
rule("^asl[w]?$", "mem", 6, SH + ": ASL <ea> 6 + fetch-EA; read and written", fetch=[0], acc=2)
rule("^(asr|ls[lr]|rox[lr])[w]?$", "mem", 5, SH + ": ASR/LSx/ROXx <ea> 5 + fetch-EA", fetch=[0],
     acc=2)
rule("^ro[lr][w]?$", "mem", 7, SH + ": ROL/ROR <ea> 7 + fetch-EA", fetch=[0], acc=2)

# ---------------------------------------------------------------- single operand
SO = "UM020 Single Operand table, cache case (T020a group_4)"
rule("^clr[bwl]$", "reg", 2, SO + ": CLR Dn 2")
rule("^clr[bwl]$", "mem", 4, SO + ": CLR <ea> 4 + calculate-EA (written only)", calc=[0])
rule("^(neg|negx|not)[bwl]$", "reg", 2, SO + ": NEG/NEGX/NOT Dn 2")
rule("^(neg|negx|not)[bwl]$", "mem", 4, SO + ": NEG/NEGX/NOT <ea> 4 + fetch-EA; read and written",
     fetch=[0], acc=2)
rule("^tst[bwl]$", "reg", 2, SO + ": TST Rn 2")
rule("^tst[bwl]$", "*", 2, SO + ": TST <ea> 2 + fetch-EA", fetch=[0])
SCC = "^s(t|f|hi|ls|cc|hs|cs|lo|ne|eq|vc|vs|pl|mi|ge|lt|gt|le)$"
rule(SCC, "dreg", 4, SO + ": Scc Dn 4 (T020a group_5)")
rule(SCC, "mem", 6, SO + ": Scc <ea> 6 + calculate-EA (T020a group_5)", calc=[0])
rule("^ext[wl]$|^extbl$", "dreg", 4, SO + ": EXT/EXTB 4")
rule("^swap$", "dreg", 4, SO + ": SWAP 4 (T020a; T020b)")
rule("^nop$", "", 2, "UM020 Control instructions, NOP 2 (T020a 0x4E71)")

# ---------------------------------------------------------------- bit manipulation
BM = "UM020 Bit Manipulation table, cache case (T020a group_0)"
rule("^(btst|bset|bclr|bchg)$", "imm|dreg,dreg", 4, BM + ": Dn destination 4")
for cls, vals in FIMM_GROUPS:
    f = vals[0]
    rule("^btst$", f"imm,{cls}", 4 + f, BM + f": BTST #,<ea> 4 + fetch-immediate-EA {cls} W {f}")
    rule("^(bset|bclr|bchg)$", f"imm,{cls}", 4 + f,
         BM + f": BSET/BCLR/BCHG #,<ea> 4 + fetch-immediate-EA {cls} W {f}; read and written", acc=2)
rule("^btst$", "dreg,mem", 4, BM + ": BTST Dn,<ea> 4 + fetch-EA", fetch=[1])
rule("^(bset|bclr|bchg)$", "dreg,mem", 4, BM + ": Dn,<ea> 4 + fetch-EA; read and written",
     fetch=[1], acc=2)

# ---------------------------------------------------------------- bit fields (register forms)
BF = ("UM020 Bit Field table, register forms, cache case, as T020a group_e gives them (T020a "
      "calibrates part of that block on hardware; T020b has no bit fields to cross-check)")
rule("^bftst$", "dreg,*,*", 6, BF + ": BFTST Dn 6")
rule("^bfext[su]$", "dreg,*,*,dreg", 8, BF + ": BFEXTU/BFEXTS Dn 8")
rule("^bfins$", "dreg,dreg,*,*", 10, BF + ": BFINS Dn 10")
rule("^bfffo$", "dreg,*,*,dreg", 18, BF + ": BFFFO Dn 18")
rule("^bfffo$", "mem,*,*,dreg", 18,
     "EST: BFFFO Dn 18 (UM020 via T020a) + calculate-EA + one operand read; the memory row of "
     "the UM020 bit-field table was not available in a transcription", calc=[0])
rule("^bf(tst|ext[su])$", "mem,*,*;mem,*,*,dreg", 8,
     "EST: register-form figure (UM020 via T020a, BFTST 6 / BFEXT 8) + calculate-EA + one read; "
     "memory rows not available in a transcription", calc=[0])

# ---------------------------------------------------------------- CAS
CAS = "UM020 CAS table (T020a group_0): 15 when the compare succeeds (single-threaded guest) + calculate-immediate-EA (.W)"
rule("^cas[bwl]$", "dreg,dreg,ind", 17, CAS + ": (An) 2; read and written", acc=2)
rule("^cas[bwl]$", "dreg,dreg,postinc|predec|disp|abs", 19, CAS + ": 4; read and written", acc=2)
rule("^cas[bwl]$", "dreg,dreg,index", 21, CAS + ": (d8,An,Xn) 6; read and written", acc=2)

# ---------------------------------------------------------------- address / stack / control
CTL = "UM020 Control instructions table, cache case (T020a group_4)"
rule("^lea$", "*,areg", 2, CTL + ": LEA 2 + calculate-EA; no data access", calc=[0], acc=0)
rule("^pea$", "*", 5, CTL + ": PEA 5 + calculate-EA; one push", calc=[0], acc=1)
rule("^linkw$", "areg,imm", 5, CTL + ": LINK.W 5; one push", acc=1)
rule("^linkl$", "areg,imm", 6, CTL + ": LINK.L 6; one push", acc=1)
rule("^unlk$", "areg", 6, CTL + ": UNLK 6; one pop", acc=1)
rule("^rts$", "", 10, CTL + ": RTS 10 (T020a 0x4E75); one pop", acc=1)
rule("^rtd$", "imm", 10, CTL + ": RTD 10 (T020a 0x4E74); one pop", acc=1)
# JSR 5 + jump-EA, JMP 4 + jump-EA; jump-EA: (An) 2, (d16,An)/(d16,PC) 4, indexed 6, abs 2
JEA = {"ind": 2, "disp": 4, "pcrel": 4, "index": 6, "abs": 2}
for cls, j in JEA.items():
    rule("^jsr$", cls, 5 + j, CTL + f": JSR 5 + jump-EA {cls} {j} (T020a jump_ea); one push", acc=1)
    rule("^jmp$", cls, 4 + j, CTL + f": JMP 4 + jump-EA {cls} {j} (T020a jump_ea); no data access",
         acc=0)
rule("^bsr[swl]$", "target", 7, CTL + ": BSR 7 (T020a group_6); one push", acc=1)
rule("^bra[swl]$", "target", 6, "UM020 Conditional Branch table: BRA = taken branch 6 (T020a group_6; T020b)")
BCC = "^b(hi|ls|cc|hs|cs|lo|ne|eq|vc|vs|pl|mi|ge|lt|gt|le)"
rule(BCC + "s$", "target", 5,
     "UM020 Bcc.B taken 6, not taken 4 (T020a group_6; T020b): blend = mean 5")
rule(BCC + "[wl]$", "target", 6,
     "UM020 Bcc.W/.L taken 6, not taken 6 (T020a group_6; T020b): blend = 6")
rule("^db(t|f|ra|hi|ls|cc|hs|cs|lo|ne|eq|vc|vs|pl|mi|ge|lt|gt|le)$", "dreg,target", 6,
     "UM020 DBcc, condition false and count not expired (looping) 6 (T020a group_5)")
# MOVEM: to registers 8 + 4n, to memory 4 + 3n, + calculate-immediate-EA (.W)
N_ST, N_LD, N_LD_DISP = 6, 6, 7
CIMMW = {"ind": 2, "postinc": 4, "predec": 4, "disp": 4, "index": 6, "abs": 4, "pcrel": 4}
MV = ("UM020 MOVEM (T020a group_4): {form}, + calculate-immediate-EA {cls} {c}; n = {n} "
      "registers assumed (mean register-list length of fb89_guest's static MOVEM.L {which}, "
      "objdump), one access per register")
for cls, c in CIMMW.items():
    if cls != "postinc":
        rule("^moveml$", f"reglist,{cls}", 4 + 3 * N_ST + c,
             MV.format(form="registers to memory 4 + 3n", cls=cls, c=c, n=N_ST, which="stores"),
             acc=N_ST)
    if cls != "predec":
        n = N_LD_DISP if cls != "postinc" else N_LD
        rule("^moveml$", f"{cls},reglist", 8 + 4 * n + c,
             MV.format(form="memory to registers 8 + 4n", cls=cls, c=c, n=n,
                       which="loads " + ("(An)+" if cls == "postinc" else "other modes")),
             acc=n)
rule("^movemw$", "reglist,mem", 4 + 3 * N_ST + 4,
     "UM020 MOVEM.W as MOVEM.L (same table), n = 6 assumed", acc=N_ST)
rule("^movemw$", "mem,reglist", 8 + 4 * N_LD + 4,
     "UM020 MOVEM.W as MOVEM.L (same table), n = 6 assumed", acc=N_LD)
rule("^trap$", "imm", 20,
     "EST: exception entry of a four-word (format $0) frame, 20 clocks as UM020 gives for the "
     "illegal/line-A/F-line traps (T020a exception_cycles); the system call itself is OS time "
     "and not modelled; frame 2 writes + vector read", acc=3)

# ---------------------------------------------------------------- MC68881
# UM881 Table 8-1 totals: FPn, integer, single, double, extended (packed not used)
T881 = {
    "move": [33, 60, 52, 58, 56], "int": [65, 92, 74, 80, 78], "sinh": [687, 714, 706, 712, 710],
    "intrz": [55, 82, 74, 80, 78], "sqrt": [107, 134, 126, 132, 130],
    "lognp1": [571, 598, 590, 596, 594], "etoxm1": [545, 572, 564, 570, 568],
    "tanh": [661, 688, 680, 686, 684], "atan": [403, 430, 422, 428, 426],
    "asin": [581, 608, 600, 606, 604], "atanh": [693, 720, 712, 718, 716],
    "sin": [391, 418, 410, 416, 414], "tan": [473, 500, 492, 498, 495],
    "etox": [497, 524, 516, 522, 520], "twotox": [567, 594, 586, 592, 590],
    "tentox": [567, 594, 586, 592, 590], "logn": [525, 552, 544, 550, 548],
    "log10": [581, 608, 600, 606, 604], "log2": [581, 608, 600, 606, 604],
    "abs": [35, 62, 54, 60, 58], "cosh": [607, 634, 626, 632, 630], "neg": [35, 62, 54, 60, 58],
    "acos": [625, 652, 644, 650, 648], "cos": [391, 418, 410, 416, 414],
    "getexp": [35, 72, 64, 70, 68], "getman": [31, 58, 50, 56, 54], "div": [105, 132, 124, 130, 128],
    "mod": [80, 99, 91, 97, 95], "add": [51, 80, 72, 78, 76], "mul": [71, 100, 92, 98, 96],
    "sgldiv": [69, 98, 90, 96, 94], "rem": [100, 129, 121, 127, 125],
    "scale": [41, 70, 62, 68, 66], "sglmul": [59, 88, 80, 86, 84], "sub": [51, 80, 72, 78, 76],
    "cmp": [35, 62, 54, 60, 58], "tst": [33, 60, 52, 58, 56],
}
# group rows with identical figures
groups = {}
for stem, row in T881.items():
    groups.setdefault(tuple(row), []).append(stem)
COL = {"b": 1, "w": 1, "l": 1, "s": 2, "d": 3, "x": 4}
LW = {"b": 1, "w": 1, "l": 1, "s": 1, "d": 2, "x": 3}
P = 8   # MPU protocol: command CIR write 3 clocks + response CIR read 5 clocks (2 wait states)
T881S = "UM881 Table 8-1 (T881 alu table)"
SPLIT = ("split: cpu = 8 protocol clocks (command CIR write 3 + response CIR read 5, the "
         "UM881 section 8 bus assumptions)")
FPU_MEM_ORDER = ["d", "s", "x", "l", "w", "b"]
# the operations compiled code uses get every source form; the rarer ones (transcendental,
# FGETEXP, FMOD, ...) get register, memory and Dn sources but no immediate forms
COMMON = {"move", "tst", "add", "sub", "mul", "div", "abs", "neg", "cmp", "int", "intrz", "sqrt"}
for row, stems in groups.items():
    alt = "|".join(sorted(stems))
    names = "/".join("F" + s.upper() for s in sorted(stems))
    common = bool(COMMON & set(stems))
    reg = row[0]
    # register to register; QEMU prints d (or x) for these whatever the precision
    shapes = "fpreg,fpreg;fpreg" if "tst" in stems else "fpreg,fpreg"
    rule(f"^f({alt})[bwlsdx]$", shapes, P, f"{T881S}: {names} FPm,FPn {reg}; {SPLIT}, "
         f"fpu = {reg} - 8", fpu=reg - P)
    for fmt_group in ("d", "s", "x", "bwl"):
        fmt = fmt_group[-1]
        col = COL[fmt]
        tot = row[col]
        L = LW[fmt]
        fpu = tot - (P + 6 * L + 2)
        mn = f"^f({alt})[{fmt_group}]$"
        what = {"d": "double", "s": "single", "x": "extended", "bwl": "integer"}[fmt_group]
        rule(mn, "mem,fpreg;mem" if "tst" in stems else "mem,fpreg", P + 6 * L,
             f"{T881S}: {names} <ea>,FPn {what} {tot} (taken as the (An) case); {SPLIT} + "
             f"{L} x (memory read 3 + operand CIR write 3) + calculate-EA (2 for (An)); "
             f"fpu = {tot} - {P + 6 * L + 2} = {fpu}", fpu=fpu, calc=[0], acc=L)
        if common:
            rule(mn, "imm,fpreg;imm" if "tst" in stems else "imm,fpreg", P + 3 * L,
                 f"{T881S}: {names} #<data>,FPn {what}: FPU part as the memory case ({fpu}); "
                 f"cpu = 8 protocol + {L} operand CIR write(s) 3 + the immediate's fetch from the "
                 f"instruction stream (ea.fetch imm.{fmt}) [EST]", fpu=fpu, fetch=[0], acc=0)
        if fmt_group in ("s", "bwl"):
            rule(mn, "dreg,fpreg;dreg" if "tst" in stems else "dreg,fpreg", P + 3,
                 f"{T881S}: {names} Dn,FPn {what} = {tot} - 5 (UM881 note, quoted by T881 with Table 8-2: "
                 f"MPU data register source, subtract 5); fpu as the memory case {fpu}, cpu = {tot - 5 - fpu}",
                 fpu=fpu)
# FMOVE FPn,<ea>: UM881 Table 8-2 (T881 store): long 100, single 80, extended 72, word 100,
# double 86, byte 100
STORE = {"l": 100, "s": 80, "x": 72, "w": 100, "d": 86, "b": 100}
for fmt, tot in STORE.items():
    L = LW[fmt]
    fpu = tot - (P + 6 * L + 2)
    name = {"l": "long", "s": "single", "x": "extended", "w": "word", "d": "double", "b": "byte"}[fmt]
    rule(f"^fmove{fmt}$", "fpreg,mem", P + 6 * L,
         f"UM881 Table 8-2 (T881 store): FMOVE FPn,<ea> {name} {tot} (taken as the (An) case); "
         f"{SPLIT} + {L} x (operand CIR read 3 + memory write 3) + calculate-EA; fpu = {fpu}",
         fpu=fpu, calc=[1], acc=L)
    if fmt in "bwls":
        rule(f"^fmove{fmt}$", "fpreg,dreg", tot - 2 - fpu,
             f"UM881 Table 8-2 (T881 store): FMOVE FPn,Dn {name} = {tot} - 2 (UM881 note, quoted by T881 with Table "
             f"8-2: MPU data register destination, subtract 2); fpu as the memory case {fpu}", fpu=fpu)
# FMOVE to/from FPCR/FPSR/FPIAR: T881 move_creg 29
rule("^fmovel$", "dreg,fpcr;fpcr,dreg", 11,
     "UM881 Table 8-2 (T881 move_creg): FMOVE to/from a control register 29; cpu = 8 protocol + "
     "3 (one operand CIR transfer), fpu = 18", fpu=18)
rule("^fmovel$", "mem,fpcr;fpcr,mem;imm,fpcr", 14,
     "UM881 Table 8-2 (T881 move_creg) 29 + EST: a memory operand adds a 3-clock memory cycle "
     "and calculate-EA; fpu = 18", fpu=18, calc=[0, 1])
rule("^fmovem[l]$", "*,fpcr;fpcr,*", 14,
     "UM881 Table 8-2 (T881 move_creg) 29 per register, one register assumed [EST]", fpu=18,
     calc=[0, 1])
# FMOVEM.X: to <ea> 35 + 25n, to registers 33 + 31n (T881 fmovem_to_ea/_to_regs, Table 8-2)
NF = 3
for cls in MEMS:
    rule("^fmovemx$", f"reglist,{cls}", P + 18 * NF,
         f"UM881 Table 8-2 (T881): FMOVEM.X to <ea> 35 + 25n, n = {NF} assumed (mean FP "
         f"register-list length of fb89_guest's static FMOVEM, objdump) = {35 + 25 * NF}; cpu = 8 "
         f"protocol + 18 per register (3 long words x (CIR read 3 + memory write 3)) + "
         f"calculate-EA; fpu = {35 + 25 * NF - P - 18 * NF - 2}",
         fpu=35 + 25 * NF - P - 18 * NF - 2, calc=[1], acc=3 * NF)
    rule("^fmovemx$", f"{cls},reglist", P + 18 * NF,
         f"UM881 Table 8-2 (T881): FMOVEM.X to registers 33 + 31n, n = {NF} assumed = "
         f"{33 + 31 * NF}; cpu = 8 protocol + 18 per register + calculate-EA; "
         f"fpu = {33 + 31 * NF - P - 18 * NF - 2}",
         fpu=33 + 31 * NF - P - 18 * NF - 2, calc=[0], acc=3 * NF)
# FMOVECR, FSINCOS: not in the transcription
rule("^fmovecrx$", "imm,fpreg", P,
     "EST: FMOVECR not found in a transcription of UM881 Table 8-1; priced as FMOVE FPm,FPn 33 "
     "(a constant-ROM read into a register); cpu 8 protocol, fpu 25", fpu=33 - P)
rule("^fsincos[bwlsdx]$", "fpreg,fpreg,fpreg", P,
     "EST: FSINCOS not found in a transcription of UM881 Table 8-1; priced as FSIN FPm,FPn 391 "
     "(a lower bound: one argument reduction and approximation) ", fpu=391 - P)
rule("^fsincos[bwlsdx]$", "mem,fpreg,fpreg", P + 12,
     "EST: FSINCOS priced as FSIN <ea>,FPn double 416 (UM881 Table 8-1 via T881)", fpu=416 - 22,
     calc=[0], acc=2)
# FBcc / FScc / FDBcc / FNOP: not in the transcription; MPU protocol + the integer branch
FCC = "(f|eq|ogt|oge|olt|ole|ogl|or|un|ueq|ugt|uge|ult|ule|ne|t|sf|seq|gt|ge|lt|le|gl|gle|ngle|ngl|nle|nlt|nge|ngt|sne|st)"
rule(f"^fb{FCC}[wl]?$", "target", 14,
     "EST: FBcc not found in a transcription of UM881 section 8; condition CIR write 3 + response "
     "CIR read 5 (UM881 section 8 bus assumptions) + the UM020 Bcc.W branch 6 (taken and not "
     "taken alike); the FPU evaluates the predicate within the response read (fpu 0)")
rule(f"^fs{FCC}$", "dreg", 12,
     "EST: FScc Dn: condition CIR write 3 + response CIR read 5 (UM881 section 8 assumptions) + "
     "UM020 Scc Dn 4")
rule(f"^fs{FCC}$", "mem", 14,
     "EST: FScc <ea>: condition CIR write 3 + response CIR read 5 + UM020 Scc <ea> 6 + "
     "calculate-EA", calc=[0])
rule(f"^fdb{FCC}$", "dreg,target", 14,
     "EST: FDBcc: condition CIR write 3 + response CIR read 5 + UM020 DBcc looping 6")
rule("^fnop$", "", P, "UM881 Table 8-2 (T881 nop): FNOP 16; cpu 8 protocol, fpu 8", fpu=8)

DEFAULT = {"cpu": 6, "source": "EST: an instruction no rule matches (the evaluator reports "
           "it): 6 clocks, about the modelled mean of fb89's integer instructions (5.9 on the "
           "Sun-3/260, 6.4 on the Sun-3/60, over the three reference scenes)"}

SOURCES = {
    "UM020": "Motorola, MC68020/MC68EC020 Microprocessors User's Manual (1992), section 8, "
             "Instruction Execution Timing: the cache-case column (instruction words in the "
             "on-chip cache, no overlap with neighbouring instructions). Figures read from two "
             "public transcriptions: T020a (complete) and T020b (a subset, which agrees with "
             "T020a wherever both give a figure).",
    "T020a": "benletchford/m68k-rs, src/core/timing_020.rs (commit 011f9c12fb2c), Case{cache,...} "
             "entries: fetch_ea, fetch_immediate_ea, calculate_ea, calculate_immediate_ea, "
             "jump_ea, MOVE_CACHE and the per-group tables. Its TAKEN_BRANCH_REFILL is "
             "that project's addition and is not used; part of its bit-field block is "
             "calibrated on an A1200 (only its register rows are used here, marked so).",
    "T020b": "mras0/acycles, cpu_model_020.cpp (commit ccc842a3d662), cycle_counts{best,cache,"
             "worst}: fetch EA, fetch immediate EA, MOVE, arithmetic, MUL/DIV, shifts, branches.",
    "UM881": "Motorola, MC68881/MC68882 Floating-Point Coprocessor User's Manual, "
             "section 8, Execution Timing (assumptions stated at the head of the section: FPCP idle when a command arrives; "
             "long-word aligned operands; 32-bit bus; zero-wait 3-clock memory; CIR accesses "
             "zero-wait except response and save CIRs, 2 wait states (5-clock reads); MPU and "
             "FPCP at the same clock). Paged copy: easymanua.ls/freescale-semiconductor/mc68881/"
             "manual?p=308 ff. Table 8-1/8-2 figures read from transcription T881.",
    "T881": "twvd/snow, core/src/cpu_m68k/fpu/timings.rs (commit 6e82d938a428), const MC68881: "
            "'MC68881 timings, Table 8-1 and 8-2 of the MC68881 user's manual' (alu rows FPn/"
            "int/sgl/dbl/ext, store by format, nop, move_creg, fmovem, Dn discounts 5 and 2).",
    "SUN": "MAME src/mame/sun/sun3.cpp (mamedev/mame, commit 0d310501db1f), header model table: "
           "3/60 '68020 @ 20MHz, 68881 (stock) ... 3 MIPS ... 200ns cycle' (100 ns 1M x 9 SIMMs); "
           "3/260 '68020 @ 25MHz, 68881 @ 20MHz (stock) ... 4 MIPS ... 64K write-back cache, "
           "direct-mapped, virtually-indexed and virtually-tagged, with 16-byte lines'.",
    "EST": "fb89's own derivation; the rule's source string gives the reasoning "
           "(docs/HOST_COST_MODEL.md).",
}

COMMON_NOTES = (
    "Cache case throughout: every instruction word hits the MC68020's 256-byte on-chip "
    "instruction cache and no pipeline overlap beyond the UM020 cache-case column is credited. "
    "Wait states are charged per data access only (memory_wait_states x accesses). Conditional "
    "branches are a blend: Bcc.B mean of taken 6 / not taken 4, Bcc.W/.L 6 either way, BRA "
    "taken, DBcc looping, FBcc as FScc protocol + Bcc.W. FPU instructions: cpu = the MPU's "
    "coprocessor-interface clocks (8 protocol clocks, 6 per transferred long word, calculate-EA), "
    "fpu = the UM881 table total minus those; the CPU waits for every FPU instruction (no "
    "CPU/FPU concurrency). MOVEM assumes 6 registers (7 for (d16,An) loads) and FMOVEM 3, the "
    "mean list lengths in fb89_guest. Not modelled: instruction-cache misses, data cache "
    "behaviour, MMU/page faults, branch outcomes, OS time. See docs/HOST_COST_MODEL.md.")


def cache_rules(read, write, src):
    """The events of the Sun-3/260's data cache (the plugin's "@dcache_64k_16b_wb_*"): misses
    at `read` and `write` clocks, and a dirty line written back before a fill replaces it at
    `write`; with read = write = 0, a machine without a cache."""
    return [{"mnemonic": "@dcache_64k_16b_wb_read_miss", "cpu": read, "source": src},
            {"mnemonic": "@dcache_64k_16b_wb_write_miss", "cpu": write, "source": src},
            {"mnemonic": "@dcache_64k_16b_wb_writeback", "cpu": write, "source": src},
            {"mnemonic": "@dcache_.*", "cpu": 0, "source": "another machine's cache: no cost"}]


def profile(name, desc, cpu, fpu, cpu_mhz, fpu_mhz, ws, notes, caches):
    return {
        "schema": 1,
        "name": name,
        "description": desc,
        "isa": "m68k",
        "cpu": cpu,
        "fpu": fpu,
        "cpu_clock_mhz": cpu_mhz,
        "fpu_clock_mhz": fpu_mhz,
        "memory_wait_states": ws,
        "sources": SOURCES,
        "notes": notes + " " + COMMON_NOTES,
        "ea": {"fetch": FETCH, "calc": CALC, "source": EA_SOURCE},
        "rules": caches + rules,
        "default": DEFAULT,
    }


p60 = profile(
    "sun3-60",
    "Sun-3/60: MC68020 at 20 MHz with an MC68881 at 20 MHz, no external cache",
    "MC68020 at 20 MHz", "MC68881 at 20 MHz",
    20.0, 20.0, 1,
    "SUN: 20 MHz MC68020 and MC68881, 200 ns memory cycle, no external cache. A 20 MHz MC68020 "
    "bus cycle is 3 clocks = 150 ns; a 200 ns memory cycle needs 4 clocks, so every data "
    "access is charged 1 wait state (memory_wait_states 1). CPU and FPU share the 20 MHz clock, "
    "the UM881 tables' own assumption.",
    cache_rules(0, 0, "SUN: the Sun-3/60 has no cache; every data access is charged its wait "
                "state instead"))
p260 = profile(
    "sun3-260",
    "Sun-3/260: MC68020 at 25 MHz with an MC68881 at 20 MHz, 64 KB write-back external cache",
    "MC68020 at 25 MHz", "MC68881 at 20 MHz",
    25.0, 20.0, 0,
    "SUN: 25 MHz MC68020, 20 MHz MC68881, 64 KB direct-mapped write-back cache with 16-byte "
    "lines. A hit costs 0 wait states (memory_wait_states 0); the plugin counts the data "
    "misses and the write-backs of dirty lines they cause, priced below; the virtually-tagged "
    "cache's flushes are not modelled. The FPU runs "
    "at 20 MHz: its part (fpu) is priced at its own clock, the coprocessor-interface part (cpu) "
    "at the MPU's 25 MHz, although CIR accesses are paced by the slower FPU.",
    cache_rules(10, 10, "EST: a 16-byte line filled from the 64-bit ECC memory in two transfers "
                "of about 200 ns (the Sun-3/60's memory cycle, SUN), 400 ns = 10 clocks at 25 MHz, "
                "and the same again for a dirty line written back before the fill; write-back, "
                "write-allocate (SunOS). No measured figure was found "
                "(docs/HOST_COST_MODEL.md, 'Caches')"))

for p in (p60, p260):
    with open(f"{OUT}/{p['name']}.json", "w") as f:
        json.dump(p, f, indent=2)
        f.write("\n")
print(len(rules), "rules")
