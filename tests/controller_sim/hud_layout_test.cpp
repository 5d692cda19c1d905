// The viewer's text layout without a window: status lines wrapped so that no row is longer
// than the window has room for and no character is lost, every row inside the window and
// off the image, the key panel inside the window and absent until asked for, at the
// viewer's scales 0.5, 1 and 2; and the scale at which a window fits the screen.
#include "controller_sim/hud_layout.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
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

// --- fitting the screen ----------------------------------------------------------------

// The window's size at `scale` for a width x height frame under `hud`.
std::pair<int, int> window_at(unsigned width, unsigned height, const Hud& hud, double scale) {
    const HudLayout l = layout_hud(scaled_size(width, scale), scaled_size(height, scale), hud, 0);
    return {l.window_width, l.window_height};
}

TEST(FitScale, AWindowThatFitsKeepsTheScaleAsked) {
    const Hud hud = viewer_hud();
    EXPECT_EQ(fit_scale(480, 360, hud, 0, 2, 1280, 1024), 2);
    EXPECT_EQ(fit_scale(1024, 780, hud, 0, 1, 1280, 1024), 1);
    EXPECT_EQ(fit_scale(1024, 780, hud, 0, 0.75, 1280, 1024), 0.75);
}

TEST(FitScale, ATooLargeWindowTakesTheLargestWholeScaleBelowThatFits) {
    const Hud hud = viewer_hud();
    ASSERT_GT(window_at(1024, 780, hud, 2).first, 1280);
    EXPECT_EQ(fit_scale(1024, 780, hud, 0, 2, 1280, 1024), 1);
    EXPECT_EQ(fit_scale(1024, 780, hud, 0, 8, 1280, 1024), 1);
    EXPECT_EQ(fit_scale(400, 300, hud, 0, 8, 1280, 1024), 2);    // 1600 wide at 4, 1200 at 3
    EXPECT_EQ(fit_scale(400, 300, hud, 0, 3.5, 1300, 2000), 3);  // 1400 wide at 3.5
}

TEST(FitScale, BelowScaleOneItHalvesUntilTheWindowFits) {
    const Hud hud = viewer_hud();
    EXPECT_EQ(fit_scale(2048, 1560, hud, 0, 1, 1280, 1024), 0.5);
    EXPECT_EQ(fit_scale(2048, 1560, hud, 0, 2, 1280, 1024), 0.5);
    EXPECT_EQ(fit_scale(2048, 1560, hud, 0, 0.75, 1280, 1024), 0.5);
    EXPECT_EQ(fit_scale(4096, 3120, hud, 0, 1, 1280, 1024), 0.25);
    EXPECT_EQ(fit_scale(4096, 4096, hud, 0, 1, 1280, 1024), 0.125);  // 1024x1024 and a bar at 1/4
    EXPECT_EQ(fit_scale(8192, 8192, hud, 0, 1, 800, 600), 0.125);    // none fits: the least
}

// Whatever the frame and the screen, the window at the scale chosen fits the screen, the
// status rows kept included, unless no scale can make it fit.
TEST(FitScale, TheWindowAtTheScaleChosenFitsTheScreen) {
    const Hud hud = viewer_hud();
    for (unsigned w : {64u, 320u, 1024u, 2048u, 4096u})
        for (unsigned h : {48u, 240u, 780u, 1560u, 4096u})
            for (double asked : {0.125, 0.5, 1.0, 2.0, 8.0})
                for (auto [sw, sh] : {std::pair{1280, 1024}, std::pair{1920, 1080}}) {
                    const double s = fit_scale(w, h, hud, 6, asked, sw, sh);
                    EXPECT_LE(s, asked);
                    const HudLayout l = layout_hud(scaled_size(w, s), scaled_size(h, s), hud, 6);
                    if (s > 0.125 || (l.window_width <= sw && l.window_height <= sh)) {
                        EXPECT_LE(l.window_width, sw) << w << "x" << h << " at " << asked;
                        EXPECT_LE(l.window_height, sh) << w << "x" << h << " at " << asked;
                    }
                }
}

}  // namespace
}  // namespace fb89::controller
