#!/usr/bin/env python3
"""Writes period/sparc/profiles/sun4-260.json, sparcstation-1.json and sparcstation-2.json:
one integer rule list, and per machine its FPU table, its data cache and its register-window
count (docs/HOST_COST_MODEL.md, "SPARC").

The SPARC classifier (period/sparc/classify.c) keys an instruction by its mnemonic alone,
so a rule is a mnemonic regex and the cycles it costs: a V7 timing table does not depend on
addressing modes. Edit the rules here and run `python3 period/sparc/profiles/generate.py`;
the JSON files are what fb89 embeds and reads.

Every figure carries a source tag (SOURCES below gives each in full):
  SIS     gdb's SIS simulator, a V7 model "roughly equivalent to the Cypress C601": integer
          T_LD 2, T_LDD 3, T_ST 3, T_STD 4, T_LDST 4, T_JMPL 2, T_RETT 2, others 1; load-use
          +1; an annulled slot 1; TRAP_C 3. Every machine's integer unit.
  FPA     the Sun-3 FPA's microcode (SunOS 4.1.3 usr.etc/fpa/microcode), which drives the
          Weitek 1164/1165 the Sun-4/260's FPC drives: its operations counted per routine.
  SUNAS, GAS  Sun's assembler (which FPops run on which Weitek chip) and GNU as (the fmovs
          after every fdiv on the 1165).
  MAMEFPU MAME's SPARCstation 1 core (complete_fp_execution): the WTL3170's table.
  CYPRESS GCC's cypress.md: the CY7C601/602 pipeline, the SPARCstation 2's (TI's 602a).
  SUNOS   SunOS 4.1.3 sources: window trap handlers, libm's software sqrt, the kernel's FPU
          emulation (an unimplemented fsqrt on the Weitek 1164/1165).
  LIBGCC  libgcc's V7 .umul/.udiv, counted under the emulator.
  MAME    MAME src/mame/sun/sun4.cpp, header table of machines.
  EST     our derivation, reasoning in the string.
"""
import json
import os

OUT = os.path.dirname(os.path.abspath(__file__))

rules = []


def rule(mnemonic, cpu, src, fpu=0.0, stand_in=False):
    r = {"mnemonic": mnemonic, "cpu": cpu}
    if fpu:
        r["fpu"] = fpu
    if stand_in:
        r["stand_in"] = True
    r["source"] = src
    rules.append(r)


# ---- integer unit (SIS, V7) ------------------------------------------------------------
rule("ld|ldub|lduh|ldsb|ldsh", 2, "SIS T_LD 2")
rule("ldd", 3, "SIS T_LDD 3")
rule("st|stb|sth", 3, "SIS T_ST 3")
rule("std", 4, "SIS T_STD 4")
rule("ldstub", 4, "SIS T_LDST 4")
rule("jmpl", 2, "SIS T_JMPL 2 (call through a register, ret, retl)")
rule("rett", 2, "SIS T_RETT 2")
rule("call|ba|ba,a|bn|bn,a|bicc|bicc,a|fba|fba,a|fbfcc|fbfcc,a|cbccc", 1,
     "SIS: a branch or call is 1 cycle, taken or not; its delay slot is an instruction of "
     "its own, an annulled one @annulled_slot")
rule("nop|sethi|add|addcc|addx|addxcc|sub|subcc|subx|subxcc|and|andcc|andn|andncc|or|orcc"
     "|orn|orncc|xor|xorcc|xnor|xnorcc|sll|srl|sra|mulscc|taddcc|tsubcc|taddcctv|tsubcctv"
     "|save|restore|rdy|wry|unimp", 1,
     "SIS: every other integer instruction 1 cycle (save and restore too; their window "
     "traps are @window_overflow and @window_underflow)")
rule("ticc", 4, "SIS TRAP_C 3 + the trap instruction: a system call's trap entry (the "
     "system call itself is OS time, not modelled)")
