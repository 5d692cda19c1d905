// fb89 calibrate [SCENE...]: the paper's calibration (§3) for this machine, chosen by
// experiments/calibration.h on A-F by default (with --method beam, on G, H, I and the
// mirrored Cornell box), repeated until two sweeps agree (calibrate_stably: timing is
// noisy), printed on stdout -- the table, the sweeps' choices, and a last line with the
// chosen threshold (-q: that line alone) -- and saved where `render --method hybrid|beam`
// and `compare` pick it up (cli/calibration.h). A choice of 0 (the hybrid off) is a
// warning on stderr saying why. The paper's 0.04 is always on the ramp and stays available
// as `--threshold paper`.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/calibration.h"
#include "cli/common.h"
#include "cli/data_dir.h"
#include "cli/period_host.h"
#include "experiments/calibration.h"
#include "experiments/experiments.h"
#include "host/raster/hybrid.h"

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
    HostArgs host;
    bool dry_run = false, quiet = false;
};

// The sweeps' choices, e.g. "2 sweeps chose 0.0102, 0.0102 (stable)".
std::string stability(const experiments::Calibration& c, bool period) {
    if (period) return "the 1989 host's counts are exact: one sweep";
    std::string list;
    for (double t : c.choices)
        list += (list.empty() ? "" : ", ") + fmt::format("{:.6g}", t);
    return fmt::format(
        "{} sweeps chose {} ({})", c.choices.size(), list,
        c.stable ? "stable: the last two agree" : "not stable: the one chosen most often is taken");
}

std::string where_saved(const CalibrateArgs& a) {
    return a.dry_run ? "not saved (--dry-run)" : "saved to " + calibration_path();
}

