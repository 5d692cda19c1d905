// Tests for fb89 view, used as a person would: under Xvfb, play a recorded stream to its
// end, take a screenshot of the window, and compare it pixel for pixel with the PNG that
// fb89 replay writes for the same stream (and with the controller's own framebuffer, tinted
// by the opcode overlay when it is on); and without any display, the one-line refusal.
#include <gtest/gtest.h>

#include <array>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "controller_sim/recorder.h"
#include "protocol/stream_reader.h"

namespace fb89::testing {
namespace {

namespace fs = std::filesystem;

bool have_xvfb_run() {
    return fb89::testing::on_path("xvfb-run");
}

// The viewer under Xvfb, with SDL told to use it; a generous time-out.
std::string under_xvfb() {
    return "timeout 120 " + xvfb_run() + "env SDL_VIDEODRIVER=x11 ";
}

// Renders scene A at `size` into a stream in this test's folder.
fs::path record_stream(const std::string& size) {
    const fs::path stream = test_dir() / "s.fb89";
    const CliRun r = run_fb89(std::string("render ") + FB89_SCENES_DIR + "/A.json --size " + size +
                              " --method warnock --stream " + stream.string() + " --quiet");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return stream;
}

// The stream replayed in this process into the controller: its last frame as drawn.
controller::PngImage replayed_frame(const fs::path& stream) {
    protocol::StreamReader reader(stream.string());
    controller::Controller ctl;
    reader.replay_into(ctl);
    const controller::Framebuffer& fb = ctl.framebuffer();
    const auto px = fb.pixels();
    return controller::PngImage{fb.width(), fb.height(), 3, {px.begin(), px.end()}};
}

// The same, tinted by the opcode overlay as the viewer composes it.
controller::PngImage overlaid_frame(const fs::path& stream) {
    protocol::StreamReader reader(stream.string());
    controller::Controller ctl;
    controller::Recorder writers;
    writers.attach(ctl);
    reader.replay_into(ctl);
    const controller::Framebuffer& fb = ctl.framebuffer();
    std::vector<uint8_t> rgb;
    controller::compose_image(fb, &writers, rgb);
    return controller::PngImage{fb.width(), fb.height(), 3, rgb};
}

void expect_same_image(const controller::PngImage& shot, const controller::PngImage& ref) {
    ASSERT_EQ(shot.width, ref.width);
    ASSERT_EQ(shot.height, ref.height);
    ASSERT_EQ(shot.channels, 3u);
    std::size_t differ = 0, first = 0;
    for (std::size_t i = 0; i < ref.pixels.size(); ++i)
        if (shot.pixels[i] != ref.pixels[i] && differ++ == 0) first = i / 3;
    EXPECT_EQ(differ, 0u) << "first differing pixel (" << first % ref.width << ","
                          << first / ref.width << ")";
}

TEST(ViewCommand, ScreenshotAfterPlayingToTheEndMatchesReplayPng) {
    if (!have_xvfb_run())
        GTEST_SKIP() << "xvfb-run is not installed (scripts/bootstrap installs xvfb)";
    // larger than the window the viewer opens with, so the window must grow to fit
    const fs::path stream = record_stream("700x520");
    const fs::path shot = test_dir() / "shot.png", ref = test_dir() / "replay.png";
    fs::remove(shot);
    const CliRun replay = run_fb89("replay " + stream.string() + " --png " + ref.string() + " -q");
    ASSERT_EQ(replay.exit_code, 0) << replay.err;
    const CliRun r = run_fb89("view " + stream.string() + " --screenshot " + shot.string() +
                                  " --exit-at-end --speed 1000000",
                              under_xvfb());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(fs::exists(shot));
    expect_same_image(controller::read_png(shot), controller::read_png(ref));
}

// The screenshot is what the window shows of the image: without the overlay, the frame
// alone, wherever the play started.
TEST(ViewCommand, ScreenshotWithoutTheOverlayIsTheFrameAloneWhateverTheStartPosition) {
    if (!have_xvfb_run())
        GTEST_SKIP() << "xvfb-run is not installed (scripts/bootstrap installs xvfb)";
    const fs::path stream = record_stream("256x195");
    const fs::path shot = test_dir() / "shot.png";
    fs::remove(shot);
    const CliRun r = run_fb89("view " + stream.string() + " --screenshot " + shot.string() +
                                  " --exit-at-end --start-call 3",
                              under_xvfb());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_same_image(controller::read_png(shot), replayed_frame(stream));
}

// With the overlay on, the screenshot is the tinted image the window shows: it differs from
// the plain one wherever the overlay draws, and is the overlay composed in this process.
TEST(ViewCommand, ScreenshotWithTheOverlayIsTheTintedImage) {
    if (!have_xvfb_run())
        GTEST_SKIP() << "xvfb-run is not installed (scripts/bootstrap installs xvfb)";
    const fs::path stream = record_stream("256x195");
    const fs::path plain = test_dir() / "plain.png", tinted = test_dir() / "tinted.png";
    fs::remove(plain);
    fs::remove(tinted);
    const std::string play = "view " + stream.string() + " --exit-at-end --screenshot ";
    const CliRun a = run_fb89(play + plain.string(), under_xvfb());
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const CliRun b = run_fb89(play + tinted.string() + " --overlay", under_xvfb());
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const controller::PngImage with = controller::read_png(tinted);
    const controller::PngImage without = controller::read_png(plain);
    const controller::PngImage expected = overlaid_frame(stream);
    expect_same_image(without, replayed_frame(stream));
    expect_same_image(with, expected);

    // where the overlay draws (its tint changes the pixel), the two shots differ; elsewhere
    // they agree
    ASSERT_EQ(with.pixels.size(), without.pixels.size());
    std::size_t drawn = 0;
    for (std::size_t i = 0; i < without.pixels.size(); i += 3) {
        const bool tinted_here = !std::equal(expected.pixels.begin() + static_cast<long>(i),
                                             expected.pixels.begin() + static_cast<long>(i) + 3,
                                             without.pixels.begin() + static_cast<long>(i));
        const bool differ = !std::equal(with.pixels.begin() + static_cast<long>(i),
                                        with.pixels.begin() + static_cast<long>(i) + 3,
                                        without.pixels.begin() + static_cast<long>(i));
        drawn += tinted_here;
        EXPECT_EQ(differ, tinted_here) << "pixel " << i / 3;
        if (differ != tinted_here) break;
    }
    EXPECT_GT(drawn, without.pixels.size() / 3 / 2) << "the overlay tints too few pixels";
}

// As a person runs it on a machine with no screen: no DISPLAY, no SDL_VIDEODRIVER. One line
// saying why and what to do instead, exit 2; no window on SDL's offscreen driver, no
// complaint of SDL's own.
// Below 1 the window shrinks the frame: every other pixel at 0.5, nearest sampled.
TEST(ViewCommand, AScaleBelowOneShrinksTheFrame) {
    if (!have_xvfb_run())
        GTEST_SKIP() << "xvfb-run is not installed (scripts/bootstrap installs xvfb)";
    const fs::path stream = record_stream("640x480");
    const fs::path shot = test_dir() / "half.png";
    fs::remove(shot);
    const CliRun r = run_fb89("view " + stream.string() + " --scale 0.5 --screenshot " +
                                  shot.string() + " --exit-at-end --speed 1000000",
                              under_xvfb());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const controller::PngImage half = controller::read_png(shot);
    EXPECT_EQ(half.width, 320u);
    EXPECT_EQ(half.height, 240u);
    // scene A is made of large faces: at the middle of a face the half-size window shows the
    // frame's colour there
    const controller::PngImage full = replayed_frame(stream);
    auto at = [](const controller::PngImage& img, uint32_t x, uint32_t y) {
        const size_t i = (size_t{y} * img.width + x) * 3;
        return std::array<uint8_t, 3>{img.pixels[i], img.pixels[i + 1], img.pixels[i + 2]};
    };
    EXPECT_EQ(at(half, 160, 120), at(full, 320, 240));
    EXPECT_EQ(run_fb89("view " + stream.string() + " --scale 0.1").exit_code, 2) << "below 1/8";
}

// A window larger than the screen (xvfb-run's is 1280x1024) is shown at the largest scale
// that fits, and stderr says which: a whole scale below the one asked, else a half or less.
TEST(ViewCommand, AWindowLargerThanTheScreenIsShownAtTheLargestScaleThatFits) {
    if (!have_xvfb_run())
        GTEST_SKIP() << "xvfb-run is not installed (scripts/bootstrap installs xvfb)";
    struct Case {
        std::string size, scale, used;
        uint32_t image_w, image_h;
    };
    const Case cases[] = {
        {"1024x780", "2", "1", 1024, 780},  // 2048x1648 asked for
        {"1024x780", "3", "1", 1024, 780},  // neither 3 nor 2 fits
        {"2048x1560", "1", "0.5", 1024, 780},
    };
    for (const Case& c : cases) {
        const fs::path stream = record_stream(c.size);
        const fs::path shot = test_dir() / "shot.png", window = test_dir() / "window.png";
        fs::remove(shot);
        fs::remove(window);
        const CliRun r = run_fb89("view " + stream.string() + " --scale " + c.scale +
                                      " --exit-at-end --screenshot " + shot.string() +
                                      " --window-screenshot " + window.string(),
                                  under_xvfb());
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const controller::PngImage image = controller::read_png(shot);
        const controller::PngImage whole = controller::read_png(window);
        const std::string what = c.size + " at scale " + c.scale;
        EXPECT_EQ(image.width, c.image_w) << what;
        EXPECT_EQ(image.height, c.image_h) << what;
        EXPECT_LE(whole.width, 1280u) << what;
        EXPECT_LE(whole.height, 1024u) << what;
        EXPECT_EQ(r.err.rfind("fb89 view: --scale " + c.scale + " makes a ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(" window; the screen has 1280x1024: scale " + c.used + " used\n"),
                  std::string::npos)
            << r.err;
    }
    // a window that fits is left at the scale asked, without a word
    const fs::path stream = record_stream("480x360");
    const CliRun r = run_fb89("view " + stream.string() + " --scale 2 --exit-at-end", under_xvfb());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

TEST(ViewCommand, WithNoDisplayAtAllExitsTwoInOneLine) {
    const fs::path stream = record_stream("64x48");
    const CliRun r = run_fb89("view " + stream.string(),
                              "timeout 60 env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER ");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.find("fb89: error: no display"), 0u) << r.err;
    EXPECT_NE(r.err.find("xvfb-run"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.find("XDG_RUNTIME_DIR"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
}

TEST(ViewCommand, WithoutADisplayExitsTwoSayingSo) {
    const fs::path stream = record_stream("64x48");
    const CliRun r = run_fb89("view " + stream.string() + " --exit-at-end",
                              "env -u DISPLAY -u WAYLAND_DISPLAY SDL_VIDEODRIVER=x11 ");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
}

// Refused before a window opens (no display needed): a speed that is not one, in words,
// and a start past the stream's last command, as dump refuses --calls past it.
TEST(ViewCommand, ASpeedOfZeroAndAStartPastTheEndAreRefusedInWords) {
    const fs::path stream = record_stream("64x48");
    CliRun r = run_fb89("view " + stream.string() + " --speed 0");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("'0' is not a speed: give a number above 0 and at most 1e+09, e.g. 0.1 "
                         "(slower) or 10 (faster)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.err.find("1.79769e+308"), std::string::npos) << r.err;
    const CliRun info = run_fb89("info " + stream.string() + " --json");
    const std::size_t commands = nlohmann::json::parse(info.out)["commands"].get<std::size_t>();
    r = run_fb89("view " + stream.string() + " --start-call " + std::to_string(commands),
                 "env -u DISPLAY -u WAYLAND_DISPLAY ");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "fb89: usage: --start-call: command " + std::to_string(commands) +
                         " is past the stream's last (it has " + std::to_string(commands) +
                         " commands)\n");
}

TEST(ViewCommand, MissingStreamExitsTwo) {
    const CliRun r = run_fb89("view " + (test_dir() / "absent.fb89").string() + " --exit-at-end");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(r.err.empty());
}

}  // namespace
}  // namespace fb89::testing