rule("flush", 1, "EST: an instruction-cache flush; the Sun-4's IU has no instruction cache "
     "to flush, so 1 cycle")

# ---- events the counts show as pseudo-classes -------------------------------------------
rule("@load_use", 1, "SIS: an instruction that uses the register the load before it wrote "
     "waits one cycle (LOAD_DEL)")
rule("@annulled_slot", 1, "SIS interf.c: an annulled delay-slot instruction still takes "
     "its cycle")
# ---- FP loads and stores: the integer unit's memory cycles (SIS), on every machine ----------
rule("ldf", 2, "SIS T_LD 2 (an FP load as an integer one)")
rule("lddf", 3, "SIS T_LDD 3")
rule("stf", 3, "SIS T_ST 3")
rule("stdf", 4, "SIS T_STD 4")
rule("ldfsr", 2, "SIS T_LD 2")
rule("stfsr", 3, "SIS T_ST 3")

# ---- what neither machine has: V8/V9 forms in Debian's V8plus libraries, priced as the V7
# ---- sequences that would stand in for them (stand_in: reported apart per run) ----------
STAND = "EST, stand-in: "
rule("bpcc|bpcc,a|fbpfcc|fbpfcc,a", 1, STAND + "a V9 predicted branch is a V7 branch, 1 "
     "(SIS)", stand_in=True)
rule("bpr", 2, STAND + "V9 brz/brlz/... is a V7 tst and branch, 1 + 1 (SIS)", stand_in=True)
rule("movcc|movr|fmovcc", 2, STAND + "a V9 conditional move is a V7 branch over a move, "
     "1 + 1 (SIS)", stand_in=True)
rule("return", 3, STAND + "V9 return is a V7 jmpl and restore, 2 + 1 (SIS); its window "
     "trap, if any, is @window_underflow", stand_in=True)
rule("umul|smul|umulcc|smulcc", 34, STAND + "a V8 multiply is a call of libgcc's .umul: "
     "call and delay slot 2 + 23 instructions (both operands under 4096) or 40 (LIBGCC, "
     "counted), the mean of the two paths, 34", stand_in=True)
rule("udiv|sdiv|udivcc|sdivcc", 90, STAND + "a V8 divide is a call of libgcc's .udiv: "
     "2 + 43 (quotient < 16) to 131 (quotient near 10^6) instructions, about 22 a 4-bit "
     "digit of the quotient (LIBGCC, counted); 90 for the library's typical 5-digit "
     "quotients", stand_in=True)
rule("mulx", 110, STAND + "a V9 64-bit multiply is three 32-bit .umul calls and adds "
     "(3 x 34 + 8)", stand_in=True)
rule("udivx|sdivx", 300, STAND + "a V9 64-bit divide is libgcc's __udivdi3 in V7 code, "
     "a shift-and-subtract loop over the quotient's bits: about 300", stand_in=True)
rule("sllx|srlx|srax", 4, STAND + "a 64-bit shift of a register pair: two shifts, the "
     "carried bits shifted back and or-ed in, 4 (SIS 1 each)", stand_in=True)
rule("ldx", 3, STAND + "a V9 64-bit load is a V7 ldd, SIS T_LDD 3", stand_in=True)
rule("stx", 4, STAND + "a V9 64-bit store is a V7 std, SIS T_STD 4", stand_in=True)
rule("ldsw", 2, STAND + "V9 ldsw is a V7 ld, SIS T_LD 2", stand_in=True)
rule("swap", 4, STAND + "V8 swap (the MB86900 has none) is a ld and st under a lock; in a "
     "single-threaded program SIS T_LDST 4", stand_in=True)
rule("casa|casxa", 7, STAND + "compare-and-swap in a single-threaded program is ld, cmp, "
     "bne, st: 2 + 1 + 1 + 3 (SIS)", stand_in=True)
rule("stbar|rdasr|prefetch|prefetcha|flushw", 1, STAND + "a V8/V9 barrier, prefetch or "
     "flushw has no V7 work of its own (a flushw's spills are @window_overflow): 1",
     stand_in=True)
