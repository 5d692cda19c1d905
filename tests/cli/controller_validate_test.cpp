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
          "before 2 (missed), now 4  ok", "before 8 (missed), now 6.29375  ok",
          "a FILL_RECT or a DRAW_SPAN: its length", "a FACE's row loop: its cache segments",
          "BYTE, September 1988", "C_cmd: the loop's fetch",
          // what TI's own routines imply, and TI's simulator on the same FILLs and LINE
          "the frame's clear by FILL XY, as TI's clear_screen (ms)",
          "[TI] TDB10/OEMPRIMS/CLEARSCR.ASM",
          "the frame's clear by serial-register transfers (390 VRAM rows), as TI's clear_page",
          "the whole VRAM (512 rows) as TI's clear_frame_buffer", "TIGA's call around a primitive",
          "now 145  ok", "FILL XY 100 x 1 from x = 0, 8 bpp (a 100-pixel span) (states)",
          "[SIM] TI's GSPSIM 1.04, tests/ti-gsp/fills.asm m1-m2 -- 107 (within 10%)", "now 109  ok",
          "a 100-pixel DRAW_SPAN by FILL XY (TI's draw_line)",
          "TMS34020 : TMS34010, a 100x100 FILL_RECT",
          "TMS34020 : TMS34010, a 100-pixel span by LINE",
          "[SIM] TI's GSPSIM 1.04, tests/ti-gsp/fills.asm m15-m16 -- 6",
          // the listing executed beside the model, kind by kind, nothing left unexplained
          "The listing executed (fb89 replay --gsp)", "DRAW_SPAN", "FACE  ", "+0  ok"})
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
    // each line with its cycles, its address and words, as TI's assembler writes them
    EXPECT_NE(r.out.find("   2  000000D0 0165                      JUMP   A5              ; "
                         "dispatch"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("; COMMON            21 cycles"), std::string::npos) << r.out;
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
