// Calibration against noise (experiments/calibration.h): sweeps are repeated until two in
// a row choose the same threshold; without agreement the threshold chosen most often wins;
// a 1989 host's exact counts need one sweep.
#include "experiments/calibration.h"

#include <gtest/gtest.h>

#include <vector>

#include "experiments/period_runs.h"

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
