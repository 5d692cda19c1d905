// What every experiment is given: the scenes, an image size, how many timed rounds, the
// controller's cost profile, and whether to show progress.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "host/methods.h"
#include "host/trace/ray_tracer.h"

namespace fb89::experiments {

class PeriodRuns;

struct ImageSize {
    int width = 0, height = 0;
};

struct ExperimentSettings {
    std::vector<std::string> scenes;
    ImageSize size;  // 0 x 0: each scene's own
    int repeat = 7;
    std::string profile = "tms34010-50mhz";
    bool progress = false;
    // what the ray tracer and the beam-ray hybrid's rays walk (ray_tracer.h)
    host::Accel accel = host::Accel::Bvh;
    // split: these methods only, in the paper's order (empty: every one)
    std::vector<host::Method> methods;
    // A 1989 host (period_runs.h): host times are modelled from emulated runs, once each,
    // instead of timed here in repeated rounds. Null: this machine.
    std::shared_ptr<PeriodRuns> period;
};

}  // namespace fb89::experiments
