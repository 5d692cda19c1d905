// "did you mean" for the names a user gives: every command taking a scene, a method, a
// controller profile or a host answers a near miss with exit 2, one line naming the option
// and the nearest known name, and writes nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace {

struct HintCase {
    std::string args;  // after fb89
    std::string says;  // part of the one line of error
};

TEST(NameHints, EveryCommandAnswersANearMissWithTheNearestName) {
    const std::string out = (fb89::testing::test_dir() / "out.png").string();
    const std::vector<HintCase> cases = {
        {"render A --method zbufer",
         "render: --method: unknown method 'zbufer'; did you mean "
         "'zbuffer'?"},
        {"experiment split A --methods scanlin",
         "--methods: unknown method 'scanlin'; did you "
         "mean 'scanline'?"},
        {"calibrate --method beem", "--method: unknown method 'beem'; did you mean 'beam'?"},
        {"render A --profile tms34010-50mz",
         "--profile: unknown profile 'tms34010-50mz'; did "
         "you mean 'tms34010-50mhz'?"},
        {"replay in.fb89 --profile idael", "did you mean 'ideal'?"},
        {"view in.fb89 --profile idael", "did you mean 'ideal'?"},
        {"info in.fb89 --profile idael", "did you mean 'ideal'?"},
        {"controller --listen sock --profile idael", "did you mean 'ideal'?"},
        {"radiosity garish_room --profile idael", "did you mean 'ideal'?"},
        {"sweep threshold A --profile idael", "did you mean 'ideal'?"},
        {"compare A --profile idael", "did you mean 'ideal'?"},
        {"experiment fig2.1 --profile idael", "did you mean 'ideal'?"},
        {"render A --host sun3-6", "--host: unknown host 'sun3-6'; did you mean 'sun3-60'?"},
        {"compare A --host sparcstation1", "did you mean 'sparcstation-1'?"},
        {"experiment split A --host pc-386-52", "did you mean 'pc-386-25'?"},
        {"sweep threshold A --host natve", "did you mean 'native'?"},
        {"calibrate --host sun4260", "did you mean 'sun4-260'?"},
        {"host-validate --profile sun4-26",
         "unknown host profile 'sun4-26'; did you mean "
         "'sun4-260'?"},
        {"render demoo --png " + out,
         "demoo: cannot open the scene file: no bundled scene of that name, nor a file in the "
         "current folder; did you mean 'demo'?"},
        {"compare demoo", "did you mean 'demo'?"},
        {"radiosity garish_rom", "did you mean 'garish_room'?"},
        {"sweep threshold A fF", "did you mean 'F'?"},
        {"calibrate cornel_box --dry-run", "did you mean 'cornell_box'?"},
        {"experiment fig2.1 cornell_mirorr", "did you mean 'cornell_mirror'?"},
        // a name cut short: the names it opens
        {"render A --profile tms34020", "did you mean 'tms34020-40mhz'?"},
        {"render A --host sparc", "did you mean 'sparcstation-1' or 'sparcstation-2'?"},
        // the options with a fixed set of choices
        {"radiosity garish_room --ff hirarchical",
         "radiosity: --ff: unknown choice 'hirarchical'; did you mean 'hierarchical'?"},
        {"radiosity garish_room --solver gaus-seidel", "did you mean 'gauss-seidel'?"},
        {"render A --accel gird", "--accel: unknown choice 'gird'; did you mean 'grid'?"},
        {"render A --depth-estimate windw", "did you mean 'window'?"},
        {"experiment split A --accel bhv", "did you mean 'bvh'?"},
        {"sweep thresold A", "unknown choice 'thresold'; did you mean 'threshold'?"},
        {"sweep threshold A --window-test centers", "did you mean 'centres'?"},
        {"experiment fig2.2", "unknown experiment 'fig2.2'; did you mean 'fig2.1'?"},
        {"list scene", "did you mean 'scenes'?"},
        {"rendr A", "unknown command 'rendr'; did you mean 'render'?"},
        {"dump in.fb89 --calls /spna", "unknown filter '/spna'"},
        {"dump in.fb89 --calls /spna", "did you mean '/span'?"},
        {"render A --method raytrace --isa baselin", "did you mean 'baseline'?"},
        {"host-run --isa spar --results r x", "did you mean 'sparc'?"},
        {"render A --metod zbuffer", "unknown option '--metod'; did you mean '--method'?"},
    };
    for (const HintCase& c : cases) {
        const fb89::testing::CliRun r = fb89::testing::run_fb89(c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\n" << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(out));
}

// CLI11's own problems with a value, said in fb89's words: the option, what is wrong and
// what to give.
TEST(NameHints, AValueCLI11RefusesIsSaidInTheProjectsWords) {
    const std::vector<HintCase> cases = {
        {"radiosity garish_room --patches 0", "radiosity: --patches: 0 is not in [1, 8192]"},
        {"view in.fb89 --scale 9", "view: --scale: 9 is not in [0.125, 8]"},
        {"render A --method zbuffer --method hybrid",
         "render: --method: given 2 times; give it once"},
        {"render A --png", "render: --png: needs a value after it"},
        {"radiosity garish_room --ff", "--ff: needs one of flux, hybrid"},
        {"model --json --csv out.csv", "exclude each other: give one of them"},
    };
    for (const HintCase& c : cases) {
        const fb89::testing::CliRun r = fb89::testing::run_fb89(c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
        for (const char* raw :
             {"Value ", "not in range", "At Most", " required but ", " not in {", " excludes "})
            EXPECT_EQ(r.err.find(raw), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\n" << r.err;
    }
}

}  // namespace
