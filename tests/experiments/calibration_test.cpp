// Calibration against noise (experiments/calibration.h): sweeps are repeated until two in
// a row choose the same threshold; without agreement the threshold chosen most often wins;
// a 1989 host's exact counts need one sweep.
#include "experiments/calibration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "experiments/experiments.h"
#include "experiments/period_runs.h"
#include "host/trace/beam_ray_hybrid.h"

namespace fb89::experiments {
namespace {

// A calibration whose sweeps choose `choices`, one after another.
struct Scripted {
    std::vector<double> choices;
    size_t next = 0;
    Calibration operator()() {
        Calibration c;
        c.chosen = choices.at(next++);
        return c;
    }
};

// The beam default is the threshold calibration chooses (docs/RESULTS.md §4), so it must be a
// point calibration can choose: one of the ramp's values, exactly.
TEST(CalibrateBeam, TheDefaultThresholdIsAPointOfTheRamp) {
    const std::vector<double> ramp = beam_threshold_ramp();
    EXPECT_NE(std::find(ramp.begin(), ramp.end(), host::kDefaultBeamThreshold), ramp.end());
}

TEST(CalibrateStably, StopsWhenTwoSweepsInARowAgree) {
    Scripted sweeps{{0.01, 0.04, 0.04, 0.5}};
    const Calibration c = calibrate_stably({}, std::ref(sweeps));
    EXPECT_EQ(c.chosen, 0.04);
    EXPECT_TRUE(c.stable);
    EXPECT_EQ(c.choices, (std::vector<double>{0.01, 0.04, 0.04}));
}

TEST(CalibrateStably, TwoAgreeingSweepsAreEnough) {
    Scripted sweeps{{0.02, 0.02}};
    const Calibration c = calibrate_stably({}, std::ref(sweeps));
    EXPECT_EQ(c.choices.size(), 2u);
    EXPECT_TRUE(c.stable);
}

TEST(CalibrateStably, WithoutAgreementTheMostOftenChosenWinsAndItIsSaid) {
    Scripted sweeps{{0.01, 0.04, 0.01, 0.04}};
    const Calibration c = calibrate_stably({}, std::ref(sweeps), 4);
    EXPECT_FALSE(c.stable);
    EXPECT_EQ(c.choices.size(), 4u);
    EXPECT_EQ(c.chosen, 0.04);  // a tie: the later
    Scripted three{{0, 0.01, 0}};
    const Calibration d = calibrate_stably({}, std::ref(three), 3);
    EXPECT_FALSE(d.stable);
    EXPECT_EQ(d.chosen, 0);
}

}  // namespace
}  // namespace fb89::experiments
