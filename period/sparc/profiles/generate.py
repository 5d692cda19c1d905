#!/usr/bin/env python3
"""Writes period/sparc/profiles/sun4-260.json and sparcstation-1.json: one rule list, two
machines (docs/HOST_COST_MODEL.md, "SPARC").

The SPARC classifier (period/sparc/classify.c) keys an instruction by its mnemonic alone,
so a rule is a mnemonic regex and the cycles it costs: a V7 timing table does not depend on
addressing modes. Edit the rules here and run `python3 period/sparc/profiles/generate.py`;
the JSON files are what fb89 embeds and reads.

Every figure carries a source tag:
  SIS     gdb's SIS simulator (sim/erc32/exec.c, interf.c, README.sis), a V7 model of the
          Matra 90C601E/90C602E, "roughly equivalent to the Cypress C601 and C602": integer
          T_LD 2, T_LDD 3, T_ST 3, T_STD 4, T_LDST 4, T_JMPL 2, T_RETT 2, others 1; load-use
          +1; an annulled slot 1; TRAP_C 3. (Its FPU figures, T_FMULd 9, T_FADDd 4 ..., are
          a Cypress-class FPU's, not used.)
  MAMEFPU MAME src/devices/cpu/sparc/sparc.cpp, complete_fp_execution: the cycles a result
          register stays busy after each FPop in MAME's SPARCstation 1 core (fadd 8/8,
          fmul 8/14, fdiv 40/68, fcmp 4/4, fmov/fneg/fabs 4, fitos/fitod 16/8, fstoi/fdtoi
          16/8, fstod/fdtos 8). No Weitek WTL1164/1165 or WTL3170 table was found: these
          stand in for both machines' FPUs.
  SUNOS   SunOS 4.1.3 sources (Arquivotheca/SunOS-4.1.3): the window overflow and underflow
          handlers (sys/sparc/overflow.s, underflow.s, and the trap vector of
          sys/sun4/locore.s), libm's software sqrt (usr.lib/libm/sparc/sqrt.S), which period
          software called because neither FPU executes fsqrt.
  LIBGCC  libgcc's V7 .umul/.udiv (libgcc/config/sparc/lb1spc.S), the code -mcpu=v7 calls,
          their instructions counted under the emulator with the counting plugin.
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
rule("@window_overflow", 80,
     "EST from SUNOS sys/sparc/overflow.s, user-mode common path: the 4-instruction trap "
     "vector and 43 handler instructions (8 std, 3 ld, 1 lda of the page map, 5 taken "
     "branches, jmp and rett), priced with SIS's figures: TRAP_C 3 + 47 + 8 x 3 (std) + "
     "3 x 1 (ld) + 1 (lda) + 1 (jmp) + 1 (rett) = 80")
rule("@window_underflow", 75,
     "EST from SUNOS sys/sparc/underflow.s, user-mode common path: the 4-instruction trap "
     "vector and 46 handler instructions (8 ldd, 3 ld, 1 lda), priced with SIS's figures: "
     "TRAP_C 3 + 50 + 8 x 2 (ldd) + 3 x 1 (ld) + 1 (lda) + 1 (jmp) + 1 (rett) = 75")

# ---- floating-point unit (MAME's SPARCstation 1 figures, for the Weitek parts) ----------
# No Weitek WTL1164/1165 or WTL3170 table was found. MAME's SPARC core, written for the
# SPARCstation 1 and its WTL3170, holds a result register busy for these many cycles after
# an FPop (sparc.cpp, complete_fp_execution, m_fpr_pending); they stand in for both
# machines' FPUs (the Sun-4/260's 1164/1165 behind the FPC is of the same vendor, one
# generation before). SIS's Cypress-class figures, about half these for doubles, made
# FFBENCH on the Sun-4 45% faster than measured (docs/HOST_COST_MODEL.md, "SPARC"). The IU
# issues an FPop in one cycle; fb89 prices the whole latency of every FPop, as if the IU
# waited for each (no IU/FPU overlap is credited).
FPU = "MAME sparc.cpp m_fpr_pending (the SPARCstation 1's core; standing in for the Weitek FPU)"
rule("ldf", 2, "SIS T_LD 2 (an FP load as an integer one)")
rule("lddf", 3, "SIS T_LDD 3")
rule("stf", 3, "SIS T_ST 3")
rule("stdf", 4, "SIS T_STD 4")
rule("ldfsr", 2, "SIS T_LD 2")
rule("stfsr", 3, "SIS T_ST 3")
rule("fmovs|fnegs|fabss", 1, FPU + ": FMOVs, FNEGs, FABSs 4", fpu=3)
rule("fadds|faddd|fsubs|fsubd", 1, FPU + ": FADDs/d, FSUBs/d 8", fpu=7)
rule("fmuls", 1, FPU + ": FMULs 8", fpu=7)
rule("fmuld", 1, FPU + ": FMULd 14", fpu=13)
rule("fdivs", 1, FPU + ": FDIVs 40", fpu=39)
rule("fdivd", 1, FPU + ": FDIVd 68", fpu=67)
rule("fcmps|fcmpd|fcmpes|fcmped", 1, FPU + ": FCMPs/d 4", fpu=3)
rule("fitos|fstoi", 1, FPU + ": FiTOs 16, FsTOi 16 (the latter 'Guessed' there)", fpu=15)
rule("fitod|fdtoi", 1, FPU + ": FiTOd 8, FdTOi 8 (the latter 'Guessed' there)", fpu=7)
rule("fstod|fdtos", 1, FPU + ": FsTOd, FdTOs 8", fpu=7)

# ---- what neither machine has: V8/V9 forms in Debian's V8plus libraries, priced as the V7
# ---- sequences that would stand in for them (stand_in: reported apart per run) ----------
STAND = "EST, stand-in: "
rule("fsqrts|fsqrtd", 300, "EST, stand-in: neither the Weitek 1164/1165 nor the WTL3170 "
     "executes fsqrt (it traps to the kernel's emulation); period software called libm's "
     "sqrt instead. SUNOS usr.lib/libm/sparc/sqrt.S's common path: about 130 instructions "
     "with 2 fdivd (2 x 35), 8 fmuld (8 x 9) and 5 fadd/fsub (5 x 4) and some 45 loads and "
     "stores, about 300 cycles", stand_in=True)
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
rule("fmovd|fnegd|fabsd", 1, STAND + "a V9 double move is two V7 fmovs, 2 x 4 (MAMEFPU)",
     fpu=7, stand_in=True)
rule("impdep1", 1, STAND + "a VIS operation (fzero, fone: a register set to a constant) is "
     "two V7 fmovs from a register holding it, 2 x 4 (MAMEFPU)", fpu=7, stand_in=True)
rule("fsmuld", 1, STAND + "V8 fsmuld is two fstod and an fmuld, 8 + 8 + 14 (MAMEFPU)",
     fpu=29, stand_in=True)
rule("fstox|fdtox|fxtos|fxtod", 1, STAND + "a V9 64-bit integer conversion is a V7 "
     "conversion and integer fix-ups, about 10", fpu=9, stand_in=True)
rule("lda|lduba|lduha|ldsba|ldsha|ldswa|ldfa", 2, STAND + "a V9 user alternate-space load "
     "is a V7 load, SIS T_LD 2", stand_in=True)
rule("ldda|lddfa|ldxa", 3, STAND + "SIS T_LDD 3", stand_in=True)
rule("sta|stba|stha|stfa", 3, STAND + "SIS T_ST 3", stand_in=True)
rule("stda|stdfa|stxa", 4, STAND + "SIS T_STD 4", stand_in=True)

DEFAULT = {"cpu": 2, "source": "EST: an instruction no rule names (none in fb89's runs); "
           "about the mean of the table"}

SOURCES = {
    "SIS": "gdb's SIS simulator, sim/erc32/exec.c (T_LD, T_LDD, T_ST, T_STD, T_LDST, T_JMPL, "
           "T_RETT, TRAP_C, LOAD_DEL and the T_F* FPU times), interf.c (the annulled slot) and "
           "README.sis (a model of the Matra 90C601E/90C602E, roughly the Cypress C601/C602), "
           "as in bminor/binutils-gdb commit 223f25a3b6ee.",
    "SUNOS": "SunOS 4.1.3 sources (Arquivotheca/SunOS-4.1.3, commit 2e8a93c3946e): "
             "sys/sparc/overflow.s, sys/sparc/underflow.s, sys/sun4/locore.s (WIN_TRAP), "
             "sys/sparc/asm_linkage.h (SAVE_WINDOW, RESTORE_WINDOW), usr.lib/libm/sparc/sqrt.S "
             "(software sqrt), sys/sparc/reg.h (FPU versions: 0/1 Weitek 1164/5 on the "
             "Sun-4/260, 3 Weitek 3170 on the SPARCstation 1).",
    "LIBGCC": "libgcc/config/sparc/lb1spc.S (.umul: 13 mulscc steps when both operands are "
              "below 4096, else 33; .udiv after the SPARC V8 manual's Appendix E), counted "
              "under qemu with fb89's plugin.",
    "MAMEFPU": "MAME src/devices/cpu/sparc/sparc.cpp (mamedev/mame, commit 029464383775), "
               "sparc_base_device::complete_fp_execution: m_fpr_pending per FPop, in MAME's core "
               "for the SPARCstation 1; no source cited there, FSTOI and FDTOI marked 'Guessed "
               "based on FITOS/FITOD'.",
    "MAME": "MAME src/mame/sun/sun4.cpp (mamedev/mame), header: Sun-4/260 'SF9010 @ 16.67 MHz, "
            "Weitek 1164/1165, 10 MIPS, 1.6 MFLOPS'; SPARCstation 1 'MB86901A or LSI L64801 "
            "@ 20 MHz, Weitek 3170, 12.5 MIPS, 1.4 MFLOPS, 10 SPECmark89, 64K write-through "
            "cache'.",
    "EST": "fb89's own derivation; the rule's source string gives the reasoning "
           "(docs/HOST_COST_MODEL.md, 'SPARC').",
}

COMMON_NOTES = (
    "Integer timings: SIS's V7 model (no MB86900 or L64801 table was found). Instruction "
    "fetches are taken to hit; data misses are counted and priced. FPU: MAME's SPARCstation "
    "1 figures stand in for the Weitek parts; the whole latency of every FPop is priced (no "
    "IU/FPU overlap credited). fsqrt, which neither "
    "FPU executes, is priced as libm's software sqrt. V8/V9 instructions from Debian's "
    "V8plus libraries are priced as the V7 sequences standing in for them (stand_in). "
    "Register windows: 7; their overflow and underflow traps are counted by the plugin "
    "and priced from SunOS's handlers. Not modelled: cache misses, the FPU's concurrency "
    "with the IU, OS time (system calls, interrupts, context switches and the window "
    "spills they cause). See docs/HOST_COST_MODEL.md.")


def cache_rules(own, read, write, src):
    """The misses of the machine's own data cache (the plugin's key prefix `own`) at `read`
    and `write` cycles; the other simulated caches' misses cost nothing here."""
    return [{"mnemonic": f"@dcache_{own}_read_miss", "cpu": read, "source": src},
            {"mnemonic": f"@dcache_{own}_write_miss", "cpu": write, "source": src},
            {"mnemonic": "@dcache_.*", "cpu": 0,
             "source": "another machine's cache, simulated beside this one's: no cost here"}]