int run_calibrate_beam(const CalibrateArgs& a) {
    experiments::ExperimentSettings s;
    s.scenes = a.scenes;
    if (s.scenes.empty())
        s.scenes = {bundled_scene("G.json"), bundled_scene("H.json"), bundled_scene("I.json"),
                    bundled_scene("cornell_mirror.json")};
    s.repeat = a.repeat;
    s.progress = !a.quiet && isatty(STDERR_FILENO);
    s.period = make_period_runs(a.host);
    const experiments::Calibration c =
        experiments::calibrate_stably(s, [&] { return experiments::calibrate_beam(s); });
    if (report_emitted(s, a.host)) return kSuccess;
    experiments::Table sweep = c.sweep;
    sweep.map_column("scene", scene_display_name);
    if (!a.csv.empty()) write_text(a.csv, sweep.csv());
    nlohmann::json details;
    details["scenes"] = s.scenes;
    details["repeat"] = s.repeat;
    details["raytrace_total_ms"] = c.reference_ms;
    details["total_ms_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, ms] : c.total)
        details["total_ms_by_threshold"].push_back({std::isinf(t) ? 1e300 : t, ms});
    details["chosen_total_ms"] = c.total.at(c.chosen);
    details["sweeps"] = nlohmann::json::array();
    for (double t : c.choices)  // JSON has no infinity: "inf", as the saved threshold
        details["sweeps"].push_back(std::isinf(t) ? nlohmann::json("inf") : nlohmann::json(t));
    details["stable"] = c.stable;
    if (!a.dry_run) save_beam_calibration(c.chosen, details.dump(), a.host.host);
    if (claims_stdout({{"--csv", a.csv}})) return kSuccess;
    std::string out;
    if (!a.quiet) {
        out += fmt::format("the beam-ray hybrid's threshold (Expr. 2.7) on {} scenes, {} host:\n",
                           s.scenes.size(), a.host.host);
        out += fmt::format("{:>12}  {:>12}  {:>12}\n", "threshold", "total ms", "vs rays");
        for (const auto& [t, ms] : c.total)
            out += fmt::format("{:>12.6g}  {:>12.3f}  {:>12.3f}{}\n", t, ms, ms / c.reference_ms,
                               t == c.chosen ? "  <- chosen" : "");
        out += fmt::format("{}; the ray tracer alone {:.3f} ms\n", stability(c, bool(s.period)),
                           c.reference_ms);
    }
    out += fmt::format(
        "chosen beam threshold {:.6g}: {:.3f} ms over {} scenes, {:.3f} of the ray "
        "tracer's; {}\n",
        c.chosen, c.total.at(c.chosen), s.scenes.size(), c.total.at(c.chosen) / c.reference_ms,
        where_saved(a));
    std::cout << out;
    return kSuccess;
}

int run_calibrate(const CalibrateArgs& a) {
    if (a.method == "beam") return run_calibrate_beam(a);
    if (!(a.from > 0 && a.to > a.from)) throw UsageError("--from and --to: need 0 < from < to");
    experiments::ExperimentSettings s;
    s.scenes = a.scenes;
    if (s.scenes.empty())
        for (char c = 'A'; c <= 'F'; ++c)
            s.scenes.push_back(bundled_scene(fmt::format("{}.json", c)));
    s.repeat = a.repeat;
    s.progress = !a.quiet && isatty(STDERR_FILENO);
    s.period = make_period_runs(a.host);
    const auto ramp = experiments::threshold_ramp(a.from, a.to, a.steps);
    const experiments::Calibration c = experiments::calibrate_stably(
        s, [&] { return experiments::calibrate_hybrid(s, ramp, a.tolerance); });
    if (report_emitted(s, a.host)) return kSuccess;
    experiments::Table sweep = c.sweep;
    sweep.map_column("scene", scene_display_name);
    if (!a.csv.empty()) write_text(a.csv, sweep.csv());
    const double zbuffer = c.reference_ms, paper = c.total.at(host::kPaperThreshold);
    const double chosen_ms = c.total.at(c.chosen);

    nlohmann::json details;
    details["scenes"] = s.scenes;
    details["repeat"] = s.repeat;
    details["total_ms_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, ms] : c.total)
        details["total_ms_by_threshold"].push_back({t, ms});
    details["zbuffer_total_ms"] = zbuffer;
    details["tolerance"] = a.tolerance;
    details["worst_ratio_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, w] : c.worst)
        details["worst_ratio_by_threshold"].push_back({t, w});
    details["chosen_total_ms"] = chosen_ms;
    details["sweeps"] = c.choices;
    details["stable"] = c.stable;
    details["calibrated_at_unix"] = std::chrono::duration_cast<std::chrono::seconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count();
    details["host"] = a.host.host;
    if (!a.dry_run) save_calibration(c.chosen, details.dump(), a.host.host);

    // a choice of 0 switches the hybrid off for every later `render --method hybrid`: say so
    // loudly, and why
    std::string warning;
    if (c.chosen == 0) {
        double best = 0, best_ms = std::numeric_limits<double>::infinity();
        for (const auto& [t, ms] : c.total)
            if (t > 0 && ms < best_ms) best = t, best_ms = ms;
        warning = fmt::format(
            "fb89: warning: calibration chose threshold 0: the hybrid hands every window to the "
            "Z-buffer and runs as a plain Z-buffer. No threshold made it faster than the pure "
            "Z-buffer without a scene more than {:.0f}% slower (its best total, at {:.6g}, is "
            "{:+.1f}% against the Z-buffer's). `--threshold paper` still gives the paper's 0.04.\n",
            100 * a.tolerance, best, 100 * (best_ms / zbuffer - 1));
    }
    if (claims_stdout({{"--csv", a.csv}})) {
        std::cerr << warning;
        return kSuccess;
    }
    std::string out;
    if (!a.quiet) {
        out += fmt::format("the hybrid's threshold (Expr. 3.1) on {} scenes, {} host:\n",
                           s.scenes.size(), a.host.host);
        out += fmt::format("{:>12}  {:>12}  {:>10}  {:>12}\n", "threshold", "total ms",
                           "vs zbuffer", "worst scene");
        for (const auto& [t, ms] : c.total)
            out += fmt::format("{:>12.6g}  {:>12.3f}  {:>10.3f}  {:>12.3f}{}\n", t, ms,
                               ms / zbuffer, c.worst.at(t), t == c.chosen ? "  <- chosen" : "");
        out += fmt::format("{}; the pure Z-buffer {:.3f} ms, the paper's 0.04 {:.3f} ms\n",
                           stability(c, bool(s.period)), zbuffer, paper);
    }
    out += fmt::format(
        "chosen threshold {:.6g}: {:.3f} ms over {} scenes, {:+.1f}% against the "
        "pure Z-buffer; {}\n",
        c.chosen, chosen_ms, s.scenes.size(), 100 * (chosen_ms / zbuffer - 1), where_saved(a));
    std::cout << out << std::flush;
    std::cerr << warning;  // after the table, the last thing on the screen
    return kSuccess;
}

}  // namespace

void register_calibrate(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<CalibrateArgs>();
    CLI::App* sub = app.add_subcommand(
        "calibrate",
        "Choose the hybrid's Expr. 3.1 threshold (or with --method beam the beam-ray "
        "hybrid's Expr. 2.7 threshold) for this machine (the paper's §3 method) and save it "
        "where render's --threshold calibrated finds it: $XDG_CONFIG_HOME/fb89/calibration.json, "
        "else ~/.config/fb89/calibration.json");
    sub->add_option("--method", a->method,
                    "hybrid (Warnock/Z-buffer, §3) or beam (beam-ray, §4; ramp 0, 0.01 ... "
                    "1000, inf; --from/--to/--steps/--tolerance do not apply)")
        ->check(CLI::IsMember({"hybrid", "beam"}))
        ->capture_default_str();
    sub->add_option(
        "scenes", a->scenes,
        "Scenes to calibrate on, files or bundled scenes by name (default: A to F; with --method "
        "beam, G, H, I and cornell_mirror)");
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
    add_host_options(sub, a->host);
    sub->add_flag("--dry-run", a->dry_run, "Print the choice without saving it");
    sub->add_flag("--quiet,-q", a->quiet,
                  "Print only the line with the chosen threshold (no table, no progress)");
    add_isa_option(sub);
    sub->callback([a, &exit_code] {
        for (std::string& scene : a->scenes)
            scene = resolve_scene(scene);
        exit_code = run_calibrate(*a);
    });
}

}  // namespace fb89::cli
