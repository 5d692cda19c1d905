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
    EXPECT_NE(seen.find("round 2/4"), std::string::npos) << seen;
    EXPECT_NE(seen.find("s left"), std::string::npos) << seen;
}

TEST(Progress, NothingWhenStderrIsNotATerminalOrWithQuiet) {
    CliRun piped = run_fb89(kExperiment.substr(kExperiment.find("experiment")) + " --csv -");
    ASSERT_EQ(piped.exit_code, 0) << piped.err;
    EXPECT_EQ(piped.err.find("round"), std::string::npos) << piped.err;
    const std::string log = (test_dir() / "quiet.txt").string();
    const std::string cmd =
        "script -qec '" + kExperiment + " -q --csv /dev/null' " + log + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(slurp(log).find("round"), std::string::npos) << slurp(log);
}

}  // namespace
