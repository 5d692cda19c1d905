// Progress on long work: shown on stderr with the time left when stderr is a terminal
// (`script` gives the command one), and nothing when it is not or with -q.
#include <gtest/gtest.h>

#include <cstdlib>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

const std::string kExperiment = std::string(FB89_CLI_PATH) + " experiment fig2.1 " +
                                FB89_SCENES_DIR + "/A.json --size 64x48 --repeat 3";

TEST(Progress, ATerminalSeesRoundsAndTheTimeLeft) {
    const std::string log = (test_dir() / "tty.txt").string();
    const std::string cmd =
        "script -qec '" + kExperiment + " --csv /dev/null' " + log + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string seen = slurp(log);
    EXPECT_NE(seen.find("2/4 rounds"), std::string::npos) << seen;
    EXPECT_NE(seen.find("s left"), std::string::npos) << seen;
}

TEST(Progress, NothingWhenStderrIsNotATerminalOrWithQuiet) {
    CliRun piped = run_fb89(kExperiment.substr(kExperiment.find("experiment")) + " --csv -");
    ASSERT_EQ(piped.exit_code, 0) << piped.err;
    EXPECT_EQ(piped.err.find("rounds"), std::string::npos) << piped.err;
    const std::string log = (test_dir() / "quiet.txt").string();
    const std::string cmd =
        "script -qec '" + kExperiment + " -q --csv /dev/null' " + log + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(slurp(log).find("rounds"), std::string::npos) << slurp(log);
}

// The radiosity stages report how far they have got, with the time left.
TEST(Progress, RadiosityShowsEachStageWithTheTimeLeft) {
    const std::string log = (test_dir() / "radiosity.txt").string();
    const std::string cmd = "script -qec '" + std::string(FB89_CLI_PATH) + " radiosity " +
                            FB89_SCENES_DIR + "/garish_room.json --patches 1200 --ff exact' " +
                            log + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string seen = slurp(log);
    EXPECT_NE(seen.find("radiosity: visibility (flux tracing): "), std::string::npos) << seen;
    EXPECT_NE(seen.find("radiosity: form factors: "), std::string::npos) << seen;
    EXPECT_NE(seen.find("%, about "), std::string::npos) << seen;
    EXPECT_NE(seen.find("radiosity: rendering"), std::string::npos) << seen;
}

// Fig. 2.4 counts the scenes it has done, its ideal scenes among them.
TEST(Progress, Fig24CountsItsScenes) {
    const std::string log = (test_dir() / "fig24.txt").string();
    const std::string cmd = "script -qec '" + std::string(FB89_CLI_PATH) + " experiment fig2.4 " +
                            FB89_SCENES_DIR + "/A.json --csv /dev/null' " + log +
                            " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string seen = slurp(log);
    EXPECT_NE(seen.find("fig2.4: 1/22 scenes, about "), std::string::npos) << seen;
    EXPECT_NE(seen.find("fig2.4: 21/22 scenes"), std::string::npos) << seen;
}

}  // namespace
