// fb89 calibrate [SCENE...]: the paper's calibration (§3), done for this machine. The
// hybrid is timed along a ramp of Expr. 3.1 thresholds on a set of scenes (default A-F),
// interleaved; the threshold with the least total time over the set is chosen, printed,
// and saved where `render --method hybrid` picks it up (cli/calibration.h). The paper's
// 0.04 is always on the ramp and stays available as `--threshold paper`.
//
// One addition to the paper's rule: a total is dominated by the slowest scenes, so a
// threshold that wins on them may cost the light ones dearly. A threshold is eligible
// only if no scene is more than --tolerance (default 3%) slower than with the pure
// Z-buffer (threshold 0, always eligible): the paper's "negligible degradation".
//
// With --method beam it chooses the beam-ray hybrid's Expr. 2.7 threshold the same way
// (§4: "determined using the same method"), on G, H, I and the mirrored Cornell box by
// default, from 0 (the ray tracer at once) through a log ramp to infinity (beams down to
// single pixels); every threshold shows the same frame, so only time decides.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/calibration.h"
#include "cli/common.h"
#include "cli/experiments.h"

namespace fb89::cli {

namespace {

struct CalibrateArgs {
    std::vector<std::string> scenes;
    double from = 0.0005, to = 2.0;
    int steps = 12;
    int repeat = 5;
    double tolerance = 0.03;
    std::string csv;
    std::string method = "hybrid";
    bool dry_run = false, quiet = false;
};

int run_calibrate_beam(const CalibrateArgs& a) {
    ExperimentSettings s;
    s.scenes = a.scenes;
    if (s.scenes.empty())
        s.scenes = {"scenes/G.json", "scenes/H.json", "scenes/I.json",
                    "scenes/cornell_mirror.json"};
    s.repeat = a.repeat;
    s.progress = !a.quiet && isatty(STDERR_FILENO);
    Table table = experiment_beam_threshold(s, beam_threshold_ramp());
    if (!a.csv.empty()) write_text(a.csv, table.csv());
    std::map<double, double> total;
    double rays_total = 0;
    for (const auto& row : table.rows()) {
        if (row[1] == "raytrace") {
            rays_total += std::stod(row[3]);
            continue;
        }
        total[std::stod(row[1])] += std::stod(row[3]);
    }
    auto best = total.begin();
    for (auto it = total.begin(); it != total.end(); ++it)
        if (it->second < best->second) best = it;
    nlohmann::json details;
    details["scenes"] = s.scenes;
    details["repeat"] = s.repeat;
    details["raytrace_total_ms"] = rays_total;
    details["total_ms_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, ms] : total)
        details["total_ms_by_threshold"].push_back({std::isinf(t) ? 1e300 : t, ms});
    details["chosen_total_ms"] = best->second;
    if (!a.dry_run) save_beam_calibration(best->first, details.dump());
    if (!a.quiet) {
        std::cerr << fmt::format("{:>12}  {:>12}  {:>12}\n", "threshold", "total ms", "vs rays");
        for (const auto& [t, ms] : total)
            std::cerr << fmt::format("{:>12.6g}  {:>12.3f}  {:>12.3f}{}\n", t, ms, ms / rays_total,
                                     t == best->first ? "  <- chosen" : "");
        std::cerr << fmt::format(
            "ray tracer alone {:.3f} ms, chosen {:.6g}: {:.3f} ms over {} scenes{}\n", rays_total,
            best->first, best->second, s.scenes.size(),
            a.dry_run ? " (not saved: --dry-run)" : " (saved to " + calibration_path() + ")");
    }
    std::cout << fmt::format("{:.6g}\n", best->first);
    return kSuccess;
}

int run_calibrate(const CalibrateArgs& a) {
    if (a.method == "beam") return run_calibrate_beam(a);
    if (!(a.from > 0 && a.to > a.from)) throw UsageError("--from and --to: need 0 < from < to");
    ExperimentSettings s;
    s.scenes = a.scenes;
    if (s.scenes.empty())
        for (char c = 'A'; c <= 'F'; ++c)
            s.scenes.push_back(fmt::format("scenes/{}.json", c));
    s.repeat = a.repeat;
    s.progress = !a.quiet && isatty(STDERR_FILENO);
    std::vector<double> thresholds{0.0, kPaperThreshold};
    for (double t : threshold_ramp(a.from, a.to, a.steps))
        thresholds.push_back(t);
    std::sort(thresholds.begin(), thresholds.end());
    thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());

    Table table = sweep_threshold(s, thresholds, host::RenderOptions{});
    if (!a.csv.empty()) write_text(a.csv, table.csv());

    // total of the per-scene medians, and the worst scene against the Z-buffer, per threshold
    std::map<double, double> total, worst;
    for (const auto& row : table.rows()) {
        const double t = std::stod(row[1]);
        total[t] += std::stod(row[3]);
        worst[t] = std::max(worst[t], row[4].empty() ? 1.0 : std::stod(row[4]));
    }
    auto best = total.find(0.0);
    for (auto it = total.begin(); it != total.end(); ++it)
        if (worst[it->first] <= 1.0 + a.tolerance && it->second < best->second) best = it;
    const double zbuffer = total.at(0.0), paper = total.at(kPaperThreshold);

    nlohmann::json details;
    details["scenes"] = s.scenes;
    details["repeat"] = s.repeat;
    details["total_ms_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, ms] : total)
        details["total_ms_by_threshold"].push_back({t, ms});
    details["zbuffer_total_ms"] = zbuffer;
    details["tolerance"] = a.tolerance;
    details["worst_ratio_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, w] : worst)
        details["worst_ratio_by_threshold"].push_back({t, w});
    details["chosen_total_ms"] = best->second;
    details["calibrated_at_unix"] = std::chrono::duration_cast<std::chrono::seconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count();
    if (!a.dry_run) save_calibration(best->first, details.dump());

    if (!a.quiet) {
        std::cerr << fmt::format("{:>12}  {:>12}  {:>10}  {:>12}\n", "threshold", "total ms",
                                 "vs zbuffer", "worst scene");
        for (const auto& [t, ms] : total)
            std::cerr << fmt::format("{:>12.6g}  {:>12.3f}  {:>10.3f}  {:>12.3f}{}\n", t, ms,
                                     ms / zbuffer, worst[t], t == best->first ? "  <- chosen" : "");
        std::cerr << fmt::format(
            "pure Z-buffer {:.3f} ms, paper's 0.04 {:.3f} ms, chosen {:.6g}: {:.3f} ms over {} "
            "scenes{}\n",
            zbuffer, paper, best->first, best->second, s.scenes.size(),
            a.dry_run ? " (not saved: --dry-run)" : " (saved to " + calibration_path() + ")");
    }
    std::cout << fmt::format("{:.6g}\n", best->first);
    return kSuccess;
}

}  // namespace

void register_calibrate(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<CalibrateArgs>();
    CLI::App* sub = app.add_subcommand(
        "calibrate",
        "Choose the hybrid's Expr. 3.1 threshold (or with --method beam the beam-ray "
        "hybrid's Expr. 2.7 threshold) for this machine (the paper's §3 method)");
    sub->add_option("--method", a->method,
                    "hybrid (Warnock/Z-buffer, §3) or beam (beam-ray, §4; ramp 0, 0.01 ... "
                    "1000, inf; --from/--to/--steps/--tolerance do not apply)")
        ->check(CLI::IsMember({"hybrid", "beam"}))
        ->capture_default_str();
    sub->add_option("scenes", a->scenes,
                    "Scenes to calibrate on (default scenes/A.json ... F.json)");
    sub->add_option("--from", a->from, "Smallest threshold of the ramp (> 0)")
        ->capture_default_str();
    sub->add_option("--to", a->to, "Largest threshold of the ramp")->capture_default_str();
    sub->add_option("--steps", a->steps,
                    "Thresholds on the ramp, log-spaced (0 and 0.04 are added)")
        ->check(CLI::Range(1, 200))
        ->capture_default_str();
    sub->add_option("--repeat", a->repeat, "Interleaved timing rounds per scene (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--tolerance", a->tolerance,
                    "A threshold is eligible only if no scene is slower than the pure Z-buffer "
                    "by more than this fraction")
        ->check(CLI::Range(0.0, 100.0))
        ->capture_default_str();
    sub->add_option("--csv", a->csv, "Also write the sweep as CSV");
    sub->add_flag("--dry-run", a->dry_run, "Print the choice without saving it");
    sub->add_flag("--quiet,-q", a->quiet, "Print only the chosen threshold");
    sub->callback([a, &exit_code] { exit_code = run_calibrate(*a); });
}

}  // namespace fb89::cli
