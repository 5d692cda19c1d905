// The paper's calibration (§3), done for this machine: the hybrid timed along a ramp of
// Expr. 3.1 thresholds on a set of scenes, interleaved, and the threshold with the least
// total time chosen. One addition to the paper's rule: a total is dominated by the slowest
// scenes, so a threshold is eligible only if no scene is more than `tolerance` slower than
// with the pure Z-buffer (threshold 0, always eligible): the paper's "negligible
// degradation". The beam-ray hybrid's Expr. 2.7 threshold is chosen the same way (§4:
// "determined using the same method"); every beam threshold shows the same frame, so only
// time decides. `fb89 calibrate` prints the result and saves the choice.
#pragma once

#include <functional>
#include <map>
#include <vector>

#include "experiments/settings.h"
#include "experiments/table.h"

namespace fb89::experiments {

struct Calibration {
    Table sweep;                     // the timed sweep, one row per scene and threshold
    std::map<double, double> total;  // threshold -> sum of the scenes' median CPU ms
    std::map<double, double> worst;  // threshold -> the worst scene's ratio to the reference
    double reference_ms = 0;         // the pure Z-buffer's (hybrid) or ray tracer's (beam) total
    double chosen = 0;
    // Stability against noise (calibrate_stably): each sweep's choice in order, and whether
    // the last two agreed.
    std::vector<double> choices;
    bool stable = true;
};

// Timing is noisy: a busy moment can make a sweep choose otherwise. calibrate_stably()
// repeats `calibrate` until two sweeps in a row choose the same threshold, at most
// `max_sweeps` times; the last sweep's table and totals are kept, `choices` lists every
// sweep's choice, and when no two in a row agreed, `chosen` is the threshold chosen most
// often (the later on a tie) and `stable` is false. A 1989 host's counts are exact: one sweep
// is enough there (settings.period set).
Calibration calibrate_stably(const ExperimentSettings& settings,
                             const std::function<Calibration()>& calibrate, int max_sweeps = 4);

// The hybrid at 0, the paper's 0.04 and `thresholds`; `tolerance` as above.
Calibration calibrate_hybrid(const ExperimentSettings& settings,
                             const std::vector<double>& thresholds, double tolerance);
// The beam-ray hybrid along beam_threshold_ramp(), against the ray tracer alone.
Calibration calibrate_beam(const ExperimentSettings& settings);

}  // namespace fb89::experiments
