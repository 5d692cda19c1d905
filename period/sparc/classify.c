/*
 * classify.c - the counting plugin's part for SPARC (period/plugin/isa.h): the Sun-4's
 * MB86900 / L64801 integer units (SPARC V7) with their Weitek floating-point units, run
 * as 32-bit code under qemu-sparc32plus.
 *
 * Keys come from the instruction word itself (SPARC encodes every instruction in one
 * 32-bit word, in the guest's big-endian order), not from the disassembly: the key is
 * the architecture manual's mnemonic -- "ld", "std", "addcc", "bicc", "bicc,a", "fmuld",
 * "save" -- which is all a V7 timing table needs (its times do not depend on the
 * addressing mode). Instructions V7 does not have, which Debian's 32-bit libraries use
 * (they are built for V8plus), keep their own mnemonics ("umul", "bpcc", "movcc",
 * "return", "casa", "sllx" ...): the profiles price each as the V7 sequence that would
 * stand in for it (docs/HOST_COST_MODEL.md, "SPARC").
 *
 * Pseudo-classes, for time a V7 chip spends that no instruction count shows:
 * - "@load_use": an instruction that uses a register the instruction before it loads
 *   (one cycle of interlock on the MB86900); found within a block at translation.
 * - "@annulled_slot": a delay slot a not-taken annulling branch skips (the chip still
 *   spends its cycle); counted by the core from the blocks' executions.
 * - "@window_overflow", "@window_underflow": register-window traps. qemu-user spills
 *   and fills windows inside QEMU, so the guest never runs a trap handler; this file keeps
 *   the depth of the window stack on every save, restore and V9 return, and counts a trap
 *   where an MB86900 with `windows` windows (7 by default; plugin option windows=N, which
 *   must match QEMU's -cpu nwindows) would take one. One window is kept invalid for the
 *   trap handler, as SunOS and Linux do, so at most windows - 1 are resident. A flush of
 *   the windows ("ta 3", V9 "flushw", used by setjmp and C++ unwinding) spills every
 *   resident window but the current one. System calls and context switches, which may
 *   spill too, are not modelled. A chip with more windows (the SPARCstation 2's CY7C601 has
 *   8) is followed beside it (also_windows=N), its traps counted as "@window_overflow_Nw"
 *   and "@window_underflow_Nw".
 */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "period/plugin/isa.h"

static uint32_t word_of(const struct fb89_insn *insn)
{
    const uint8_t *b = insn->bytes;
    if (!b || insn->size < 4) {
        return 0;
    }
    return (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3];
}

#define OP(w) ((w) >> 30)
#define OP2(w) (((w) >> 22) & 7)
#define OP3(w) (((w) >> 19) & 0x3f)
#define RD(w) (((w) >> 25) & 31)
#define RS1(w) (((w) >> 14) & 31)
#define RS2(w) ((w) & 31)
#define IMM(w) (((w) >> 13) & 1)
#define ANNUL(w) (((w) >> 29) & 1)
#define COND(w) (((w) >> 25) & 15)
#define OPF(w) (((w) >> 5) & 0x1ff)

/* ---- mnemonics ------------------------------------------------------------------- */

/* Format 3, op = 2: arithmetic, logic, shifts, control transfer, FPU operate. */
static const char *const arith[64] = {
    "add",    "and",     "or",     "xor",      "sub",    "andn",   "orn",    "xnor",
    "addx",   "mulx",    "umul",   "smul",     "subx",   "udivx",  "udiv",   "sdiv",
    "addcc",  "andcc",   "orcc",   "xorcc",    "subcc",  "andncc", "orncc",  "xnorcc",
    "addxcc", "op3_19",  "umulcc", "smulcc",   "subxcc", "op3_1d", "udivcc", "sdivcc",
    "taddcc", "tsubcc",  "taddcctv", "tsubcctv", "mulscc", "sll",  "srl",    "sra",
    "rdy",    "rdpsr",   "rdwim",  "rdtbr",    "movcc",  "sdivx",  "popc",   "movr",
    "wry",    "wrpsr",   "wrwim",  "wrtbr",    "fpop1",  "fpop2",  "impdep1", "impdep2",
    "jmpl",   "return",  "ticc",   "flush",    "save",   "restore", "done",  "op3_3f",
};

