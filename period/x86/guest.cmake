# The 386 guest build's own part (included by cmake/guest.cmake). Debian's gcc-multilib,
# which would link /usr/include/asm for -m32, conflicts with the m68k and SPARC cross
# compilers; the kernel's headers for both x86 widths are in /usr/include/x86_64-linux-gnu/asm
# (asm/unistd.h picks the 32-bit table under __i386__), linked here into a folder of the
# guest build's own.
set(x86_include ${CMAKE_BINARY_DIR}/x86-include)
file(MAKE_DIRECTORY ${x86_include})
if(NOT EXISTS /usr/include/x86_64-linux-gnu/asm/unistd.h)
  message(FATAL_ERROR "guest build: /usr/include/x86_64-linux-gnu/asm is missing (linux-libc-dev)")
endif()
file(CREATE_LINK /usr/include/x86_64-linux-gnu/asm ${x86_include}/asm SYMBOLIC)
include_directories(SYSTEM ${x86_include})
