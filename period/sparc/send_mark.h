// The guest's send mark on SPARC (period/guest/guest_main.cpp): system call 0xfb8a with the
// commands sent so far, in the section the phase markers name to the plugin
// (period/guest/phase_marker.h), so that none of it is counted. A leaf written out (GCC gives
// a C++ version a register window of its own), so that the plugin's window model, which does
// not see this code, stays in step. The count's low word comes in %o1 (a 64-bit argument
// takes %o0 and %o1).
#pragma once

#include <cstdint>

#include "period/guest/phase_marker.h"

extern "C" void fb89_send_mark(uint64_t commands);
__asm__(
    ".section fb89_marks,\"ax\",@progbits\n"
    ".global fb89_send_mark\n"
    ".type fb89_send_mark, #function\n"
    ".align 4\n"
    "fb89_send_mark:\n"
    "\tmov %o1, %o0\n"
    "\tsethi %hi(0xfb8a), %g1\n"
    "\tor %g1, %lo(0xfb8a), %g1\n"
    "\tta 0x10\n"
    "\tretl\n"
    "\tnop\n"
    ".size fb89_send_mark, .-fb89_send_mark\n"
    ".previous\n");
static_assert(fb89::period::kSendSyscall == 0xfb8a);
