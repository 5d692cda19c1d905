// Discovering fb89: `fb89 list`, -V, unknown commands with the nearest known one, defaults
// that work from any directory, and an installed prefix that runs on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

TEST(ListCommand, NamesEveryMethodProfileHostSceneAndExperiment) {
    CliRun r = run_fb89("list");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* name :
         {"zbuffer",  "scanline",         "warnock",        "hybrid",         "raytrace",
          "beam",     "tms34010-50mhz",   "ideal",          "native",         "sun3-60",
          "sun3-260", "sun4-260",         "sparcstation-1", "sparcstation-2", "CY7C601",
          "\n  A ",   "\n  garish_room ", "fig3.1",         "split",          "radiosity"})
        EXPECT_NE(r.out.find(name), std::string::npos) << name << "\n" << r.out;
    CliRun methods = run_fb89("list methods");
    EXPECT_EQ(methods.out.find("sun3-60"), std::string::npos) << "one kind only";
    EXPECT_EQ(run_fb89("list method").exit_code, 2);
}

// The structure each method says it uses is the one its render counts: a method that walks
// the BVH counts bvh_nodes_visited, one whose beams query the grid counts query_cells, and
// one whose line offers "[--accel grid: ...]" counts cells_visited and no BVH nodes with it
// (the others refuse --accel).
TEST(ListCommand, EachMethodNamesTheAccelerationStructureItUses) {
    const CliRun list = run_fb89("list methods");
    ASSERT_EQ(list.exit_code, 0) << list.err;
    for (const char* method : {"zbuffer", "scanline", "warnock", "hybrid", "raytrace", "beam"}) {
        const auto at = list.out.find(std::string("\n  ") + method + " ");
        ASSERT_NE(at, std::string::npos) << method << "\n" << list.out;
        const std::string whole = list.out.substr(at + 1, list.out.find('\n', at + 1) - at - 1);
        const auto option = whole.find(" [--accel grid:");
        const std::string line = whole.substr(0, option);
        const std::string render =
            std::string("render G --size 96x73 -q --stats - --method ") + method;
        auto counters_of = [](const CliRun& r) {
            return nlohmann::json::parse(r.out).at("host").at("counters");
        };
        auto counted = [](const nlohmann::json& counters, const char* name) {
            return counters.contains(name) && counters.at(name).get<uint64_t>() > 0;
        };
        const CliRun r = run_fb89(render);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const nlohmann::json counters = counters_of(r);
        EXPECT_EQ(line.find("BVH") != std::string::npos, counted(counters, "bvh_nodes_visited"))
            << line;
        EXPECT_EQ(line.find("grid") != std::string::npos, counted(counters, "query_cells")) << line;
        EXPECT_FALSE(counted(counters, "cells_visited")) << line;
        const CliRun grid = run_fb89(render + " --accel grid");
        if (option == std::string::npos) {
            EXPECT_EQ(grid.exit_code, 2) << whole;
            continue;
        }
        ASSERT_EQ(grid.exit_code, 0) << grid.err;
        const nlohmann::json grid_counters = counters_of(grid);
        EXPECT_TRUE(counted(grid_counters, "cells_visited")) << whole;
        EXPECT_FALSE(counted(grid_counters, "bvh_nodes_visited")) << whole;
    }
}

TEST(ListCommand, ScenesAreListedByNameWithWholeSentences) {
    const CliRun r = run_fb89("list scenes");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::istringstream lines(r.out);
    std::string line;
    std::getline(lines, line);  // the heading
    int scenes = 0;
    while (std::getline(lines, line)) {
        ++scenes;
        // "  NAME  description": a name that `render` takes, and a description not cut short
        EXPECT_EQ(line.rfind("  ", 0), 0u) << line;
        EXPECT_EQ(line.find(".json"), std::string::npos) << line;
        EXPECT_NE(line.back(), ',') << line;
        EXPECT_EQ(line.find("(§4, Fig."), std::string::npos) << line;
        EXPECT_EQ(std::count(line.begin(), line.end(), '('),
                  std::count(line.begin(), line.end(), ')'))
            << line;
    }
    EXPECT_GE(scenes, 15);
    const CliRun kind = run_fb89("list methodz");
    EXPECT_EQ(kind.exit_code, 2);
    EXPECT_NE(kind.err.find("unknown kind 'methodz'; did you mean 'methods'?"), std::string::npos)
        << kind.err;
    EXPECT_EQ(std::count(kind.err.begin(), kind.err.end(), '\n'), 1) << kind.err;
}

