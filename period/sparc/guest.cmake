# The SPARC guest build's own part (included by cmake/guest.cmake): 64-bit integer helpers
# in V7 code in place of Debian's V8plus libgcc ones (v7_runtime.c), linked into every
# program, and the V7 purity check.
add_library(fb89_v7_runtime OBJECT ${PROJECT_SOURCE_DIR}/period/sparc/v7_runtime.c)
set_target_properties(fb89_v7_runtime PROPERTIES C_STANDARD 11)
link_libraries(fb89_v7_runtime)
# the V7 purity check: no C library, for a CPU with nothing newer than V7 (v7_check.c)
add_executable(fb89_v7_check ${PROJECT_SOURCE_DIR}/period/sparc/v7_check.c)
target_compile_options(fb89_v7_check PRIVATE -ffreestanding)
target_link_options(fb89_v7_check PRIVATE -nostdlib)
target_link_libraries(fb89_v7_check PRIVATE gcc)