rule("popc", 40, STAND + "a population count is a V7 loop over the bits: about 40",
     stand_in=True)
rule("fstox|fdtox|fxtos|fxtod", 1, STAND + "a V9 64-bit integer conversion is a V7 "
     "conversion and integer fix-ups, about 10", fpu=9, stand_in=True)
rule("lda|lduba|lduha|ldsba|ldsha|ldswa|ldfa", 2, STAND + "a V9 user alternate-space load "
     "is a V7 load, SIS T_LD 2", stand_in=True)
rule("ldda|lddfa|ldxa", 3, STAND + "SIS T_LDD 3", stand_in=True)
rule("sta|stba|stha|stfa", 3, STAND + "SIS T_ST 3", stand_in=True)
rule("stda|stdfa|stxa", 4, STAND + "SIS T_STD 4", stand_in=True)

DEFAULT = {"cpu": 2, "source": "EST: an instruction no rule names (none in fb89's runs); "
           "about the mean of the table"}

# ---- each machine's floating-point unit --------------------------------------------------
# The IU issues an FPop in one cycle (cpu 1); `fpu` is the rest of its latency. fb89 prices the
# whole latency of every FPop, as if the IU waited for each (no IU/FPU overlap is credited).


def fp(mnemonic, latency, src, stand_in=False):
    """An FPop of `latency` cycles: 1 to issue, the rest the FPU's."""
    r = {"mnemonic": mnemonic, "cpu": 1, "fpu": float(latency - 1)}
    if stand_in:
        r["stand_in"] = True
    r["source"] = src
    return r


FPA = ("FPA (the Sun-3 FPA's microcode, which drives the same two Weitek chips): a whole "
       "operation from register file to register file, operands loaded 32 bits at a time, the "
       "chip's wait, the result unloaded and written back")
WEITEK_1164 = [
    fp("fmovs|fnegs|fabss", 4, "SUNAS: FMOV, FABS and FNEG execute on the FPC itself (no "
       "Weitek chip); MAMEFPU: 4"),
    fp("fadds|fsubs", 10, FPA + ": c.sadd/c.ssub, 2 loads, 4 waiting, 1 unload, 3 writing back "
       "and dispatching, about 10 microcycles"),
    fp("faddd|fsubd", 13, FPA + ": c.dadd/c.dsub on the 1165, 4 loads, 4 waiting, 2 unloads, 3 "
       "writing back, about 13 microcycles"),
    fp("fmuls", 10, FPA + ": c.smul on the 1164, about 10 microcycles"),
    fp("fmuld", 14, FPA + ": c.dmul on the 1164, 4 loads, 6 waiting, 2 unloads, about 14 "
       "microcycles (the 1164's own double multiply is 0.60 us flow-through: Trissel, "
       "net.micro.16k, 1985)"),
    fp("fdivs", 35 + 4, FPA + ": c.sdiv on the 1165 (lpreg 13: 'a delay of 28'), about 35 "
       "microcycles; + the fmovs that follows every fdiv on these machines (the 1165's divide "
       "could leave a wrong result without it: GAS SPECIAL_CASE_FDIV), 4"),
    fp("fdivd", 67 + 4, FPA + ": c.ddiv on the 1165 (lpreg 27: 'a delay of 56'), about 67 "
       "microcycles; + the fmovs that follows every fdiv on these machines (GAS "
       "SPECIAL_CASE_FDIV), 4"),
    fp("fcmps|fcmpd|fcmpes|fcmped", 11, FPA + ": c.dcmp, 4 loads, 4 waiting and the status "
       "test, about 11 microcycles"),
    fp("fitos|fstoi", 16, "MAMEFPU: FiTOs 16, FsTOi 16 (no FPA routine counted for the "
       "conversions)"),
    fp("fitod|fdtoi", 8, "MAMEFPU: FiTOd 8, FdTOi 8"),
    fp("fstod|fdtos", 8, "MAMEFPU: FsTOd, FdTOs 8"),
    fp("fsqrts|fsqrtd", 11000, "EST from SUNOS: the 1164/1165 have no square root ('Weitek fpu "
       "- fsqrt not available', diagnostics/fpurel/instruction.c), so fsqrt is an "
       "unimplemented FPop: a deferred fp_exception trap, the FQ dumped (sys/sparc/float.s), "
       "fp_runq simulating it (sys/sparc/fpu/fpu.c) by _fp_sqrt's bit-by-bit root over a "
       "113-bit significand (sys/sparc/fpu/div.c: 17 + 3 x 32 steps, each a 4-word shift, a "
       "multiword compare call and, on about half, 4 multiword add/subtract calls: some 60 "
       "instructions, about 95 cycles at SIS's figures), then the 32 FP registers re-read "
       "through a jump table and the trap returned: 113 x 95 + about 300 for unpacking, "
       "packing and the trap path, about 11000"),
    fp("fmovd|fnegd|fabsd|impdep1", 8, "EST, stand-in: a V9 double move (or VIS fzero/fone) is "
       "two V7 fmovs, 2 x 4", stand_in=True),
    fp("fsmuld", 8 + 8 + 14, "EST, stand-in: V8 fsmuld is two fstod and an fmuld, 8 + 8 + 14",
       stand_in=True),
]