/* Format 3, op = 3: loads and stores. */
static const char *const memory[64] = {
    "ld",    "ldub",   "lduh",   "ldd",    "st",    "stb",    "sth",    "std",
    "ldsw",  "ldsb",   "ldsh",   "ldx",    "op3_0c", "ldstub", "stx",   "swap",
    "lda",   "lduba",  "lduha",  "ldda",   "sta",   "stba",   "stha",   "stda",
    "ldswa", "ldsba",  "ldsha",  "ldxa",   "op3_1c", "ldstuba", "stxa", "swapa",
    "ldf",   "ldfsr",  "ldqf",   "lddf",   "stf",   "stfsr",  "stqf",   "stdf",
    "op3_28", "op3_29", "op3_2a", "op3_2b", "op3_2c", "prefetch", "op3_2e", "op3_2f",
    "ldfa",  "op3_31", "ldqfa",  "lddfa",  "stfa",  "op3_35", "stqfa",  "stdfa",
    "op3_38", "op3_39", "op3_3a", "op3_3b", "casa",  "prefetcha", "casxa", "op3_3f",
};

/* FPop1 (op3 0x34) by opf; NULL: not one we know. */
static const char *fpop1(uint32_t opf)
{
    switch (opf) {
    case 0x01: return "fmovs";
    case 0x02: return "fmovd";
    case 0x05: return "fnegs";
    case 0x06: return "fnegd";
    case 0x09: return "fabss";
    case 0x0a: return "fabsd";
    case 0x29: return "fsqrts";
    case 0x2a: return "fsqrtd";
    case 0x2b: return "fsqrtq";
    case 0x41: return "fadds";
    case 0x42: return "faddd";
    case 0x43: return "faddq";
    case 0x45: return "fsubs";
    case 0x46: return "fsubd";
    case 0x47: return "fsubq";
    case 0x49: return "fmuls";
    case 0x4a: return "fmuld";
    case 0x4b: return "fmulq";
    case 0x4d: return "fdivs";
    case 0x4e: return "fdivd";
    case 0x4f: return "fdivq";
    case 0x69: return "fsmuld";
    case 0x6e: return "fdmulq";
    case 0x81: return "fstox";
    case 0x82: return "fdtox";
    case 0x84: return "fxtos";
    case 0x88: return "fxtod";
    case 0xc4: return "fitos";
    case 0xc6: return "fdtos";
    case 0xc8: return "fitod";
    case 0xc9: return "fstod";
    case 0xcb: return "fqtod";
    case 0xcd: return "fstoq";
    case 0xce: return "fdtoq";
    case 0xd1: return "fstoi";
    case 0xd2: return "fdtoi";
    case 0xd3: return "fqtoi";
    default: return NULL;
    }
}

/* FPop2 (op3 0x35): compares; the V9 conditional FP moves on the rest. */
static const char *fpop2(uint32_t opf)
{
    switch (opf) {
    case 0x51: return "fcmps";
    case 0x52: return "fcmpd";
    case 0x53: return "fcmpq";
    case 0x55: return "fcmpes";
    case 0x56: return "fcmped";
    case 0x57: return "fcmpeq";
    default: return "fmovcc";
    }
}

/* The mnemonic of a word, V7 names first. */
static const char *mnemonic(uint32_t w)
{
    switch (OP(w)) {
    case 1:
        return "call";
    case 0:
        switch (OP2(w)) {
        case 0: return "unimp";
        case 1: return ANNUL(w) ? "bpcc,a" : "bpcc";   /* V9: predicted branch */
        case 2:
            if (COND(w) == 8) {
                return ANNUL(w) ? "ba,a" : "ba";
            }
            if (COND(w) == 0) {
                return ANNUL(w) ? "bn,a" : "bn";
            }
            return ANNUL(w) ? "bicc,a" : "bicc";
        case 3: return "bpr";                          /* V9: brz, brlz, ... */
        case 4: return RD(w) == 0 && (w & 0x3fffff) == 0 ? "nop" : "sethi";
        case 5: return ANNUL(w) ? "fbpfcc,a" : "fbpfcc"; /* V9 */
        case 6:
            if (COND(w) == 8) {
                return ANNUL(w) ? "fba,a" : "fba";
            }
            return ANNUL(w) ? "fbfcc,a" : "fbfcc";
        default: return "cbccc";
        }
    case 2: {
        const uint32_t op3 = OP3(w);
        if (op3 >= 0x25 && op3 <= 0x27 && (w >> 12 & 1)) {
            return op3 == 0x25 ? "sllx" : op3 == 0x26 ? "srlx" : "srax"; /* V9 */
        }
        if (op3 == 0x28 && RS1(w) != 0) {
            return RS1(w) == 15 && RD(w) == 0 ? "stbar" : "rdasr";  /* V8: stbar, V9: membar */
        }
        if (op3 == 0x2b && RD(w) == 0 && RS1(w) == 0 && IMM(w) == 0) {
            return "flushw";                                          /* V9 */
        }
        if (op3 == 0x34) {
            const char *f = fpop1(OPF(w));
            return f ? f : "fpop1";
        }
        if (op3 == 0x35) {
            return fpop2(OPF(w));
        }
        if (op3 == 0x3a) {
            return "ticc";
        }
        return arith[op3];
    }
    default:
        return memory[OP3(w)];
    }
}

