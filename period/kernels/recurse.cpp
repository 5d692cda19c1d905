// fb89_kernel_recurse DEPTH: a recursion of known depth, for checking how the counting
// plugin counts register-window traps on SPARC (period/sparc/classify.c). Inside phase 3
// `descend(DEPTH)` calls itself DEPTH times and returns, so phase 3 executes exactly
// DEPTH + 1 saves and DEPTH + 1 restores; with W windows (W - 1 resident) a deep enough
// call spills and fills one window per level beyond the ones the register file holds, so
// two depths' overflow and underflow counts differ by exactly the difference of the
// depths. On the MC68020 it is just calls. Prints the sum it computes and exits 0.
#include <cstdio>
#include <cstdlib>

#include "period/guest/phase_marker.h"

namespace {

// Not a tail call, and no loop the compiler can make of it: the frame holds `here`,
// read after the inner call returns; noipa keeps GCC from splitting it in two (which would
// give two frames a level).
[[gnu::noipa]] int descend(int n) {
    if (n == 0) return 0;
    volatile int here = n;
    return descend(n - 1) + here;
}

}  // namespace

int main(int argc, char** argv) {
    using fb89::period::mark;
    using fb89::period::Phase;
    const int depth = argc > 1 ? std::atoi(argv[1]) : 100;
    if (depth < 0 || depth > 100000) return 2;
    mark(Phase::HiddenSurface);
    const int sum = descend(depth);
    mark(Phase::Output);
    std::printf("recurse depth=%d sum=%d\n", depth, sum);
    return sum == depth * (depth + 1) / 2 ? 0 : 1;
}
