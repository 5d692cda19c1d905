// `fb89 replay STREAM --gsp` as a user runs it: every bundled scene's stream for every
// method through the emulated GSP, its frame equal to the controller's and its cycles equal
// to the model's but for what the model leaves out (the "unexplained" column all +0); the
// PNG the same as without --gsp; a command traced instruction by instruction; a user's
// listing in place of the built-in one, and its errors named by file and line.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <sstream>
#include <string>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::put;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

std::filesystem::path source_dir() {
    return std::filesystem::path(FB89_SCENES_DIR).parent_path();
}

const char* const kMethods[] = {"zbuffer", "scanline", "warnock", "hybrid", "raytrace",
                                "beam",    "zspans",   "faces",   "hzb",    "mlrta"};

// The opcode rows of replay --gsp's table whose last column (unexplained) is not +0.
std::string unexplained_rows(const std::string& out) {
    std::istringstream lines(out);
    std::string line, bad;
    while (std::getline(lines, line)) {
        if (line.empty() || !std::isupper(static_cast<unsigned char>(line[0]))) continue;
        if (line.rfind("FRAME_", 0) != 0 && line.rfind("FILL_", 0) != 0 &&
            line.rfind("DRAW_", 0) != 0 && line.rfind("DEPTH_", 0) != 0 &&
            line.rfind("FACE ", 0) != 0)
            continue;
        if (line.size() < 3 || line.substr(line.size() - 3) != " +0") bad += line + "\n";
    }
    return bad;
}

TEST(ReplayGsp, EveryBundledSceneAndMethodDrawsTheControllersFrameToTheCycle) {
    const std::filesystem::path scenes = FB89_SCENES_DIR;
    int runs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
        if (entry.path().extension() != ".json") continue;
        const std::string scene = entry.path().stem().string();
        // the scenes of more colours than 8 bits hold go through the 16-bit profile
        const bool many = scene == "D" || scene == "E" || scene == "F";
        const std::string profile =
            many ? " --profile " + (source_dir() / "controller_sim" / "profiles" / "variants" /
                                    "tms34010-50mhz-16bpp.json")
                                       .string()
                 : "";
        for (const char* method : kMethods) {
            const std::string stream = (test_dir() / "s.fb89").string();
            const CliRun render = run_fb89("render " + entry.path().string() + " --method " +
                                           method + " --size 96x72 --stream " + stream + " -q");
            ASSERT_EQ(render.exit_code, 0) << scene << " " << method << render.err;
            const CliRun r = run_fb89("replay " + stream + " --gsp" + profile);
            EXPECT_EQ(r.exit_code, 0) << scene << " " << method << "\n" << r.out << r.err;
            EXPECT_NE(r.out.find("every one equal pixel for pixel"), std::string::npos)
                << scene << " " << method << "\n"
                << r.out;
            EXPECT_EQ(unexplained_rows(r.out), "") << scene << " " << method << "\n" << r.out;
            ++runs;
        }
    }
    EXPECT_EQ(runs, 16 * 10);
}

TEST(ReplayGsp, WritesThePngTheModelWritesAndTracesACommand) {
    const std::string stream = (test_dir() / "demo.fb89").string();
    ASSERT_EQ(run_fb89("render " + std::string(FB89_SCENES_DIR) +
                       "/demo.json --method faces --size 160x120 --stream " + stream + " -q")
                  .exit_code,
              0);
    const std::string gsp_png = (test_dir() / "gsp.png").string();
    const std::string model_png = (test_dir() / "model.png").string();
    const CliRun r = run_fb89("replay " + stream + " --gsp --png " + gsp_png + " --gsp-trace 3");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    ASSERT_EQ(run_fb89("replay " + stream + " -q --png " + model_png).exit_code, 0);
    EXPECT_EQ(slurp(gsp_png), slurp(model_png));
    EXPECT_NE(r.out.find("time: executed "), std::string::npos) << r.out;
    // the trace: command 3 (a FACE) from the loop's first instruction to its return
    const std::size_t at = r.out.find("command 3, executed instruction by instruction");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_NE(r.out.find("next:     CMP    A1,A0", at), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("DIVS   A11,A6", at), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("JRUC   next", at), std::string::npos) << r.out;
}

TEST(ReplayGsp, AUsersListingRunsInPlaceAndItsErrorsNameTheLine) {
    const std::string stream = (test_dir() / "s.fb89").string();
    ASSERT_EQ(run_fb89("render " + std::string(FB89_SCENES_DIR) +
                       "/A.json --method zbuffer --size 64x48 --stream " + stream + " -q")
                  .exit_code,
              0);
    // the built-in listing, copied, runs as the built-in one does
    const std::string mine = (test_dir() / "mine.asm").string();
    put(mine, slurp(source_dir() / "controller_sim" / "gsp" / "tms34010.asm"));
    const CliRun same = run_fb89("replay " + stream + " --gsp --listing " + mine);
    EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
    EXPECT_NE(same.out.find("every one equal pixel for pixel"), std::string::npos) << same.out;
    // an unknown mnemonic: the file and line, exit 2
    put(mine, "next:     CMP    A1,A0\n          FROB   A1\n");
    const CliRun bad = run_fb89("replay " + stream + " --gsp --listing " + mine);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("mine.asm line 2"), std::string::npos) << bad.err;
    // a handler that never returns: the instruction budget, the line and the command
    std::string looping = slurp(source_dir() / "controller_sim" / "gsp" / "tms34010.asm");
    looping.insert(looping.find("span_fill:\n") + 11, "spin:     JRUC   spin\n");
    put(mine, looping);
    const CliRun spin = run_fb89("replay " + stream + " --gsp --listing " + mine);
    EXPECT_EQ(spin.exit_code, 2);
    EXPECT_NE(spin.err.find("a loop that does not end"), std::string::npos) << spin.err;
    EXPECT_NE(spin.err.find("JRUC   spin"), std::string::npos) << spin.err;
    // --listing without --gsp, and a profile without a listing
    EXPECT_EQ(run_fb89("replay " + stream + " --listing " + mine).exit_code, 2);
    const CliRun ideal = run_fb89("replay " + stream + " --gsp --profile ideal");
    EXPECT_EQ(ideal.exit_code, 2);
    EXPECT_NE(ideal.err.find("has no listing"), std::string::npos) << ideal.err;
}

}  // namespace
