// The register add of the intloop kernel (period/kernels/intloop.cpp) on the 386: one
// `addl %reg,%reg`, as the compilers of 1990 emitted for `j+=k` in registers (GCC would fold
// eighteen of them into one multiply).
#pragma once

[[gnu::always_inline]] inline void register_add(int& j, int k) {
    asm volatile("addl %1,%0" : "+r"(j) : "r"(k));
}
