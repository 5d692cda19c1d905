// fb89_kernel_fault: a guest that fails on purpose, for the tests of how fb89 stops and
// reports a 1989-host run that goes wrong (tests/period/failure_test.cpp). It marks the
// phases as the real guest does, then in Phase::HiddenSurface does what its first argument
// says: `crash` (writes through a null pointer), `loop` (never ends), `hog` (allocates memory
// until there is none), `exit` (exits 3), `term` (sends itself SIGTERM, as a kill from
// outside would; not a crash). Any other first argument, such as
// the scene a real guest is given, crashes, so that it can stand in for the guest program
// ($FB89_GUEST) in command-line tests.
#include <csignal>
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
        volatile unsigned i = 0;
        for (;;)
            i = i + 1;
    }
    if (std::strcmp(what, "hog") == 0) {
        // 8 MiB at a time, one byte of each 4 KiB page touched: resident all the same, and
        // reached without emulating a store to every byte
        std::vector<char*> blocks;
        for (;;) {
            volatile char* block = new char[8 << 20];
            for (int i = 0; i < (8 << 20); i += 4096)
                block[i] = 1;
            blocks.push_back(const_cast<char*>(block));
        }
    }
    if (std::strcmp(what, "exit") == 0) return 3;
    if (std::strcmp(what, "term") == 0) std::raise(SIGTERM);
    volatile int* nowhere = nullptr;
    *nowhere = 1;
    return 0;
}
