// fb89 sweep threshold SCENE...: the hybrid's Expr. 3.1 threshold along a ramp (the
// paper's Fig. 3.1), with 0 (pure Z-buffer) and inf (pure Warnock) as references. One
// CSV row per scene and threshold: host time (median of interleaved repeats), counted
// operations, controller commands, modelled controller time and bus time.
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <limits>

#include <fmt/format.h>

#include "cli/commands.h"
#include "frontend/data_dir.h"
#include "frontend/period_host.h"
#include "frontend/runs.h"

namespace fb89::cli {

using namespace experiments;

namespace {

struct SweepArgs {
    SweepRequest request;
    std::string what, csv;
    bool quiet = false;
};

int sweep_command(SweepArgs& a) {
    if (a.what != "threshold")
        throw UsageError(fmt::format("unknown sweep '{}' (known: threshold)", a.what));
    a.request.progress = !a.quiet && isatty(STDERR_FILENO);
    const RunOutcome out = run_threshold_sweep(a.request);
    if (report_emitted(out.settings, a.request.host)) return kSuccess;
    if (!a.csv.empty()) write_text(a.csv, out.table.csv());
    if (!a.quiet && a.csv != "-") std::cout << out.table.text();
    return kSuccess;
}

}  // namespace

void register_sweep(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<SweepArgs>();
    CLI::App* sub = app.add_subcommand("sweep", "Sweep a parameter of a method over scenes (CSV)");
    sub->add_option("what", a->what, "What to sweep: threshold (the hybrid's Expr. 3.1)")
        ->check(CLI::IsMember({"threshold"}))
        ->required();
    sub->add_option("scenes", a->request.scenes, scene_argument_help("Scenes: files"))->required();
    sub->add_option("--from", a->request.from, "Smallest threshold of the ramp (> 0)")
        ->capture_default_str();
    sub->add_option("--to", a->request.to, "Largest threshold of the ramp")->capture_default_str();
    sub->add_option("--steps", a->request.steps, "Thresholds on the ramp, log-spaced")
        ->check(cli_check(limits::kSteps))
        ->capture_default_str();
    sub->add_option("--repeat", a->request.repeat, "Interleaved timing rounds (median)")
        ->check(cli_check(limits::kRepeat))
        ->capture_default_str();
    sub->add_option("--window-test", a->request.window_test, "area or centres")
        ->check(CLI::IsMember({"area", "centres"}))
        ->capture_default_str();
    sub->add_option("--depth-estimate", a->request.depth_estimate, "window or scene")
        ->check(CLI::IsMember({"window", "scene"}))
        ->capture_default_str();
    sub->add_option("--csv", a->csv, "Write the results as CSV ('-' for stdout)");
    sub->add_option("--size", a->request.size, "Image size WxH, overriding the scenes'");
    sub->add_option("--profile", a->request.profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    add_host_options(sub, a->request.host);
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    add_isa_option(sub);
    sub->callback([a, &exit_code] {
        for (std::string& scene : a->request.scenes)
            scene = resolve_scene(scene);
        exit_code = sweep_command(*a);
    });
}

}  // namespace fb89::cli
