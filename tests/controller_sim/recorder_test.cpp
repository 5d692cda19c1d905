// Tests for controller_sim/recorder: the last writer of each pixel and the opcode overlay,
// without a window; the depth commands' pixels as the controller's depth test drew them.
#include "controller_sim/recorder.h"

#include <gtest/gtest.h>

#include "controller_sim/controller.h"
#include "controller_sim/framebuffer.h"
#include "protocol/coverage.h"
#include "protocol/depth_fixed.h"

namespace fb89::controller {
namespace {

using protocol::Command;
using protocol::Opcode;
using protocol::Rgb;

// Feeds commands, numbered from 0, to a controller with a recorder attached.
struct Rig {
    Controller controller{load_profile("ideal")};
    Recorder recorder;
    Rig() { recorder.attach(controller); }
    void run(const std::vector<Command>& commands) {
        for (const Command& c : commands)
            controller.execute(c);
    }
};

TEST(Recorder, FrameBeginWritesEveryPixelThenLaterCommandsOverwrite) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 8, 6, Rgb{0, 0, 0}}, protocol::Marker{"x"},
             protocol::FillRect{1, 1, 3, 2, Rgb{255, 0, 0}},
             protocol::DrawSpan{2, 2, 6, Rgb{0, 255, 0}}, protocol::FrameEnd{}});
    ASSERT_EQ(rig.recorder.width(), 8u);
    ASSERT_EQ(rig.recorder.height(), 6u);
    EXPECT_EQ(rig.recorder.writer(0, 0)->number, 0u);
    EXPECT_EQ(rig.recorder.writer(0, 0)->opcode(), Opcode::FrameBegin);
    EXPECT_EQ(rig.recorder.writer(1, 1)->number, 2u);
    EXPECT_EQ(rig.recorder.writer(1, 1)->opcode(), Opcode::FillRect);
    EXPECT_EQ(rig.recorder.writer(2, 2)->number, 3u);  // the span overwrote the fill
    EXPECT_EQ(rig.recorder.writer(6, 2)->opcode(), Opcode::DrawSpan);
    EXPECT_EQ(rig.recorder.writer(7, 2)->opcode(), Opcode::FrameBegin);
    EXPECT_EQ(protocol::to_string(*rig.recorder.writer(3, 1)->command),
              protocol::to_string(Command{protocol::FillRect{1, 1, 3, 2, Rgb{255, 0, 0}}}));
    EXPECT_FALSE(rig.recorder.writer(8, 0));
    EXPECT_EQ(rig.recorder.writers(), 3u);
}

TEST(Recorder, ClipsAsTheControllerDoesAndIgnoresCommandsOutsideFrames) {
    Rig rig;
    rig.run({protocol::FillRect{0, 0, 2, 2, Rgb{9, 9, 9}},  // before any frame: nothing
             protocol::FrameBegin{0, 4, 4, Rgb{}}, protocol::FillRect{-2, 2, 4, 9, Rgb{1, 2, 3}},
             protocol::DrawSpan{9, 0, 3, Rgb{}},  // wholly outside
             protocol::FrameEnd{}, protocol::FillRect{0, 0, 4, 4, Rgb{7, 7, 7}}});  // after
    EXPECT_EQ(rig.recorder.writer(1, 3)->opcode(), Opcode::FillRect);
    EXPECT_EQ(rig.recorder.writer(2, 3)->opcode(), Opcode::FrameBegin);
    EXPECT_EQ(rig.recorder.writer(0, 0)->opcode(), Opcode::FrameBegin);
    EXPECT_EQ(rig.recorder.writers(), 2u);
}

TEST(Recorder, NewFrameForgetsThePreviousFramesWriters) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 4, 4, Rgb{}}, protocol::FillRect{0, 0, 4, 4, Rgb{1, 1, 1}},
             protocol::FrameEnd{}, protocol::FrameBegin{1, 2, 3, Rgb{}}});
    EXPECT_EQ(rig.recorder.width(), 2u);
    EXPECT_EQ(rig.recorder.height(), 3u);
    EXPECT_EQ(rig.recorder.writer(1, 2)->number, 3u);
    EXPECT_EQ(rig.recorder.writers(), 1u);
}

