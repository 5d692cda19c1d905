/*
 * v7_check.c - fb89_v7_check: a program with no C library, built like the Sun-4 guest
 * (-m32 -mcpu=v7) with fb89's V7 64-bit helpers (v7_runtime.c) and libgcc's V7 .umul and
 * .udiv, for a CPU that has nothing newer than V7: `qemu-sparc -cpu "Fujitsu
 * MB86904,-mul,-div,-fsqrt"` stops it with SIGILL on any V8 or V9 instruction. It runs
 * what fb89's code leans on -- 32- and 64-bit multiplies and divides, 64-bit conversions to
 * double, a recursion through the register windows, register adds -- checks each answer,
 * and exits 0 when every one is right (1 otherwise).
 */
#include <stdint.h>

/* The entry point: QEMU gives it a stack; main's status goes to exit(2) (Linux/SPARC's
   system call 1, through trap 0x10). */
__asm__(".section \".text\"\n"
        ".global _start\n"
        "_start:\n"
        "    call main\n"
        "    nop\n"
        "    mov 1, %g1\n"
        "    ta 0x10\n");

/* Values the compiler cannot see through. */
static volatile uint64_t big_a = 0x123456789abcdefULL, big_b = 0xfedcbaULL;
static volatile int64_t negative = -987654321012345LL;
static volatile uint32_t small_a = 123457, small_b = 97;

__attribute__((noinline, noipa)) static int descend(int n)
{
    if (n == 0) {
        return 0;
    }
    volatile int here = n;
    return descend(n - 1) + here;
}

int main(void)
{
    int wrong = 0;
    const uint64_t a = big_a, b = big_b;
    const int64_t n = negative;
    /* 64-bit multiply, divide, remainder: the answer put back together */
    const uint64_t q = a / b, r = a % b;
    wrong += q * b + r != a;
    wrong += r >= b;
    const int64_t sq = n / 12345, sr = n % 12345;
    wrong += sq * 12345 + sr != n;
    wrong += sr > 0;
    wrong += (uint64_t)0xffffffffULL * 0xffffffffULL != 0xfffffffe00000001ULL;
    /* 32-bit: libgcc's .umul and .udiv */
    const uint32_t x = small_a, y = small_b;
    wrong += (x / y) * y + x % y != x;
    wrong += x * y != 11975329u;
    /* 64-bit integers to double */
    const double d = (double)(int64_t)n;
    wrong += d != -987654321012345.0;
    wrong += (double)(uint64_t)a != 81985529216486895.0;
    /* a recursion deeper than the register file */
    wrong += descend(100) != 5050;
    /* register adds */
    int j = 0;
    for (int i = 0; i < 1000; i++) {
        j += (int)y;
    }
    wrong += j != 97000;
    return wrong ? 1 : 0;
}
