// Tests for controller_sim/view_player: playback paced by modelled time, steps, frame
// moves and seeks, on small streams written to files (no window).
#include "controller_sim/view_player.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "protocol/coverage.h"
#include "protocol/depth_fixed.h"
#include "protocol/stream_writer.h"
#include "tests/scratch.h"

namespace fb89::controller {
namespace {

using protocol::Command;
using protocol::Rgb;
using Clock = ViewPlayer::Clock;

// Three frames numbered 10, 11, 12 of 8x6; frame k fills a rect of colour k. Commands 0-3
// are frame 10, 4-7 frame 11, 8-11 frame 12.
std::string write_stream(const std::string& name, bool with_index) {
    const auto path = fb89::testing::scratch_path("view_player_" + name);
    protocol::StreamWriter w(path.string(), {{"scene", "test"}});
    for (uint32_t k = 0; k < 3; ++k) {
        const auto v = static_cast<uint8_t>(k + 1);
        w.frame_begin(protocol::FrameBegin{10 + k, 8, 6, Rgb{}});
        w.fill_rect(protocol::FillRect{0, 0, 4, 4, Rgb{v, v, v}});
        w.draw_span(protocol::DrawSpan{5, 0, 7, Rgb{v, 0, 0}});
        w.frame_end(protocol::FrameEnd{});
    }
    if (with_index) w.close();
    return path.string();
}

// Two 8x6 frames with send times (format version 2): frame 0 fills at 1000 µs and 1500 µs,
// the host done at 2000 µs; frame 1 spans at 300 µs, with no HOST_END.
std::string write_timed_stream(const std::string& name) {
    const auto path = fb89::testing::scratch_path("view_player_" + name);
    protocol::StreamWriter w(path.string(), {{"scene", "test"}}, protocol::Timing::Timed);
    w.frame_begin(protocol::FrameBegin{0, 8, 6, Rgb{}});
    w.send_time(1'000'000);
    w.fill_rect(protocol::FillRect{0, 0, 4, 4, Rgb{1, 1, 1}});
    w.send_time(1'500'000);
    w.fill_rect(protocol::FillRect{4, 0, 4, 4, Rgb{2, 2, 2}});
    w.host_end(2'000'000);
    w.frame_end(protocol::FrameEnd{});
    w.frame_begin(protocol::FrameBegin{1, 8, 6, Rgb{}});
    w.send_time(300'000);
    w.draw_span(protocol::DrawSpan{5, 0, 7, Rgb{3, 0, 0}});
    w.frame_end(protocol::FrameEnd{});
    w.close();
    return path.string();
}

Clock::time_point far() {
    return Clock::now() + std::chrono::hours(1);
}

TEST(ViewPlayer, PlaySpendsTheBudgetInModelledTimeAndCarriesTheDebt) {
    ViewPlayer p(write_stream("budget", true), load_profile("tms34010-50mhz"));
    // FRAME_BEGIN 8x6 alone takes more than 1 µs: one command, then the budget is spent
    const double left = p.play(1.0, far());
    EXPECT_EQ(p.next_command(), 1u);
    EXPECT_NEAR(left, 1.0 - p.elapsed_us(), 1e-9);
    EXPECT_LT(left, 0);
    EXPECT_EQ(p.play(left, far()), left);  // in debt: nothing runs
    EXPECT_EQ(p.next_command(), 1u);
    p.play(1e9, far());
    EXPECT_TRUE(p.at_end());
    EXPECT_EQ(p.controller().frames().size(), 3u);
}

TEST(ViewPlayer, NextFrameRunsToThisFramesEndThenTheNextsAndPauses) {
    ViewPlayer p(write_stream("next", true), load_profile("ideal"));
    ASSERT_TRUE(p.step());  // inside frame 10
    p.next_frame();
    p.run(far());
    EXPECT_EQ(p.goal(), ViewGoal::Pause);
    EXPECT_EQ(p.next_command(), 4u);
    p.next_frame();
    p.run(far());
    EXPECT_EQ(p.next_command(), 8u);
    EXPECT_EQ(p.frame_number(), 11);
    EXPECT_EQ(p.controller().framebuffer().pixel(0, 0), (Rgb{2, 2, 2}));
}

TEST(ViewPlayer, PreviousFrameShowsTheFrameBeforeCompleteWithOrWithoutIndex) {
    for (bool with_index : {true, false}) {
        ViewPlayer p(write_stream(with_index ? "prev_index" : "prev_cut", with_index),
                     load_profile("ideal"));
        EXPECT_EQ(p.frame_count().has_value(), with_index);
        p.set_goal(ViewGoal::End);
        p.run(far());
        ASSERT_TRUE(p.at_end());
        EXPECT_EQ(p.frame_ordinal(), 2);
        p.previous_frame();
        p.run(far());
        EXPECT_EQ(p.frame_number(), 11) << with_index;
        EXPECT_EQ(p.next_command(), 8u);
        EXPECT_EQ(p.controller().framebuffer().pixel(7, 5), (Rgb{2, 0, 0}));
        EXPECT_EQ(p.recorder().writer(7, 5)->number, 6u);
        EXPECT_EQ(p.goal(), ViewGoal::Pause);
    }
}

TEST(ViewPlayer, StartsAtAFrameNumberOrACommandAndThenPlays) {
    ViewPlayer by_frame(write_stream("start_frame", true), load_profile("ideal"));
    by_frame.seek_frame_number(12);
    EXPECT_EQ(by_frame.next_command(), 8u);
    EXPECT_EQ(by_frame.goal(), ViewGoal::Play);

    ViewPlayer by_call(write_stream("start_call", true), load_profile("ideal"));
    by_call.seek_command(6);
    by_call.run(far());
    EXPECT_EQ(by_call.next_command(), 6u);
    EXPECT_EQ(by_call.goal(), ViewGoal::Play);
    EXPECT_EQ(by_call.frame_number(), 11);

    ViewPlayer no_index(write_stream("start_frame_cut", false), load_profile("ideal"));
    no_index.seek_frame_number(11);
    no_index.run(far());
    EXPECT_EQ(no_index.next_command(), 5u);
    EXPECT_TRUE(no_index.error().empty());
    EXPECT_THROW(by_frame.seek_frame_number(99), std::invalid_argument);
}

TEST(ViewPlayer, RestartGoesBackToTheFirstCommandPaused) {
    ViewPlayer p(write_stream("restart", true), load_profile("ideal"));
    p.set_goal(ViewGoal::End);
    p.run(far());
    p.restart();
    EXPECT_EQ(p.next_command(), 0u);
    EXPECT_FALSE(p.at_end());
    EXPECT_EQ(p.goal(), ViewGoal::Pause);
    EXPECT_EQ(p.frame_ordinal(), -1);
}

TEST(ViewPlayer, ToEndJumpsToTheLastFrameThroughTheIndex) {
    ViewPlayer p(write_stream("to_end", true), load_profile("ideal"));
    p.to_end();
    EXPECT_EQ(p.next_command(), 8u);  // skipped frames 10 and 11
    p.run(far());
    EXPECT_TRUE(p.at_end());
    EXPECT_EQ(p.frame_number(), 12);
    EXPECT_EQ(p.controller().frames().size(), 1u);
    EXPECT_EQ(p.controller().framebuffer().pixel(0, 0), (Rgb{3, 3, 3}));
}

// A stream with send times plays at the pipeline's pace: under the ideal profile the
// controller takes no time, so each frame lasts until the host's end (frame 0: 2000 µs) or,
// without one, its last send (frame 1: 300 µs), and the controller idles all of it.
TEST(ViewPlayer, ATimedStreamPlaysAtThePipelinesPace) {
    ViewPlayer p(write_timed_stream("timed_ideal"), load_profile("ideal"));
    ASSERT_TRUE(p.timed());
    ASSERT_TRUE(p.step());  // FRAME_BEGIN, at 0
    EXPECT_EQ(p.elapsed_us(), 0);
    // 500 µs of budget: the fills are sent at 1000 µs and later, so the first is all it buys
    // (its time spent after it ran: the budget goes into debt)
    const double left = p.play(500, far());
    EXPECT_EQ(p.next_command(), 2u);
    EXPECT_EQ(p.elapsed_us(), 1000);
    EXPECT_EQ(left, -500);
    p.play(1e9, far());
    EXPECT_TRUE(p.at_end());
    EXPECT_EQ(p.elapsed_us(), 2000 + 300);
    EXPECT_EQ(p.frame_us(), 300);
    EXPECT_EQ(p.pipeline_so_far().controller_busy_us, 0);
    EXPECT_EQ(p.pipeline_so_far().host_stalled_us, 0);

    // the same stream untimed in the player's eyes: the controller's own pace, no waiting
    ViewPlayer untimed(write_stream("untimed", true), load_profile("ideal"));
    EXPECT_FALSE(untimed.timed());
}

// Under the TMS34010 with a buffer of one command, the host stalls on each fill until the
// controller has drawn the one before: the player shows the stalls the pipeline counts.
TEST(ViewPlayer, ABufferTooSmallStallsTheHostAndThePlayerSaysHowLong) {
    const CostProfile profile = load_profile("tms34010-50mhz");
    const uint64_t buffer = *std::max_element(profile.bytes.begin(), profile.bytes.end());
    const std::string path = fb89::testing::scratch_path("view_player_stall").string();
    {
        protocol::StreamWriter w(path, {}, protocol::Timing::Timed);
        w.frame_begin(protocol::FrameBegin{0, 64, 64, Rgb{}});
        for (int i = 0; i < 4; ++i)
            w.fill_rect(protocol::FillRect{0, 0, 64, 64, Rgb{9, 9, 9}});  // all sent at 0
        w.frame_end(protocol::FrameEnd{});
        w.close();
    }
    // the expectation from the pipeline and the controller directly
    Controller ctl(profile);
    TimedPipeline pipe(buffer);
    protocol::StreamReader reader(path);
    protocol::Command c;
    while (reader.next(c)) {
        ctl.execute(c);
        pipe.push({0, ctl.last_cost().bytes, ctl.last_cost().bus_us, ctl.last_cost().exec_us});
    }
    const PipelineFigures want = pipe.finish(0);
    ASSERT_GT(want.host_stalled_us, 0);

    ViewPlayer p(path, profile, buffer);
    p.play(1e9, far());
    ASSERT_TRUE(p.at_end()) << p.error();
    EXPECT_EQ(p.buffer_bytes(), buffer);
    EXPECT_EQ(p.elapsed_us(), want.frame_us);
    EXPECT_EQ(p.pipeline_so_far().host_stalled_us, want.host_stalled_us);
    EXPECT_EQ(p.pipeline_so_far().controller_busy_us, want.controller_busy_us);
    EXPECT_EQ(p.pipeline_so_far().high_water_bytes, buffer);
}

// Two zspans-like 8x4 frames numbered 0 and 1 (commands 0-6 and 7-13): a near DEPTH_SPAN, a
// farther one over it and past it, and a FACE nearer than both on part of them.
std::string write_depth_stream(const std::string& name) {
    const auto path = fb89::testing::scratch_path("view_player_" + name);
    constexpr uint32_t kNear = protocol::kDepthOne / 4, kFar = protocol::kDepthOne / 2;
    constexpr int64_t kPx = protocol::kSubpixel;
    protocol::StreamWriter w(path.string(), {{"scene", "test"}}, protocol::Timing::Untimed,
                             protocol::Commands::Depth);
    for (uint32_t k = 0; k < 2; ++k) {
        w.frame_begin(protocol::FrameBegin{k, 8, 4, Rgb{}});
        w.marker(protocol::Marker{"zspans"});
        w.depth_clear(protocol::DepthClear{});
        w.depth_span(protocol::DepthSpan{1, 0, 3, kNear, 0, Rgb{1, 0, 0}});
        w.depth_span(protocol::DepthSpan{1, 0, 7, kFar, 0, Rgb{2, 0, 0}});
        // pixels [5, 7) x [0, 3): nearest
        w.face(
            protocol::Face{Rgb{3, 0, 0},
                           0,
                           0,
                           kNear / 2,
                           0,
                           0,
                           {{5 * kPx, 0}, {7 * kPx, 0}, {7 * kPx, 3 * kPx}, {5 * kPx, 3 * kPx}}});
        w.frame_end(protocol::FrameEnd{});
    }
    w.close();
    return path.string();
}

// The writers of row 1 of the frame starting at command `first`.
void expect_depth_writers(const ViewPlayer& p, uint64_t first) {
    const Recorder& r = p.recorder();
    for (uint32_t x = 0; x < 4; ++x)  // the near span: the farther one after it drew none
        EXPECT_EQ(r.writer(x, 1)->number, first + 3) << x;
    EXPECT_EQ(r.writer(4, 1)->number, first + 4);  // the farther span, where it was nearest
    EXPECT_EQ(r.writer(7, 1)->number, first + 4);
    EXPECT_EQ(r.writer(5, 1)->number, first + 5);  // the face, over the farther span
    EXPECT_EQ(r.writer(5, 1)->opcode(), protocol::Opcode::Face);
    EXPECT_EQ(r.writer(6, 0)->number, first + 5);
    EXPECT_EQ(r.writer(0, 0)->number, first);  // background: nothing drew there
    EXPECT_EQ(r.writer(4, 1)->pixels, 4u);
    EXPECT_EQ(r.writer(5, 1)->pixels, 6u);
}

TEST(ViewPlayer, DepthSpanAndFacePixelsAreTheirsByStreamNumberAlsoAfterASeek) {
    ViewPlayer p(write_depth_stream("depth"), load_profile("ideal"));
    p.next_frame();
    p.run(far());
    ASSERT_TRUE(p.error().empty()) << p.error();
    EXPECT_EQ(p.next_command(), 7u);
    expect_depth_writers(p, 0);

    p.set_goal(ViewGoal::End);
    p.run(far());
    ASSERT_TRUE(p.at_end());
    expect_depth_writers(p, 7);

    p.seek_frame_number(1);  // through the index: a fresh controller from command 7
    EXPECT_EQ(p.next_command(), 7u);
    p.set_goal(ViewGoal::End);
    p.run(far());
    ASSERT_TRUE(p.at_end());
    ASSERT_TRUE(p.error().empty()) << p.error();
    expect_depth_writers(p, 7);
}

}  // namespace
}  // namespace fb89::controller
