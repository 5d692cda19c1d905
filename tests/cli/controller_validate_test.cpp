// `fb89 controller-validate` as a user runs it: the controller's figures beside its sources,
// before and after, as text and CSV; the listing with its cycles; exit codes.
#include <gtest/gtest.h>

#include <string>

#include "tests/cli/cli_runner.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

TEST(ControllerValidate, PrintsEveryFigureWithItsSourceBeforeAndNow) {
    const CliRun r = run_fb89("controller-validate --check");
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    for (const char* text :
         {"tms34010-50mhz now", "a pixel of LINE at 8 bpp (states)", "[DS] SPVS002C p. 34",
          "before 2 (missed), now 4  ok", "before 8 (missed), now 6.25  ok",
          "the tiling commands' executive: its length", "BYTE, September 1988",
          "C_cmd: the loop's fetch"})
        EXPECT_NE(r.out.find(text), std::string::npos) << text << " not in\n" << r.out;
    EXPECT_EQ(r.out.find("MISSED"), std::string::npos) << r.out;
}

TEST(ControllerValidate, WritesCsvAndPrintsTheListingWithItsCycles) {
    const std::string csv = (test_dir() / "checks.csv").string();
    CliRun r = run_fb89("controller-validate --listing --csv " + csv);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string text = slurp(csv);
    EXPECT_EQ(text.rfind("figure,unit,source,stated,before,after,checked,pass,before_pass\n", 0),
              0u)
        << text;
    EXPECT_NE(text.find("a pixel of LINE at 8 bpp,states,"), std::string::npos) << text;
    EXPECT_NE(text.find(",2,4,yes,yes,no\n"), std::string::npos) << text;
    EXPECT_NE(r.out.find("   2            JUMP   A5              ; dispatch"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("; COMMON            18 cycles"), std::string::npos) << r.out;
    // to standard output, only the CSV
    r = run_fb89("controller-validate --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out.rfind("figure,unit,", 0), 0u) << r.out;
}

TEST(ControllerValidate, AProfileWithoutAListingIsAUsageError) {
    CliRun r = run_fb89("controller-validate --profile tms34010-mame");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("gives its cycle figures itself"), std::string::npos) << r.err;
    r = run_fb89("controller-validate --profile tms9918");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("tms9918"), std::string::npos) << r.err;
}

}  // namespace