WEITEK_3170 = [
    fp("fmovs|fnegs|fabss", 4, "MAMEFPU: FMOVs, FNEGs, FABSs 4"),
    fp("fadds|faddd|fsubs|fsubd", 8, "MAMEFPU: FADDs/d, FSUBs/d 8"),
    fp("fmuls", 8, "MAMEFPU: FMULs 8"),
    fp("fmuld", 14, "MAMEFPU: FMULd 14"),
    fp("fdivs", 40, "MAMEFPU: FDIVs 40"),
    fp("fdivd", 68, "MAMEFPU: FDIVd 68"),
    fp("fcmps|fcmpd|fcmpes|fcmped", 4, "MAMEFPU: FCMPs/d 4"),
    fp("fitos|fstoi", 16, "MAMEFPU: FiTOs 16, FsTOi 16 (the latter 'Guessed' there)"),
    fp("fitod|fdtoi", 8, "MAMEFPU: FiTOd 8, FdTOi 8 (the latter 'Guessed' there)"),
    fp("fstod|fdtos", 8, "MAMEFPU: FsTOd, FdTOs 8"),
    fp("fsqrts|fsqrtd", 300, "EST, stand-in: fb89 takes the WTL3170 to execute no fsqrt (TME "
       "marks it unimplemented on the 317x) and prices the software sqrt period programs "
       "called: SUNOS usr.lib/libm/sparc/sqrt.S's common path, about 130 instructions with 2 "
       "fdivd, 8 fmuld and 5 fadd/fsub and some 45 loads and stores, about 300 cycles",
       stand_in=True),
    fp("fmovd|fnegd|fabsd|impdep1", 8, "EST, stand-in: a V9 double move (or VIS fzero/fone) is "
       "two V7 fmovs, 2 x 4 (MAMEFPU)", stand_in=True),
    fp("fsmuld", 8 + 8 + 14, "EST, stand-in: V8 fsmuld is two fstod and an fmuld, 8 + 8 + 14 "
       "(MAMEFPU)", stand_in=True),
]