TEST(Recorder, OverlayTintsEachPixelByItsWritersOpcodeAndLeavesTheImageOtherwise) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 3, 1, Rgb{30, 60, 90}},
             protocol::FillRect{1, 0, 1, 1, Rgb{255, 255, 255}},
             protocol::DrawSpan{0, 2, 2, Rgb{0, 0, 0}}, protocol::FrameEnd{}});
    std::vector<uint8_t> plain, tinted;
    compose_image(rig.controller.framebuffer(), nullptr, plain);
    compose_image(rig.controller.framebuffer(), &rig.recorder, tinted);
    const auto fb = rig.controller.framebuffer().pixels();
    EXPECT_TRUE(std::equal(plain.begin(), plain.end(), fb.begin(), fb.end()));
    const Rgb expected[3] = {tint(Rgb{30, 60, 90}, Opcode::FrameBegin),
                             tint(Rgb{255, 255, 255}, Opcode::FillRect),
                             tint(Rgb{0, 0, 0}, Opcode::DrawSpan)};
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ((Rgb{tinted[i * 3], tinted[i * 3 + 1], tinted[i * 3 + 2]}), expected[i]) << i;
    // 1 part pixel, 2 parts tint: a black span turns two thirds red
    EXPECT_EQ(tint(Rgb{0, 0, 0}, Opcode::DrawSpan), (Rgb{160, 26, 26}));
    EXPECT_NE(opcode_tint(Opcode::FillRect), opcode_tint(Opcode::DrawSpan));
}

TEST(Recorder, OverlayOfAnotherSizeIsIgnored) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 2, 2, Rgb{5, 5, 5}}});
    Recorder other;
    other.record(0, protocol::FrameBegin{0, 3, 3, Rgb{}});
    std::vector<uint8_t> rgb;
    compose_image(rig.controller.framebuffer(), &other, rgb);
    EXPECT_EQ(rgb, std::vector<uint8_t>(12, 5));
}

// --- the depth commands ------------------------------------------------------------------

constexpr uint32_t kRecNear = protocol::kDepthOne / 4, kRecMid = protocol::kDepthOne / 2,
                   kRecFar = protocol::kDepthOne / 4 * 3;
constexpr int64_t kRecPx = protocol::kSubpixel;

// The rectangle of pixels [x0, x1) x [y0, y1) as a FACE at depth z, positively wound.
protocol::Face recorded_rect_face(int64_t x0, int64_t y0, int64_t x1, int64_t y1, uint32_t z,
                                  Rgb c) {
    return protocol::Face{c,
                          0,
                          0,
                          z,
                          0,
                          0,
                          {protocol::SnappedPoint{x0 * kRecPx, y0 * kRecPx},
                           protocol::SnappedPoint{x1 * kRecPx, y0 * kRecPx},
                           protocol::SnappedPoint{x1 * kRecPx, y1 * kRecPx},
                           protocol::SnappedPoint{x0 * kRecPx, y1 * kRecPx}}};
}

// Every pixel's writer drew the colour the pixel has (each command has its own colour).
void expect_writers_drew_the_pixels(const Rig& rig) {
    const Framebuffer& fb = rig.controller.framebuffer();
    for (uint32_t y = 0; y < fb.height(); ++y)
        for (uint32_t x = 0; x < fb.width(); ++x) {
            const auto w = rig.recorder.writer(x, y);
            ASSERT_TRUE(w) << x << "," << y;
            const Rgb drawn = std::visit(
                [](const auto& c) -> Rgb {
                    using C = std::decay_t<decltype(c)>;
                    if constexpr (std::is_same_v<C, protocol::FrameBegin>)
                        return c.background;
                    else if constexpr (requires { c.color; })
                        return c.color;
                    else
                        return Rgb{1, 2, 3};  // never a writer
                },
                *w->command);
            EXPECT_EQ(drawn, fb.pixel(x, y)) << "(" << x << "," << y << ") by #" << w->number;
        }
}

