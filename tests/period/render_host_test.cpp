// `fb89 render --host`: a 1989 host's times beside the controller's, the split in one line,
// the figures in --stats, and the errors a user can meet.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

const std::string kScenes = FB89_SCENES_DIR;

TEST(PeriodRender, ASun360HostPrintsItsPhasesAndTheSplit) {
    const std::string stats = (test_dir() / "s.json").string();
    CliRun r =
        run_fb89("render " + kScenes + "/A.json --size 256x195 --host sun3-60 --stats " + stats);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("host sun3-60 (MC68020 + MC68881"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("the native one's frame"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("split: host sun3-60"), std::string::npos) << r.out;
    const auto j = nlohmann::json::parse(slurp(stats))["period_host"];
    EXPECT_EQ(j["profile"], "sun3-60");
    EXPECT_TRUE(j["same_frame"].get<bool>());
    EXPECT_GT(j["phases"]["hidden_surface"]["ms"].get<double>(), 0);
    // counts are exact: the same run gives the same modelled time
    const std::string again = (test_dir() / "t.json").string();
    ASSERT_EQ(
        run_fb89("render " + kScenes + "/A.json --size 256x195 --host sun3-60 -q --stats " + again)
            .exit_code,
        0);
    EXPECT_EQ(nlohmann::json::parse(slurp(again))["period_host"]["end_to_end_ms"],
              j["end_to_end_ms"]);
}

TEST(PeriodRender, NativeRunsEndWithTheSplitToo) {
    CliRun r = run_fb89("render " + kScenes + "/A.json --size 256x195");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("split: host native"), std::string::npos) << r.out;
}

TEST(PeriodRender, AnUnknownHostOrAMissingEmulatorExitsTwoSayingWhat) {
    CliRun unknown = run_fb89("render " + kScenes + "/A.json --host sun3-61");
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_NE(unknown.err.find("unknown host 'sun3-61'"), std::string::npos) << unknown.err;
    EXPECT_NE(unknown.err.find("sun3-60"), std::string::npos) << unknown.err;
    CliRun missing =
        run_fb89("render " + kScenes + "/A.json --host sun3-60", "FB89_QEMU=/nonexistent ");
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("qemu-user"), std::string::npos) << missing.err;
}

}  // namespace
