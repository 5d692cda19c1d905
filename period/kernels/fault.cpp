// fb89_kernel_fault: a guest that fails on purpose, for the tests of how fb89 stops and
// reports a 1989-host run that goes wrong (tests/period/failure_test.cpp). It marks the
// phases as the real guest does, then in Phase::HiddenSurface does what its first argument
// says: `crash` (writes through a null pointer), `loop` (never ends), `hog` (allocates and
// touches memory until there is none), `exit` (exits 3). Any other first argument, such as
// the scene a real guest is given, crashes, so that it can stand in for the guest program
// ($FB89_GUEST) in command-line tests.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "period/guest/phase_marker.h"

int main(int argc, char** argv) {
    using fb89::period::mark;
    using fb89::period::Phase;
    mark(Phase::Startup);
    mark(Phase::Load);
    mark(Phase::Setup);
    mark(Phase::HiddenSurface);
    const char* what = argc > 1 ? argv[1] : "crash";
    if (std::strcmp(what, "loop") == 0) {
        for (volatile unsigned i = 0;; i = i + 1) {
        }
    }
    if (std::strcmp(what, "hog") == 0) {
        std::vector<char*> blocks;
        for (;;) {
            char* block = new char[8 << 20];
            std::memset(block, 1, 8 << 20);
            blocks.push_back(block);
        }
    }
    if (std::strcmp(what, "exit") == 0) return 3;
    volatile int* nowhere = nullptr;
    *nowhere = 1;
    return 0;
}
