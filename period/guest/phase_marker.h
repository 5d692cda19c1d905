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

inline void mark(Phase phase) {
    ::syscall(kMarkerSyscall, static_cast<long>(phase));
}

}  // namespace fb89::period
