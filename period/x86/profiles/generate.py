#!/usr/bin/env python3
"""Writes period/x86/profiles/pc-386-25.json: a 386/25 PC with a 387 (docs/HOST_COST_MODEL.md,
"The 386 PC").

The x86 classifier (period/x86/classify.c) keys an instruction by its mnemonic as QEMU prints
it and its operands' kinds (reg, mem, memi, imm, st0, sti, seg, target), which is what the
386's and the 387's clock tables depend on. A rule is a mnemonic regex, an operand pattern
and the clocks: `cpu` the 386's, `fpu` the 387's (the 386 waits for the 387: no overlap is
credited). Edit the rules here and run `python3 period/x86/profiles/generate.py`; the JSON
is what fb89 embeds and reads.

Every figure carries a source tag (SOURCES below gives each in full):
  I386   the 80386's clock counts (Intel, 80386 Programmer's Reference Manual, 1986, ch. 17)
         as MAME transcribes them, the i386 column of src/devices/cpu/i386/cycles.h
  I387   the 387 DX's clock counts (Intel's data sheet) as 86Box transcribes them,
         x87_timings_387 in src/cpu/x87_timings.c; a range is taken at its mean
  EST    our derivation, reasoning in the string
"""
import json
import os
import re

OUT = os.path.dirname(os.path.abspath(__file__))

SOURCES = {
    "I386": "MAME src/devices/cpu/i386/cycles.h (mamedev/mame 5d5e698e5c22), x86_cycle_table, "
            "the i386 column (real mode / protected mode; fb89's guest is protected-mode code): "
            "Intel's 80386 clock counts, which assume the instruction prefetched and decoded, "
            "memory with no wait states, and add m for a transfer of control (the components of "
            "the next instruction).",
    "I387": "86Box src/cpu/x87_timings.c (86Box/86Box 26c884e3fedc), x87_timings_387: the 387 "
            "DX's clock counts by operation and operand (st(i), 32-bit, 64-bit real, 16/32/64-bit "
            "integer), a range given as its mean.",
    "EST": "fb89's own estimate; the reasoning is in the rule's source.",
}

rules = []
M = 2  # EST: m, the next instruction's components a transfer of control adds (I386's "+m")


def rule(mnemonic, operands, cpu, src, fpu=0.0, stand_in=False, accesses=None):
    r = {"mnemonic": "^(" + mnemonic + ")$"}
    if operands is not None:
        r["operands"] = operands
        calc = [i for i, o in enumerate(operands.split(",")) if "memi" in o.split("|")]
        if calc:
            r["calc"] = calc
    r["cpu"] = cpu
    if fpu:
        r["fpu"] = fpu
    if accesses is not None:
        r["accesses"] = accesses
    if stand_in:
        r["stand_in"] = True
    r["source"] = src
    rules.append(r)


MEM = "mem|memi"
ALU = "add|sub|and|or|xor|adc|sbb"

# ---- events ----------------------------------------------------------------------------------
rule("@dcache_32k_4b_wt_read_miss", None, 2,
     "EST: a read the 82385's cache misses goes to the Deskpro 386/25's DRAM; two wait states "
     "(80 ns DRAM behind the 82385 at 25 MHz; no figure of the machine's was found)")
rule("@dcache_32k_4b_wt_write_miss", None, 0,
     "EST: the 82385 is write-through with a posted write: the 386 goes on at once")
rule("@dcache_.*", None, 0, "another machine's cache: not this one's")

# ---- integer: moves ------------------------------------------------------------------------
for s in "lwb":
    rule(f"mov{s}", "reg|imm|seg,reg|seg", 2, "I386 MOV_REG_REG / MOV_IMM_REG 2")
    rule(f"mov{s}", f"reg|imm,{MEM}", 2, "I386 MOV_REG_MEM / MOV_IMM_MEM 2 (a store)")
    rule(f"mov{s}", f"{MEM},reg", 4, "I386 MOV_MEM_REG 4 (a load)")
