// A soak's outcome: frames expected, received and mismatched, the failures named by cycle,
// the resources sampled, and the verdict: no frame lost or different, no descriptor more at
// the end than after the first cycle, no file left behind, and resident memory flat (its
// least-squares slope over the second half, times the cycles there, within the bound).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/soak/resource_sampler.h"
#include "bench/soak/soak_plan.h"

namespace fb89::soak {

struct SoakResult {
    std::string mode;  // inprocess, cli, controller
    int cycles_planned = 0, cycles = 0;
    std::vector<std::string> scenes, methods;
    double wall_s = 0;
    std::string watched;                         // whose resources `samples` holds
    std::vector<ResourceSample> samples;         // the watched process
    std::vector<ResourceSample> parent_samples;  // controller mode: fb89_soak itself too
    uint64_t frames_expected = 0, frames_received = 0, frames_mismatched = 0;
    uint64_t commands_checked = 0;
    uint64_t stray_files = 0;           // files left in the work folder that nobody asked for
    std::vector<std::string> failures;  // the first kFailuresKept, by cycle
    uint64_t failure_count = 0;
    std::vector<std::string> notes;  // what the summary should say besides the figures
    double max_rss_growth_kib = 0;

    static constexpr std::size_t kFailuresKept = 20;
    void fail(std::string what);
};

SoakResult start_result(const std::string& mode, const SoakOptions& options);

struct Verdict {
    double slope_kib_per_cycle = 0;         // NaN: too few samples in the second half
    double growth_kib = 0;                  // slope x half the cycles
    double heap_slope_bytes_per_cycle = 0;  // this process's heap (NaN when not sampled)
    bool rss_ok = true, fds_ok = true, frames_ok = true, files_ok = true;
    bool pass() const { return rss_ok && fds_ok && frames_ok && files_ok; }
};

Verdict judge(const SoakResult& r);
std::string summary(const SoakResult& r, const Verdict& v);
nlohmann::json to_json(const SoakResult& r, const Verdict& v);

}  // namespace fb89::soak
