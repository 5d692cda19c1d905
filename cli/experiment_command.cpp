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

#include "cli/calibration.h"
#include "cli/common.h"
#include "cli/data_dir.h"
#include "cli/period_host.h"
#include "experiments/catalog.h"
#include "experiments/experiments.h"

namespace fb89::cli {

using namespace experiments;

namespace {

struct ExperimentArgs {
    HostArgs host;
    std::string name;
    std::vector<std::string> scenes;
    std::string csv;
    std::string size;
    std::string profile = "tms34010-50mhz";
    int repeat = 7;
    std::string threshold = "calibrated";
    std::string beam_threshold = "calibrated";
    std::vector<std::string> sizes;
    std::string out_dir = "out/masks";
    std::string accel = "bvh";
    int patches = 0;
    int reference_rays = 4;
    bool quiet = false;
};

std::vector<std::string> experiment_names() {
    std::vector<std::string> names;
    for (const ExperimentInfo& e : experiment_catalog())
        names.emplace_back(e.name);
    return names;
}

std::string known_experiments() {
    std::string known;
    for (const ExperimentInfo& e : experiment_catalog())
        known += (known.empty() ? "" : ", ") + std::string(e.name);
    return known;
}

std::vector<std::string> default_scenes(const std::string& name) {
    std::vector<std::string> out;
    if (const ExperimentInfo* e = find_experiment(name))
        for (std::string_view scene : e->scenes)
            out.push_back(bundled_scene(std::string(scene)));
    return out;
}

int run_experiment(const ExperimentArgs& args) {
    ExperimentSettings settings;
    settings.scenes = args.scenes.empty() ? default_scenes(args.name) : args.scenes;
    settings.repeat = args.repeat;
    settings.profile = args.profile;
    settings.progress = !args.quiet && isatty(STDERR_FILENO);
    settings.accel = host::parse_accel(args.accel);
    if (!args.size.empty()) settings.size = parse_size(args.size);
    settings.period = make_period_runs(args.host);
    if (settings.period) settings.repeat = 1;

    Table table;
    if (args.name == "fig2.1")
        table = experiment_fig2_1(settings);
    else if (args.name == "fig2.4")
        table = experiment_fig2_4(settings);
    else if (args.name == "fig3.1")
        table =
            experiment_fig3_1(settings, resolve_threshold(args.threshold, nullptr, args.host.host));
    else if (args.name == "hybrid")
        table =
            experiment_hybrid(settings, resolve_threshold(args.threshold, nullptr, args.host.host));
    else if (args.name == "accuracy")
        table = experiment_accuracy(settings,
                                    resolve_threshold(args.threshold, nullptr, args.host.host));
    else if (args.name == "fig4.8" || args.name == "fig4.11" || args.name == "fig4.12") {
        std::vector<ImageSize> sizes;
        for (const auto& text : args.sizes)
            sizes.push_back(parse_size(text));
        if (sizes.empty()) sizes = {{256, 195}, {512, 390}, {1024, 780}, {2048, 1560}};
        table = experiment_beam_resolution(
            settings, sizes, resolve_beam_threshold(args.beam_threshold, nullptr, args.host.host));
    } else if (args.name == "fig4.7")
        table = experiment_beam_masks(
            settings, resolve_beam_threshold(args.beam_threshold, nullptr, args.host.host),
            args.out_dir);
    else if (args.name == "beam-threshold")
        table = experiment_beam_threshold(settings, beam_threshold_ramp());
    else if (args.name == "split")
        table = experiment_split(settings);
    else if (args.name == "radiosity")
        table = experiment_radiosity(settings, args.patches);
    else if (args.name == "ff-error" || args.name == "radiosity-error")
        table = experiment_form_factor_error(settings, args.patches > 0 ? args.patches : 250,
                                             args.reference_rays, args.name == "radiosity-error");
    else
        throw UsageError(fmt::format("unknown experiment '{}'{} (known: {}; fb89 list experiments)",
                                     args.name, nearest_hint(args.name, experiment_names()),
                                     known_experiments()));

    if (report_emitted(settings, args.host)) return kSuccess;
    table.map_column("scene", scene_display_name);
    if (!args.csv.empty()) write_text(args.csv, table.csv());
    if (!args.quiet && args.csv != "-") std::cout << table.text();
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
    sub->add_option("name", args->name, "The experiment:" + described)->required();
    sub->add_option("scenes", args->scenes,
                    "Scenes (default: the experiment's bundled scenes; fb89 list experiments)");
    sub->add_option("--csv", args->csv, "Write the results as CSV ('-' for stdout)");
    sub->add_option("--size", args->size, "Image size WxH, overriding the scenes'");
    sub->add_option("--repeat", args->repeat, "Interleaved timing rounds per method (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--profile", args->profile, profile_option_help())->capture_default_str();
    sub->add_option("--threshold", args->threshold,
                    "fig3.1 and accuracy: the hybrid's threshold (number, paper or calibrated)")
        ->capture_default_str();
    sub->add_option("--beam-threshold", args->beam_threshold,
                    "fig4.*: the beam-ray hybrid's Expr. 2.7 threshold (number, inf or "
                    "calibrated)")
        ->capture_default_str();
    sub->add_option("--sizes", args->sizes,
                    "fig4.8/4.11/4.12: image sizes WxH (default 256x195 512x390 1024x780 "
                    "2048x1560)");
    sub->add_option("--out-dir", args->out_dir, "fig4.7: where the frames and masks go")
        ->capture_default_str();
    sub->add_option("--patches", args->patches,
                    "radiosity, ff-error, radiosity-error: patches asked per room (0: what "
                    "gives the paper's 832 and 1,348 on the two rooms; 250 for the error "
                    "experiments)")
        ->check(CLI::Range(0, 100000));
    sub->add_option("--reference-rays", args->reference_rays,
                    "ff-error, radiosity-error: the reference's points per patch side (n^4 "
                    "rays per pair)")
        ->check(CLI::Range(2, 16))
        ->capture_default_str();
    add_host_options(sub, args->host);
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->add_option("--accel", args->accel,
                    "fig4.*, beam-threshold, split: what the rays of raytrace and beam walk: bvh, "
                    "or grid (the paper's uniform grid)")
        ->check(CLI::IsMember({"bvh", "grid"}))
        ->capture_default_str();
    add_isa_option(sub);
    sub->callback([args, &exit_code] {
        for (std::string& scene : args->scenes)
            scene = resolve_scene(scene);
        exit_code = run_experiment(*args);
    });
}

}  // namespace fb89::cli