rule("movzbl|movzwl|movsbl|movswl|movzbw|movsbw", "reg,reg", 3, "I386 MOVZX/MOVSX_REG_REG 3")
rule("movzbl|movzwl|movsbl|movswl|movzbw|movsbw", f"{MEM},reg", 6, "I386 MOVZX/MOVSX_MEM_REG 6")
rule("leal|leaw", None, 2, "I386 LEA 2", accesses=0)
rule("xchgl|xchgw|xchgb", "reg,reg", 3, "I386 XCHG_REG_REG 3")
rule("xchgl|xchgw|xchgb", None, 5, "I386 XCHG_REG_MEM 5", accesses=2)
rule("pushl|pushw", "reg|imm|seg", 2, "I386 PUSH_REG_SHORT / PUSH_IMM 2", accesses=1)
rule("pushl|pushw", None, 5, "I386 PUSH_RM 5", accesses=2)
rule("popl|popw", "reg|seg", 4, "I386 POP_REG_SHORT 4", accesses=1)
rule("popl|popw", None, 5, "I386 POP_RM 5", accesses=2)
rule("pushfl|pushfw", None, 4, "I386 PUSHF 4", accesses=1)
rule("popfl|popfw", None, 5, "I386 POPF 5", accesses=1)
rule("cltd|cwtd", None, 2, "I386 CWD 2")
rule("cwtl|cbtw", None, 3, "I386 CBW 3")
# ---- integer: arithmetic and logic ------------------------------------------------------------
for s in "lwb":
    rule(f"(?:{ALU}){s}", "reg|imm,reg", 2, "I386 ALU_REG_REG / ALU_IMM_REG 2")
    rule(f"(?:{ALU}){s}", f"{MEM},reg", 6, "I386 ALU_MEM_REG 6 (the operand loaded)")
    rule(f"(?:{ALU}){s}", f"reg|imm,{MEM}", 7, "I386 ALU_REG_MEM / ALU_IMM_MEM 7 (read and written)",
         accesses=2)
    rule(f"cmp{s}", "reg|imm,reg", 2, "I386 CMP_REG_REG / CMP_IMM_REG 2")
    rule(f"cmp{s}", f"{MEM},reg", 6, "I386 CMP_MEM_REG 6")
    rule(f"cmp{s}", f"reg|imm,{MEM}", 5, "I386 CMP_REG_MEM / CMP_IMM_MEM 5")
    rule(f"test{s}", "reg|imm,reg", 2, "I386 TEST_REG_REG / TEST_IMM_REG 2")
    rule(f"test{s}", None, 5, "I386 TEST_REG_MEM / TEST_IMM_MEM 5")
    rule(f"(?:inc|dec|neg|not){s}", "reg", 2, "I386 INC/DEC/NEG/NOT_REG 2")
    rule(f"(?:inc|dec|neg|not){s}", None, 6, "I386 INC/DEC/NEG/NOT_MEM 6", accesses=2)
    rule(f"(?:shl|shr|sar|sal|rol|ror){s}", "reg|imm,reg", 3, "I386 ROTATE_REG 3 (shifts alike)")
    rule(f"(?:shl|shr|sar|sal|rol|ror){s}", "reg", 3, "I386 ROTATE_REG 3 (by one)")
    rule(f"(?:shl|shr|sar|sal|rol|ror){s}", None, 7, "I386 ROTATE_MEM 7", accesses=2)
    rule(f"(?:rcl|rcr){s}", "reg|imm,reg", 9, "I386 ROTATE_CARRY_REG 9")
    rule(f"(?:rcl|rcr){s}", None, 10, "I386 ROTATE_CARRY_MEM 10", accesses=2)
rule("shldl|shrdl", "reg|imm,reg,reg|imm", 3, "I386 SHLD/SHRD_REG 3")
rule("shldl|shrdl|shld|shrd", None, 3, "I386 SHLD/SHRD_REG 3 (a register destination)")
rule("imull|imulw", f"reg,reg|imm,reg,reg", 24,
     "I386 IMUL r32 9-38 (MAME gives the worst, 41): the early-out multiplier's clocks by the "
     "multiplier's size; EST the range's mean, 24")
