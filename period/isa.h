// The period hosts' instruction sets: what runs fb89's host code for each (the emulator,
// the cross-built guest and kernels), as gem5 keeps one folder per ISA beside the CPU
// models every ISA shares. A host profile names its instruction set ("isa"); adding a
// third (a 386 + 387, a MIPS R2000) is a folder period/<isa>/ (toolchain, the plugin's
// classifier, profiles), an entry here and one in period/CMakeLists.txt.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fb89::period {

struct InstructionSet {
    std::string_view name;                         // "m68k", "sparc": the profiles' "isa"
    std::string_view description;                  // for `fb89 list hosts`
    std::string_view qemu;                         // the emulator program, found on PATH
    std::vector<std::string_view> qemu_options;    // before -plugin, e.g. {"-cpu", "m68020"}
    std::vector<std::string_view> plugin_options;  // the plugin's own, e.g. {"windows=7"}
    std::string_view env;                          // "M68K": $FB89_M68K_QEMU, $FB89_M68K_GUEST, ...
    std::string_view packages;                     // the Debian packages of its cross toolchain
    std::string_view guest_path;                   // what the cross build made ("" when not built)
    std::string_view kernels_dir;
};

std::span<const InstructionSet> instruction_sets();
// Throws std::runtime_error naming the known ones.
const InstructionSet& instruction_set(std::string_view name);

}  // namespace fb89::period