// A zspans-like frame: spans of three surfaces at three depths, sent far to near and back.
TEST(RecorderDepth, DepthSpanPixelsBelongToTheSpanThatDrewThemNotToAFartherOneAfter) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 8, 3, Rgb{9, 9, 9}},              // 0
             protocol::DepthClear{},                                   // 1
             protocol::DepthSpan{1, 0, 3, kRecMid, 0, Rgb{1, 0, 0}},   // 2: x 0-3
             protocol::DepthSpan{1, 2, 7, kRecNear, 0, Rgb{2, 0, 0}},  // 3: nearer, x 2-7
             protocol::DepthSpan{1, 0, 7, kRecFar, 0, Rgb{3, 0, 0}},   // 4: farther than all
             protocol::DepthSpan{0, 5, 6, kRecFar, 0, Rgb{4, 0, 0}},   // 5: row 0, over nothing
             protocol::FrameEnd{}});
    const Recorder& r = rig.recorder;
    EXPECT_EQ(r.writer(0, 1)->number, 2u);
    EXPECT_EQ(r.writer(1, 1)->number, 2u);
    for (uint32_t x = 2; x < 8; ++x)
        EXPECT_EQ(r.writer(x, 1)->number, 3u) << x;  // the farther #4 drew none of them
    EXPECT_EQ(r.writer(1, 1)->opcode(), Opcode::DepthSpan);
    EXPECT_EQ(r.writer(5, 0)->number, 5u);
    EXPECT_EQ(r.writer(4, 0)->number, 0u);  // the background; DEPTH_CLEAR drew nothing
    EXPECT_EQ(r.writer(0, 2)->opcode(), Opcode::FrameBegin);
    EXPECT_EQ(r.writers(), 4u);             // FRAME_BEGIN, #2, #3, #5: not #1 nor #4
    EXPECT_EQ(r.writer(0, 1)->pixels, 4u);  // what #2 drew, though #3 took two of them since
    EXPECT_EQ(r.writer(7, 1)->pixels, 6u);
    expect_writers_drew_the_pixels(rig);
}

// A span whose depth crosses the buffer's: it draws where it is nearer, in several runs.
TEST(RecorderDepth, ADepthSpanClaimsOnlyThePixelsItsTestDrewInEveryRunOfThem) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 8, 1, Rgb{}}, protocol::DepthClear{},
             protocol::DepthSpan{0, 0, 7, kRecMid, 0, Rgb{1, 1, 1}},   // 2: the whole row
             protocol::DepthSpan{0, 1, 1, kRecNear, 0, Rgb{2, 2, 2}},  // 3: pixel 1, nearest
             protocol::DepthSpan{0, 4, 5, kRecNear, 0, Rgb{3, 3, 3}},  // 4: pixels 4, 5
             // 5: between the two depths: drawn at 0, 2-3 and 6-7 only
             protocol::DepthSpan{0, 0, 7, (kRecNear + kRecMid) / 2, 0, Rgb{4, 4, 4}}});
    const uint64_t expected[8] = {5, 3, 5, 5, 4, 4, 5, 5};
    for (uint32_t x = 0; x < 8; ++x)
        EXPECT_EQ(rig.recorder.writer(x, 0)->number, expected[x]) << x;
    EXPECT_EQ(rig.recorder.writer(0, 0)->pixels, 5u);
    expect_writers_drew_the_pixels(rig);
    // the controller told exactly those runs
    const std::vector<PixelRect> runs(rig.controller.depth_drawn().begin(),
                                      rig.controller.depth_drawn().end());
    EXPECT_EQ(runs, (std::vector<PixelRect>{{0, 0, 1, 1}, {2, 0, 2, 1}, {6, 0, 2, 1}}));
}

TEST(RecorderDepth, FacePixelsBelongToTheFaceThatDrewThemAndAFartherFaceTakesTheRest) {
    Rig rig;
    rig.run(
        {protocol::FrameBegin{0, 8, 6, Rgb{9, 9, 9}}, protocol::DepthClear{},
         recorded_rect_face(0, 0, 4, 4, kRecNear, Rgb{1, 0, 0}),  // 2
         recorded_rect_face(2, 2, 8, 6, kRecFar, Rgb{2, 0, 0}),   // 3: behind #2 where they overlap
         protocol::FrameEnd{}});
    const Recorder& r = rig.recorder;
    EXPECT_EQ(r.writer(3, 3)->number, 2u);
    EXPECT_EQ(r.writer(3, 3)->opcode(), Opcode::Face);
    EXPECT_EQ(r.writer(4, 3)->number, 3u);
    EXPECT_EQ(r.writer(2, 4)->number, 3u);
    EXPECT_EQ(r.writer(5, 1)->number, 0u);
    EXPECT_EQ(r.writer(3, 3)->pixels, 16u);
    EXPECT_EQ(r.writer(7, 5)->pixels, 24u - 4u);  // its 6x4 less the 2x2 behind #2
    expect_writers_drew_the_pixels(rig);
}