rule("imull|imulw", None, 24, "as IMUL r32 (EST mean 24); a memory operand adds its load, 3",)
rule("imull|mull|imulw|mulw", "reg", 24, "I386 MUL/IMUL r32 9-38: EST the mean, 24")
rule("imull|mull|imulw|mulw", None, 27, "I386 MUL/IMUL m32 12-41: EST the mean, 27")
rule("divl", "reg", 38, "I386 DIV32_ACC_REG 38")
rule("divl", None, 41, "I386 DIV32_ACC_MEM 41")
rule("idivl", "reg", 43, "I386 IDIV32_ACC_REG 43")
rule("idivl", None, 46, "I386 IDIV32_ACC_MEM 46")
rule("set[a-z]+", "reg", 4, "I386 SETCC_REG 4")
rule("set[a-z]+", None, 5, "I386 SETCC_MEM 5")
rule("bsfl|bsrl", None, 9 + 3 * 16, "I386 BSR_BASE 9 + 3 a bit: EST sixteen bits scanned")
rule("btl|btw", "reg|imm,reg", 3, "I386 BT_REG_REG / BT_IMM_REG 3")
rule("btl|btw", None, 12, "I386 BT_REG_MEM 12")
# ---- control ---------------------------------------------------------------------------------
rule("jmp", "target", 7 + M, "I386 JMP 7 + m (m = 2, EST)")
rule("j[a-z]+", "target", 3 + (7 + M - 3) / 2,
     "I386 JCC taken 7 + m, not taken 3 (JCC_DISP8, _NOBRANCH): EST half taken, m = 2: 6")
rule("jmpl|jmp", "reg", 7 + M, "I386 JMP_REG 7 + m")
rule("jmpl|jmp", None, 10 + M, "I386 JMP_MEM 10 + m")
rule("calll|call", "target|reg", 7 + M, "I386 CALL / CALL_REG 7 + m", accesses=1)
rule("calll|call", None, 10 + M, "I386 CALL_MEM 10 + m", accesses=2)
rule("retl|ret", None, 10 + M, "I386 RET / RET_IMM 10 + m", accesses=1)
rule("leave|leavel", None, 4, "I386 LEAVE 4", accesses=1)
rule("enter|enterl", None, 10, "I386 ENTER 10", accesses=1)
rule("nop|nopl|nopw|xchgw", None, 3, "I386 NOP 3 (a multi-byte NOP as one)")
rule("int", None, 37, "I386 INT 37: a system call's entry (the system call itself is OS time, "
     "not modelled)")
rule("cld|std|clc|stc|cmc", None, 2, "I386 CLD/STD/CLC/STC/CMC 2")
rule("sahf", None, 3, "I386 SAHF 3")
rule("lahf", None, 2, "I386 LAHF 2")
# ---- strings: QEMU runs a REP string instruction as one execution an iteration -----------------
rule("rep_movs[lwb]", None, 8, "I386 REP_MOVS 8 an iteration (its base 8 once, left out)",
     accesses=2)
rule("rep_stos[lwb]", None, 5, "I386 REP_STOS 5 an iteration", accesses=1)
rule("rep_lods[lwb]", None, 5, "I386 REP_LODS 5 an iteration", accesses=1)
rule("(?:repe|repne|repz|repnz)_scas[lwb]", None, 5, "I386 REP_SCAS 5 an iteration", accesses=1)
rule("(?:repe|repne|repz|repnz)_cmps[lwb]", None, 5, "I386 REP_CMPS 5 an iteration", accesses=2)
rule("movs[lwb]", None, 8, "I386 MOVS 8", accesses=2)
rule("stos[lwb]", None, 5, "I386 STOS 5", accesses=1)
rule("lods[lwb]", None, 5, "I386 LODS 5", accesses=1)
rule("scas[lwb]", None, 8, "I386 SCAS 8", accesses=1)
rule("cmps[lwb]", None, 10, "I386 CMPS 10", accesses=2)

