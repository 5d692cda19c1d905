// The period hosts' instruction sets: what runs fb89's host code for each (the emulator,
// the cross-built guest and kernels), as gem5 keeps one folder per ISA beside the CPU
// models every ISA shares. A host profile names its instruction set ("isa"). Each is a folder
// period/<isa>/ and nothing else: isa.json (what this file reads: its emulator, options,
// compiler and Debian packages), toolchain.cmake, classify.c (the plugin's part), the
// guest's send_mark.h and register_add.h, an optional guest.cmake, and profiles/. The build
// finds the folders (period/CMakeLists.txt).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fb89::period {

struct InstructionSet {
    std::string name;                         // "m68k", "sparc": the profiles' "isa"
    std::string description;                  // for `fb89 list hosts`
    std::string qemu;                         // the emulator program, found on PATH
    std::vector<std::string> qemu_options;    // before -plugin, e.g. {"-cpu", "m68020"}
    std::vector<std::string> plugin_options;  // the plugin's own, e.g. {"windows=7"}
    std::string env;                          // "M68K": $FB89_M68K_QEMU, $FB89_M68K_GUEST, ...
    std::string packages;                     // the Debian packages of its cross toolchain
    std::string guest_path;                   // what the cross build made ("" when not built)
    std::string kernels_dir;
};

std::span<const InstructionSet> instruction_sets();
// Throws std::runtime_error naming the known ones.
const InstructionSet& instruction_set(std::string_view name);

// What the build knows of one instruction set: its isa.json and where its cross build put the
// guest and kernels ("" when it was off). Written by period/CMakeLists.txt.
struct InstructionSetSource {
    std::string_view json;
    std::string_view origin;  // the file, for errors
    std::string_view guest_path;
    std::string_view kernels_dir;
};
std::span<const InstructionSetSource> instruction_set_sources();

}  // namespace fb89::period
