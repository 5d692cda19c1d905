// The two validations as the command line (`fb89 host-validate`, `fb89 controller-validate`)
// and the Python module (fb89.host_validate(), fb89.controller_validate()) both run them:
//   - the modelled 1989 hosts against published figures of the period
//     (docs/HOST_COST_MODEL.md, "Validation"): each validation kernel (period/kernels) run
//     once on each emulated instruction set a profile needs, each host profile pricing its
//     timed phase, the modelled speed set beside the published figures of
//     period/validation.json with the error (modelled / published - 1), and the ratios
//     between machines that validation.json names beside the ratios of their modelled figures;
//   - the controller's cost model against TI's data sheet and the other sources
//     (experiments/controller_validation.h; docs/COST_MODEL.md, "Checked where checks exist").
// Each gives the text the command prints, the CSV its --csv writes, and whether every check
// passed (what --check exits 1 on).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "controller_sim/profile.h"
#include "frontend/option_limits.h"

namespace fb89::frontend {

struct ValidationReport {
    std::string text;     // what the command prints
    std::string csv;      // what --csv writes (a header row, then one row a check)
    std::string listing;  // controller-validate --listing: the command loop with its cycles
    bool all_pass = true;
};

struct HostValidationRequest {
    std::vector<std::string> profiles;  // host profiles (names or .json files); none: every one
                                        // a figure names
    int classes = 0;  // also the N instruction classes that take most of each kernel's time
    Spelling spelling = Spelling::Option;
    std::function<void(const std::string&)> note;  // what is run, as it runs (may be empty)
};

// Throws UsageError naming the profile option for a profile that is none.
ValidationReport host_validation(const HostValidationRequest& r);

struct ControllerValidationRequest {
    std::string profile = std::string(controller::kDefaultProfile);  // one with a listing
    bool listing = false;
    Spelling spelling = Spelling::Option;
};

// Throws UsageError naming the profile option for a profile that is none or has no listing.
ValidationReport controller_validation(const ControllerValidationRequest& r);

}  // namespace fb89::frontend
