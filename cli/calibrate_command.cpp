// fb89 calibrate [SCENE...]: the paper's calibration (§3) for this machine, chosen by
// experiments/calibration.h on A-F by default (with --method beam, on G, H, I and the
// mirrored Cornell box), repeated until two sweeps agree (calibrate_stably: timing is
// noisy), printed on stdout -- the table, the sweeps' choices, and a last line with the
// chosen threshold (-q: that line alone) -- and saved where `render --method hybrid|beam`
// and `compare` pick it up (frontend/calibration.h). A choice of 0 (the hybrid off) is a
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

#include "cli/commands.h"
#include "experiments/calibration.h"
#include "frontend/calibration.h"
#include "frontend/data_dir.h"
#include "frontend/period_host.h"
#include "frontend/runs.h"
#include "host/raster/hybrid.h"

namespace fb89::cli {

namespace {

struct CalibrateArgs {
    CalibrateRequest request;
    std::string csv;
    bool quiet = false;
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

std::string where_saved(const CalibrationOutcome& out) {
    return out.saved_to.empty() ? "not saved (--dry-run)" : "saved to " + out.saved_to;
}

std::string beam_text(const CalibrateArgs& a, const CalibrationOutcome& out) {
    const experiments::Calibration& c = out.calibration;
    const experiments::ExperimentSettings& s = out.settings;
    std::string text;
    if (!a.quiet) {
        text += fmt::format("the beam-ray hybrid's threshold (Expr. 2.7) on {} scenes, {} host:\n",
                            s.scenes.size(), a.request.host.host);
        text += fmt::format("{:>12}  {:>12}  {:>12}\n", "threshold", "total ms", "vs rays");
        for (const auto& [t, ms] : c.total)
            text += fmt::format("{:>12.6g}  {:>12.3f}  {:>12.3f}{}\n", t, ms, ms / c.reference_ms,
                                t == c.chosen ? "  <- chosen" : "");
        text += fmt::format("{}; the ray tracer alone {:.3f} ms\n", stability(c, bool(s.period)),
                            c.reference_ms);
    }
    text += fmt::format(
        "chosen beam threshold {:.6g}: {:.3f} ms over {} scenes, {:.3f} of the ray "
        "tracer's; {}\n",
        c.chosen, c.total.at(c.chosen), s.scenes.size(), c.total.at(c.chosen) / c.reference_ms,
        where_saved(out));
    return text;
}

std::string hybrid_text(const CalibrateArgs& a, const CalibrationOutcome& out) {
    const experiments::Calibration& c = out.calibration;
    const experiments::ExperimentSettings& s = out.settings;
    const double zbuffer = c.reference_ms, paper = c.total.at(host::kPaperThreshold);
    const double chosen_ms = c.total.at(c.chosen);
    std::string text;
    if (!a.quiet) {
        text += fmt::format("the hybrid's threshold (Expr. 3.1) on {} scenes, {} host:\n",
                            s.scenes.size(), a.request.host.host);
        text += fmt::format("{:>12}  {:>12}  {:>10}  {:>12}\n", "threshold", "total ms",
                            "vs zbuffer", "worst scene");
        for (const auto& [t, ms] : c.total)
            text += fmt::format("{:>12.6g}  {:>12.3f}  {:>10.3f}  {:>12.3f}{}\n", t, ms,
                                ms / zbuffer, c.worst.at(t), t == c.chosen ? "  <- chosen" : "");
        text += fmt::format("{}; the pure Z-buffer {:.3f} ms, the paper's 0.04 {:.3f} ms\n",
                            stability(c, bool(s.period)), zbuffer, paper);
    }
    text += fmt::format(
        "chosen threshold {:.6g}: {:.3f} ms over {} scenes, {:+.1f}% against the "
        "pure Z-buffer; {}\n",
        c.chosen, chosen_ms, s.scenes.size(), 100 * (chosen_ms / zbuffer - 1), where_saved(out));
    return text;
}

int calibrate_command(CalibrateArgs& a) {
    a.request.progress = !a.quiet && isatty(STDERR_FILENO);
    const CalibrationOutcome out = run_calibration(a.request);
    if (report_emitted(out.settings, a.request.host)) return kSuccess;
    if (!a.csv.empty()) write_text(a.csv, out.calibration.sweep.csv());
    const std::string warning = out.warning.empty() ? "" : "fb89: warning: " + out.warning + "\n";
    if (claims_stdout({{"--csv", a.csv}})) {
        std::cerr << warning;
        return kSuccess;
    }
    std::cout << (a.request.method == "beam" ? beam_text(a, out) : hybrid_text(a, out))
              << std::flush;
    std::cerr << warning;  // after the table, the last thing on the screen
    return kSuccess;
}

}  // namespace

void register_calibrate(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<CalibrateArgs>();
    CLI::App* sub = app.add_subcommand(
        "calibrate",
        "Choose the hybrid's Expr. 3.1 threshold (or with --method beam the beam-ray "
        "hybrid's Expr. 2.7 threshold) for this machine, or the --host given (the paper's §3 "
        "method), and save it where render's --threshold calibrated (--beam-threshold "
        "calibrated) finds it for that method and host: $FB89_CALIBRATION if set, else "
        "$XDG_CONFIG_HOME/fb89/calibration.json, else ~/.config/fb89/calibration.json");
    sub->add_option("--method", a->request.method,
                    "hybrid (Warnock/Z-buffer, §3) or beam (beam-ray, §4; ramp 0, 0.01 ... "
                    "1000, inf; --from/--to/--steps/--tolerance do not apply)")
        ->check(one_of_validator("method", {"hybrid", "beam"}))
        ->capture_default_str();
    sub->add_option("scenes", a->request.scenes,
                    scene_argument_help("Scenes to calibrate on: files") +
                        "; default A to F, with --method beam G, H, I and cornell_mirror");
    sub->add_option("--from", a->request.from, "Smallest threshold of the ramp (> 0)")
        ->capture_default_str();
    sub->add_option("--to", a->request.to, "Largest threshold of the ramp")->capture_default_str();
    sub->add_option("--steps", a->request.steps,
                    "Thresholds on the ramp, log-spaced (0 and 0.04 are added)")
        ->check(cli_check(limits::kSteps))
        ->capture_default_str();
    sub->add_option("--repeat", a->request.repeat, "Interleaved timing rounds per scene (median)")
        ->check(cli_check(limits::kRepeat))
        ->capture_default_str();
    sub->add_option("--tolerance", a->request.tolerance,
                    "A threshold is eligible only if no scene is slower than the pure Z-buffer "
                    "by more than this fraction")
        ->check(cli_check(limits::kTolerance))
        ->capture_default_str();
    sub->add_option("--csv", a->csv, "Also write the sweep as CSV");
    add_host_options(sub, a->request.host);
    sub->add_flag("--dry-run", a->request.dry_run, "Print the choice without saving it");
    sub->add_flag("--quiet,-q", a->quiet,
                  "Print only the line with the chosen threshold (no table, no progress)");
    add_isa_option(sub);
    sub->callback([a, &exit_code] {
        for (std::string& scene : a->request.scenes)
            scene = resolve_scene(scene);
        exit_code = calibrate_command(*a);
    });
}

}  // namespace fb89::cli
