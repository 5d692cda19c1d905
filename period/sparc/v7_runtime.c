/*
 * v7_runtime.c - 64-bit integer helpers in SPARC V7 code, linked into the Sun-4 guest
 * (cmake/guest.cmake) in place of libgcc's. Debian's 32-bit libgcc is built for V8plus:
 * its __muldi3 multiplies with umul and mulx, its divisions with udivx, which an MB86900
 * does not have. fb89's own code calls these helpers in its timed phases (the raster
 * methods' 64-bit edge functions), so they are given here in instructions the chip has,
 * and the emulator counts what a V7 machine would run instead of pricing stand-ins.
 *
 * The full 32 x 32 -> 64-bit product uses the multiply-step instruction, as the SPARC
 * architecture manual's sample multiply does: %y holds one factor, 32 mulscc steps add
 * the other in, a last step with 0 aligns the result, and a correction adds the first
 * factor to the high word when the second has its top bit set (mulscc takes it as
 * signed). Divisions are shift-and-subtract over the quotient's bits, with 32-bit
 * divisions (libgcc's V7 .udiv) where the operands allow.
 */
#include <stdint.h>

typedef uint64_t u64;
typedef int64_t s64;
typedef uint32_t u32;
typedef int32_t s32;

#define STEP "mulscc %%g1, %3, %%g1\n\t"
#define STEP4 STEP STEP STEP STEP
#define STEP32 STEP4 STEP4 STEP4 STEP4 STEP4 STEP4 STEP4 STEP4

static u64 product(u32 a, u32 b) {
    u32 hi, lo;
    __asm__(
        "wr %%g0, %2, %%y\n\t" /* the three instructions after it fill wr's delay */
        "sra %3, 31, %%g2\n\t"
        "and %2, %%g2, %%g2\n\t" /* a, if b's top bit is set: added to the high word */
        "andcc %%g0, 0, %%g1\n\t" STEP32
        "mulscc %%g1, 0, %%g1\n\t"
        "add %%g1, %%g2, %0\n\t"
        "rd %%y, %1"
        : "=r"(hi), "=r"(lo)
        : "r"(a), "r"(b)
        : "g1", "g2", "cc");
    return (u64)hi << 32 | lo;
}

u64 __muldi3(u64 a, u64 b) {
    const u32 alo = (u32)a, ahi = (u32)(a >> 32), blo = (u32)b, bhi = (u32)(b >> 32);
    return product(alo, blo) + ((u64)(alo * bhi + ahi * blo) << 32);
}

/* The quotient of n / d (d != 0), and the remainder in *r. */
static u64 divide(u64 n, u64 d, u64* r) {
    if ((n >> 32) == 0 && (d >> 32) == 0) {
        const u32 q = (u32)n / (u32)d;
        *r = (u32)n - q * (u32)d;
        return q;
    }
    if (d > n) {
        *r = n;
        return 0;
    }
    /* line the divisor up under the dividend's top bit, then one quotient bit a step */
    int shift = 0;
    while ((d << 1) > d && (d << 1) <= n) {
        d <<= 1;
        shift++;
    }
    u64 q = 0;
    for (int i = 0; i <= shift; i++) {
        q <<= 1;
        if (n >= d) {
            n -= d;
            q |= 1;
        }
        d >>= 1;
    }
    *r = n;
    return q;
}

u64 __udivdi3(u64 n, u64 d) {
    u64 r;
    return divide(n, d, &r);
}

u64 __umoddi3(u64 n, u64 d) {
    u64 r;
    divide(n, d, &r);
    return r;
}

s64 __divdi3(s64 n, s64 d) {
    const int negative = (n < 0) != (d < 0);
    u64 r;
    const u64 q = divide(n < 0 ? -(u64)n : (u64)n, d < 0 ? -(u64)d : (u64)d, &r);
    return negative ? -(s64)q : (s64)q;
}

s64 __moddi3(s64 n, s64 d) {
    u64 r;
    divide(n < 0 ? -(u64)n : (u64)n, d < 0 ? -(u64)d : (u64)d, &r);
    return n < 0 ? -(s64)r : (s64)r;
}

/* 64-bit integers to double: each half converted exactly, one rounding in the sum. */
double __floatundidf(u64 v) {
    return (double)(u32)(v >> 32) * 4294967296.0 + (double)(u32)v;
}

double __floatdidf(s64 v) {
    return (double)(s32)(v >> 32) * 4294967296.0 + (double)(u32)v;
}