TEST(ListCommand, NoCommandSaysHowToStart) {
    const CliRun r = run_fb89("");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("fb89 COMMAND [OPTIONS], e.g. `fb89 render demo`"), std::string::npos)
        << r.err;
}

TEST(ListCommand, VersionAndUnknownCommandsSayWhatTheyShould) {
    CliRun v = run_fb89("-V");
    EXPECT_EQ(v.exit_code, 0);
    EXPECT_EQ(v.out.rfind("fb89 ", 0), 0u) << v.out;
    CliRun typo = run_fb89("rendr A");
    EXPECT_EQ(typo.exit_code, 2);
    EXPECT_NE(typo.err.find("unknown command 'rendr'; did you mean 'render'?"), std::string::npos)
        << typo.err;
    CliRun version = run_fb89("version");
    EXPECT_EQ(version.exit_code, 2);
    EXPECT_NE(version.err.find("unknown command 'version'; did you mean '--version'?"),
              std::string::npos)
        << version.err;
    CliRun option = run_fb89("render A --thresold 0.1");
    EXPECT_EQ(option.exit_code, 2);
    EXPECT_NE(option.err.find("render: unknown option '--thresold'; did you mean '--threshold'? "
                              "(fb89 render --help lists them)"),
              std::string::npos)
        << option.err;
    EXPECT_EQ(std::count(option.err.begin(), option.err.end(), '\n'), 1) << "one error, once";
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
    EXPECT_NE(csv.find("\nF,warnock-centres,"), std::string::npos) << csv;
}

TEST(ListCommand, AnInstalledPrefixRunsOnItsOwn) {
    const auto prefix = test_dir() / "prefix";
    std::filesystem::remove_all(prefix);
    const std::string install = "cmake --install " + std::string(FB89_BUILD_DIR) + " --prefix " +
                                prefix.string() + " > " + (test_dir() / "install.log").string();
    ASSERT_EQ(std::system(install.c_str()), 0);
    const std::string fb89 = (prefix / "bin" / "fb89").string();
    ASSERT_TRUE(std::filesystem::exists(fb89));
    EXPECT_TRUE(std::filesystem::exists(prefix / "share/fb89/scenes/A.json"));
    // the man pages, made from the help at build time: fb89(1) and one per command, in
    // UTF-8, each with the exit codes and the environment
    const std::string man = slurp(prefix / "share/man/man1/fb89.1");
    EXPECT_NE(man.find(".TH FB89"), std::string::npos) << man.substr(0, 200);
    EXPECT_NE(man.find("the paper's §5"), std::string::npos) << "UTF-8, not question marks";
    const CliRun help = run_fb89("--help");
    // the commands: from "Subcommands:" to the blank line before the names of methods, hosts ...
    std::string commands = help.out.substr(help.out.find("Subcommands:"));
    commands = commands.substr(0, commands.find("\n\n") + 1);
    int pages = 0;
    for (const char* command :
         {"render", "model", "experiment", "sweep", "compare", "calibrate", "replay", "dump",
          "info", "trim", "diff", "controller", "view", "radiosity", "host-run", "host-validate",
          "controller-validate", "list", "help"}) {
        EXPECT_NE(commands.find(std::string("\n  ") + command + " "), std::string::npos) << command;
        const std::string page =
            slurp(prefix / "share/man/man1" / (std::string("fb89-") + command + ".1"));
        ++pages;
        std::string upper = std::string("FB89-") + command;
        std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
        EXPECT_NE(page.find(".TH " + upper + " "), std::string::npos) << command;
        for (const char* part : {".SH \"EXIT STATUS\"", ".SH ENVIRONMENT", "FB89_DATA_DIR",
                                 "FB89_GUEST_TIME_LIMIT", "FB89_GUEST_MEMORY_LIMIT", ".SH OPTIONS"})
            EXPECT_NE(page.find(part), std::string::npos) << command << ": " << part;
        EXPECT_EQ(page.find("?"
                            "?"),
                  std::string::npos)
            << command;
    }
    // every command fb89 --help lists has its page
    int listed = 0;
    for (size_t at = commands.find("\n  "); at != std::string::npos;
         at = commands.find("\n  ", at + 1))
        ++listed;
    EXPECT_EQ(listed, pages) << commands;
    const std::string render = slurp(prefix / "share/man/man1/fb89-render.1");
    EXPECT_NE(render.find("\\-\\-method"), std::string::npos) << "the command's own options";
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
