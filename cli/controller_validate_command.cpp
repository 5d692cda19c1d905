// fb89 controller-validate: the controller's cost model held to TI's data sheet and the other
// sources (experiments/controller_validation.h; docs/COST_MODEL.md, "Checked where checks
// exist"). Each row prints the figure, what the source states, the first cost model's figure
// (tms34010-mame) and the model's now; --listing prints the command loop with each
// instruction's cycles; --check exits 1 when a figure misses what its source states.
#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.h"
#include "controller_sim/gsp_listing.h"
#include "experiments/controller_validation.h"
#include "experiments/measure.h"
#include "frontend/data_dir.h"
#include "host/scene/scene.h"

namespace fb89::cli {

namespace {

struct ControllerValidateArgs {
    std::string profile = std::string(controller::kDefaultProfile);
    std::string csv;
    bool listing = false, check = false, quiet = false;
};

std::string number(double v) {
    return std::isnan(v) ? std::string("-") : fmt::format("{:.6g}", v);
}
std::string csv_number(double v) {
    return std::isnan(v) ? std::string() : fmt::format("{:.6g}", v);
}

int run_controller_validate(const ControllerValidateArgs& a) {
    const controller::CostProfile after = profile_option(a.profile, "--profile");
    if (after.gsp.empty())
        throw UsageError(fmt::format(
            "--profile: {} gives its cycle figures itself (no \"gsp\" listing): there is no "
            "memory-cycle model to check",
            after.name));
    const controller::CostProfile before = controller::load_profile("tms34010-mame");
    const controller::CostProfile tms34020 = controller::load_profile("tms34020-40mhz");

    // The demo's Z-buffer frame, rendered here once, for the 34020 : 34010 ratio.
    host::Scene scene;
    experiments::ExperimentSettings settings;
    const host::ScreenScene screen =
        experiments::load_screen(bundled_scene("demo.json"), settings, scene);
    const auto measured =
        experiments::measure_interleaved(screen, {host::Method::ZBuffer}, 1, "demo", false);
    const auto rows =
        experiments::controller_validation(after, before, tms34020, measured.at(0).commands);

    bool all_pass = true;
    std::string table = fmt::format(
        "The controller against its sources: {} now, before it the first cost model "
        "(tms34010-mame)\n\n",
        after.name);
    std::string csv = "figure,unit,source,stated,before,after,checked,pass,before_pass\n";
    for (const auto& r : rows) {
        all_pass = all_pass && r.pass;
        const std::string verdict = !r.checked ? "" : r.pass ? "  ok" : "  MISSED";
        const std::string was = !r.checked ? "" : r.before_pass ? "" : " (missed)";
        table += fmt::format("{} ({})\n    {}{}\n    before {}{}, now {}{}\n", r.figure, r.unit,
                             r.source, r.stated.empty() ? "" : fmt::format(" -- {}", r.stated),
                             number(r.before), was, number(r.after), verdict);
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", csv_field(r.figure), csv_field(r.unit),
                           csv_field(r.source), csv_field(r.stated), csv_number(r.before),
                           csv_number(r.after), r.checked ? "yes" : "no", r.pass ? "yes" : "no",
                           r.before_pass ? "yes" : "no");
    }
    if (!a.csv.empty()) write_text(a.csv, csv);
    if (!a.quiet && a.csv != "-") {
        std::cout << table;
        if (a.listing) {
            std::cout << "\n"
                      << controller::annotated_listing(controller::builtin_listing(after.gsp),
                                                       controller::memory_timing(after));
        }
    }
    return a.check && !all_pass ? kCheckFailed : kSuccess;
}

}  // namespace

void register_controller_validate(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<ControllerValidateArgs>();
    CLI::App* sub = app.add_subcommand(
        "controller-validate",
        "Set the controller's cost model beside TI's data sheet: memory cycles, the host port, "
        "refresh, the command loop's listing, the TMS34020 against BYTE's figures");
    sub->add_option("--profile", a->profile,
                    "Controller cost profile with a listing: " + name_list(profile_names()) +
                        " or a .json file (fb89 list profiles)")
        ->check(profile_validator());
    sub->add_option("--csv", a->csv, "Write the checks as CSV ('-' for stdout)");
    sub->add_flag("--listing", a->listing,
                  "Also print the command loop (controller_sim/gsp/*.asm), each instruction "
                  "with its cycles");
    sub->add_flag("--check", a->check, "Exit 1 when a figure misses what its source states");
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    sub->callback([a, &exit_code] { exit_code = run_controller_validate(*a); });
}

}  // namespace fb89::cli
