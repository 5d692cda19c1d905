// `fb89 sweep`, `fb89 calibrate` and `fb89 experiment` as a user runs them: CSV with a
// header row, the calibration saved where render picks it up, exit codes.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;

using fb89::testing::CliRun;
using fb89::testing::slurp;
using fb89::testing::test_dir;

// Runs fb89 from the repository root (scenes/A.json ... are the defaults there), with a
// calibration file of this test's own.
CliRun fb89(const std::string& args) {
    return fb89::testing::run_fb89(
        args, "cd " + fs::path(FB89_SCENES_DIR).parent_path().string() +
                  " && FB89_CALIBRATION=" + (test_dir() / "calibration.json").string() + " ");
}

size_t lines(const std::string& text) {
    return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(SweepCommand, WritesOneCsvRowPerSceneAndThresholdWithTheReferences) {
    CliRun r = fb89(
        "sweep threshold scenes/A.json scenes/B.json --from 0.001 --to 0.1 --steps 3 "
        "--repeat 1 --size 256x195 --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("scene,threshold,hs_wall_ms,hs_cpu_ms", 0), 0u) << r.out;
    EXPECT_EQ(lines(r.out), 1u + 2u * (3u + 2u));  // header; per scene 0, 3 ramp, inf
    EXPECT_NE(r.out.find("scenes/B.json,inf,"), std::string::npos);
}

TEST(SweepCommand, BadArgumentsExitTwo) {
    EXPECT_EQ(fb89("sweep threshold scenes/A.json --from 0 --to 1").exit_code, 2);
    EXPECT_EQ(fb89("sweep depth scenes/A.json").exit_code, 2);
    EXPECT_EQ(fb89("sweep threshold").exit_code, 2);
    CliRun missing = fb89("sweep threshold nowhere.json --repeat 1");
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("nowhere.json"), std::string::npos) << missing.err;
}

TEST(CalibrateCommand, SavesTheChosenThresholdForRender) {
    fs::remove(test_dir() / "calibration.json");  // nothing left from a last run
    CliRun r = fb89("calibrate scenes/A.json scenes/C.json --steps 3 --repeat 1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const double chosen = std::stod(r.out);
    nlohmann::json saved = nlohmann::json::parse(slurp(test_dir() / "calibration.json"));
    EXPECT_DOUBLE_EQ(saved["threshold"].get<double>(), chosen);
    EXPECT_EQ(saved["hybrid"]["scenes"].size(), 2u);
    // render picks it up by default
    CliRun render = fb89("render scenes/A.json --method hybrid --size 128x98 -q --stats -");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(render.out)["threshold"].get<double>(), chosen);
    // and the paper's stays available
    CliRun paper =
        fb89("render scenes/A.json --method hybrid --threshold paper --size 128x98 -q --stats -");
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(paper.out)["threshold"].get<double>(), 0.04);
}

TEST(CalibrateCommand, WithoutCalibrationRenderUsesThePapersThreshold) {
    CliRun render = fb89("render scenes/A.json --method hybrid --size 128x98 --stats -");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_NE(render.err.find("hybrid threshold 0.04 (paper (not calibrated yet))"),
              std::string::npos)
        << render.err;
}

TEST(ExperimentCommand, UnknownExperimentExitsTwo) {
    CliRun r = fb89("experiment fig9.9");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown experiment 'fig9.9'"), std::string::npos) << r.err;
}

TEST(ExperimentCommand, AccuracyCountsNoWrongPixelForExactSettings) {
    CliRun r = fb89(
        "experiment accuracy scenes/C.json --size 256x195 --repeat 1 --threshold 0.01 --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream csv(r.out);
    std::string line;
    std::getline(csv, line);
    size_t exact_rows = 0;
    while (std::getline(csv, line)) {
        if (line.find("exact") == std::string::npos && line.find(",zbuffer,") == std::string::npos)
            continue;
        ++exact_rows;
        // pixels_wrong is the second-to-last column
        std::string rest = line.substr(0, line.rfind(','));
        EXPECT_EQ(rest.substr(rest.rfind(',') + 1), "0") << line;
    }
    EXPECT_EQ(exact_rows, 3u);
}

}  // namespace

namespace {

TEST(CalibrateCommand, KeepsBothThresholdsInOneFile) {
    fs::remove(test_dir() / "calibration.json");
    CliRun hybrid = fb89("calibrate scenes/A.json --steps 2 --repeat 1");
    ASSERT_EQ(hybrid.exit_code, 0) << hybrid.err;
    CliRun beam = fb89("calibrate --method beam scenes/G.json --repeat 1");
    ASSERT_EQ(beam.exit_code, 0) << beam.err;
    nlohmann::json saved = nlohmann::json::parse(slurp(test_dir() / "calibration.json"));
    EXPECT_DOUBLE_EQ(saved["threshold"].get<double>(), std::stod(hybrid.out));
    // a number, or "inf" (JSON has no infinity)
    auto as_text = [](const nlohmann::json& v) {
        return v.is_string() ? v.get<std::string>() : fmt::format("{:.6g}", v.get<double>());
    };
    const std::string chosen = beam.out.substr(0, beam.out.find('\n'));
    EXPECT_EQ(as_text(saved["beam_threshold"]), chosen);
    EXPECT_EQ(saved["beam"]["scenes"].size(), 1u);
    // render --method beam picks the beam threshold up
    CliRun render = fb89("render scenes/G.json --method beam --size 64x49 -q --stats -");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(as_text(nlohmann::json::parse(render.out)["beam_threshold"]), chosen);
}

}  // namespace
