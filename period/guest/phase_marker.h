// Phase markers: the guest tells the counting plugin (period/plugin) which of the host's
// phases it is in by a system call Linux/m68k does not have. QEMU answers it with ENOSYS and
// carries on; the plugin sees its number and argument and attributes what follows to that
// phase. Natively (tests of the guest program) the call fails the same way and costs a
// system call.
#pragma once

#include <unistd.h>

#include <sys/syscall.h>

#include "period/phases.h"

namespace fb89::period {

inline constexpr long kMarkerSyscall = 0xfb89;
// A send mark (guest_main.cpp): the host has sent this many commands so far.
inline constexpr long kSendSyscall = 0xfb8a;

}  // namespace fb89::period

// The send marks' code, in a section of its own whose bounds the linker names; weak, so that
// a program without send marks (the kernels) has none and passes 0, 0.
extern "C" {
extern const char __start_fb89_marks[] __attribute__((weak));
extern const char __stop_fb89_marks[] __attribute__((weak));
}

namespace fb89::period {

// Each marker also names the send marks' code, which the plugin then does not count.
inline void mark(Phase phase) {
    ::syscall(kMarkerSyscall, static_cast<long>(phase), reinterpret_cast<long>(__start_fb89_marks),
              reinterpret_cast<long>(__stop_fb89_marks));
}

}  // namespace fb89::period