def profile(name, desc, cpu, fpu, mhz, notes, caches):
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
        "rules": caches + rules,
        "default": DEFAULT,
    }


machines = [
    profile("sun4-260",
            "Sun-4/260: Fujitsu MB86900 at 16.67 MHz, Weitek WTL1164/1165 through the FPC, "
            "128 KB virtual cache",
            "MB86900 at 16.67 MHz", "Weitek 1164/1165 + FPC",
            16.67,
            "MAME: SF9010 (= MB86900) at 16.67 MHz, Weitek 1164/1165, rated 10 MIPS and 1.6 "
            "MFLOPS, 128 KB virtual cache: direct-mapped, write-back, 16-byte lines (SunOS), "
            "its data misses counted by the plugin and priced as below; hits at 0 wait "
            "states. The FPU is taken at the IU's clock.",
            cache_rules("128k_wb", 7, 7,
                        "EST: a 16-byte line filled from the 64-bit ECC memory in two transfers "
                        "of about 200 ns (the Sun-3/60's memory cycle, SUN), 400 ns = 7 clocks "
                        "at 16.67 MHz; write-allocate (SunOS sets a page's modified bit 'on the "
                        "first write miss'). No measured figure was found "
                        "(docs/HOST_COST_MODEL.md, 'Caches')")),
    profile("sparcstation-1",
            "SPARCstation 1: LSI L64801 at 20 MHz, Weitek WTL3170, 64 KB write-through cache",
            "L64801 at 20 MHz", "Weitek 3170", 20.0,
            "MAME: MB86901A or LSI L64801 at 20 MHz, Weitek 3170, rated 12.5 MIPS, 1.4 MFLOPS "
            "and 10 SPECmark89, 64 KB write-through direct-mapped cache with 16-byte lines "
            "(SunOS, NetBSD): read misses counted by the plugin and priced as below, stores "
            "absorbed by the store buffer. Same IU timings as the MB86900 (the same V7 "
            "pipeline).",
            cache_rules("64k_wt", 10, 0,
                        "EST: a 16-byte line filled over the 32-bit memory path from 100 ns "
                        "DRAM (SunOS, the parts it accepts), a first word of about 200 ns and "
                        "three page-mode words of about 100 ns, 500 ns = 10 clocks at 20 MHz; at "
                        "least the 6-7 clocks an uncached read takes by the boot code's 3 MIPS "
                        "with the cache off. A store that misses goes to memory through the "
                        "store buffer and invalidates the line (no write-allocate): 0. No "
                        "measured figure was found (docs/HOST_COST_MODEL.md, 'Caches')")),
]

for p in machines:
    with open(os.path.join(OUT, p["name"] + ".json"), "w") as f:
        json.dump(p, f, indent=2)
        f.write("\n")
print(len(rules), "rules")