CY7C602 = [
    fp("fmovs|fnegs|fabss", 5, "CYPRESS: cyp_fp_alu 5 (type fpmove)"),
    fp("fadds|faddd|fsubs|fsubd", 5, "CYPRESS: cyp_fp_alu 5"),
    fp("fmuls|fmuld", 7, "CYPRESS: cyp_fp_mult 7"),
    fp("fdivs|fdivd", 37, "CYPRESS: cyp_fp_div 37"),
    fp("fsqrts|fsqrtd", 63, "CYPRESS: cyp_fp_sqrt 63 (the 602 executes fsqrt)"),
    fp("fcmps|fcmpd|fcmpes|fcmped", 5, "EST: the FP ALU's 5 (CYPRESS cyp_fp_alu); GCC's "
       "cypress_costs gives 1 for the compare alone, but an fbfcc may not follow it at once"),
    fp("fitos|fstoi|fitod|fdtoi|fstod|fdtos", 5, "CYPRESS: cyp_fp_alu 5 (type fp)"),
    fp("fmovd|fnegd|fabsd|impdep1", 10, "EST, stand-in: a V9 double move (or VIS fzero/fone) "
       "is two V7 fmovs, 2 x 5 (CYPRESS)", stand_in=True),
    fp("fsmuld", 5 + 5 + 7, "EST, stand-in: V8 fsmuld is two fstod and an fmuld, 5 + 5 + 7 "
       "(CYPRESS)", stand_in=True),
]

SOURCES = {
    "SIS": "gdb's SIS simulator, sim/erc32/exec.c (T_LD, T_LDD, T_ST, T_STD, T_LDST, T_JMPL, "
           "T_RETT, TRAP_C, LOAD_DEL and the T_F* FPU times), interf.c (the annulled slot) and "
           "README.sis (a model of the Matra 90C601E/90C602E, roughly the Cypress C601/C602), "
           "as in bminor/binutils-gdb commit 223f25a3b6ee.",
    "SUNOS": "SunOS 4.1.3 sources (Arquivotheca/SunOS-4.1.3, commit 2e8a93c3946e): "
             "sys/sparc/overflow.s, sys/sparc/underflow.s, sys/sun4/locore.s (WIN_TRAP), "
             "sys/sparc/asm_linkage.h (SAVE_WINDOW, RESTORE_WINDOW), usr.lib/libm/sparc/sqrt.S "
             "(software sqrt), sys/sparc/float.s and sys/sparc/fpu/fpu.c, div.c (the kernel's "
             "emulation of an unimplemented FPop), diagnostics/fpurel (fsqrt skipped on the "
             "Weitek FPU), sys/sparc/reg.h (FPU versions: 0/1 Weitek 1164/5 on the Sun-4/260, "
             "2 TI 8847, 3 Weitek 3170 on the SPARCstation 1).",
    "FPA": "the Sun-3 FPA's microcode in the SunOS 4.1.3 sources (usr.etc/fpa/microcode/com.u, "
           "mis.u: 'FPA MICROCODE, Written by Mark Moyer'), the same Weitek WTL1164 "
           "(multiplier) and WTL1165 (ALU) the Sun-4/260's FPC drives; one microinstruction a "
           "cycle, counted per routine from the first operand load to the dispatch of the next "
           "(fb89's count).",
    "SUNAS": "Sun's SPARC assembler sources (opcode table, CHIPFABS): 'FMUL executes on Weitek "
             "1164 chip; FMOV, FABS, and FNEG execute on the FPU itself (no Weitek chip), and "
             "the rest execute on the Weitek 1165 chip.'",
    "GAS": "binutils gas/config/tc-sparc.c, SPECIAL_CASE_FDIV: an fmovs of the result after "
           "every fdiv, for the Sun-4/260's Weitek 1165.",
    "CYPRESS": "GCC gcc/config/sparc/cypress.md (gcc-mirror/gcc 167637297f0d), the Cypress "
               "CY7C601/CY7C602 pipeline: cyp_load 2, cyp_fp_alu 5 (fp, fpmove), cyp_fp_mult "
               "7, cyp_fp_div 37 (single and double), cyp_fp_sqrt 63; the SPARCstation 2's TI "
               "TMS390C602A is the CY7C602's second source (Linux and NetBSD cpu.c name the "
               "two as FPU versions 2 and 3 of the CY7C601).",
    "LIBGCC": "libgcc/config/sparc/lb1spc.S (.umul: 13 mulscc steps when both operands are "
              "below 4096, else 33; .udiv after the SPARC V8 manual's Appendix E), counted "
              "under qemu with fb89's plugin.",
    "MAMEFPU": "MAME src/devices/cpu/sparc/sparc.cpp (mamedev/mame, commit 029464383775), "
               "sparc_base_device::complete_fp_execution: m_fpr_pending per FPop, in MAME's core "
               "for the SPARCstation 1 and its Weitek 3170; no source cited there, FSTOI and "
               "FDTOI marked 'Guessed based on FITOS/FITOD'.",
    "MAME": "MAME src/mame/sun/sun4.cpp (mamedev/mame 0003eedd210c), header: Sun-4/260 'SF9010 "
            "@ 16.67MHz, Weitek 1164/1165, 10 MIPS, 1.6 MFLOPS'; SPARCstation 1 'MB86901A or "
            "LSI L64801 @ 20MHz, Weitek 3170, 12.5 MIPS, 1.4 MFLOPS, 10 SPECmark89, 64K "
            "write-through ... 16-byte lines'; SPARCstation 2 'CY7C601 @ 40MHz, TI TMS390C601A "
            "(602A ?) ... 28.5 MIPS, 4.2 MFLOPS ... 64K write-through, direct-mapped, virtually "
            "indexed, virtually tagged, 32-byte lines'.",
    "EST": "fb89's own derivation; the rule's source string gives the reasoning "
           "(docs/HOST_COST_MODEL.md, 'SPARC').",
}