# ---- the 387 (the 386 waits: its ESC instructions take the 387's time) -------------------------
ESC = 3  # EST: the 386's side of the coprocessor protocol for one 387 instruction
WORD = 5  # EST: and for each doubleword of a memory operand, read and handed to the 387


def fp(mnemonic, operands, clocks, src, stand_in=False, cpu=0):
    """A 387 instruction: its clocks on the 387, and on the 386 the protocol: the opcode
    handed over (ESC) and each doubleword of a memory operand read or written and passed
    through the 386 (WORD each; the 387 has no bus of its own), taken from the mnemonic's
    operand size."""
    words = 0
    if operands is None or "mem" in (operands or ""):
        if re.search(r"(?:fld|fst|fstp)t$", mnemonic.split("|")[0]):
            words = 3
        elif re.search(r"^fi.*ll$|^fi.*q$", mnemonic.split("|")[0]):
            words = 2
        elif re.search(r"^fi", mnemonic.split("|")[0]):
            words = 1
        elif re.search(r"l$", mnemonic.split("|")[0]) and not mnemonic.startswith("fucom"):
            words = 2
        elif re.search(r"s$", mnemonic.split("|")[0]):
            words = 1
    rule(mnemonic, operands, cpu + ESC + WORD * words,
         src + f"; the 386: ESC {ESC} + {words} doubleword(s) x {WORD} (EST)",
         fpu=clocks, stand_in=stand_in)


fp("fld", "st0|sti", 14, "I387 fld st(i) 14")
fp("flds", None, 20, "I387 fld m32 20")
fp("fldl", None, 25, "I387 fld m64 25")
fp("fldt", None, 44, "I387 fld m80 44")
fp("fldz|fld1", None, 22, "I387 fldz/fld1 20-24")
fp("fldpi|fldl2e|fldl2t|fldlg2|fldln2", None, 40, "I387 fld constant 40")
fp("fst|fstp", "st0|sti", 11, "I387 fst st(i) 11")
fp("fsts|fstps", None, 44, "I387 fst m32 44")
fp("fstl|fstpl", None, 45, "I387 fst m64 45")
fp("fstpt", None, 53, "I387 fstp m80 53")
fp("fnstsw|fstsw|fnstcw|fstcw", None, 15, "I387 fstcw/fstsw 15")
fp("fldcw", None, 19, "I387 fldcw 19")
fp("fldenv", None, 71, "I387 fldenv 71")
fp("fnstenv|fstenv", None, 103, "I387 fstenv 103")
fp("fxch", None, 18, "I387 fxch 18")
STACK = ("st0|sti,st0|sti", "st0|sti")  # the register forms, with two operands or one
for ops in STACK:
    fp("fadd|faddp|fsub|fsubp|fsubr|fsubrp", ops, 28, "I387 fadd st(i) 23-34")
fp("fadds|fsubs|fsubrs", None, 28, "I387 fadd m32 24-32")
fp("faddl|fsubl|fsubrl", None, 33, "I387 fadd m64 29-37")
FMUL = "; EST: the top of the range, the 387 multiplying at the extended precision Linux (and DOS) leave it in"
for ops in STACK:
    fp("fmul|fmulp", ops, 57, "I387 fmul st(i) 29-57" + FMUL)
fp("fmuls", None, 35, "I387 fmul m32 27-35" + FMUL)
fp("fmull", None, 57, "I387 fmul m64 32-57" + FMUL)
for ops in STACK:
    fp("fdiv|fdivp|fdivr|fdivrp", ops, 89, "I387 fdiv st(i) 88-91")
