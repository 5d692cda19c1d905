// Progress on long work: shown on stderr with the time left when stderr is a terminal
// (run_in_terminal gives the command one), and nothing when it is not or with -q.
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::run_in_terminal;

const std::string kExperiment = std::string(FB89_CLI_PATH) + " experiment fig2.1 " +
                                FB89_SCENES_DIR + "/A.json --size 64x48 --repeat 3";

// The CSV goes to the test's own folder (never a system path such as /dev/null).
std::string csv_option() {
    return " --csv " + (fb89::testing::test_dir() / "out.csv").string();
}

TEST(Progress, ATerminalSeesRoundsAndTheTimeLeft) {
    const CliRun tty = run_in_terminal(kExperiment + csv_option());
    ASSERT_EQ(tty.exit_code, 0) << tty.out;
    EXPECT_NE(tty.out.find("2/4 rounds"), std::string::npos) << tty.out;
    EXPECT_NE(tty.out.find("s left"), std::string::npos) << tty.out;
    // the table follows the progress, which has been wiped from its line
    EXPECT_NE(tty.out.find("warnock-centres"), std::string::npos) << tty.out;
}

TEST(Progress, NothingWhenStderrIsNotATerminalOrWithQuiet) {
    CliRun piped = run_fb89(kExperiment.substr(kExperiment.find("experiment")) + " --csv -");
    ASSERT_EQ(piped.exit_code, 0) << piped.err;
    EXPECT_EQ(piped.err.find("rounds"), std::string::npos) << piped.err;
    EXPECT_NE(piped.out.find("warnock-centres"), std::string::npos) << piped.out;
    const CliRun quiet = run_in_terminal(kExperiment + " -q" + csv_option());
    ASSERT_EQ(quiet.exit_code, 0) << quiet.out;
    EXPECT_EQ(quiet.out, "");
    // the same command without -q shows its rounds on this terminal
    const CliRun shown = run_in_terminal(kExperiment + csv_option());
    ASSERT_EQ(shown.exit_code, 0) << shown.out;
    EXPECT_NE(shown.out.find("rounds"), std::string::npos) << shown.out;
}

// The radiosity stages report how far they have got, with the time left.
TEST(Progress, RadiosityShowsEachStageWithTheTimeLeft) {
    const CliRun tty =
        run_in_terminal(std::string(FB89_CLI_PATH) + " radiosity " + FB89_SCENES_DIR +
                        "/garish_room.json --patches 1200 --ff exact");
    ASSERT_EQ(tty.exit_code, 0) << tty.out;
    EXPECT_NE(tty.out.find("radiosity: visibility (flux tracing): "), std::string::npos) << tty.out;
    EXPECT_NE(tty.out.find("radiosity: form factors: "), std::string::npos) << tty.out;
    EXPECT_NE(tty.out.find("%, about "), std::string::npos) << tty.out;
    EXPECT_NE(tty.out.find("radiosity: rendering"), std::string::npos) << tty.out;
}

// Fig. 2.4 counts the scenes it has done, its ideal scenes among them.
TEST(Progress, Fig24CountsItsScenes) {
    const CliRun tty = run_in_terminal(std::string(FB89_CLI_PATH) + " experiment fig2.4 " +
                                       FB89_SCENES_DIR + "/A.json" + csv_option());
    ASSERT_EQ(tty.exit_code, 0) << tty.out;
    EXPECT_NE(tty.out.find("fig2.4: 1/22 scenes, about "), std::string::npos) << tty.out;
    EXPECT_NE(tty.out.find("fig2.4: 21/22 scenes"), std::string::npos) << tty.out;
}

// A command that outlives its limit is killed, not waited for.
TEST(Progress, TheTerminalRunnerStopsACommandPastItsLimit) {
    const CliRun slow = run_in_terminal("sleep 30", std::chrono::seconds(1));
    EXPECT_EQ(slow.exit_code, -1);
}

}  // namespace