static void make_key(const struct fb89_insn *insn, char *key)
{
    if (insn->size != 4 || !insn->bytes) {
        snprintf(key, FB89_KEY_MAX, "(size %zu)", insn->size);
        return;
    }
    snprintf(key, FB89_KEY_MAX, "%s", mnemonic(word_of(insn)));
}

/* ---- load-use interlocks ------------------------------------------------------------ */

/* Registers an instruction reads, as bit masks: integer r0..r31 (r0 never counts), and
   floating-point f0..f31. */
struct uses {
    uint32_t r, f;
};

/* The registers a load writes (r for integer loads, f for FP loads); 0 if it is no load. */
static struct uses loaded(uint32_t w)
{
    struct uses u = {0, 0};
    if (OP(w) != 3) {
        return u;
    }
    const uint32_t op3 = OP3(w), rd = RD(w);
    switch (op3) {
    case 0x00: case 0x01: case 0x02: case 0x08: case 0x09: case 0x0a: case 0x0b:
    case 0x0d: case 0x0f:
        u.r = rd ? 1u << rd : 0;
        break;
    case 0x03: /* ldd: an even/odd pair */
        u.r = (3u << (rd & ~1u)) & ~1u;
        break;
    case 0x20:
        u.f = 1u << rd;
        break;
    case 0x23: /* lddf */
        u.f = 3u << (rd & ~1u);
        break;
    default:
        break;
    }
    return u;
}

/* An f register and its pair's other half: a double occupies an even/odd pair. Reads are
   taken by pairs (a single-precision read of the other half counts too: an upper bound). */
static uint32_t pair(uint32_t f)
{
    return 3u << (f & ~1u);
}

/* The registers an instruction reads. */
static struct uses read_by(uint32_t w)
{
    struct uses u = {0, 0};
    const uint32_t rs1 = RS1(w), rs2 = RS2(w), rd = RD(w);
    const uint32_t source = 1u << rs1 | (IMM(w) ? 0 : 1u << rs2);
    switch (OP(w)) {
    case 2:
        if (OP3(w) == 0x34) { /* FPop1: rs2, and rs1 for the two-operand arithmetic */
            const bool two = OPF(w) >= 0x40 && OPF(w) < 0x70;
            u.f = pair(rs2) | (two ? pair(rs1) : 0);
        } else if (OP3(w) == 0x35) { /* compares */
            u.f = pair(rs1) | pair(rs2);
        } else {
            u.r = source;
        }
        break;
    case 3: {
        u.r = source; /* the address */
        const uint32_t op3 = OP3(w);
        if (op3 == 0x04 || op3 == 0x05 || op3 == 0x06 || op3 == 0x0e) {
            u.r |= 1u << rd; /* the value stored */
        } else if (op3 == 0x07) {
            u.r |= 3u << (rd & ~1u);
        } else if (op3 == 0x24) {
            u.f = 1u << rd;
        } else if (op3 == 0x27) {
            u.f = 3u << (rd & ~1u);
        }
        break;
    }
    default:
        break;
    }
    u.r &= ~1u; /* %g0 */
    return u;
}

static void block_extras(const struct fb89_insn *insns, size_t n,
                         void (*add)(const char *key, size_t at))
{
    for (size_t i = 0; i + 1 < n; i++) {
        const struct uses l = loaded(word_of(&insns[i]));
        if (!l.r && !l.f) {
            continue;
        }
        const struct uses r = read_by(word_of(&insns[i + 1]));
        if ((l.r & r.r) || (l.f & r.f)) {
            add("@load_use", i + 1);
        }
    }
}

/* ---- delay slots --------------------------------------------------------------------- */

static uint64_t annulling_branch(const struct fb89_insn *last)
{
    const uint32_t w = word_of(last);
    if (OP(w) != 0 || !ANNUL(w)) {
        return 0;
    }
    const uint32_t op2 = OP2(w);
    /* Bicc, BPcc, FBfcc, FBPfcc with a = 1 (BPr too); "ba,a" never runs its slot */
    if (op2 == 1 || op2 == 2 || op2 == 3 || op2 == 5 || op2 == 6) {
        return last->vaddr;
    }
    return 0;
}

/* ---- register windows ---------------------------------------------------------------- */

/*
 * QEMU runs the guest as a V9 CPU whose window count fb89 sets to the MB86900's (isa.cpp:
 * -cpu "TI UltraSparc II,nwindows=7"). Its linux-user loop then spills and fills exactly
 * where an MB86900 under SunOS would trap: a save with no free window, a restore whose
 * caller's window is not resident. QEMU restarts the save or restore after its own trap,
 * and a V9 flushw once for every window it spills; on_event says so, and the core takes
 * back what the restarts count twice.
 */
