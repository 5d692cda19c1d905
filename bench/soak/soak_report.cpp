#include "bench/soak/soak_report.h"

#include <cmath>

#include <fmt/format.h>

namespace fb89::soak {

namespace {

bool no_fd_growth(const std::vector<ResourceSample>& samples) {
    return samples.empty() || samples.back().fds <= samples.front().fds;
}

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& s : items)
        out += (out.empty() ? "" : " ") + s;
    return out;
}

std::string resources_line(const std::string& who, const std::vector<ResourceSample>& s) {
    if (s.empty()) return fmt::format("  {}: no samples\n", who);
    uint64_t peak = 0;
    for (const ResourceSample& x : s)
        peak = std::max(peak, x.rss_kib);
    std::string out = fmt::format(
        "  {}: RSS {} KiB after cycle {}, {} KiB after cycle {} (peak sampled {} KiB); fds {} -> "
        "{}\n",
        who, s.front().rss_kib, s.front().cycle, s.back().rss_kib, s.back().cycle, peak,
        s.front().fds, s.back().fds);
    if (s.front().trimmed_kib > 0)
        out += fmt::format(
            "  {}: RSS after malloc_trim {} KiB after cycle {}, {} KiB after cycle {}; heap in "
            "use {} -> {} bytes\n",
            who, s.front().trimmed_kib, s.front().cycle, s.back().trimmed_kib, s.back().cycle,
            s.front().heap_bytes, s.back().heap_bytes);
    return out;
}

nlohmann::json samples_json(const std::vector<ResourceSample>& samples) {
    nlohmann::json out = nlohmann::json::array();
    for (const ResourceSample& s : samples)
        out.push_back({{"cycle", s.cycle},
                       {"rss_kib", s.rss_kib},
                       {"trimmed_rss_kib", s.trimmed_kib},
                       {"heap_bytes", s.heap_bytes},
                       {"fds", s.fds}});
    return out;
}

}  // namespace

void SoakResult::fail(std::string what) {
    ++failure_count;
    if (failures.size() < kFailuresKept) failures.push_back(std::move(what));
}

SoakResult start_result(const std::string& mode, const SoakOptions& options) {
    SoakResult r;
    r.mode = mode;
    r.cycles_planned = options.cycles;
    for (const auto& s : options.scenes)
        r.scenes.push_back(s.stem().string());
    r.methods = options.methods;
    r.max_rss_growth_kib = options.max_rss_growth_kib;
    // room for every sample up front, so that the soak's own records do not grow its heap
    const std::size_t samples = static_cast<std::size_t>(options.cycles / options.every) + 2;
    r.samples.reserve(samples);
    r.parent_samples.reserve(samples);
    r.failures.reserve(SoakResult::kFailuresKept);
    return r;
}

Verdict judge(const SoakResult& r) {
    Verdict v;
    v.slope_kib_per_cycle = rss_slope_kib_per_cycle(r.samples, r.cycles);
    v.growth_kib = v.slope_kib_per_cycle * r.cycles / 2;
    v.heap_slope_bytes_per_cycle = r.samples.empty() || r.samples.front().heap_bytes == 0
                                       ? NAN
                                       : heap_slope_bytes_per_cycle(r.samples, r.cycles);
    if (r.max_rss_growth_kib > 0 && std::isfinite(v.growth_kib))
        v.rss_ok = v.growth_kib <= r.max_rss_growth_kib;
    v.fds_ok = no_fd_growth(r.samples) && no_fd_growth(r.parent_samples);
    v.frames_ok = r.failure_count == 0 && r.frames_received == r.frames_expected &&
                  r.frames_mismatched == 0 && r.cycles == r.cycles_planned;
    v.files_ok = r.stray_files == 0;
    return v;
}

