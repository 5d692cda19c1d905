// fb89_kernel_intloop: the register-add loop of Appel & Li's VM-PUP benchmark (vmpup.c,
// 1990), for every period host's instruction set (docs/HOST_COST_MODEL.md, "Validation").
// vmpup.c times
//
//     register int i, j, k;
//     i = ADDS/20; j = 0;
//     do {j+=k; ... 18 times ...} while (--i>0);
//
// with ADDS = 1000000 and prints the time divided by ADDS as microseconds per add (0.120 on a
// Sun-3/60 under SunOS 4.0). The same loop runs here inside Phase::HiddenSurface, so the
// modelled time of phase 3 divided by 1000000 is the figure vmpup.c prints.
//
// The compilers of 1990 emitted one register add per `j+=k`; GCC would fold eighteen of
// them into one multiply, so each add is written as that instruction, in the instruction
// set's folder (period/<isa>/register_add.h). The loop control is the compiler's.
#include <cstdio>

#include "period/guest/phase_marker.h"
#include "register_add.h"  // period/<isa>/register_add.h, on the guest build's include path

namespace {

constexpr int kAdds = 1000000;  // vmpup.c's ADDS

[[gnu::always_inline]] inline void add(int& j, int k) {
    register_add(j, k);
}

}  // namespace

int main(int argc, char**) {
    using fb89::period::mark;
    using fb89::period::Phase;

    mark(Phase::Load);
    int i = kAdds / 20;
    int j = 0;
    const int k = argc + 2;  // 3, and unknown to the compiler

    mark(Phase::HiddenSurface);
    do {
        add(j, k), add(j, k), add(j, k), add(j, k), add(j, k), add(j, k);
        add(j, k), add(j, k), add(j, k), add(j, k), add(j, k), add(j, k);
        add(j, k), add(j, k), add(j, k), add(j, k), add(j, k), add(j, k);
    } while (--i > 0);

    mark(Phase::Output);
    const int expected = 18 * (kAdds / 20) * k;
    std::printf("intloop adds=%d j=%d expected=%d\n", 18 * (kAdds / 20), j, expected);
    return j == expected ? 0 : 1;
}
