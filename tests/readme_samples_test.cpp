// The README samples' matcher (tests/readme_samples.h): it lets the numbers a run measures go,
// and catches a changed word, column, line, count, cycle count, modelled time or checksum.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/readme_samples.h"

namespace {

using fb89::testing::matches;

// The figures' matcher: a changed count, cycle count or modelled time is a difference; a
// measured time (wall, CPU, send times and what follows from them) is not.
TEST(ReadmeTour, TheFiguresMatcherSeesAChangedCountAndNotAMeasuredTime) {
    const std::vector<std::string> sample = {
        " frame  size  commands  cycles  modelled ms  checksum",
        "     0  1024x780  7,667  1,034,743  172.357  2a4e14adb9f420df",
        "...",
        "  hidden-surface*       0.770 ms      0.769 ms",
        "      1 @155       MARKER \"zbuffer\"  sent 808.328 us",
        "benchmark: 7,667 commands, 1,333,043 pixels in 0.0013 s wall: 5.942 M commands/s"};
    const std::string head = " frame  size  commands  cycles  modelled ms  checksum\n";
    const std::string row = "     0  1024x780  7,667  1,034,743  172.357  2a4e14adb9f420df\n";
    const std::string measured =
        "  hidden-surface*       0.912 ms      0.901 ms\n"
        "      1 @155       MARKER \"zbuffer\"  sent 1605.058 us\n"
        "benchmark: 7,667 commands, 1,333,043 pixels in 0.0127 s wall: 0.602 M commands/s\n";
    EXPECT_EQ(matches(sample, head + row + "x\n" + measured, true), "");
    // the cycles and the modelled time of another profile
    EXPECT_NE(
        matches(sample,
                head + "     0  1024x780  7,667  1,729,028  180.222  2a4e14adb9f420df\n" + measured,
                true),
        "");
    // a count, a checksum, a byte offset
    EXPECT_NE(
        matches(sample,
                head + "     0  1024x780  7,668  1,034,743  172.357  2a4e14adb9f420df\n" + measured,
                true),
        "");
    EXPECT_NE(
        matches(sample,
                head + "     0  1024x780  7,667  1,034,743  172.357  2a4e14adb9f420de\n" + measured,
                true),
        "");
    EXPECT_NE(
        matches(sample,
                head + row + "      1 @156       MARKER \"zbuffer\"  sent 1.0 us\n" +
                    "benchmark: 7,667 commands, 1,333,043 pixels in 1 s wall: 1 M commands/s\n",
                true),
        "");
    // shape alone lets the figures go
    EXPECT_EQ(
        matches(sample, head + "     0  1024x780  7,668  1,729,028  180.222  2a4e14adb9f420df\n" +
                            measured),
        "");
}

// The matcher itself: it accepts other numbers, and catches a changed word, a missing
// column, a missing line and an extra one.
TEST(ReadmeTour, TheShapeMatcherSeesWhatChanged) {
    const std::vector<std::string> sample = {"frame  size  commands", "    0  1024x780  7,667",
                                             "...", "total 12.5 ms"};
    EXPECT_EQ(matches(sample, "frame  size  commands\n 0   640x480  99\nx\ny\ntotal 3.25 ms\n"),
              "");
    EXPECT_NE(matches(sample, "frame  size  cmds\n 0   640x480  99\ntotal 3.25 ms\n"), "");
    EXPECT_NE(matches(sample, "frame  size  commands\n 0   640x480\ntotal 3.25 ms\n"), "");
    EXPECT_NE(matches(sample, "frame  size  commands\n 0   640x480  99\n"), "");
    EXPECT_NE(matches(sample, "frame  size  commands\n 0  1x1  9\ntotal 1 ms\nmore\n"), "");
}

}  // namespace
