// fb89 compare SCENE: speed against accuracy for one scene in one command. Every method,
// with its default options, timed as the experiments time them (here or on a 1989 --host),
// its commands costed by the controller and its face ids counted against the Z-buffer's;
// a contact sheet PNG of the frames with their figures, and the table as text, CSV or JSON.
#include <unistd.h>

#include <cmath>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/common.h"
#include "cli/period_host.h"
#include "controller_sim/png_io.h"
#include "experiments/compare.h"

namespace fb89::cli {

using namespace experiments;

namespace {

struct CompareArgs {
    HostArgs host;
    std::string scene, size, threshold, beam_threshold, csv, json;
    std::string sheet = "compare.png";
    std::string profile = "tms34010-50mhz";
    int repeat = 3;
    bool quiet = false;
};

// A threshold given as a number (or inf); throws UsageError naming the option.
double parse_threshold(const std::string& text, const std::string& option) {
    try {
        size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && !std::isnan(v)) return v;
    } catch (const std::logic_error&) {
    }
    throw UsageError(fmt::format("{}: '{}' is not a number", option, text));
}

// Every method with its defaults, the thresholds replaced when given.
std::vector<host::MethodOptions> settings_of(const CompareArgs& a) {
    std::vector<host::MethodOptions> settings = every_method();
    for (host::MethodOptions& o : settings) {
        if (!a.threshold.empty()) o.hybrid.threshold = parse_threshold(a.threshold, "--threshold");
        if (!a.beam_threshold.empty())
            o.beam.threshold = parse_threshold(a.beam_threshold, "--beam-threshold");
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
    for (const CompareRow& r : c.rows)
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
                        {"pixels_differing", r.pixels_differing}});
    return rows;
}

int run_compare(const CompareArgs& a) {
    const std::vector<host::MethodOptions> settings = settings_of(a);
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
    const Table table = comparison_table(c);
    if (!a.csv.empty()) write_text(a.csv, table.csv());
    if (!a.json.empty()) write_json(a.json, rows_json(c));
    if (!a.quiet && !stdout_taken) std::cout << table.text();
    Console{a.quiet}.note(
        fmt::format("contact sheet: {} ({}x{})", a.sheet, c.sheet.width(), c.sheet.height()));
    return kSuccess;
}

}  // namespace

void register_compare(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<CompareArgs>();
    CLI::App* sub = app.add_subcommand(
        "compare", "Every method on one scene: speed against accuracy, and a contact sheet PNG");
    sub->add_option("scene", a->scene, "Scene file")->required();
    sub->add_option("--sheet", a->sheet, "Write the contact sheet of every method's frame (PNG)")
        ->capture_default_str();
    sub->add_option("--csv", a->csv, "Write the table as CSV ('-' for stdout)");
    sub->add_option("--json", a->json, "Write the table as JSON ('-' for stdout)");
    sub->add_option("--repeat", a->repeat, "Interleaved timing rounds (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--size", a->size, "Image size WxH, overriding the scene's");
    sub->add_option("--profile", a->profile, profile_option_help())->capture_default_str();
    sub->add_option("--threshold", a->threshold,
                    "Hybrid: Expr. 3.1 threshold, a number or inf (default: the paper's 0.04)");
    sub->add_option("--beam-threshold", a->beam_threshold,
                    "Beam: Expr. 2.7 threshold, a number or inf (default: the built-in one)");
    add_host_options(sub, a->host);
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    sub->callback([a, &exit_code] { exit_code = run_compare(*a); });
}

}  // namespace fb89::cli
