// `fb89 render --host`: a 1989 host's times beside the controller's, the split in one line,
// the figures in --stats, and the errors a user can meet.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"
#include "tests/scenes_dir.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

using fb89::testing::kScenes;

TEST(PeriodRender, ASun360HostPrintsItsPhasesAndTheSplit) {
    const std::string stats = (test_dir() / "s.json").string();
    CliRun r =
        run_fb89("render " + kScenes + "/A.json --size 256x195 --host sun3-60 --stats " + stats);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("host sun3-60 (MC68020 at 20 MHz + MC68881 at 20 MHz"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("the same frame as the native run's"), std::string::npos) << r.out;
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

// The Sun-4: its own guest under qemu-sparc32plus, the same frame as natively, and the
// report's SPARC lines: register-window traps per phase and the stand-ins' share.
TEST(PeriodRender, ASun4HostPrintsItsWindowTrapsAndStandInsAndTheSplit) {
    const std::string stats = (test_dir() / "s4.json").string();
    CliRun r = run_fb89("render " + kScenes +
                        "/A.json --size 256x195 --host sun4-260 --classes 5 " + "--stats " + stats);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // the classes that take most of each phase: five lines under each heading
    const size_t heading = r.out.find("hidden_surface phase, the classes that take most of its ");
    ASSERT_NE(heading, std::string::npos) << r.out;
    EXPECT_NE(r.out.find("setup phase, the classes that take most of its "), std::string::npos);
    EXPECT_NE(r.out.find("%  ", heading), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("host sun4-260 (MB86900 at 16.67 MHz + Weitek 1164/1165 + FPC"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("window traps     overflow/underflow: load "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("% of the modelled time: instructions the machine does not have"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("the same frame as the native run's"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("split: host sun4-260"), std::string::npos) << r.out;
    const auto j = nlohmann::json::parse(slurp(stats))["period_host"];
    EXPECT_EQ(j["profile"], "sun4-260");
    EXPECT_TRUE(j["same_frame"].get<bool>());
    const auto& hs = j["phases"]["hidden_surface"];
    EXPECT_GT(hs["ms"].get<double>(), 0);
    EXPECT_GE(hs["stand_in_ms"].get<double>(), 0);
    EXPECT_LT(hs["stand_in_ms"].get<double>(), hs["ms"].get<double>());
    EXPECT_TRUE(hs["events"].contains("@window_overflow"));
}

// On a 1989 host the send times are counted from the emulated instructions: the frame goes
// through the pipeline in time, and two runs write the same timeline byte for byte.
TEST(PeriodRender, TheSendTimesAreCountedTheSameTwice) {
    for (const std::string host : {"sun3-60", "sun4-260"}) {
        SCOPED_TRACE(host);
        std::string timelines[2];
        for (int i = 0; i < 2; ++i) {
            const std::string path = (test_dir() / (host + std::to_string(i) + ".json")).string();
            const std::string stats = (test_dir() / (host + "-stats.json")).string();
            CliRun r = run_fb89("render " + kScenes + "/A.json --size 128x98 -m scanline --host " +
                                host + " --timeline " + path + " --stats " + stats);
            ASSERT_EQ(r.exit_code, 0) << r.err;
            EXPECT_NE(r.out.find("pipeline (send times counted, buffer unbounded): frame "),
                      std::string::npos)
                << r.out;
            timelines[i] = slurp(path);
            const auto j = nlohmann::json::parse(slurp(stats));
            EXPECT_EQ(j["pipeline"]["send_times"], "counted");
            // the host's work in the pipeline is its set-up and hidden-surface time, to the
            // nanosecond (the pipeline's grain, as streams keep the times)
            EXPECT_NEAR(j["pipeline"]["host_ms"].get<double>(),
                        j["period_host"]["phases"]["setup"]["ms"].get<double>() +
                            j["period_host"]["phases"]["hidden_surface"]["ms"].get<double>(),
                        0.5e-6);
        }
        EXPECT_EQ(timelines[0], timelines[1]);
        const auto t = nlohmann::json::parse(timelines[0]);
        EXPECT_EQ(t["otherData"]["send_times"], "counted");
        double last = 0;
        for (const auto& e : t["traceEvents"])
            if (e["ph"] == "i") {
                EXPECT_GE(e["ts"].get<double>(), last);
                last = e["ts"];
            }
        EXPECT_GT(last, 0);
    }
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
