// fb89 view's text as a person sees it: under Xvfb, the whole window saved at the end of
// the stream (--window-screenshot) and its text read back from the pixels in the viewer's
// font. At scales 0.5, 1 and 2 every status field the README promises is there whole (the
// pipeline line's controller idle and buffer high water, a damaged stream's error line),
// inside the window and off the image; the key panel covers nothing until asked for, and
// then fits the window.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "cli_runner.h"
#include "controller_sim/hud_layout.h"
#include "controller_sim/png_io.h"
#include "tests/cli/bitmap_text.h"

namespace fb89::testing {
namespace {

namespace fs = std::filesystem;

constexpr protocol::Rgb kStatusInk{230, 230, 230}, kPanelInk{255, 230, 140};

// The viewer under Xvfb, with SDL told to use it.
std::string under_plain_xvfb() {
    return xvfb_run() + "env SDL_VIDEODRIVER=x11 ";
}

// Renders scene A at `size` with send times (so the viewer shows the pipeline line) into
// `name` in this test's folder.
fs::path record_text_stream(const std::string& size, const std::string& name = "s.fb89") {
    const fs::path stream = test_dir() / name;
    fs::create_directories(stream.parent_path());
    const CliRun r = run_fb89(std::string("render ") + FB89_SCENES_DIR + "/A.json --size " + size +
                              " --method warnock --stream " + stream.string() + " --quiet");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return stream;
}

struct TextShots {
    controller::PngImage window, image;
};

// Plays `stream` to its end at `scale` (with `more` options) and saves both screenshots.
TextShots play(const fs::path& stream, double scale, const std::string& more = "") {
    const fs::path window = test_dir() / "window.png", image = test_dir() / "image.png";
    fs::remove(window);
    fs::remove(image);
    const CliRun r = run_fb89("view " + stream.string() + " --scale " + std::to_string(scale) +
                                  " --exit-at-end --speed 1000000 --screenshot " + image.string() +
                                  " --window-screenshot " + window.string() + " " + more,
                              "timeout 120 " + under_plain_xvfb());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    if (!fs::exists(window) || !fs::exists(image)) return {};
    return {controller::read_png(window), controller::read_png(image)};
}

// The text scale the window's width implies (the layout's rule, 2 from 960 pixels on).
int text_scale(const controller::PngImage& window) {
    return controller::layout_hud(static_cast<int>(window.width), 1, {}).text_scale;
}

// The part of the window under the image: where the status bar is.
PixelArea below_image(const TextShots& s) {
    return {0, s.image.height, s.window.width, s.window.height - s.image.height};
}

PixelArea whole(const controller::PngImage& img) {
    return {0, 0, img.width, img.height};
}

// The window's top-left image-sized part is the image shot, pixel for pixel: nothing of the
// text covers it.
void expect_image_uncovered(const TextShots& s) {
    ASSERT_GE(s.window.width, s.image.width);
    ASSERT_GE(s.window.height, s.image.height);
    std::size_t differ = 0;
    for (uint32_t y = 0; y < s.image.height; ++y)
        for (uint32_t x = 0; x < s.image.width; ++x)
            for (uint32_t k = 0; k < 3; ++k)
                differ += s.window.pixels[(std::size_t{y} * s.window.width + x) * 3 + k] !=
                          s.image.pixels[(std::size_t{y} * s.image.width + x) * 3 + k];
    EXPECT_EQ(differ, 0u) << "channels of the image covered";
}

// Every pixel of `ink` lies inside the window with at least one pixel to spare on each
// side (text cut by the window's edge would reach it).
void expect_inside_with_margin(const controller::PngImage& window, protocol::Rgb ink) {
    const auto extent = ink_extent(window, whole(window), ink);
    ASSERT_TRUE(extent.has_value()) << "no text at all";
    EXPECT_GE(extent->x, 1u);
    EXPECT_GE(extent->y, 1u);
    EXPECT_LT(extent->x + extent->width, window.width) << "text reaches the right edge";
    EXPECT_LT(extent->y + extent->height, window.height) << "text reaches the bottom edge";
}

std::string left_trimmed(const std::string& row) {
    return row.substr(std::min(row.find_first_not_of(' '), row.size()));
}

class ViewTextAtScale : public ::testing::TestWithParam<double> {};

TEST_P(ViewTextAtScale, EveryStatusFieldIsWholeInsideTheWindowAndOffTheImage) {
    if (!on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
    const TextShots s = play(record_text_stream("480x360"), GetParam());
    ASSERT_GT(s.window.width, 0u);
    EXPECT_EQ(s.image.width, static_cast<uint32_t>(480 * GetParam()));
    expect_image_uncovered(s);
    expect_inside_with_margin(s.window, kStatusInk);

    const std::vector<std::string> rows =
        read_bitmap_text(s.window, below_image(s), kStatusInk, text_scale(s.window));
    ASSERT_FALSE(rows.empty()) << "the status text does not read as the viewer's font";
    const std::string text = ink_of(rows);
    for (const char* field :
         {"frame0[1/1]", "cmd", "msinframe", "END", "pipeline:sendtimes", "hostwaitedforthebus",
          "controlleridle", "bufferhighwater", "last#", "FRAME_END", "h:keys"})
        EXPECT_NE(text.find(field), std::string::npos) << field << " missing from:\n" << text;
    EXPECT_TRUE(std::regex_search(text, std::regex(R"(controlleridle[0-9]+\.[0-9]{3}ms)"))) << text;
    EXPECT_TRUE(std::regex_search(text, std::regex(R"(bufferhighwater[0-9]+bytes)"))) << text;
    // and nothing of the key panel
    EXPECT_FALSE(ink_extent(s.window, whole(s.window), kPanelInk).has_value());
}

TEST_P(ViewTextAtScale, TheKeyPanelAskedForFitsTheWindowAboveTheStatusBar) {
    if (!on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
    const TextShots s = play(record_text_stream("480x360"), GetParam(), "--show-keys");
    ASSERT_GT(s.window.width, 0u);
    expect_inside_with_margin(s.window, kPanelInk);
    const std::vector<std::string> rows =
        read_bitmap_text(s.window, whole(s.window), kPanelInk, text_scale(s.window));
    ASSERT_FALSE(rows.empty()) << "the key panel does not read as the viewer's font";
    EXPECT_EQ(left_trimmed(rows.front()), "fb89 view - keys");
    EXPECT_EQ(left_trimmed(rows.back()), "q, Esc   quit");
    const std::string keys = ink_of(rows);
    EXPECT_NE(keys.find("hhide/showthesekeys"), std::string::npos) << keys;
    const std::string status =
        ink_of(read_bitmap_text(s.window, below_image(s), kStatusInk, text_scale(s.window)));
    EXPECT_NE(status.find("h:hidekeys"), std::string::npos) << status;
}

INSTANTIATE_TEST_SUITE_P(Scales, ViewTextAtScale, ::testing::Values(0.5, 1.0, 2.0));

// A frame far smaller than the key panel, shrunk further: the window leaves it room.
TEST(ViewText, TheKeyPanelFitsTheWindowOfATinyFrame) {
    if (!on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
    const TextShots s = play(record_text_stream("64x48"), 0.5, "--show-keys");
    ASSERT_GT(s.window.width, 0u);
    expect_inside_with_margin(s.window, kPanelInk);
    const std::vector<std::string> rows = read_bitmap_text(s.window, whole(s.window), kPanelInk, 1);
    ASSERT_FALSE(rows.empty());
    EXPECT_EQ(left_trimmed(rows.back()), "q, Esc   quit");
    const std::vector<std::string> status =
        read_bitmap_text(s.window, below_image(s), kStatusInk, 1);
    EXPECT_NE(ink_of(status).find("bufferhighwater"), std::string::npos) << ink_of(status);
}

// A stream cut short, in a folder with a long name: the viewer stops at the damage and shows
// the error -- the one `view --exit-at-end` prints -- whole, however long its path.
class DamagedStreamAtScale : public ::testing::TestWithParam<double> {};

TEST_P(DamagedStreamAtScale, TheErrorLineIsWholeInsideTheWindow) {
    if (!on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path full = record_text_stream("480x360");
    const fs::path cut = test_dir() / "a_folder_with_a_rather_long_name_for_the_damaged_stream" /
                         "damaged_stream_cut_short.fb89";
    fs::create_directories(cut.parent_path());
    const std::string bytes = slurp(full);
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    const CliRun told =
        run_fb89("view " + cut.string() + " --exit-at-end", "timeout 120 " + under_plain_xvfb());
    ASSERT_EQ(told.exit_code, 2) << told.err;
    ASSERT_EQ(told.err.rfind("fb89 view: ", 0), 0u) << told.err;
    const std::string error = told.err.substr(11, told.err.find('\n') - 11);

    // played as a person would: the window stays open at the damage until closed. The shot
    // is put in place when the viewer exits (with its command's other outputs), so the
    // script waits for its temporary to appear in a folder of its own, then closes it.
    const fs::path shots = test_dir() / "shots", rc = test_dir() / "rc";
    const fs::path window = shots / "window.png";
    fs::remove_all(shots);
    fs::create_directories(shots);
    std::ofstream(test_dir() / "run.sh")
        << FB89_CLI_PATH << " view " << cut.string() << " --speed 1000000 --scale " << GetParam()
        << " --window-screenshot " << window.string() << " & pid=$!\n"
        << "for i in $(seq 1 600); do [ -n \"$(ls -A " << shots.string()
        << ")\" ] && break; sleep 0.1; done\n"
        << "kill -TERM $pid; wait $pid; echo $? > " << rc.string() << "\n";
    const std::string run =
        "timeout 120 " + under_plain_xvfb() + "sh " + (test_dir() / "run.sh").string();
    ASSERT_EQ(std::system(run.c_str()), 0);
    EXPECT_EQ(slurp(rc), "0\n") << "asked to quit (SIGTERM), the viewer exits 0";
    ASSERT_TRUE(fs::exists(window));
    const controller::PngImage shot = controller::read_png(window);
    expect_inside_with_margin(shot, kStatusInk);
    const auto image_h = static_cast<uint32_t>(360 * GetParam());
    const std::vector<std::string> rows = read_bitmap_text(
        shot, {0, image_h, shot.width, shot.height - image_h}, kStatusInk, text_scale(shot));
    const std::string text = ink_of(rows);
    EXPECT_NE(text.find(ink_of({"stream error: " + error})), std::string::npos)
        << "expected the error\n  " << error << "\nin the rows\n"
        << ::testing::PrintToString(rows);
}

INSTANTIATE_TEST_SUITE_P(Scales, DamagedStreamAtScale, ::testing::Values(0.5, 1.0, 2.0));

}  // namespace
}  // namespace fb89::testing
