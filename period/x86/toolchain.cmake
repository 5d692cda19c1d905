# Toolchain for the 386 PC period host: Debian's own GCC in 32-bit mode for the Intel 80386
# with the 80387 (g++-12-multilib, libc6-dev-i386), static, -O2. -march=i386 keeps fb89's own
# code to the 386's instructions (no cmov, bswap, cmpxchg or SSE) and -mfpmath=387 puts its
# floating point on the 387's stack. Debian's 32-bit C and C++ libraries are built for newer
# x86 (i686); what of them runs is priced as the 386 sequences that would stand in for it
# (docs/HOST_COST_MODEL.md, "The 386 PC"). Run by qemu-i386. Used by the guest build
# (cmake/guest.cmake).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR i386)
set(CMAKE_C_COMPILER gcc)
set(CMAKE_CXX_COMPILER g++)
set(CMAKE_C_FLAGS_INIT "-m32 -march=i386 -mtune=i386 -mfpmath=387")
set(CMAKE_CXX_FLAGS_INIT "-m32 -march=i386 -mtune=i386 -mfpmath=387")
set(CMAKE_C_FLAGS_RELEASE_INIT "-O2 -DNDEBUG")
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-O2 -DNDEBUG")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-m32 -static")
set(CMAKE_CXX_STANDARD_LIBRARIES "-latomic")
set(CMAKE_LIBRARY_ARCHITECTURE i386-linux-gnu)
set(FB89_GUEST ON CACHE BOOL "Build the guest (host code for an emulated period host)" FORCE)
