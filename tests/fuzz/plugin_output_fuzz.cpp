// Fuzz target: the counting plugin's output as fb89 reads it (period/plugin writes a JSON
// file of per-phase instruction class counts; run_guest and the cached --results files of
// experiments go through period::parse_guest_counts, then period::price with the host
// profile). Bad input must throw std::runtime_error naming the file; nothing else may
// escape. Counts that load, priced by the built-in sun3-60 profile, must give per-phase and
// end-to-end times that are finite and >= 0, and the phase lookup must find what was read.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "period/host_cost.h"
#include "period/host_profile.h"
#include "period/validation.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using fb89::fuzz::finding;
namespace period = fb89::period;

void check(const period::GuestCounts& counts) {
    static const period::HostProfile profile = period::load_host_profile("sun3-60");
    for (const period::PhaseCounts& c : counts.phases) {
        const period::PhaseCounts* found = counts.phase(c.phase);
        if (!found || found->phase != c.phase) finding("phase() does not find a phase read");
    }
    const period::HostCost cost = period::price(counts, profile);
    for (const period::PhaseCost& c : cost.phases)
        if (!std::isfinite(c.ms) || c.ms < 0 || !std::isfinite(c.cpu_cycles) ||
            !std::isfinite(c.fpu_cycles))
            finding("a phase priced at a time that is not finite and >= 0");
    const double e2e = cost.end_to_end_ms();
    if (!std::isfinite(e2e) || e2e < 0) finding("an end-to-end time not finite and >= 0");
    // host validate's figure at a given clock (the cycles path; price's ms path is above)
    const double s = period::timed_seconds(counts, profile, 20.0);
    if (!std::isfinite(s) || s < 0) finding("timed_seconds not finite and >= 0");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    static const std::string kOrigin = "counts.json";
    try {
        check(period::parse_guest_counts(text, kOrigin));
    } catch (const std::runtime_error& e) {
        if (std::string_view(e.what()).find(kOrigin) == std::string_view::npos)
            finding("an error that does not name the file");
    }
    return 0;
}
