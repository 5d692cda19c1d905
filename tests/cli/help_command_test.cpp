// fb89 help and the help texts: `fb89 help CMD` is `fb89 CMD --help`, alone `fb89 --help`;
// an unknown command is a usage error with the nearest; and every name a registry holds
// (methods, controller profiles, hosts, bundled scenes) is in the help of each option that
// takes it, in every command offering that option, and at the foot of `fb89 --help`.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "tests/cli/help_text.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::names;
using fb89::testing::run_fb89;

TEST(HelpCommand, HelpOfACommandIsTheCommandsOwnHelp) {
    const std::vector<std::string> commands = fb89::testing::listed_commands();
    ASSERT_GE(commands.size(), 18u);
    for (const std::string& command : commands) {
        const CliRun help = run_fb89("help " + command);
        const CliRun own = run_fb89(command + " --help");
        EXPECT_EQ(help.exit_code, 0) << command << ": " << help.err;
        EXPECT_EQ(help.out, own.out) << command;
        EXPECT_NE(help.out.find("Usage: "), std::string::npos) << command;
    }
}

TEST(HelpCommand, HelpAloneIsFb89Help) {
    const CliRun help = run_fb89("help");
    EXPECT_EQ(help.exit_code, 0) << help.err;
    EXPECT_EQ(help.out, run_fb89("--help").out);
    EXPECT_NE(help.out.find("Subcommands:"), std::string::npos) << help.out;
}

TEST(HelpCommand, AnUnknownCommandIsAUsageErrorNamingTheNearest) {
    const CliRun typo = run_fb89("help rendr");
    EXPECT_EQ(typo.exit_code, 2);
    EXPECT_TRUE(typo.out.empty()) << typo.out;
    EXPECT_EQ(typo.err,
              "fb89: usage: help: unknown command 'rendr'; did you mean 'render'? "
              "(fb89 --help lists them)\n");
    const CliRun far = run_fb89("help frobnicate");
    EXPECT_EQ(far.exit_code, 2);
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
    EXPECT_NE(far.err.find("unknown command 'frobnicate'"), std::string::npos) << far.err;
    EXPECT_EQ(run_fb89("help render model").exit_code, 2);
}

TEST(HelpCommand, EveryRegisteredNameIsInTheHelpOfEachOptionTakingIt) {
    std::set<std::string> checked;
    for (const std::string& command : fb89::testing::listed_commands()) {
        const auto paragraphs =
            fb89::testing::option_paragraphs(run_fb89(command + " --help").out, false);
        checked.merge(fb89::testing::expect_every_name_in(command, paragraphs,
                                                          "fb89 " + command + " --help"));
    }
    // the commands that take these names offer them (a renamed option would skip its check)
    for (const char* expected : {"render --method",      "render --host",
                                 "render --profile",     "render scene",
                                 "experiment --methods", "experiment --host",
                                 "experiment --profile", "experiment scenes",
                                 "sweep --host",         "sweep --profile",
                                 "sweep scenes",         "compare --host",
                                 "compare --profile",    "compare scene",
                                 "calibrate --host",     "calibrate --method",
                                 "calibrate scenes",     "replay --profile",
                                 "view --profile",       "controller --profile",
                                 "radiosity --profile",  "radiosity scene",
                                 "info --profile",       "host-validate --profile",
                                 "host-run scene",       "controller-validate --profile"})
        EXPECT_EQ(checked.count(expected), 1u) << expected;
}

TEST(HelpCommand, Fb89HelpNamesEveryMethodHostProfileAndScene) {
    const std::string help = run_fb89("--help").out;
    const std::string foot = help.substr(help.find("\n\n", help.find("Subcommands:")));
    for (const auto& kind : {fb89::testing::registered_methods(), fb89::testing::registered_hosts(),
                             fb89::testing::registered_profiles(), fb89::testing::bundled_scenes()})
        for (const std::string& name : kind)
            EXPECT_TRUE(names(foot, name)) << name << "\n" << foot;
    EXPECT_NE(foot.find("fb89 help COMMAND"), std::string::npos) << foot;
}

}  // namespace
