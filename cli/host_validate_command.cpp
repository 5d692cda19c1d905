// fb89 host-validate: the modelled 1989 hosts against published figures
// (docs/HOST_COST_MODEL.md, "Validation"). Each validation kernel (period/kernels) runs once
// on each emulated instruction set a profile needs (its counts do not depend on the
// profile), each host profile prices its timed phase, and the modelled speed is printed
// beside the published figures of period/validation.json with the error (modelled /
// published - 1), and the ratios between machines that validation.json names beside the ratios
// of their modelled figures. --check exits 1 when a check fails (|error| over the figure's
// tolerance for a figure of the profiled machine itself, or over a ratio's). The work is
// frontend/validations.h's, shared with fb89.host_validate() in Python.
#include <iostream>
#include <string>

#include "cli/commands.h"
#include "frontend/validations.h"

namespace fb89::cli {

namespace {

struct HostValidateArgs {
    frontend::HostValidationRequest request;
    std::string csv;
    bool check = false, quiet = false;
};

int run_host_validate(HostValidateArgs& a) {
    const Console console{a.quiet};
    a.request.note = [&](const std::string& text) { console.note(text); };
    const frontend::ValidationReport report = frontend::host_validation(a.request);
    if (!a.csv.empty()) write_text(a.csv, report.csv);
    if (!a.quiet && a.csv != "-") std::cout << report.text;
    return a.check && !report.all_pass ? kCheckFailed : kSuccess;
}

}  // namespace

void register_host_validate(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<HostValidateArgs>();
    CLI::App* sub = app.add_subcommand("host-validate",
                                       "Set the modelled 1989 hosts (kernels on the emulated " +
                                           name_list(instruction_set_names()) +
                                           ", priced by host profiles) beside published "
                                           "figures of the period");
    sub->add_option("--profile", a->request.profiles,
                    "Host profile: " + name_list(host_profile_names()) +
                        ", or a .json file "
                        "(fb89 list hosts); default: every profile a figure names")
        ->check(host_profile_validator());
    sub->add_option("--csv", a->csv, "Write the comparison as CSV ('-' for stdout)");
    sub->add_option("--classes", a->request.classes,
                    "Also list the N instruction classes that take most of each kernel's "
                    "modelled time, with the rule that prices each")
        ->check(CLI::Range(0, 1000));
    sub->add_flag(
        "--check", a->check,
        "Exit 1 when a figure's or a ratio's check fails (an error beyond its tolerance)");
    sub->add_flag("--quiet,-q", a->quiet, "Print nothing but errors");
    sub->callback([a, &exit_code] { exit_code = run_host_validate(*a); });
}

}  // namespace fb89::cli
