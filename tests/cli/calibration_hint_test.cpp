// The thresholds' first line, as a user meets it: a run asked for the calibrated threshold
// without its calibration names what is missing and the exact command that makes it, and the
// experiments of a hybrid say their threshold first, as README.md says every command does.
// The calibration file is the test's own ($FB89_CALIBRATION), never the user's.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::test_dir;

std::string calibration_file() {
    return (test_dir() / "calibration.json").string();
}

CliRun fb89_in_test_dir(const std::string& args) {
    return fb89::testing::run_fb89(
        args, "cd " + test_dir().string() + " && FB89_CALIBRATION=" + calibration_file() + " ");
}

std::string first_line(const std::string& text) {
    return text.substr(0, text.find('\n'));
}

TEST(CalibrationHint, RenderOfTheBeamHybridNamesTheBeamCalibration) {
    std::filesystem::remove(calibration_file());
    std::ofstream(calibration_file()) << R"({"threshold": 0.01, "hybrid": {}})";
    const CliRun r = fb89_in_test_dir("render G --method beam --size 64x49");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("(the built-in one: not calibrated yet for method beam on host native: "
                         "`fb89 calibrate --method beam` makes it)"),
              std::string::npos)
        << r.out;
}

TEST(CalibrationHint, ExperimentHybridSaysItsThresholdOnTheFirstLine) {
    std::filesystem::remove(calibration_file());
    const CliRun paper = fb89_in_test_dir("experiment hybrid A --size 64x49 --repeat 1");
    ASSERT_EQ(paper.exit_code, 0) << paper.err;
    EXPECT_EQ(first_line(paper.out),
              "hybrid threshold 0.04 (the paper's: not calibrated yet for method hybrid on host "
              "native: `fb89 calibrate` makes it)")
        << paper.out;
    std::ofstream(calibration_file()) << R"({"threshold": 0.01, "hybrid": {}})";
    const CliRun calibrated = fb89_in_test_dir("experiment hybrid A --size 64x49 --repeat 1");
    ASSERT_EQ(calibrated.exit_code, 0) << calibrated.err;
    EXPECT_EQ(first_line(calibrated.out), "hybrid threshold 0.01 (calibrated here)")
        << calibrated.out;
    // the table alone where it is written: to standard output as CSV
    const CliRun csv = fb89_in_test_dir("experiment hybrid A --size 64x49 --repeat 1 --csv -");
    ASSERT_EQ(csv.exit_code, 0) << csv.err;
    EXPECT_EQ(csv.out.rfind("scene,", 0), 0u) << csv.out;
}

}  // namespace
