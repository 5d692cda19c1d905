// The soak (bench/soak): the slope it fits to resident memory, and a short run of each of
// fb89_soak's three modes, checked for frames lost or changed, descriptors leaked and files
// left behind, never for memory or time (20 cycles are all warm-up).
#include "bench/soak/rss_slope.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"

namespace fb89::soak {
namespace {

TEST(SoakSlope, LineThroughTheSecondHalfGivesItsSlopeAndWarmUpIsLeftOut) {
    std::vector<ResourceSample> samples;
    samples.push_back({1, 900, 6});  // warm-up, far off the line
    for (int c = 50; c <= 100; c += 10)
        samples.push_back({c, 5000 + 2 * static_cast<uint64_t>(c), 6});
    EXPECT_NEAR(rss_slope_kib_per_cycle(samples, 100), 2.0, 1e-12);
}

TEST(SoakSlope, FlatSamplesHaveNoSlopeAndFewerThanTwoHaveNone) {
    EXPECT_EQ(rss_slope_kib_per_cycle({{50, 7000, 6}, {75, 7000, 6}, {100, 7000, 6}}, 100), 0.0);
    EXPECT_TRUE(std::isnan(rss_slope_kib_per_cycle({{10, 1, 6}, {100, 7000, 6}}, 100)));
}

#ifdef FB89_SOAK_PATH

// Runs fb89_soak MODE with small scenes, its JSON and work folder in this test's folder.
nlohmann::json run_soak(const std::string& mode, const std::string& args, int& exit_code) {
    const std::filesystem::path dir = testing::test_dir();
    std::filesystem::remove_all(dir / "work");
    const std::string cmd = std::string(FB89_SOAK_PATH) + " " + mode + " " + args +
                            " --scenes-dir " + FB89_SCENES_DIR +
                            " --scene A --scene B --scene G --scene cornell_box"
                            " --fb89 " +
                            FB89_CLI_PATH + " --max-rss-growth 0 -q" + " --work " +
                            (dir / "work").string() + " --json " + (dir / "soak.json").string() +
                            " >" + (dir / "stdout").string() + " 2>" + (dir / "stderr").string();
    const int status = std::system(cmd.c_str());
    exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return nlohmann::json::parse(testing::slurp(dir / "soak.json"));
}

void expect_every_frame_and_no_leak(const nlohmann::json& j, int cycles) {
    EXPECT_EQ(j.at("cycles"), cycles);
    EXPECT_EQ(j.at("frames_expected"), cycles);
    EXPECT_EQ(j.at("frames_lost"), 0);
    EXPECT_EQ(j.at("frames_mismatched"), 0);
    EXPECT_EQ(j.at("failure_count"), 0) << j.at("failures").dump(2);
    EXPECT_GT(j.at("commands_checked").get<uint64_t>(), 0u);
    ASSERT_GE(j.at("samples").size(), 2u);
    EXPECT_LE(j.at("fds_last").get<int>(), j.at("fds_first").get<int>());
    EXPECT_TRUE(j.at("pass").get<bool>());
}

TEST(SoakHarness, TwentyInProcessCyclesLoseNoFrameAndLeakNoDescriptor) {
    int code = -1;
    const nlohmann::json j = run_soak("inprocess", "--cycles 20 --every 5", code);
    EXPECT_EQ(code, 0) << testing::slurp(testing::test_dir() / "stdout");
    expect_every_frame_and_no_leak(j, 20);
}

TEST(SoakHarness, SixCliCyclesAgreeAndLeaveOnlyTheirOutputs) {
    int code = -1;
    const nlohmann::json j = run_soak("cli", "--cycles 6 --every 2", code);
    EXPECT_EQ(code, 0) << testing::slurp(testing::test_dir() / "stdout");
    expect_every_frame_and_no_leak(j, 6);
    EXPECT_EQ(j.at("stray_files"), 0);
}

TEST(SoakHarness, ControllerServesTwentyHostsAndKeepsEveryFrame) {
    int code = -1;
    const nlohmann::json j = run_soak("controller", "--cycles 20 --every 5", code);
    EXPECT_EQ(code, 0) << testing::slurp(testing::test_dir() / "stdout");
    expect_every_frame_and_no_leak(j, 20);
    EXPECT_EQ(j.at("parent_samples").size(), j.at("samples").size());
}

#endif  // FB89_SOAK_PATH

}  // namespace
}  // namespace fb89::soak
