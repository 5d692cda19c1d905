// Discovering fb89: `fb89 list`, -V, unknown commands with the nearest known one, defaults
// that work from any directory, and an installed prefix that runs on its own.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

TEST(ListCommand, NamesEveryMethodProfileHostSceneAndExperiment) {
    CliRun r = run_fb89("list");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name : {"zbuffer", "scanline", "warnock", "hybrid", "raytrace", "beam",
                             "tms34010-50mhz", "ideal", "native", "sun3-60", "sun3-260", "A.json",
                             "garish_room.json", "fig3.1", "split", "radiosity"})
        EXPECT_NE(r.out.find(name), std::string::npos) << name << "\n" << r.out;
    CliRun methods = run_fb89("list methods");
    EXPECT_EQ(methods.out.find("sun3-60"), std::string::npos) << "one kind only";
    EXPECT_EQ(run_fb89("list method").exit_code, 2);
}

TEST(ListCommand, VersionAndUnknownCommandsSayWhatTheyShould) {
    CliRun v = run_fb89("-V");
    EXPECT_EQ(v.exit_code, 0);
    EXPECT_EQ(v.out.rfind("fb89 ", 0), 0u) << v.out;
    CliRun typo = run_fb89("rendr scenes/A.json");
    EXPECT_EQ(typo.exit_code, 2);
    EXPECT_NE(typo.err.find("unknown command 'rendr'; did you mean 'render'?"), std::string::npos)
        << typo.err;
    CliRun version = run_fb89("version");
    EXPECT_EQ(version.exit_code, 2);
    EXPECT_NE(version.err.find("unknown command 'version'; did you mean '--version'?"),
              std::string::npos)
        << version.err;
    CliRun option = run_fb89("render scenes/A.json --thresold 0.1");
    EXPECT_EQ(option.exit_code, 2);
    EXPECT_NE(option.err.find("--thresold: did you mean '--threshold'?"), std::string::npos)
        << option.err;
    CliRun help = run_fb89("render --help");
    for (const char* named : {"zbuffer, scanline", "tms34010-50mhz", "sun3-60"})
        EXPECT_NE(help.out.find(named), std::string::npos) << named << "\n" << help.out;
    CliRun far = run_fb89("frobnicate");
    EXPECT_EQ(far.exit_code, 2);
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST(ListCommand, DefaultScenesWorkFromAnyDirectory) {
    const auto dir = test_dir();
    CliRun r = run_fb89("experiment fig2.1 --repeat 1 --size 64x48 -q --csv out.csv",
                        "cd " + dir.string() + " && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string csv = slurp(dir / "out.csv");
    EXPECT_NE(csv.find("F.json,warnock-centres"), std::string::npos) << csv;
}

TEST(ListCommand, AnInstalledPrefixRunsOnItsOwn) {
    const auto prefix = test_dir() / "prefix";
    std::filesystem::remove_all(prefix);
    const std::string install = "cmake --install " + std::string(FB89_BUILD_DIR) + " --prefix " +
                                prefix.string() + " >/dev/null";
    ASSERT_EQ(std::system(install.c_str()), 0);
    const std::string fb89 = (prefix / "bin" / "fb89").string();
    ASSERT_TRUE(std::filesystem::exists(fb89));
    EXPECT_TRUE(std::filesystem::exists(prefix / "share/fb89/scenes/A.json"));
    // the man page, made from the help at build time
    const std::string man = slurp(prefix / "share/man/man1/fb89.1");
    EXPECT_NE(man.find(".TH FB89"), std::string::npos) << man.substr(0, 200);
    EXPECT_NE(man.find("render"), std::string::npos);
    const std::string out = (test_dir() / "installed.txt").string();
    // from another directory, the installed binary lists its own scenes and runs a default
    const std::string cmd = "cd / && " + fb89 + " list scenes > " + out + " && " + fb89 +
                            " experiment fig2.1 --repeat 1 --size 32x24 -q --csv " +
                            (test_dir() / "fig.csv").string();
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_NE(slurp(out).find((prefix / "share/fb89/scenes").string()), std::string::npos)
        << slurp(out);
}

}  // namespace
