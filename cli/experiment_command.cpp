// fb89 experiment NAME: the paper's experiments, re-run. Each writes CSV (a header row,
// one row per scene and method) and prints a table.
//   fig2.1  Warnock vs scan-line vs Z-buffer on scenes A-F: host hidden-surface time as
//           medians of interleaved repeats, counted operations, controller commands and
//           modelled cost (paper Fig. 2.1).
//   fig2.4  Eq. 2.4's predicted window samples against the counts of an instrumented
//           Warnock, on A-F and on ideal scenes (paper Fig. 2.4).
//   fig3.1  the hybrid's time against its threshold on A and F (paper Fig. 3.1), with
//           the calibrated and the paper's thresholds, host and controller apart.
//   hybrid  the calibrated hybrid (and the paper's 0.04) against the Z-buffer per scene.
//           The experiments of a hybrid say its threshold and where it comes from first.
//   accuracy  exact and approximate Warnock and hybrid: time, commands, pixels wrong.
//   fig4.8, fig4.11, fig4.12  the beam-ray hybrid against the ray tracer alone on G, H and
//           I at 256x195 ... 2048x1560, whole process (paper Figs. 4.8, 4.11, §4's image I).
//   fig4.7  beam-ray frames of G, H and I with the ray-traced pixels blacked out (paper
//           Figs. 4.7, 4.10), written to --out-dir.
//   beam-threshold  time and pixels by beams against the Expr. 2.7 threshold.
//   radiosity  flux tracing against the decahedral hybrid on the garish room and the
//           programmer's cell: rays, volume queries, form-factor time (the paper's §5 table).
//   ff-error, radiosity-error  form-factor (and radiosity) error against time per method.
#include <unistd.h>

#include <iostream>

#include <fmt/format.h>

#include "cli/commands.h"
#include "experiments/catalog.h"
#include "frontend/calibration.h"
#include "frontend/data_dir.h"
#include "frontend/period_host.h"
#include "frontend/runs.h"

namespace fb89::cli {

using namespace experiments;

namespace {

struct ExperimentArgs {
    ExperimentRequest request;
    std::string csv;
    bool quiet = false;
};

// The threshold an experiment of a hybrid runs with and where it comes from, as render's
// first line says it ("hybrid threshold 0.04 (the paper's: not calibrated yet ...)"), or ""
// for an experiment that takes none.
std::string threshold_line(const ExperimentRequest& r) {
    const std::string& n = r.name;
    std::string source;
    if (n == "hybrid" || n == "fig3.1" || n == "accuracy") {
        const double t = resolve_threshold(r.threshold, &source, r.host.host);
        return fmt::format("hybrid threshold {:.6g} ({})\n", t, source);
    }
    if (n == "fig4.7" || n == "fig4.8" || n == "fig4.11" || n == "fig4.12" ||
        n == "successors-rays") {
        const double t = resolve_beam_threshold(r.beam_threshold, &source, r.host.host);
        return fmt::format("beam threshold {:.6g} ({})\n", t, source);
    }
    return "";
}

int experiment_command(ExperimentArgs& args) {
    args.request.progress = !args.quiet && isatty(STDERR_FILENO);
    const RunOutcome out = run_experiment(args.request);
    if (report_emitted(out.settings, args.request.host)) return kSuccess;
    if (!args.csv.empty()) write_text(args.csv, out.table.csv());
    if (!args.quiet && args.csv != "-")
        std::cout << threshold_line(args.request) << out.table.text();
    return kSuccess;
}

}  // namespace

void register_experiment(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ExperimentArgs>();
    CLI::App* sub = app.add_subcommand("experiment", "Re-run one of the paper's experiments");
    std::string described;
    for (const ExperimentInfo& e : experiment_catalog()) {
        described += fmt::format("\n  {:<16} {}", e.name, e.description);
    }
    sub->add_option("name", args->request.name, "The experiment:" + described)->required();
    sub->add_option("scenes", args->request.scenes,
                    scene_argument_help("Scenes (default: the experiment's own; fb89 list "
                                        "experiments): files"));
    sub->add_option("--csv", args->csv, "Write the results as CSV ('-' for stdout)");
    sub->add_option("--size", args->request.size, "Image size WxH, overriding the scenes'");
    sub->add_option("--repeat", args->request.repeat,
                    "Interleaved timing rounds per method (median)")
        ->check(cli_check(limits::kRepeat))
        ->capture_default_str();
    sub->add_option("--profile", args->request.profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_option("--threshold", args->request.threshold,
                    "fig3.1 and accuracy: the hybrid's threshold (number, paper or calibrated)")
        ->capture_default_str();
    sub->add_option("--beam-threshold", args->request.beam_threshold,
                    "fig4.*: the beam-ray hybrid's Expr. 2.7 threshold (number, inf or "
                    "calibrated)")
        ->capture_default_str();
    sub->add_option(
        "--sizes", args->request.sizes,
        "fig4.8/4.11/4.12, successors-rays: image sizes WxH (default 256x195 512x390 1024x780 "
        "2048x1560)");
    sub->add_option("--out-dir", args->request.out_dir, "fig4.7: where the frames and masks go")
        ->capture_default_str();
    sub->add_option("--patches", args->request.patches,
                    "radiosity, ff-error, radiosity-error: patches asked per room (0: what "
                    "gives the paper's 832 and 1,348 on the two rooms, and 4700 on the "
                    "exhibition hall; 250 a room and 1430 on the hall for the error "
                    "experiments)")
        ->check(cli_check(limits::kPatches));
    sub->add_option("--reference-rays", args->request.reference_rays,
                    "ff-error, radiosity-error: the reference's points per patch side (n^4 "
                    "rays per pair)")
        ->check(cli_check(limits::kReferenceRays))
        ->capture_default_str();
    add_host_options(sub, args->request.host);
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->add_option("--accel", args->request.accel,
                    "fig4.*, beam-threshold, split: what the rays of raytrace and beam walk and "
                    "the beams query: bvh, or grid (the paper's uniform grid)")
        ->check(CLI::IsMember({"bvh", "grid"}))
        ->capture_default_str();
    sub->add_option("--methods", args->request.methods,
                    method_option_help("split: only these methods (default every one)"))
        ->check(method_validator());
    add_isa_option(sub);
    sub->callback([args, &exit_code] {
        for (std::string& scene : args->request.scenes)
            scene = resolve_scene(scene);
        exit_code = experiment_command(*args);
    });
}

}  // namespace fb89::cli