fp("fdivs|fdivrs", None, 89, "I387 fdiv m32 89")
fp("fdivl|fdivrl", None, 94, "I387 fdiv m64 94")
fp("fcom|fcomp|fcompp|fucom|fucomp|fucompp", "st0|sti", 24, "I387 fcom st(i) 24, fucom 24")
fp("fcom|fcomp|fcompp|fucom|fucomp|fucompp", None, 24, "I387 fcom st(i) 24, fucom 24")
fp("fcoms|fcomps", None, 26, "I387 fcom m32 26")
fp("fcoml|fcompl", None, 31, "I387 fcom m64 31")
fp("ftst", None, 28, "I387 ftst 28")
fp("fxam", None, 34, "I387 fxam 30-38")
fp("fabs", None, 22, "I387 fabs 22")
fp("fchs", None, 24, "I387 fchs 24-25")
fp("fsqrt", None, 125, "I387 fsqrt 122-129")
fp("frndint", None, 73, "I387 frndint 66-80")
fp("fscale", None, 76, "I387 fscale 67-86")
fp("f2xm1", None, 343, "I387 f2xm1 211-476")
fp("fyl2x", None, 329, "I387 fyl2x 120-538")
fp("fyl2xp1", None, 402, "I387 fyl2xp1 257-547")
fp("fsin|fcos", None, 446, "I387 fsin/fcos 122-771")
fp("fsincos", None, 501, "I387 fsincos 194-809")
fp("fptan", None, 344, "I387 fptan 191-497")
fp("fpatan", None, 400, "I387 fpatan 314-487")
fp("fprem", None, 114, "I387 fprem 74-155")
fp("fprem1", None, 140, "I387 fprem1 95-185")
fp("fxtract", None, 73, "I387 fxtract 70-76")
fp("filds", None, 63, "I387 fild m16 61-65")
fp("fildl", None, 48, "I387 fild m32 45-52")
fp("fildll|fildq", None, 61, "I387 fild m64 56-67")
fp("fists|fistps", None, 88, "I387 fist m16 82-95")
fp("fistl|fistpl", None, 86, "I387 fist m32 79-93")
fp("fistpll|fistpq", None, 88, "I387 fistp m64 80-97")
fp("fiadds|fisubs|fisubrs", None, 78, "I387 fiadd m16 71-85")
fp("fiaddl|fisubl|fisubrl", None, 64, "I387 fiadd m32 57-72")
fp("fimuls", None, 81, "I387 fimul m16 76-87")
fp("fimull", None, 71, "I387 fimul m32 61-82")
fp("fidivs|fidivrs", None, 138, "I387 fidiv m16 136-140")
fp("fidivl|fidivrl", None, 123, "I387 fidiv m32 120-127")
fp("ficoms|ficomps", None, 73, "I387 ficom m16 71-75")
fp("ficoml|ficompl", None, 59, "I387 ficom m32 56-63")
fp("fnclex|fclex", None, 11, "I387 fclex 11")
fp("fninit|finit", None, 33, "I387 finit 33")
fp("ffree", None, 18, "I387 ffree 18")
fp("fincstp|fdecstp", None, 22, "I387 fincstp 22")
fp("fwait|wait", None, 6, "I387 fwait 6")
fp("fnop", None, 12, "I387 fnop 12")

# ---- what the 386 and 387 do not have: P6 and later forms in Debian's i686 C library, priced
# ---- as the sequences that would stand in for them (stand_in: reported apart) -----------------
rule("cmov[a-z]+", "reg,reg", 3 + (7 + M - 3) / 2 + 2, "EST, stand-in: a conditional jump "
     "around a move (I386 JCC half taken 6 + MOV 2)", stand_in=True)
rule("cmov[a-z]+", None, 3 + (7 + M - 3) / 2 + 4, "EST, stand-in: a conditional jump around "
     "a load (I386 JCC 6 + MOV_MEM_REG 4)", stand_in=True)
fp("fucomi|fucomip|fcomi|fcomip", None, 24 + 15, "EST, stand-in: fucom(p) and fnstsw %ax "
   "(I387 24 + 15), then sahf (I386 3)", stand_in=True, cpu=3)