std::string summary(const SoakResult& r, const Verdict& v) {
    std::string out = fmt::format(
        "fb89_soak {}: {} of {} cycles over {} scenes x {} methods in {:.1f} s ({:.1f} ms a "
        "cycle)\n",
        r.mode, r.cycles, r.cycles_planned, r.scenes.size(), r.methods.size(), r.wall_s,
        r.cycles ? 1e3 * r.wall_s / r.cycles : 0.0);
    out += fmt::format("  scenes: {}\n  methods: {}\n", joined(r.scenes), joined(r.methods));
    out += fmt::format(
        "  frames: {} expected, {} received, {} lost, {} mismatched; {} commands checked\n",
        r.frames_expected, r.frames_received, r.frames_expected - r.frames_received,
        r.frames_mismatched, r.commands_checked);
    out += resources_line(r.watched, r.samples);
    if (!r.parent_samples.empty()) out += resources_line("fb89_soak", r.parent_samples);
    const std::string bound = r.max_rss_growth_kib > 0
                                  ? fmt::format("bound {:.0f} KiB", r.max_rss_growth_kib)
                                  : std::string("not checked");
    if (std::isfinite(v.slope_kib_per_cycle))
        out += fmt::format(
            "  RSS slope over the second half{}: {:+.4f} KiB/cycle, {:+.1f} KiB over {} cycles "
            "({})\n",
            !r.samples.empty() && r.samples.front().trimmed_kib > 0 ? " (after malloc_trim)" : "",
            v.slope_kib_per_cycle, v.growth_kib, r.cycles / 2, bound);
    else
        out += "  RSS slope: none (fewer than two samples in the second half)\n";
    if (std::isfinite(v.heap_slope_bytes_per_cycle))
        out += fmt::format("  heap in use, slope over the second half: {:+.2f} bytes/cycle\n",
                           v.heap_slope_bytes_per_cycle);
    if (r.mode == "cli")
        out += fmt::format("  stray files in the work folder: {}\n", r.stray_files);
    for (const std::string& note : r.notes)
        out += "  note: " + note + "\n";
    for (const std::string& f : r.failures)
        out += "  FAILED: " + f + "\n";
    if (r.failure_count > r.failures.size())
        out += fmt::format("  ... and {} more failures\n", r.failure_count - r.failures.size());
    out += fmt::format("  verdict: {} (frames {}, fds {}, RSS {}, files {})\n",
                       v.pass() ? "PASS" : "FAIL", v.frames_ok ? "ok" : "FAILED",
                       v.fds_ok ? "ok" : "LEAK", v.rss_ok ? "flat" : "GROWS",
                       v.files_ok ? "ok" : "LEFT BEHIND");
    return out;
}

nlohmann::json to_json(const SoakResult& r, const Verdict& v) {
    auto number = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
    return {{"mode", r.mode},
            {"cycles_planned", r.cycles_planned},
            {"cycles", r.cycles},
            {"scenes", r.scenes},
            {"methods", r.methods},
            {"wall_s", r.wall_s},
            {"watched", r.watched},
            {"samples", samples_json(r.samples)},
            {"parent_samples", samples_json(r.parent_samples)},
            {"frames_expected", r.frames_expected},
            {"frames_received", r.frames_received},
            {"frames_lost", r.frames_expected - r.frames_received},
            {"frames_mismatched", r.frames_mismatched},
            {"commands_checked", r.commands_checked},
            {"stray_files", r.stray_files},
            {"failure_count", r.failure_count},
            {"failures", r.failures},
            {"notes", r.notes},
            {"rss_slope_kib_per_cycle", number(v.slope_kib_per_cycle)},
            {"heap_slope_bytes_per_cycle", number(v.heap_slope_bytes_per_cycle)},
            {"rss_growth_kib_second_half", number(v.growth_kib)},
            {"max_rss_growth_kib", r.max_rss_growth_kib},
            {"fds_first", r.samples.empty() ? 0 : r.samples.front().fds},
            {"fds_last", r.samples.empty() ? 0 : r.samples.back().fds},
            {"rss_ok", v.rss_ok},
            {"fds_ok", v.fds_ok},
            {"frames_ok", v.frames_ok},
            {"files_ok", v.files_ok},
            {"pass", v.pass()}};
}

}  // namespace fb89::soak
