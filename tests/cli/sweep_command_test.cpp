// `fb89 sweep`, `fb89 calibrate` and `fb89 experiment` as a user runs them: CSV with a
// header row, the calibration saved where render picks it up, exit codes.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <algorithm>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

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
CliRun fb89_from_root_calibrated(const std::string& args) {
    return fb89::testing::run_fb89(
        args, "cd " + fs::path(FB89_SCENES_DIR).parent_path().string() +
                  " && FB89_CALIBRATION=" + (test_dir() / "calibration.json").string() + " ");
}

size_t line_count(const std::string& text) {
    return static_cast<size_t>(std::count(text.begin(), text.end(), '\n'));
}

TEST(SweepCommand, WritesOneCsvRowPerSceneAndThresholdWithTheReferences) {
    CliRun r = fb89_from_root_calibrated(
        "sweep threshold scenes/A.json scenes/B.json --from 0.001 --to 0.1 --steps 3 "
        "--repeat 1 --size 256x195 --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("scene,threshold,hs_wall_ms,hs_cpu_ms", 0), 0u) << r.out;
    EXPECT_EQ(line_count(r.out), 1u + 2u * (3u + 2u));  // header; per scene 0, 3 ramp, inf
    EXPECT_NE(r.out.find("\nB,inf,"), std::string::npos) << r.out;  // bundled: by name
}

TEST(SweepCommand, BadArgumentsExitTwo) {
    EXPECT_EQ(fb89_from_root_calibrated("sweep threshold scenes/A.json --from 0 --to 1").exit_code,
              2);
    EXPECT_EQ(fb89_from_root_calibrated("sweep depth scenes/A.json").exit_code, 2);
    EXPECT_EQ(fb89_from_root_calibrated("sweep threshold").exit_code, 2);
    CliRun missing = fb89_from_root_calibrated("sweep threshold nowhere.json --repeat 1");
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("nowhere.json"), std::string::npos) << missing.err;
}

// The number on calibrate's last line: "chosen threshold 0.0102: ...".
double chosen_in(const std::string& out, const std::string& what = "chosen threshold ") {
    const size_t at = out.rfind(what);
    EXPECT_NE(at, std::string::npos) << out;
    return at == std::string::npos ? -1 : std::stod(out.substr(at + what.size()));
}

TEST(CalibrateCommand, SavesTheChosenThresholdForRender) {
    fs::remove(test_dir() / "calibration.json");  // nothing left from a last run
    CliRun r =
        fb89_from_root_calibrated("calibrate scenes/A.json scenes/C.json --steps 3 --repeat 1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const double chosen = chosen_in(r.out);
    nlohmann::json saved = nlohmann::json::parse(slurp(test_dir() / "calibration.json"));
    EXPECT_DOUBLE_EQ(saved["threshold"].get<double>(), chosen);
    EXPECT_EQ(saved["hybrid"]["scenes"].size(), 2u);
    // render picks it up by default
    CliRun render = fb89_from_root_calibrated(
        "render scenes/A.json --method hybrid --size 128x98 -q --stats -");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(render.out)["threshold"].get<double>(), chosen);
    // and the paper's stays available
    CliRun paper = fb89_from_root_calibrated(
        "render scenes/A.json --method hybrid --threshold paper --size 128x98 -q --stats -");
    EXPECT_DOUBLE_EQ(nlohmann::json::parse(paper.out)["threshold"].get<double>(), 0.04);
}

TEST(CalibrateCommand, WithoutCalibrationRenderAndCompareUseThePapersThresholdAndSaySo) {
    fs::remove(test_dir() / "calibration.json");
    CliRun render = fb89_from_root_calibrated("render scenes/A.json --method hybrid --size 128x98");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(render.out.rfind("hybrid threshold 0.04 (the paper's: not calibrated yet", 0), 0u)
        << render.out;
    CliRun compare =
        fb89_from_root_calibrated("compare scenes/A.json --size 128x98 --repeat 1 --sheet " +
                                  (test_dir() / "sheet.png").string());
    ASSERT_EQ(compare.exit_code, 0) << compare.err;
    EXPECT_EQ(compare.out.rfind("hybrid threshold 0.04 (the paper's: not calibrated yet", 0), 0u)
        << compare.out;
}

// calibrate's report is on stdout: the table, the sweeps' choices, and the chosen threshold
// on the last line; -q leaves that line alone. Two sweeps at least: the choice must agree.
TEST(CalibrateCommand, ReportsTheTableAndTheStableChoiceOnStdout) {
    fs::remove(test_dir() / "calibration.json");
    CliRun r = fb89_from_root_calibrated("calibrate scenes/A.json --steps 2 --repeat 1 --dry-run");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("threshold      total ms  vs zbuffer"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" sweeps chose "), std::string::npos) << r.out;
    const std::string last = r.out.substr(r.out.rfind("chosen threshold "));
    EXPECT_NE(last.find("against the pure Z-buffer; not saved (--dry-run)\n"), std::string::npos)
        << last;
    CliRun quiet =
        fb89_from_root_calibrated("calibrate scenes/A.json --steps 2 --repeat 1 --dry-run -q");
    ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
    EXPECT_EQ(quiet.out.rfind("chosen threshold ", 0), 0u) << quiet.out;
    EXPECT_EQ(std::count(quiet.out.begin(), quiet.out.end(), '\n'), 1) << quiet.out;
    EXPECT_FALSE(fs::exists(test_dir() / "calibration.json"));
}

