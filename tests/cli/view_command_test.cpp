// Tests for fb89 view, used as a person would: under Xvfb, play a recorded stream to its
// end, take a screenshot of the window, and compare it pixel for pixel with the PNG that
// fb89 replay writes for the same stream (and with the controller's own framebuffer).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "cli_runner.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "protocol/stream_reader.h"

namespace fb89::testing {
namespace {

namespace fs = std::filesystem;

bool have_xvfb_run() {
    return std::system("command -v xvfb-run >/dev/null 2>&1") == 0;
}

// xvfb-run on a free display, 24-bit so colours survive; a generous time-out.
const std::string kUnderXvfb =
    "timeout 120 xvfb-run -a -s '-screen 0 1280x1024x24' env SDL_VIDEODRIVER=x11 ";

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
                              kUnderXvfb);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(fs::exists(shot));
    expect_same_image(controller::read_png(shot), controller::read_png(ref));
}

TEST(ViewCommand, ScreenshotIsTheFrameAloneWhateverTheOverlayAndStartPosition) {
    if (!have_xvfb_run())
        GTEST_SKIP() << "xvfb-run is not installed (scripts/bootstrap installs xvfb)";
    const fs::path stream = record_stream("256x195");
    const fs::path shot = test_dir() / "shot.png";
    fs::remove(shot);
    const CliRun r = run_fb89("view " + stream.string() + " --screenshot " + shot.string() +
                                  " --exit-at-end --overlay --start-call 3",
                              kUnderXvfb);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    expect_same_image(controller::read_png(shot), replayed_frame(stream));
}

TEST(ViewCommand, WithoutADisplayExitsTwoSayingSo) {
    const fs::path stream = record_stream("64x48");
    const CliRun r = run_fb89("view " + stream.string() + " --exit-at-end",
                              "env -u DISPLAY -u WAYLAND_DISPLAY SDL_VIDEODRIVER=x11 ");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
}

TEST(ViewCommand, MissingStreamExitsTwo) {
    const CliRun r = run_fb89("view " + (test_dir() / "absent.fb89").string() + " --exit-at-end");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_FALSE(r.err.empty());
}

}  // namespace
}  // namespace fb89::testing