enum { EV_SAVE = 1, EV_RESTORE = 2, EV_FLUSH_TRAP = 3, EV_FLUSHW = 4 };

static int exec_event(const struct fb89_insn *insn)
{
    const uint32_t w = word_of(insn);
    if (OP(w) != 2) {
        return 0;
    }
    switch (OP3(w)) {
    case 0x3c: return EV_SAVE;
    case 0x3d: return EV_RESTORE;
    case 0x39: return EV_RESTORE; /* V9 return: a restore and a jump */
    case 0x2b: return RD(w) == 0 && RS1(w) == 0 && IMM(w) == 0 ? EV_FLUSHW : 0;
    case 0x3a: /* ta 3: ST_FLUSH_WINDOWS */
        return COND(w) == 8 && IMM(w) && RS1(w) == 0 && (w & 0x7f) == 3 ? EV_FLUSH_TRAP : 0;
    default: return 0;
    }
}

static unsigned windows = 7;     /* the MB86900's, and the L64801's */
static unsigned resident = 1;    /* windows of the call chain in the register file */
static uint64_t overflows, underflows;

/* Other window counts, for machines whose chips have more (the CY7C601's 8: plugin option
   also_windows=N): their traps are counted as "@window_overflow_<N>w" and
   "@window_underflow_<N>w" by the same rule; QEMU's own restarts follow `windows` alone. */
#define FB89_MAX_ALSO 2
static struct {
    unsigned windows, resident;
    uint64_t overflows, underflows;
    char overflow_key[32], underflow_key[32];
} also[FB89_MAX_ALSO];
static unsigned nalso;

/* One event on a register file of `w` windows with `*res` resident; the traps it takes are
   added to *over and *under. Returns how many times QEMU, were its count `w`, would restart
   the instruction: once after a save's or restore's trap, once a window a flushw spills. */
static unsigned window_event(int event, unsigned w, unsigned *res, uint64_t *over,
                             uint64_t *under)
{
    switch (event) {
    case EV_SAVE:
        if (*res + 1 < w) {
            (*res)++;
            return 0;
        }
        (*over)++; /* the oldest window goes to the stack; the new one takes its place */
        return 1;
    case EV_RESTORE:
        if (*res > 1) {
            (*res)--;
            return 0;
        }
        (*under)++; /* the caller's window comes back from the stack */
        return 1;
    case EV_FLUSH_TRAP:
    case EV_FLUSHW: {
        const unsigned spilled = *res - 1;
        *over += spilled;
        *res = 1;
        return event == EV_FLUSHW ? spilled : 0;
    }
    default:
        return 0;
    }
}

static unsigned on_event(int event)
{
    for (unsigned i = 0; i < nalso; i++) {
        window_event(event, also[i].windows, &also[i].resident, &also[i].overflows,
                     &also[i].underflows);
    }
    return window_event(event, windows, &resident, &overflows, &underflows);
}

static void flush_events(fb89_add_fn add)
{
    add("@window_overflow", overflows);
    add("@window_underflow", underflows);
    overflows = underflows = 0;
    for (unsigned i = 0; i < nalso; i++) {
        add(also[i].overflow_key, also[i].overflows);
        add(also[i].underflow_key, also[i].underflows);
        also[i].overflows = also[i].underflows = 0;
    }
}

/* windows=N (QEMU's count, which must match its -cpu nwindows) or also_windows=N. */
static bool option(const char *arg)
{
    const bool extra = strncmp(arg, "also_windows=", 13) == 0;
    if (!extra && strncmp(arg, "windows=", 8) != 0) {
        return false;
    }
    char *end = NULL;
    const long n = strtol(arg + (extra ? 13 : 8), &end, 10);
    if (!end || *end || n < 2 || n > 32) {
        return false;
    }
    if (!extra) {
        windows = (unsigned)n;
        return true;
    }
    if (nalso == FB89_MAX_ALSO) {
        return false;
    }
    also[nalso].windows = (unsigned)n;
    also[nalso].resident = 1;
    snprintf(also[nalso].overflow_key, sizeof(also[nalso].overflow_key),
             "@window_overflow_%ldw", n);
    snprintf(also[nalso].underflow_key, sizeof(also[nalso].underflow_key),
             "@window_underflow_%ldw", n);
    nalso++;
    return true;
}

static const char *const qemu_targets[] = {"sparc32plus", "sparc", NULL};

const struct fb89_isa fb89_isa_sparc = {
    .name = "sparc",
    .qemu_targets = qemu_targets,
    .make_key = make_key,
    .block_extras = block_extras,
    .annulling_branch = annulling_branch,
    .exec_event = exec_event,
    .on_event = on_event,
    .flush_events = flush_events,
    .option = option,
    .options_help = " [windows=N] [also_windows=N]",
};