fp("fcmov[a-z]+", None, 14 + 11, "EST, stand-in: a conditional jump around fld st(i), fstp "
   "st(j) (I387 14 + 11; I386 JCC 6)", stand_in=True, cpu=6)
rule("endbr32", None, 0, "EST, stand-in: a control-flow marker of the CET-enabled library, "
     "which a 386 build would not have: nothing", stand_in=True)
rule("cpuid", None, 20, "EST, stand-in: the library's CPU detection, which on a 386 is a few "
     "flag tests (pushfl, popfl and compares, about 20 clocks)", stand_in=True)
rule("bswapl|bswap", None, 9, "EST, stand-in: three rotates (rolw 8, roll 16, rolw 8; I386 "
     "ROTATE_REG 3 each)", stand_in=True)
rule("lock_cmpxchgl|cmpxchgl|lock_cmpxchg8b", None, 12, "EST, stand-in: a compare, a "
     "conditional jump and a store on the one-processor 386 (I386 CMP_MEM_REG 6 + JCC 3 + "
     "MOV 2 ... about 12)", stand_in=True, accesses=2)
rule("lock_xaddl|xaddl", None, 11, "EST, stand-in: a load, an add and a store (I386 4 + 2 + 2, "
     "a move 3)", stand_in=True, accesses=2)
rule("lock_(?:add|sub|inc|dec|and|or|xor)[lwb]", None, 7, "I386 ALU_REG_MEM 7 (LOCK costs "
     "nothing more on a 386 alone on its bus)", accesses=2)
rule("tzcntl|lzcntl", None, 9 + 3 * 16, "EST, stand-in: as BSF (I386 BSF_BASE 9 + 3 a bit, "
     "sixteen bits)", stand_in=True)
rule(r"\.byte", None, 4, "EST: an instruction QEMU's disassembler saw only in part (it spans "
     "a page boundary): the mean of the integer table, about 4")

DEFAULT = {"cpu": 4, "source": "EST: an instruction no rule names; about the mean of the 386's "
           "integer table"}

profile = {
    "schema": 1,
    "name": "pc-386-25",
    "description": "386/25 PC (Compaq Deskpro 386/25 class): Intel 80386 at 25 MHz, Intel 387 DX "
                   "at 25 MHz, 32 KB 82385 write-through cache",
    "isa": "x86",
    "cpu": "Intel 80386 at 25 MHz",
    "fpu": "Intel 80387 at 25 MHz",
    "cpu_clock_mhz": 25,
    "fpu_clock_mhz": 25,
    "memory_wait_states": 0,
    "memory_classes": ["mem", "memi"],
    "operand_groups": {},
    "sources": SOURCES,
    "notes": "The 386 and the 387 at 25 MHz, as the Compaq Deskpro 386/25 (1988) had them, with "
             "its 32 KB external cache (Intel 82385: direct-mapped, write-through with a posted "
             "write, filled a doubleword at a time: the plugin's cache of 4-byte lines). Integer "
             "clocks from Intel's 386 table (I386), 387 clocks from Intel's (I387); a hit costs "
             "no wait state, a read miss is priced as DRAM. The 386 waits for every 387 "
             "instruction (no overlap credited). Debian's i686 library instructions the 386 "
             "lacks (cmov, fucomi, fcmov, cpuid, endbr32 ...) are priced as 386 stand-ins "
             "(stand_in). Not modelled: the prefetch queue's stalls, instruction fetch misses, OS "
             "time. See docs/HOST_COST_MODEL.md.",
    "ea": {"fetch": {}, "calc": {"memi": 1},
           "source": "I386: an effective address with a base and an index register adds a "
                     "clock (Intel 80386 manual, chapter 17's notes); the rules' memi operands"},
    "rules": rules,
    "default": DEFAULT,
}

with open(os.path.join(OUT, "pc-386-25.json"), "w") as f:
    json.dump(profile, f, indent=2)
    f.write("\n")
