// The register add of the intloop kernel (period/kernels/intloop.cpp) on SPARC: one
// `add %rk, %rj, %rj`, as Sun's compilers emitted for `j+=k` (GCC would fold eighteen of
// them into one multiply).
#pragma once

[[gnu::always_inline]] inline void register_add(int& j, int k) {
    asm volatile("add %1, %0, %0" : "+r"(j) : "r"(k));
}
