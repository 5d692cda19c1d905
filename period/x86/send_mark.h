// The guest's send mark on the 386 (period/guest/guest_main.cpp): system call 0xfb8a with the
// commands sent so far (Linux/i386: number in %eax, argument in %ebx, int $0x80), in the
// section the phase markers name to the plugin (period/guest/phase_marker.h), so that none of
// it is counted. Written out rather than through the C library's syscall(), which lies
// outside that section.
#pragma once

#include <cstdint>

#include "period/guest/phase_marker.h"

extern "C" __attribute__((noinline, section("fb89_marks"))) void fb89_send_mark(uint64_t commands) {
    long result = fb89::period::kSendSyscall;
    __asm__ volatile("int $0x80"
                     : "+a"(result)
                     : "b"(static_cast<long>(commands))
                     : "memory", "cc");
}
