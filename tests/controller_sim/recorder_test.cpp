// Tests for controller_sim/recorder: the last writer of each pixel and the opcode overlay,
// without a window.
#include "controller_sim/recorder.h"

#include <gtest/gtest.h>

#include "controller_sim/controller.h"
#include "controller_sim/framebuffer.h"

namespace fb89::controller {
namespace {

using protocol::Command;
using protocol::Opcode;
using protocol::Rgb;

// Feeds commands, numbered from 0, to a controller with a recorder on its observer.
struct Rig {
    Controller controller{load_profile("ideal")};
    Recorder recorder;
    Rig() {
        controller.set_observer([this](uint64_t n, const Command& c) { recorder.record(n, c); });
    }
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

}  // namespace
}  // namespace fb89::controller
