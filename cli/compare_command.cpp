// fb89 compare SCENE: speed against accuracy for one scene in one command. Every method,
// with its default options, timed as the experiments time them (here or on a 1989 --host),
// its commands costed by the controller and its face ids counted against the Z-buffer's;
// a contact sheet PNG of the frames with their figures, and the table as text, CSV or JSON.
#include <unistd.h>

#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/png_io.h"
#include "experiments/compare.h"
#include "frontend/calibration.h"
#include "frontend/data_dir.h"
#include "frontend/period_host.h"

namespace fb89::cli {

using namespace experiments;

namespace {

struct CompareArgs {
    HostArgs host;
    std::string scene, size, csv, json;
    std::string threshold = "calibrated", beam_threshold = "calibrated";
    std::string sheet = "out/compare.png";
    std::string profile = "tms34010-50mhz";
    int repeat = 3;
    bool quiet = false;
};

// Every method with its defaults, the thresholds by render's rule (calibrated if saved,
// else the paper's / the built-in one); `said` gets the line that says which.
std::vector<host::MethodOptions> settings_of(const CompareArgs& a, std::string& said) {
    std::string hybrid_source, beam_source;
    const double hybrid = resolve_threshold(a.threshold, &hybrid_source, a.host.host);
    const double beam = resolve_beam_threshold(a.beam_threshold, &beam_source, a.host.host);
    said = fmt::format("hybrid threshold {:.6g} ({}), beam threshold {:.6g} ({})\n", hybrid,
                       hybrid_source, beam, beam_source);
    std::vector<host::MethodOptions> settings = every_method();
    for (host::MethodOptions& o : settings) {
        o.hybrid.threshold = hybrid;
        o.beam.threshold = beam;
        try {
            host::validate(o);
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    }
    return settings;
}

nlohmann::json rows_json(const Comparison& c) {
    nlohmann::json rows = nlohmann::json::array();
    for (const CompareRow& r : c.rows) {
        rows.push_back({{"scene", c.scene},
                        {"method", r.method},
                        {"host", c.host},
                        {"host_ms", r.host_ms},
                        {"commands", r.controller.commands},
                        {"fills", r.controller.fills},
                        {"spans", r.controller.spans},
                        {"controller_ms", r.controller.frame_ms},
                        {"frame_ms", r.frame_ms},
                        {"bound_by", r.host_bound ? "host" : "controller"},
                        {"pixels_differing", r.ids.total()},
                        {"px_coverage", r.ids.coverage},
                        {"px_other_face", r.ids.other_face}});
        if (r.pipeline)
            rows.back()["pipeline"] =
                pipeline_json(*r.pipeline, send_times_source(c.host != "native"));
    }
    return rows;
}

// What the pixels_differing column means, when any method differs from the Z-buffer.
std::string differences_note(const Comparison& c) {
    uint64_t coverage = 0, other = 0;
    for (const CompareRow& r : c.rows) {
        coverage += r.ids.coverage;
        other += r.ids.other_face;
    }
    if (coverage + other == 0) return "";
    return "pixels_differing: face ids unlike the Z-buffer's = px_coverage (a face against the "
           "background: silhouettes) + px_other_face (another face: a shared edge or a depth "
           "tie). The ray methods test each pixel centre with the watertight ray test where "
           "the raster methods apply their shared top-left rule, so a centre on an edge, or "
           "within rounding of one, may go either way: such differences are sampling, not "
           "error.\n";
}

int run_compare(const CompareArgs& a) {
    std::string thresholds;
    const std::vector<host::MethodOptions> settings = settings_of(a, thresholds);
    ExperimentSettings s;
    s.scenes = {a.scene};
    s.repeat = a.repeat;
    s.profile = a.profile;
    s.progress = !a.quiet && isatty(STDERR_FILENO);
    if (!a.size.empty()) s.size = parse_size(a.size);
    s.period = make_period_runs(a.host);
    const bool stdout_taken =
        claims_stdout({{"--sheet", a.sheet}, {"--csv", a.csv}, {"--json", a.json}});
    const Comparison c = compare_methods(a.scene, settings, s);
    if (report_emitted(s, a.host)) return kSuccess;
    make_parent_dirs(a.sheet);
    controller::write_png(a.sheet, c.sheet);
    Table table = comparison_table(c);
    table.map_column("scene", scene_display_name);
    if (!a.csv.empty()) write_text(a.csv, table.csv());
    if (!a.json.empty()) write_json(a.json, rows_json(c));
    if (!a.quiet && !stdout_taken) std::cout << thresholds << table.text() << differences_note(c);
    Console{a.quiet}.note(
        fmt::format("contact sheet: {} ({}x{})", a.sheet, c.sheet.width(), c.sheet.height()));
    return kSuccess;
}

}  // namespace

void register_compare(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<CompareArgs>();
    CLI::App* sub = app.add_subcommand(
        "compare", "Every method on one scene: speed against accuracy, and a contact sheet PNG");
    sub->add_option("scene", a->scene, scene_argument_help("Scene: a file"))->required();
    sub->add_option("--sheet", a->sheet, "Write the contact sheet of every method's frame (PNG)")
        ->capture_default_str();
    sub->add_option("--csv", a->csv, "Write the table as CSV ('-' for stdout)");
    sub->add_option("--json", a->json, "Write the table as JSON ('-' for stdout)");
    sub->add_option("--repeat", a->repeat, "Interleaved timing rounds (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--size", a->size, "Image size WxH, overriding the scene's");
    sub->add_option("--profile", a->profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_option("--threshold", a->threshold,
                    "Hybrid: Expr. 3.1 threshold: a number, inf, paper (0.04) or calibrated "
                    "(this machine's, else the paper's)")
        ->capture_default_str();
    sub->add_option("--beam-threshold", a->beam_threshold,
                    fmt::format("Beam: Expr. 2.7 threshold: a number, inf or calibrated (this "
                                "machine's, else the built-in {:g})",
                                host::kDefaultBeamThreshold))
        ->capture_default_str();
    add_host_options(sub, a->host);
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    add_isa_option(sub);
    sub->callback([a, &exit_code] {
        a->scene = resolve_scene(a->scene);
        exit_code = run_compare(*a);
    });
}

}  // namespace fb89::cli
