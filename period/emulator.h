// Running fb89's host code on an emulated period host: the guest program (period/guest),
// cross-built for the host's instruction set (period/isa.h), under its QEMU user-mode
// emulator with the counting plugin (period/plugin). The guest runs in the scene's folder
// with an empty environment and a fixed seed for the emulator's random bytes, and writes its
// command stream to a pipe, so that its counts do not depend on where the checkout or the
// output lives, nor vary from run to run.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "period/host_cost.h"
#include "period/isa.h"

namespace fb89::period {

// The emulator, the guest or the plugin is missing, or the guest failed: the message
// names what and, for a missing part, the Debian package that provides it.
class EmulatorError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// For instruction set X (period/isa.h: M68K, SPARC), each part is $FB89_X_QEMU,
// $FB89_X_GUEST, $FB89_X_KERNELS_DIR when set (for m68k also the older $FB89_QEMU,
// $FB89_GUEST, $FB89_KERNELS_DIR), else the emulator found on PATH and what the cross
// build made.
struct EmulatorParts {
    const InstructionSet* isa = nullptr;
    std::string qemu;    // e.g. qemu-m68k, found on PATH
    std::string plugin;  // $FB89_COUNT_PLUGIN, else the one built beside fb89
    std::string guest;   // the guest program the cross build made
};
// Throws EmulatorError when a part cannot be found, naming the Debian packages to install.
EmulatorParts find_emulator_parts(const InstructionSet& isa);

struct GuestRun {
    GuestCounts counts;
    std::string counts_json;      // the plugin's output as written
    std::vector<uint8_t> stream;  // the guest's command stream
    double wall_s = 0;            // how long the emulation took here
};

// Guest memory allowed by default ($FB89_GUEST_MEMORY_LIMIT MiB overrides it): far above
// what any bundled scene needs, and below what would let one run take the machine. It bounds
// the emulator's resident memory (guest and emulator together), looked at every 50 ms.
inline constexpr long kGuestMemoryMiB = 2048;

// Runs the guest on `scene` with `options` (the guest's own, e.g. {"--method", "zbuffer"}),
// for at most `time_limit_s` seconds ($FB89_GUEST_TIME_LIMIT may lower it) and
// kGuestMemoryMiB of memory. A guest that crashes, runs past the time (it is killed) or out
// of memory throws EmulatorError naming the phase it was in; nothing of its output is kept.
GuestRun run_guest(const EmulatorParts& parts, const std::filesystem::path& scene,
                   const std::vector<std::string>& options, double time_limit_s = 3600);

// The validation kernels (period/kernels, docs/HOST_COST_MODEL.md, "Validation"): small
// programs of the instruction set that take no input file. `name` is e.g.
// "fb89_kernel_linpack". Throws EmulatorError when missing.
std::filesystem::path find_kernel(const InstructionSet& isa, const std::string& name);

// Runs a kernel program under the emulator with the counting plugin, in the kernel's folder
// with an empty environment, like run_guest but with no scene and no stream options.
// `stream` holds what the kernel printed. Throws EmulatorError, also when the kernel exits
// non-zero (its own check failed).
GuestRun run_kernel(const EmulatorParts& parts, const std::filesystem::path& kernel,
                    const std::vector<std::string>& options, double time_limit_s = 3600);

}  // namespace fb89::period
