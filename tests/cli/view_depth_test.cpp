// fb89 view on streams of the controller's depth commands (fb89 render --method zspans or
// faces, stream format version 3), as a person would use it, under Xvfb: the inspector
// (--inspect, the same line the window shows under the mouse) names the DEPTH_SPAN or FACE
// that drew a pixel -- also where a later, farther one covered it without drawing -- and the
// overlay tints what each drew; the window's own inspector line, read back from a screenshot
// of it, says the same. The expectations come from the stream replayed in this
// process into a controller with a Recorder attached; that recorder is checked first against
// the framebuffer itself: every pixel's writer drew the pixel's colour.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <variant>
#include <vector>

#include "cli_runner.h"
#include "controller_sim/controller.h"
#include "controller_sim/hud_layout.h"
#include "controller_sim/png_io.h"
#include "controller_sim/recorder.h"
#include "protocol/stream_reader.h"
#include "tests/cli/bitmap_text.h"

namespace fb89::testing {
namespace {

namespace fs = std::filesystem;
using protocol::Opcode;

// The demo scene at 320x240 by `method`, into a stream in this test's folder.
fs::path record_method_stream(const std::string& method) {
    const fs::path stream = test_dir() / (method + ".fb89");
    const CliRun r = run_fb89("render demo --size 320x240 --method " + method + " --stream " +
                              stream.string() + " --quiet");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return stream;
}

// The stream replayed here: its commands, the controller and its recorder at the end.
struct Replayed {
    std::vector<protocol::Command> commands;
    controller::Controller ctl;
    controller::Recorder writers;
    explicit Replayed(const fs::path& stream) {
        writers.attach(ctl);
        protocol::StreamReader reader(stream.string());
        protocol::Command c;
        while (reader.next(c)) {
            ctl.execute(c);
            commands.push_back(c);
        }
    }
};

protocol::Rgb colour_of(const protocol::Command& c) {
    if (const auto* f = std::get_if<protocol::FrameBegin>(&c)) return f->background;
    if (const auto* s = std::get_if<protocol::DepthSpan>(&c)) return s->color;
    if (const auto* f = std::get_if<protocol::Face>(&c)) return f->color;
    ADD_FAILURE() << "a writer that is no FRAME_BEGIN, DEPTH_SPAN or FACE: "
                  << protocol::to_string(c);
    return {};
}

// Every pixel's writer drew the pixel's colour; returns how many pixels `op` wrote.
std::size_t check_writers(const Replayed& r, Opcode op) {
    const controller::Framebuffer& fb = r.ctl.framebuffer();
    std::size_t of_op = 0, wrong = 0;
    for (uint32_t y = 0; y < fb.height(); ++y)
        for (uint32_t x = 0; x < fb.width(); ++x) {
            const auto w = r.writers.writer(x, y);
            if (!w) return 0;
            of_op += w->opcode() == op;
            if (colour_of(*w->command) != fb.pixel(x, y) && wrong++ == 0)
                ADD_FAILURE() << "(" << x << "," << y << ") " << protocol::to_string(fb.pixel(x, y))
                              << " but its writer is " << controller::describe(*w);
        }
    EXPECT_EQ(wrong, 0u);
    return of_op;
}

// A pixel a DEPTH_SPAN drew that a later DEPTH_SPAN covered without drawing it (farther).
std::optional<std::pair<uint32_t, uint32_t>> kept_by_the_nearer(const Replayed& r) {
    for (uint64_t n = 0; n < r.commands.size(); ++n) {
        const auto* s = std::get_if<protocol::DepthSpan>(&r.commands[n]);
        if (!s || s->y < 0) continue;
        for (int32_t x = std::max(s->x0, 0); x <= s->x1; ++x) {
            const auto w = r.writers.writer(static_cast<uint32_t>(x), static_cast<uint32_t>(s->y));
            if (w && w->opcode() == Opcode::DepthSpan && w->number < n)
                return std::pair{static_cast<uint32_t>(x), static_cast<uint32_t>(s->y)};
        }
    }
    return std::nullopt;
}

// The inspector's line as the viewer prints it.
std::string inspector_line(const Replayed& r, uint32_t x, uint32_t y) {
    return "(" + std::to_string(x) + "," + std::to_string(y) + ") " +
           protocol::to_string(r.ctl.framebuffer().pixel(x, y)) + " by " +
           controller::describe(*r.writers.writer(x, y));
}

struct Shots {
    controller::PngImage image, window;
};

// Plays `stream` to its end with the overlay on, inspecting `pixels`: stdout, the shots.
CliRun view(const fs::path& stream, const std::vector<std::pair<uint32_t, uint32_t>>& pixels,
            Shots& shots) {
    const fs::path image = test_dir() / "overlay.png", window = test_dir() / "window.png";
    fs::remove(image);
    fs::remove(window);
    std::string args = "view " + stream.string() + " --exit-at-end --overlay --screenshot " +
                       image.string() + " --window-screenshot " + window.string();
    for (const auto& [x, y] : pixels)
        args += " --inspect " + std::to_string(x) + "," + std::to_string(y);
    const CliRun run = run_fb89(args, "timeout 120 " + xvfb_run() + "env SDL_VIDEODRIVER=x11 ");
    if (fs::exists(image)) shots.image = controller::read_png(image);
    if (fs::exists(window)) shots.window = controller::read_png(window);
    return run;
}

// The status bar's text under the image, without its spaces (bitmap_text.h).
std::string status_ink(const Shots& s) {
    const int scale = controller::layout_hud(static_cast<int>(s.window.width), 1, {}).text_scale;
    const PixelArea bar{0, s.image.height, s.window.width, s.window.height - s.image.height};
    return ink_of(read_bitmap_text(s.window, bar, protocol::Rgb{230, 230, 230}, scale));
}

// The overlay the window shows is the recorder's here, tinting what each command drew.
void expect_overlay(const controller::PngImage& shot, const Replayed& r) {
    std::vector<uint8_t> rgb;
    controller::compose_image(r.ctl.framebuffer(), &r.writers, rgb);
    ASSERT_EQ(shot.width, r.ctl.framebuffer().width());
    ASSERT_EQ(shot.height, r.ctl.framebuffer().height());
    EXPECT_TRUE(shot.pixels == rgb) << "the overlay shown is not the recorder's";
}

TEST(ViewDepth, TheInspectorNamesTheDepthSpanThatDrewAPixelNotAFartherOneAfterIt) {
    if (!on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path stream = record_method_stream("zspans");
    const Replayed r(stream);
    const std::size_t spans = check_writers(r, Opcode::DepthSpan);
    EXPECT_GT(spans, 320u * 240u / 4) << "the demo's walls and floor are DEPTH_SPANs";
    const auto kept = kept_by_the_nearer(r);
    ASSERT_TRUE(kept) << "no DEPTH_SPAN passes behind an earlier one";
    const auto [x, y] = *kept;
    // a background pixel too: the corner, sky in the demo
    const auto sky = r.writers.writer(0, 0);
    ASSERT_TRUE(sky);

    Shots shots;
    const CliRun run = view(stream, {*kept, {0, 0}}, shots);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, inspector_line(r, x, y) + "\n" + inspector_line(r, 0, 0) + "\n");
    EXPECT_NE(run.out.find(" DEPTH_SPAN y=" + std::to_string(y)), std::string::npos) << run.out;
    expect_overlay(shots.image, r);
    // the window's inspector shows the first pixel asked for, whatever the mouse does
    const std::string status = status_ink(shots);
    EXPECT_NE(status.find(ink_of({inspector_line(r, x, y)})), std::string::npos) << status;
}

TEST(ViewDepth, TheInspectorNamesTheFaceThatDrewAPixelByItsColourAndPoints) {
    if (!on_path("xvfb-run")) GTEST_SKIP() << "xvfb-run is not installed";
    const fs::path stream = record_method_stream("faces");
    const Replayed r(stream);
    EXPECT_GT(check_writers(r, Opcode::Face), 320u * 240u / 4);
    const controller::Framebuffer& fb = r.ctl.framebuffer();
    // the first FACE pixel of the middle row
    std::optional<uint32_t> x;
    const uint32_t y = fb.height() / 2;
    for (uint32_t i = 0; i < fb.width() && !x; ++i)
        if (r.writers.writer(i, y)->opcode() == Opcode::Face) x = i;
    ASSERT_TRUE(x);

    Shots shots;
    const CliRun run = view(stream, {{*x, y}}, shots);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_EQ(run.out, inspector_line(r, *x, y) + "\n");
    EXPECT_NE(run.out.find(" FACE #"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find(" points in ("), std::string::npos) << run.out;
    expect_overlay(shots.image, r);
    const std::string status = status_ink(shots);
    EXPECT_NE(status.find(ink_of({inspector_line(r, *x, y)})), std::string::npos) << status;
}

// --inspect takes X,Y: anything else is refused before a window opens, naming the option.
TEST(ViewDepth, AnInspectThatIsNoPixelIsRefusedInWords) {
    const fs::path stream = test_dir() / "absent.fb89";
    for (const char* bad : {"12", "1,2,3", "-1,2", "a,b", "1;2"}) {
        const CliRun r = run_fb89("view " + stream.string() + " --inspect '" + bad + "'",
                                  "env -u DISPLAY -u WAYLAND_DISPLAY ");
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find(std::string("--inspect: '") + bad + "' is not a pixel: give X,Y"),
                  std::string::npos)
            << r.err;
    }
}

}  // namespace
}  // namespace fb89::testing