COMMON_NOTES = (
    "Integer timings: SIS's V7 model (no MB86900, L64801 or CY7C601 table was found; SIS "
    "models a chip 'roughly equivalent to the Cypress C601'). Instruction fetches are taken "
    "to hit; data misses (and a write-back cache's write-backs) are counted by the plugin and "
    "priced. The whole latency of every FPop is priced (no IU/FPU overlap credited). V8/V9 "
    "instructions from Debian's V8plus libraries are priced as the V7 sequences standing in "
    "for them (stand_in). Register-window traps are counted by the plugin for the machine's "
    "window count and priced from SunOS's handlers. Not modelled: instruction-cache misses, "
    "the FPU's concurrency with the IU, OS time (system calls, interrupts, context switches "
    "and the window spills they cause). See docs/HOST_COST_MODEL.md.")


def cache_rules(own, read, write, writeback, src):
    """The events of the machine's own data cache (the plugin's key prefix `own`, e.g.
    "128k_16b_wb") at `read`, `write` and `writeback` cycles; the other simulated caches'
    events cost nothing here."""
    return [{"mnemonic": f"@dcache_{own}_read_miss", "cpu": read, "source": src},
            {"mnemonic": f"@dcache_{own}_write_miss", "cpu": write, "source": src},
            {"mnemonic": f"@dcache_{own}_writeback", "cpu": writeback, "source": src},
            {"mnemonic": "@dcache_.*", "cpu": 0,
             "source": "another machine's cache, simulated beside this one's: no cost here"}]


WINDOW_OVERFLOW = ("EST from SUNOS sys/sparc/overflow.s, user-mode common path: the "
                   "4-instruction trap vector and 43 handler instructions (8 std, 3 ld, 1 lda "
                   "of the page map, 5 taken branches, jmp and rett), priced with SIS's "
                   "figures: TRAP_C 3 + 47 + 8 x 3 (std) + 3 x 1 (ld) + 1 (lda) + 1 (jmp) + "
                   "1 (rett) = 80")
WINDOW_UNDERFLOW = ("EST from SUNOS sys/sparc/underflow.s, user-mode common path: the "
                    "4-instruction trap vector and 46 handler instructions (8 ldd, 3 ld, 1 "
                    "lda), priced with SIS's figures: TRAP_C 3 + 50 + 8 x 2 (ldd) + 3 x 1 (ld) "
                    "+ 1 (lda) + 1 (jmp) + 1 (rett) = 75")


