# The guest build: fb89's host library and protocol encoding, and the small guest program
# of period/guest, cross-compiled for one period host's instruction set
# (period/<isa>/toolchain.cmake: the MC68020 + MC68881, SPARC V7).
# Nothing of SDL, libpng or the controller. The header-only libraries come from the same
# Debian packages as the native build's (glm, nlohmann-json, fmt in header-only mode, CLI11,
# tinyobjloader's single header), staged in a folder of their own so that the cross
# compiler sees them and nothing else of the native /usr/include.
set(FB89_GUEST_STAGE ${CMAKE_BINARY_DIR}/guest-include)
file(MAKE_DIRECTORY ${FB89_GUEST_STAGE})
foreach(entry glm nlohmann fmt CLI tiny_obj_loader.h)
  if(NOT EXISTS /usr/include/${entry})
    message(FATAL_ERROR "guest build: /usr/include/${entry} is missing (scripts/bootstrap installs it)")
  endif()
  file(CREATE_LINK /usr/include/${entry} ${FB89_GUEST_STAGE}/${entry} SYMBOLIC)
endforeach()

function(fb89_guest_header_library name)
  add_library(${name} INTERFACE IMPORTED)
  set_target_properties(${name} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${FB89_GUEST_STAGE}
                                           INTERFACE_COMPILE_DEFINITIONS "${ARGN}")
endfunction()
fb89_guest_header_library(glm::glm)
fb89_guest_header_library(nlohmann_json::nlohmann_json)
fb89_guest_header_library(fmt::fmt FMT_HEADER_ONLY)
fb89_guest_header_library(CLI11::CLI11)
# as the native package builds it (its CMake config exports the definition)
fb89_guest_header_library(tinyobjloader::tinyobjloader TINYOBJLOADER_USE_DOUBLE)

# SPARC: 64-bit integer helpers in V7 code in place of Debian's V8plus libgcc ones
# (period/sparc/v7_runtime.c), linked into every program of the guest build.
if(CMAKE_SYSTEM_PROCESSOR STREQUAL "sparc")
  add_library(fb89_v7_runtime OBJECT ${PROJECT_SOURCE_DIR}/period/sparc/v7_runtime.c)
  set_target_properties(fb89_v7_runtime PROPERTIES C_STANDARD 11)
  link_libraries(fb89_v7_runtime)
  # the V7 purity check: no C library, for a CPU with nothing newer than V7 (v7_check.c)
  add_executable(fb89_v7_check ${PROJECT_SOURCE_DIR}/period/sparc/v7_check.c)
  target_compile_options(fb89_v7_check PRIVATE -ffreestanding)
  target_link_options(fb89_v7_check PRIVATE -nostdlib)
  target_link_libraries(fb89_v7_check PRIVATE gcc)
endif()

add_subdirectory(protocol)
add_subdirectory(host)
add_subdirectory(period/guest)
add_subdirectory(period/kernels)
