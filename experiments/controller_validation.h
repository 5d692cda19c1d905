// The controller held to its sources: each figure TI's data sheet (and the User's Guide, where
// its pages could be read) states as a number, beside what the cost model makes of it now and
// what the first cost model (MAME's figures, the profile tms34010-mame) made of it
// (fb89 controller-validate; docs/COST_MODEL.md, "Checked where checks exist").
#pragma once

#include <string>
#include <vector>

#include "controller_sim/profile.h"
#include "protocol/memory_buffer.h"

namespace fb89::experiments {

struct ValidationRow {
    std::string figure;  // what is checked
    std::string unit;
    std::string source;  // "[DS] SPVS002C p. 19", "[UG] ...", "BYTE, September 1988"
    std::string stated;  // what the source says, as a condition or a figure ("at least 4")
    double before = 0;   // the first cost model's figure
    double after = 0;    // the model's now
    // Whether the model's figure meets what the source states; a row without a condition
    // (a figure set beside a published one) is neither: `checked` false.
    bool checked = false;
    bool pass = true;
    bool before_pass = true;
};

// The rows, for the profile `after` (a "gsp" profile, normally tms34010-50mhz), the first
// cost model `before`, the TMS34020 profile and one frame's commands (the demo's, for the
// 34020 : 34010 ratio on a whole frame).
std::vector<ValidationRow> controller_validation(const controller::CostProfile& after,
                                                 const controller::CostProfile& before,
                                                 const controller::CostProfile& tms34020,
                                                 const protocol::MemoryBuffer& frame);

}  // namespace fb89::experiments
