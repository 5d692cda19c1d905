#include "period/isa.h"

#include <stdexcept>

namespace fb89::period {

namespace {

const std::vector<InstructionSet>& all() {
    static const std::vector<InstructionSet> sets = {
        {"m68k",
         "Motorola MC68020 + MC68881 (qemu-m68k -cpu m68020)",
         "qemu-m68k",
         {"-cpu", "m68020"},
         // the Sun-3/260's data cache (the Sun-3/60 has none)
         {"cache=65536:16:wb"},
         "M68K",
         "g++-m68k-linux-gnu, qemu-user",
         FB89_M68K_GUEST_PATH,
         FB89_M68K_KERNELS_DIR},
        {"sparc",
         "SPARC V7, 32-bit (qemu-sparc32plus with the MB86900's 7 register windows)",
         "qemu-sparc32plus",
         // QEMU's window count set to the MB86900's, so that its own window traps fall
         // where the chip's do (period/sparc/classify.c)
         {"-cpu", "TI UltraSparc II,nwindows=7"},
         // the MB86900's and L64801's 7 windows (and the CY7C601's 8 beside them); the
         // SPARCstation 1's (write-through), the Sun-4/260's (write-back) and the
         // SPARCstation 2's (write-through, 32-byte lines) caches
         {"windows=7", "also_windows=8", "cache=65536:16:wt", "cache=131072:16:wb",
          "cache=65536:32:wt"},
         "SPARC",
         "g++-12-sparc64-linux-gnu, g++-12-multilib-sparc64-linux-gnu, "
         "libc6-dev-sparc-sparc64-cross, qemu-user",
         FB89_SPARC_GUEST_PATH,
         FB89_SPARC_KERNELS_DIR},
    };
    return sets;
}

}  // namespace

std::span<const InstructionSet> instruction_sets() {
    return all();
}

const InstructionSet& instruction_set(std::string_view name) {
    std::string known;
    for (const InstructionSet& s : all()) {
        if (s.name == name) return s;
        known += (known.empty() ? "" : ", ") + std::string(s.name);
    }
    throw std::runtime_error("unknown instruction set '" + std::string(name) +
                             "' (known: " + known + ")");
}

}  // namespace fb89::period
