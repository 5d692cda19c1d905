// fb89 compare SCENE: speed against accuracy for one scene in one command. Every method,
// with its default options, timed as the experiments time them (here or on a 1989 --host),
// its commands costed by the controller and its face ids counted against the Z-buffer's;
// a contact sheet PNG of the frames with their figures (--sheet; written only when asked),
// and the table as text, CSV or JSON. Every frame and every count of differing pixels is
// the one the --profile's controller draws: for the depth commands, with its depth word.
#include <unistd.h>

#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "experiments/compare.h"
#include "frontend/data_dir.h"
#include "frontend/runs.h"

namespace fb89::cli {

using namespace experiments;

namespace {

struct CompareArgs {
    CompareRequest request;  // frontend/runs.h: the scene, its options and the host's
    std::string csv, json;
    std::string sheet;
    bool quiet = false;
};

// What the pixels_differing column means, when any method differs from the Z-buffer.
std::string differences_note(const Comparison& c) {
    uint64_t coverage = 0, other = 0;
    for (const CompareRow& r : c.rows) {
        coverage += r.ids.coverage;
        other += r.ids.other_face;
    }
    if (coverage + other == 0) return "";
    std::string ties;
    for (const CompareRow& r : c.rows)
        if (r.depth && r.depth->differ > 0)
            ties += fmt::format(
                "{}{}: {} of its {} differing pixels are ties of the {}-bit depth "
                "word, {} wrong\n",
                ties.empty() ? "px_ties: the controller's depth word as the "
                               "profile has it, where two faces lie within its "
                               "step and either may be kept:\n  "
                             : "  ",
                r.method, controller::grouped(r.depth->ties), controller::grouped(r.depth->differ),
                r.depth->depth_bits, controller::grouped(r.depth->wrong));
    return ties +
           "pixels_differing: face ids unlike the Z-buffer's = px_coverage (a face against the "
           "background: silhouettes) + px_other_face (another face: a shared edge or a depth "
           "tie). The ray methods test each pixel centre with the watertight ray test where "
           "the raster methods apply their shared top-left rule, so a centre on an edge, or "
           "within rounding of one, may go either way: such differences are sampling, not "
           "error.\n";
}

int run_compare(const CompareArgs& a) {
    const bool stdout_taken =
        claims_stdout({{"--sheet", a.sheet}, {"--csv", a.csv}, {"--json", a.json}});
    CompareRequest r = a.request;
    r.progress = !a.quiet && isatty(STDERR_FILENO);
    const CompareOutcome out = frontend::run_compare(r);
    if (report_emitted(out.settings, r.host)) return kSuccess;
    const Comparison& c = out.comparison;
    if (!a.sheet.empty()) {
        make_parent_dirs(a.sheet);
        controller::write_png(a.sheet, c.sheet);
    }
    if (!a.csv.empty()) write_text(a.csv, out.table.csv());
    if (!a.json.empty()) write_json(a.json, out.rows);
    if (!a.quiet && !stdout_taken)
        std::cout << out.thresholds << out.table.text() << differences_note(c);
    const Console console{a.quiet};
    for (const CompareRow& row : c.rows)
        if (row.depth) {
            const std::string note = z_fighting_note(*row.depth);
            if (!note.empty()) console.note(fmt::format("{}: {}", row.method, note));
        }
    if (!a.sheet.empty())
        console.note(
            fmt::format("contact sheet: {} ({}x{})", a.sheet, c.sheet.width(), c.sheet.height()));
    return kSuccess;
}

}  // namespace

void register_compare(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<CompareArgs>();
    CLI::App* sub = app.add_subcommand(
        "compare", "Every method on one scene: speed against accuracy, and a contact sheet PNG");
    sub->add_option("scene", a->request.scenes, scene_argument_help("Scene: a file"))
        ->expected(1)
        ->required();
    sub->add_option("--sheet", a->sheet, "Write the contact sheet of every method's frame (PNG)");
    sub->add_option("--csv", a->csv, "Write the table as CSV ('-' for stdout)");
    sub->add_option("--json", a->json, "Write the table as JSON ('-' for stdout)");
    sub->add_option("--repeat", a->request.repeat, "Interleaved timing rounds (median)")
        ->check(cli_check(limits::kRepeat))
        ->capture_default_str();
    sub->add_option("--size", a->request.size, "Image size WxH, overriding the scene's");
    sub->add_option("--profile", a->request.profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_option("--threshold", a->request.threshold,
                    "Hybrid: Expr. 3.1 threshold: a number, inf, paper (0.04) or calibrated "
                    "(this machine's, else the paper's)")
        ->capture_default_str();
    sub->add_option("--beam-threshold", a->request.beam_threshold,
                    fmt::format("Beam: Expr. 2.7 threshold: a number, inf or calibrated (this "
                                "machine's, else the built-in {:g})",
                                host::kDefaultBeamThreshold))
        ->capture_default_str();
    add_host_options(sub, a->request.host);
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    add_isa_option(sub);
    sub->callback([a, &exit_code] {
        if (a->request.scenes.size() == 1) a->request.given = a->request.scenes.front();
        for (std::string& scene : a->request.scenes)
            scene = resolve_scene(scene);
        exit_code = run_compare(*a);
    });
}

}  // namespace fb89::cli
