// fb89 sweep threshold SCENE...: the hybrid's Expr. 3.1 threshold along a ramp (the
// paper's Fig. 3.1), with 0 (pure Z-buffer) and inf (pure Warnock) as references. One
// CSV row per scene and threshold: host time (median of interleaved repeats), counted
// operations, controller commands, modelled controller time and bus time.
#include <unistd.h>

#include <cmath>
#include <iostream>
#include <limits>

#include <fmt/format.h>

#include "cli/common.h"
#include "cli/data_dir.h"
#include "cli/period_host.h"
#include "experiments/experiments.h"

namespace fb89::cli {

using namespace experiments;

namespace {

struct SweepArgs {
    HostArgs host;
    std::string what;
    std::vector<std::string> scenes;
    double from = 0.001, to = 1.0;
    int steps = 13;
    int repeat = 7;
    std::string window_test = "area", depth_estimate = "window", csv, size;
    std::string profile = "tms34010-50mhz";
    bool quiet = false;
};

int run_sweep(const SweepArgs& a) {
    if (a.what != "threshold")
        throw UsageError(fmt::format("unknown sweep '{}' (known: threshold)", a.what));
    if (!(a.from > 0 && a.to > a.from)) throw UsageError("--from and --to: need 0 < from < to");
    ExperimentSettings s;
    s.scenes = a.scenes;
    s.repeat = a.repeat;
    s.profile = a.profile;
    s.progress = !a.quiet && isatty(STDERR_FILENO);
    if (!a.size.empty()) s.size = parse_size(a.size);
    s.period = make_period_runs(a.host);
    std::vector<double> thresholds{0.0};
    for (double t : threshold_ramp(a.from, a.to, a.steps))
        thresholds.push_back(t);
    thresholds.push_back(std::numeric_limits<double>::infinity());
    host::MethodOptions base(host::Method::Hybrid);
    base.warnock.window_test =
        a.window_test == "centres" ? host::WindowTest::Centres : host::WindowTest::Area;
    base.hybrid.depth =
        a.depth_estimate == "scene" ? host::DepthEstimate::Scene : host::DepthEstimate::Window;
    Table table = sweep_threshold(s, thresholds, base);
    table.map_column("scene", scene_display_name);
    if (report_emitted(s, a.host)) return kSuccess;
    if (!a.csv.empty()) write_text(a.csv, table.csv());
    if (!a.quiet && a.csv != "-") std::cout << table.text();
    return kSuccess;
}

}  // namespace

void register_sweep(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<SweepArgs>();
    CLI::App* sub = app.add_subcommand("sweep", "Sweep a parameter of a method over scenes (CSV)");
    sub->add_option("what", a->what, "What to sweep: threshold (the hybrid's Expr. 3.1)")
        ->check(CLI::IsMember({"threshold"}))
        ->required();
    sub->add_option("scenes", a->scenes,
                    "Scenes: files, or bundled scenes by name (fb89 list scenes)")
        ->required();
    sub->add_option("--from", a->from, "Smallest threshold of the ramp (> 0)")
        ->capture_default_str();
    sub->add_option("--to", a->to, "Largest threshold of the ramp")->capture_default_str();
    sub->add_option("--steps", a->steps, "Thresholds on the ramp, log-spaced")
        ->check(CLI::Range(1, 200))
        ->capture_default_str();
    sub->add_option("--repeat", a->repeat, "Interleaved timing rounds (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--window-test", a->window_test, "area or centres")
        ->check(CLI::IsMember({"area", "centres"}))
        ->capture_default_str();
    sub->add_option("--depth-estimate", a->depth_estimate, "window or scene")
        ->check(CLI::IsMember({"window", "scene"}))
        ->capture_default_str();
    sub->add_option("--csv", a->csv, "Write the results as CSV ('-' for stdout)");
    sub->add_option("--size", a->size, "Image size WxH, overriding the scenes'");
    sub->add_option("--profile", a->profile, profile_option_help())->capture_default_str();
    add_host_options(sub, a->host);
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    add_isa_option(sub);
    sub->callback([a, &exit_code] {
        for (std::string& scene : a->scenes)
            scene = resolve_scene(scene);
        exit_code = run_sweep(*a);
    });
}

}  // namespace fb89::cli