def window_rules(windows):
    """The machine's register-window traps (the plugin counts 7 windows as @window_*, other
    counts as @window_*_<N>w) priced from SunOS's handlers; the other counts' cost nothing."""
    suffix = "" if windows == 7 else f"_{windows}w"
    which = f"a register file of {windows} windows"
    return [{"mnemonic": f"@window_overflow{suffix}", "cpu": 80,
             "source": WINDOW_OVERFLOW + f" ({which})"},
            {"mnemonic": f"@window_underflow{suffix}", "cpu": 75,
             "source": WINDOW_UNDERFLOW + f" ({which})"},
            {"mnemonic": "@window_(overflow|underflow).*", "cpu": 0,
             "source": "another window count, followed beside this machine's: no cost here"}]


def profile(name, desc, cpu, fpu, mhz, notes, events, fpu_rules):
    return {
        "schema": 1,
        "name": name,
        "description": desc,
        "isa": "sparc",
        "cpu": cpu,
        "fpu": fpu,
        "cpu_clock_mhz": mhz,
        "fpu_clock_mhz": mhz,
        "memory_wait_states": 0,
        "sources": SOURCES,
        "notes": notes + " " + COMMON_NOTES,
        "ea": {"fetch": {}, "calc": {}},
        "rules": events + fpu_rules + rules,
        "default": DEFAULT,
    }


SUN4_LINE = ("EST: a 16-byte line moved to or from the 64-bit ECC memory in two transfers of "
             "about 200 ns (the Sun-3/60's memory cycle, SUN; MAME: the 4/260 'uses same memory "
             "boards' as the Sun-3/2xx), 400 ns = 7 clocks at 16.67 MHz, for a fill (read or "
             "write miss: write-allocate, SunOS sets a page's modified bit 'on the first write "
             "miss') and again for the dirty line a fill replaces, written back first. No "
             "measured figure was found (docs/HOST_COST_MODEL.md, 'Caches')")
SS1_LINE = ("EST: a 16-byte line filled over the 32-bit memory path from 100 ns DRAM (SunOS, "
            "the parts it accepts), a first word of about 200 ns and three page-mode words of "
            "about 100 ns, 500 ns = 10 clocks at 20 MHz; at least the 6-7 clocks an uncached "
            "read takes by the boot code's 3 MIPS with the cache off. A store that misses goes "
            "to memory through the store buffer and invalidates the line (no write-allocate): "
            "0; write-through, so nothing is written back. No measured figure was found "
            "(docs/HOST_COST_MODEL.md, 'Caches')")
SS2_LINE = ("EST: a 32-byte line filled over the 32-bit memory path, its memory clocked as the "
            "SPARCstation 1's (the SBus and the memory controller at 20 MHz: MAME), a first word "
            "of about 200 ns and seven page-mode words of about 100 ns, 900 ns = 36 clocks at "
            "40 MHz. A store that misses goes through the store buffer and invalidates the line "
            "(no write-allocate): 0; write-through, so nothing is written back. No measured "
            "figure was found (docs/HOST_COST_MODEL.md, 'Caches')")

