// The guest's send mark on the MC68020 (period/guest/guest_main.cpp): system call 0xfb8a
// with the commands sent so far (Linux/m68k: number in %d0, argument in %d1, trap #0), in the
// section the phase markers name to the plugin (period/guest/phase_marker.h), so that none of
// it is counted. Written out rather than through the C library's syscall(), which lies
// outside that section.
#pragma once

#include <cstdint>

#include "period/guest/phase_marker.h"

extern "C" __attribute__((noinline, section("fb89_marks"))) void fb89_send_mark(uint64_t commands) {
    __asm__ volatile("move.l %0, %%d1\n\tmove.l %1, %%d0\n\ttrap #0"
                     :
                     : "g"(static_cast<long>(commands)), "i"(fb89::period::kSendSyscall)
                     : "d0", "d1", "memory", "cc");
}