TEST(RecorderDepth, TheDrawnPixelsAreKeptOnlyWhenAskedAndOnlyForTheLastCommand) {
    Controller ctl(load_profile("ideal"));
    ctl.execute(protocol::FrameBegin{0, 4, 1, Rgb{}});
    ctl.execute(protocol::DepthClear{});
    ctl.execute(protocol::DepthSpan{0, 0, 3, kRecMid, 0, Rgb{1, 1, 1}});
    EXPECT_TRUE(ctl.depth_drawn().empty()) << "kept without being asked";
    ctl.keep_depth_drawn(true);
    ctl.execute(protocol::DepthSpan{0, 1, 2, kRecNear, 0, Rgb{2, 2, 2}});
    ASSERT_EQ(ctl.depth_drawn().size(), 1u);
    EXPECT_EQ(ctl.depth_drawn()[0], (PixelRect{1, 0, 2, 1}));
    ctl.execute(protocol::DepthSpan{0, 0, 3, kRecFar, 0, Rgb{3, 3, 3}});  // draws nothing
    EXPECT_TRUE(ctl.depth_drawn().empty());
    ctl.execute(protocol::DepthSpan{0, 0, 0, kRecNear, 0, Rgb{4, 4, 4}});
    EXPECT_EQ(ctl.depth_drawn().size(), 1u);
    ctl.execute(protocol::Marker{"m"});  // another command: none
    EXPECT_TRUE(ctl.depth_drawn().empty());
}

TEST(RecorderDepth, TheOverlayTintsDepthSpanAndFaceEachInItsOwnColour) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 3, 1, Rgb{30, 60, 90}}, protocol::DepthClear{},
             protocol::DepthSpan{0, 0, 0, kRecMid, 0, Rgb{0, 0, 0}},
             recorded_rect_face(1, 0, 2, 1, kRecMid, Rgb{0, 0, 0})});
    std::vector<uint8_t> tinted;
    compose_image(rig.controller.framebuffer(), &rig.recorder, tinted);
    const Rgb expected[3] = {tint(Rgb{}, Opcode::DepthSpan), tint(Rgb{}, Opcode::Face),
                             tint(Rgb{30, 60, 90}, Opcode::FrameBegin)};
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ((Rgb{tinted[i * 3], tinted[i * 3 + 1], tinted[i * 3 + 2]}), expected[i]) << i;
    const Opcode drawing[] = {Opcode::FrameBegin, Opcode::FillRect, Opcode::DrawSpan,
                              Opcode::DepthSpan, Opcode::Face};
    for (Opcode a : drawing)
        for (Opcode b : drawing)
            if (a != b) {
                EXPECT_NE(opcode_tint(a), opcode_tint(b)) << to_string(a) << to_string(b);
            }
}

TEST(RecorderDepth, TheInspectorNamesAFaceByItsColourPointsBoundsAndPixelsDrawn) {
    Rig rig;
    rig.run({protocol::FrameBegin{0, 8, 6, Rgb{}}, protocol::DepthClear{},
             recorded_rect_face(1, 2, 5, 4, kRecMid, Rgb{0xbd, 0xbd, 0xb1}),
             protocol::DepthSpan{5, 1, 6, kRecMid, 0, Rgb{1, 2, 3}}});
    EXPECT_EQ(describe(*rig.recorder.writer(2, 3)),
              "#2 FACE #bdbdb1, 4 points in (1,2)-(5,4), drew 8 pixels");
    EXPECT_EQ(describe(*rig.recorder.writer(2, 5)),
              "#3 DEPTH_SPAN y=5 x0=1 x1=6 z=" + std::to_string(kRecMid) +
                  " dz=0 color=#010203, drew 6 pixels");
    EXPECT_EQ(describe(*rig.recorder.writer(0, 0)),
              "#0 " + protocol::to_string(Command{protocol::FrameBegin{0, 8, 6, Rgb{}}}));
}

}  // namespace
}  // namespace fb89::controller
