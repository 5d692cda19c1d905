# Toolchain for the Sun-3 period hosts: Debian's m68k-linux-gnu cross compiler
# (g++-m68k-linux-gnu), code for an MC68020 with an MC68881 floating-point coprocessor,
# static, -O2. Used by the guest build (cmake/guest.cmake), which the native build drives
# as an external project (period/CMakeLists.txt).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR m68k)
set(CMAKE_C_COMPILER m68k-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER m68k-linux-gnu-g++)
set(CMAKE_C_FLAGS_INIT "-mcpu=68020 -m68881")
set(CMAKE_CXX_FLAGS_INIT "-mcpu=68020 -m68881")
set(CMAKE_C_FLAGS_RELEASE_INIT "-O2 -DNDEBUG")
set(CMAKE_CXX_FLAGS_RELEASE_INIT "-O2 -DNDEBUG")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
set(CMAKE_FIND_ROOT_PATH /usr/m68k-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(FB89_GUEST ON CACHE BOOL "Build the guest (host code for an emulated period host)" FORCE)