TEST(ExperimentCommand, UnknownExperimentExitsTwo) {
    CliRun r = fb89_from_root_calibrated("experiment fig9.9");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown experiment 'fig9.9'"), std::string::npos) << r.err;
}

// The exact settings differ from the Z-buffer on no pixel; the depth commands only on ties
// of the profile's depth word (every differing pixel one, said in pixels_ties).
TEST(ExperimentCommand, AccuracyCountsNoWrongPixelForExactSettings) {
    CliRun r = fb89_from_root_calibrated(
        "experiment accuracy scenes/C.json --size 256x195 --repeat 1 --threshold 0.01 --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream csv(r.out);
    std::string line;
    std::getline(csv, line);
    const auto cells = [](const std::string& text) {
        std::vector<std::string> out;
        std::stringstream in(text);
        for (std::string cell; std::getline(in, cell, ',');)
            out.push_back(cell);
        if (!text.empty() && text.back() == ',') out.emplace_back();
        return out;
    };
    const std::vector<std::string> header = cells(line);
    const auto column = [&](const std::string& name) {
        return static_cast<size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const size_t setting = column("setting"), wrong = column("pixels_wrong"),
                 ties = column("pixels_ties"), bits = column("depth_bits");
    ASSERT_LT(std::max({setting, wrong, ties, bits}), header.size()) << line;
    size_t exact_rows = 0, depth_rows = 0;
    while (std::getline(csv, line)) {
        const std::vector<std::string> row = cells(line);
        ASSERT_EQ(row.size(), header.size()) << line;
        if (row[setting] == "zspans" || row[setting] == "faces") {
            ++depth_rows;
            EXPECT_EQ(row[ties], row[wrong]) << line;
            EXPECT_EQ(row[bits], "16") << line;
            continue;
        }
        if (row[setting].find("exact") == std::string::npos && row[setting] != "zbuffer") continue;
        ++exact_rows;
        EXPECT_EQ(row[wrong], "0") << line;
        EXPECT_EQ(row[ties], "") << line;
    }
    EXPECT_EQ(exact_rows, 3u);
    EXPECT_EQ(depth_rows, 2u);
}

}  // namespace

namespace {

TEST(CalibrateCommand, KeepsBothThresholdsInOneFile) {
    fs::remove(test_dir() / "calibration.json");
    CliRun hybrid = fb89_from_root_calibrated("calibrate scenes/A.json --steps 2 --repeat 1");
    ASSERT_EQ(hybrid.exit_code, 0) << hybrid.err;
    // G at a quarter of its size (the beam ramp at 1024x780 takes 45 s under the sanitizers)
    std::string scene = slurp(fs::path(FB89_SCENES_DIR) / "G.json");
    const std::string size = "\"width\": 1024, \"height\": 780";
    ASSERT_NE(scene.find(size), std::string::npos);
    scene.replace(scene.find(size), size.size(), "\"width\": 256, \"height\": 195");
    const fs::path small = test_dir() / "G_256x195.json";
    std::ofstream(small) << scene;
    CliRun beam =
        fb89_from_root_calibrated("calibrate --method beam '" + small.string() + "' --repeat 1");
    ASSERT_EQ(beam.exit_code, 0) << beam.err;
    nlohmann::json saved = nlohmann::json::parse(slurp(test_dir() / "calibration.json"));
    EXPECT_DOUBLE_EQ(saved["threshold"].get<double>(), chosen_in(hybrid.out));
    // a number, or "inf" (JSON has no infinity)
    auto as_text = [](const nlohmann::json& v) {
        return v.is_string() ? v.get<std::string>() : fmt::format("{:.6g}", v.get<double>());
    };
    const std::string after = "chosen beam threshold ";
    const size_t at = beam.out.rfind(after) + after.size();
    const std::string chosen = beam.out.substr(at, beam.out.find(':', at) - at);
    EXPECT_EQ(as_text(saved["beam_threshold"]), chosen);
    EXPECT_EQ(saved["beam"]["scenes"].size(), 1u);
    // render --method beam picks the beam threshold up
    CliRun render =
        fb89_from_root_calibrated("render scenes/G.json --method beam --size 64x49 -q --stats -");
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_EQ(as_text(nlohmann::json::parse(render.out)["beam_threshold"]), chosen);
}

}  // namespace
