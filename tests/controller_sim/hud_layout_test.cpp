// The viewer's text layout without a window: status lines wrapped so that no row is longer
// than the window has room for and no character is lost, every row inside the window and
// off the image, the key panel inside the window and absent until asked for, at the
// viewer's scales 0.5, 1 and 2.
#include "controller_sim/hud_layout.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "controller_sim/bitmap_font.h"

namespace fb89::controller {
namespace {

// The text without its spaces: what wrapping must keep, character for character.
std::string ink_of(const std::string& text) {
    std::string out;
    for (char c : text)
        if (c != ' ') out += c;
    return out;
}

std::string ink_of(const std::vector<TextRow>& rows) {
    std::string out;
    for (const TextRow& r : rows)
        out += ink_of(r.text);
    return out;
}

// Status lines as long as the viewer's: its pipeline line and a damaged stream's error,
// which names a long path.
Hud viewer_hud() {
    Hud hud;
    hud.status = {
        "frame 0 [1/1]  cmd 1234  t 12.345 ms in frame, 0.012 s  1x  PLAYING  overlay",
        "pipeline: send times modelled on native, buffer 16 KiB  host stalled 0.123 ms  "
        "controller idle 4.567 ms  buffer high water 16384 bytes",
        "(12,34) rgb(255,128,0) by #77 FILL_RECT x=0 y=0 w=640 h=480 rgb(255,128,0)",
        "stream error: /tmp/fb89_test.12345/ViewText.DamagedStream/a_rather_long_folder_name/"
        "s.fb89: truncated: the stream ends inside command 1234 at byte 56789  h: keys",
    };
    hud.help = {"fb89 view - keys", "space    play / pause", "h        hide / show these keys",
                "         green FILL_RECT  red DRAW_SPAN"};
    return hud;
}

TEST(WrapLine, ALineThatFitsIsOneRowAsItIs) {
    const std::string line = "frame 3  cmd 12";
    EXPECT_EQ(wrap_line(line, 40), std::vector<std::string>{line});
}

TEST(WrapLine, BreaksBetweenFieldsBeforeBreakingInsideOne) {
    EXPECT_EQ(wrap_line("host stalled 1 ms  idle 2 ms  water 3", 20),
              (std::vector<std::string>{"host stalled 1 ms", "  idle 2 ms  water 3"}));
}

TEST(WrapLine, AWordLongerThanARowIsSplitAfterASlashIfItHasOne) {
    const std::vector<std::string> rows = wrap_line("error: /a/very/long/path/name.fb89 x", 12);
    EXPECT_EQ(rows, (std::vector<std::string>{"error:", "  /a/very/", "  long/path/", "  name.fb89",
                                              "  x"}));
    EXPECT_EQ(wrap_line("0123456789abcdefghij", 8),
              (std::vector<std::string>{"01234567", "  89abcd", "  efghij"}));
}

TEST(WrapLine, NoRowIsLongerThanTheColumnsAndEveryCharacterIsKept) {
    for (const std::string& line : viewer_hud().status)
        for (int columns = 8; columns <= 140; ++columns) {
            std::string kept;
            for (const std::string& row : wrap_line(line, columns)) {
                EXPECT_LE(static_cast<int>(row.size()), columns) << row;
                kept += ink_of(row);
            }
            EXPECT_EQ(kept, ink_of(line)) << "at " << columns << " columns";
        }
}

// A 480x360 frame at the viewer's scales: 240, 480 and 960 pixels wide.
class LayoutAtScale : public ::testing::TestWithParam<double> {};

TEST_P(LayoutAtScale, EveryStatusRowIsInsideTheWindowUnderTheImageAndKeepsItsText) {
    const int w = static_cast<int>(480 * GetParam()), h = static_cast<int>(360 * GetParam());
    const Hud hud = viewer_hud();
    const HudLayout l = layout_hud(w, h, hud);
    const TextRect window{0, 0, l.window_width, l.window_height};
    EXPECT_TRUE(window.contains(l.image));
    EXPECT_TRUE(window.contains(l.bar));
    ASSERT_GT(l.status.size(), hud.status.size()) << "the long lines wrap";
    for (const TextRow& r : l.status) {
        EXPECT_TRUE(l.bar.contains(r.box)) << r.text;
        EXPECT_LE(r.box.x + r.box.width, l.window_width - kTextPad) << r.text;
        EXPECT_FALSE(r.box.overlaps(l.image)) << r.text;
    }
    std::string all;
    for (const std::string& line : hud.status)
        all += ink_of(line);
    EXPECT_EQ(ink_of(l.status), all);
    EXPECT_TRUE(l.panel_rows.empty()) << "the key panel is not shown unless asked for";
}

TEST_P(LayoutAtScale, TheKeyPanelShownIsInsideTheWindowAndDoesNotResizeIt) {
    const int w = static_cast<int>(480 * GetParam()), h = static_cast<int>(360 * GetParam());
    Hud hud = viewer_hud();
    const HudLayout hidden = layout_hud(w, h, hud);
    hud.help_shown = true;
    const HudLayout shown = layout_hud(w, h, hud);
    EXPECT_EQ(shown.window_width, hidden.window_width);
    EXPECT_EQ(shown.window_height, hidden.window_height);
    const TextRect window{0, 0, shown.window_width, shown.window_height};
    EXPECT_TRUE(window.contains(shown.panel));
    EXPECT_FALSE(shown.panel.overlaps(shown.bar));
    std::string help;
    for (const std::string& line : hud.help)
        help += ink_of(line);
    EXPECT_EQ(ink_of(shown.panel_rows), help);
    for (const TextRow& r : shown.panel_rows)
        EXPECT_TRUE(shown.panel.contains(r.box)) << r.text;
}

INSTANTIATE_TEST_SUITE_P(Scales, LayoutAtScale, ::testing::Values(0.5, 1.0, 2.0));

TEST(Layout, TextIsTwiceTheSizeInAWindowAtLeast960Wide) {
    EXPECT_EQ(layout_hud(959, 100, Hud{}).text_scale, 1);
    EXPECT_EQ(layout_hud(960, 100, Hud{}).text_scale, 2);
    EXPECT_EQ(layout_hud(10, 10, Hud{}).window_width, kMinWindowWidth);
}

// A frame far smaller than the key panel: the body grows so that the panel fits above the bar.
TEST(Layout, AFrameSmallerThanTheKeyPanelLeavesRoomForIt) {
    Hud hud = viewer_hud();
    hud.help_shown = true;
    const HudLayout l = layout_hud(32, 24, hud);
    EXPECT_GT(l.bar.y, l.image.height);
    EXPECT_LE(l.panel.y + l.panel.height, l.bar.y);
}

TEST(Layout, TheBarKeepsTheRowsItIsAskedToKeep) {
    Hud hud;
    hud.status = {"one line"};
    const HudLayout one = layout_hud(640, 480, hud);
    const HudLayout kept = layout_hud(640, 480, hud, 3);
    EXPECT_EQ(kept.bar.height - one.bar.height, 2 * kCellHeight);
    EXPECT_EQ(kept.window_height - one.window_height, 2 * kCellHeight);
}

}  // namespace
}  // namespace fb89::controller
