# Toolchain for the Sun-4 period hosts: Debian's sparc64 cross compiler in 32-bit SPARC V7
# mode (g++-12-sparc64-linux-gnu with its multilib and libc6-dev-sparc-sparc64-cross),
# static, -O2. GCC is configured --with-cpu-32=ultrasparc, so plain -m32 would mean V8plus:
# -mcpu=v7 makes fb89's own code pure V7 (multiply and divide through libgcc's .umul and
# .udiv, no fsmuld). Debian's 32-bit libraries are built for V8plus; the V8/V9 instructions
# they run are priced as V7 stand-ins (docs/HOST_COST_MODEL.md, "SPARC"). V7 has no atomic
# instructions, so std::atomic needs libatomic. The result is a SPARC32PLUS ELF file, run by
# qemu-sparc32plus. Used by the guest build (cmake/guest.cmake).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR sparc)
set(CMAKE_C_COMPILER sparc64-linux-gnu-gcc-12)
set(CMAKE_CXX_COMPILER sparc64-linux-gnu-g++-12)
set(CMAKE_C_FLAGS_INIT "-m32 -mcpu=v7")
set(CMAKE_CXX_FLAGS_INIT "-m32 -mcpu=v7")
set(CMAKE_C_FLAGS_RELEASE_INIT "-O2 -DNDEBUG")
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-O2 -DNDEBUG")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-m32 -static")
set(CMAKE_CXX_STANDARD_LIBRARIES "-latomic")
set(CMAKE_FIND_ROOT_PATH /usr/sparc64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(FB89_GUEST ON CACHE BOOL "Build the guest (host code for an emulated period host)" FORCE)
