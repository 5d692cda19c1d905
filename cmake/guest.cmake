# The guest build: fb89's host library and protocol encoding, and the small guest program
# of period/guest, cross-compiled for one period host's instruction set
# (period/<isa>/toolchain.cmake, FB89_GUEST_ISA naming the folder).
# Nothing of SDL, libpng or the controller. The header-only libraries come from the same
# Debian packages as the native build's (glm, nlohmann-json, fmt, CLI11,
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
# fmt compiled once (period/guest/fmt_compiled.cpp), not header-only in every file
add_library(fb89_guest_fmt STATIC ${PROJECT_SOURCE_DIR}/period/guest/fmt_compiled.cpp)
target_include_directories(fb89_guest_fmt SYSTEM PUBLIC ${FB89_GUEST_STAGE})
add_library(fmt::fmt ALIAS fb89_guest_fmt)
fb89_guest_header_library(CLI11::CLI11)
# as the native package builds it (its CMake config exports the definition)
fb89_guest_header_library(tinyobjloader::tinyobjloader TINYOBJLOADER_USE_DOUBLE)

# The instruction set's own part of the build: its folder's headers (send_mark.h,
# register_add.h) on every program's include path, and its guest.cmake if it has one.
if(NOT FB89_GUEST_ISA OR NOT EXISTS ${PROJECT_SOURCE_DIR}/period/${FB89_GUEST_ISA}/isa.json)
  message(FATAL_ERROR "guest build: FB89_GUEST_ISA names no folder period/<isa>/ with an isa.json")
endif()
include_directories(${PROJECT_SOURCE_DIR}/period/${FB89_GUEST_ISA})
include(${PROJECT_SOURCE_DIR}/period/${FB89_GUEST_ISA}/guest.cmake OPTIONAL)

add_subdirectory(protocol)
add_subdirectory(host)
add_subdirectory(period/guest)
add_subdirectory(period/kernels)
# Build time (every guest is built by each build tree, file by file, with a cross compiler
# slower than the native one): the standard and GLM headers most of the host library's files
# read, precompiled once for each library. Not fmt (compiled once, above) nor JSON, which few
# files read: in a precompiled header they cost every other file more to load than they
# saved. CPU-seconds of the m68k guest's build with -j2: 245 with fmt header-only and a
# header of fmt, JSON and the standard library; 190 with none; 155 as here
# (docs/BENCHMARKS.md, "Build and test time").
foreach(target fb89_protocol fb89_host)
  target_precompile_headers(${target} PRIVATE <vector> <algorithm> <cstdint> <cmath> <string>
                            <array> <stdexcept> <optional> <glm/geometric.hpp> <glm/vec3.hpp>)
endforeach()