machines = [
    profile("sun4-260",
            "Sun-4/260: Fujitsu MB86900 at 16.67 MHz, Weitek WTL1164/1165 through the FPC, "
            "128 KB virtual cache",
            "MB86900 at 16.67 MHz", "Weitek 1164/1165 + FPC (MB86910)",
            16.67,
            "MAME: SF9010 (= MB86900) at 16.67 MHz, Weitek 1164/1165, rated 10 MIPS and 1.6 "
            "MFLOPS, 128 KB virtual cache: direct-mapped, write-back, 16-byte lines (SunOS). "
            "7 register windows. FPU: FSR version 0/1, the Weitek 1164 (multiplier) and 1165 "
            "(ALU) behind Fujitsu's FPC, priced from the Sun-3 FPA's microcode for the same "
            "chips (the TI 8847 'FPU2' daughterboard, FSR version 2, sold with some 4/260s "
            "from 1989, is not modelled); no fsqrt in hardware: the kernel's emulation is "
            "priced. The FPU is taken at the IU's clock.",
            cache_rules("128k_16b_wb", 7, 7, 7, SUN4_LINE) + window_rules(7), WEITEK_1164),
    profile("sparcstation-1",
            "SPARCstation 1: LSI L64801 at 20 MHz, Weitek WTL3170, 64 KB write-through cache",
            "L64801 at 20 MHz", "Weitek 3170", 20.0,
            "MAME: MB86901A or LSI L64801 at 20 MHz, Weitek 3170, rated 12.5 MIPS, 1.4 MFLOPS "
            "and 10 SPECmark89, 64 KB write-through direct-mapped cache with 16-byte lines "
            "(SunOS, NetBSD): read misses counted by the plugin and priced as below, stores "
            "absorbed by the store buffer. 7 register windows; the same IU timings as the "
            "MB86900 (the same V7 pipeline). FPU: MAME's figures, from its SPARCstation 1 core.",
            cache_rules("64k_16b_wt", 10, 0, 0, SS1_LINE) + window_rules(7), WEITEK_3170),
    profile("sparcstation-2",
            "SPARCstation 2: Cypress CY7C601 at 40 MHz, TI TMS390C602A FPU, 64 KB "
            "write-through cache with 32-byte lines",
            "CY7C601 at 40 MHz", "TI TMS390C602A (= Cypress CY7C602)", 40.0,
            "MAME: CY7C601 at 40 MHz, TI TMS390C601A (602A ?), rated 28.5 MIPS, 4.2 MFLOPS, "
            "21.8 SPECint92 and 22.8 SPECfp92, 64 KB write-through direct-mapped virtually "
            "indexed and tagged cache with 32-byte lines; its FPU the TI 602a (Sun's Numerical "
            "Computation Guide, Table B-1), the CY7C602's second source. 8 register windows "
            "(the CY7C601's). Integer timings: SIS's, a model of a chip roughly equivalent to "
            "the C601; FPU: GCC's Cypress pipeline. First supported in SunOS 4.1.1 (1990).",
            cache_rules("64k_32b_wt", 36, 0, 0, SS2_LINE) + window_rules(8), CY7C602),
]

# A variant, not built in (period/sparc/profiles/variants/, read with --host FILE): the
# Sun-4/260 with its square roots priced as the software sqrt period software called in their
# place (Sun's compilers emitted no fsqrt for this FPU), so that fb89's binary, which executes
# fsqrtd and so traps to the kernel on the real machine, can be set beside figures measured
# with period code (docs/RESULTS.md, "The Sun-4").
LIBM_SQRT = fp("fsqrts|fsqrtd", 300, "EST, stand-in: libm's software sqrt in place of the "
               "trapping fsqrt, as Sun's compilers built code for the Weitek FPU: SUNOS "
               "usr.lib/libm/sparc/sqrt.S's common path, about 130 instructions with 2 fdivd, 8 "
               "fmuld and 5 fadd/fsub and some 45 loads and stores, about 300 cycles",
               stand_in=True)
variant = json.loads(json.dumps(machines[0]))
variant["name"] = "sun4-260-libm-sqrt"
variant["description"] += "; square roots as libm's software sqrt instead of the kernel's fsqrt"
variant["rules"] = [LIBM_SQRT if r["mnemonic"] == "fsqrts|fsqrtd" else r for r in variant["rules"]]
os.makedirs(os.path.join(OUT, "variants"), exist_ok=True)

for p, folder in [(m, OUT) for m in machines] + [(variant, os.path.join(OUT, "variants"))]:
    with open(os.path.join(folder, p["name"] + ".json"), "w") as f:
        json.dump(p, f, indent=2)
        f.write("\n")
print(len(rules), "common rules")
