// fb89 controller-validate: the controller's cost model held to TI's data sheet and the other
// sources (experiments/controller_validation.h; docs/COST_MODEL.md, "Checked where checks
// exist"). Each row prints the figure, what the source states, the first cost model's figure
// (tms34010-mame) and the model's now; --listing prints the command loop with each
// instruction's cycles; --check exits 1 when a figure misses what its source states. The work
// is frontend/validations.h's, shared with fb89.controller_validate() in Python.
#include <iostream>

#include "cli/commands.h"
#include "frontend/validations.h"

namespace fb89::cli {

namespace {

struct ControllerValidateArgs {
    frontend::ControllerValidationRequest request;
    std::string csv;
    bool check = false, quiet = false;
};

int run_controller_validate(const ControllerValidateArgs& a) {
    const frontend::ValidationReport report = frontend::controller_validation(a.request);
    if (!a.csv.empty()) write_text(a.csv, report.csv);
    if (!a.quiet && a.csv != "-") {
        std::cout << report.text;
        if (a.request.listing) std::cout << "\n" << report.listing;
    }
    return a.check && !report.all_pass ? kCheckFailed : kSuccess;
}

}  // namespace

void register_controller_validate(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<ControllerValidateArgs>();
    CLI::App* sub = app.add_subcommand(
        "controller-validate",
        "Set the controller's cost model beside TI's data sheet: memory cycles, the host port, "
        "refresh, the command loop's listing, the TMS34020 against BYTE's figures");
    sub->add_option("--profile", a->request.profile,
                    "Controller cost profile with a listing: " + name_list(profile_names()) +
                        " or a .json file (fb89 list profiles)")
        ->check(profile_validator());
    sub->add_option("--csv", a->csv, "Write the checks as CSV ('-' for stdout)");
    sub->add_flag("--listing", a->request.listing,
                  "Also print the command loop (controller_sim/gsp/*.asm), each instruction "
                  "with its cycles");
    sub->add_flag("--check", a->check, "Exit 1 when a figure misses what its source states");
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    sub->callback([a, &exit_code] { exit_code = run_controller_validate(*a); });
}

}  // namespace fb89::cli
