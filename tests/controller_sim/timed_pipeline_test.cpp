// Tests of controller_sim/timed_pipeline: pipelines worked out by hand, exact in microseconds.
#include "controller_sim/timed_pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

namespace fb89::controller {
namespace {

TEST(TimedPipeline, AHostBoundFrameLeavesTheControllerIdle) {
    // sends at 0, 10, 20; 1 us on the bus, 2 executing; the host ends at 30
    TimedPipeline p;
    EXPECT_EQ(p.push({0, 10, 1, 2}), 3);
    EXPECT_EQ(p.push({10, 10, 1, 2}), 13);
    EXPECT_EQ(p.push({20, 10, 1, 2}), 23);
    const PipelineFigures f = p.finish(30);
    EXPECT_EQ(f.frame_us, 30);
    EXPECT_EQ(f.host_us, 30);
    EXPECT_EQ(f.host_stalled_us, 0);
    EXPECT_EQ(f.stalls, 0u);
    EXPECT_EQ(f.bus_busy_us, 3);
    EXPECT_EQ(f.controller_busy_us, 6);
    EXPECT_EQ(f.controller_idle_us, 24);
    EXPECT_EQ(f.high_water_bytes, 10u);
    EXPECT_DOUBLE_EQ(f.controller_utilization(), 0.2);
    EXPECT_DOUBLE_EQ(f.host_utilization(), 1.0);
}

TEST(TimedPipeline, AFullBufferStallsTheHostAndMovesEveryLaterSend) {
    // a 20-byte buffer, four 10-byte commands all sent at 0: 1 us on the bus, 10 executing.
    // c0 crosses 0-1 and runs 1-11; c1 waits for the bus (a 1 us stall), crosses 1-2, runs
    // 11-21; c2 is ready at 1, the bus is free at 2 but the buffer holds c0 and c1 until c0
    // is done at 11: a 10 us stall, crosses 11-12, runs 21-31; c3 is ready at 11, the buffer
    // frees at 21: crosses 21-22, runs 31-41.
    TimedPipeline p(20);
    CommandTiming t[4];
    EXPECT_EQ(p.push({0, 10, 1, 10}, &t[0]), 11);
    EXPECT_EQ(p.push({0, 10, 1, 10}, &t[1]), 21);
    EXPECT_EQ(p.push({0, 10, 1, 10}, &t[2]), 31);
    EXPECT_EQ(p.push({0, 10, 1, 10}, &t[3]), 41);
    // where each went: sent (moved by the stalls before it), across the bus, run
    const double expect[4][5] = {
        {0, 0, 1, 1, 11}, {0, 1, 2, 11, 21}, {1, 11, 12, 21, 31}, {11, 21, 22, 31, 41}};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(t[i].sent_us, expect[i][0]) << i;
        EXPECT_EQ(t[i].bus_start_us, expect[i][1]) << i;
        EXPECT_EQ(t[i].arrived_us, expect[i][2]) << i;
        EXPECT_EQ(t[i].exec_start_us, expect[i][3]) << i;
        EXPECT_EQ(t[i].done_us, expect[i][4]) << i;
        EXPECT_EQ(t[i].bytes, 10u);
    }
    const PipelineFigures f = p.finish(0);
    EXPECT_EQ(f.host_stalled_us, 21);
    EXPECT_EQ(f.stalls, 3u);
    EXPECT_EQ(f.host_us, 0);  // all the host did was wait
    EXPECT_EQ(f.frame_us, 41);
    EXPECT_EQ(f.controller_busy_us, 40);
    EXPECT_EQ(f.controller_idle_us, 1);  // the first command's crossing
    EXPECT_EQ(f.high_water_bytes, 20u);
    // unbounded, the same frame stalls the host only on the bus
    TimedPipeline open;
    for (int i = 0; i < 4; ++i)
        open.push({0, 10, 1, 10});
    const PipelineFigures g = open.finish(0);
    EXPECT_EQ(g.frame_us, 41);
    EXPECT_EQ(g.host_stalled_us, 3);  // c1, c2 and c3 each wait 1 us for the bus
    EXPECT_EQ(g.high_water_bytes, 40u);
}

TEST(TimedPipeline, TheClearRunsWhileTheHostSetsUp) {
    // FRAME_BEGIN sent at 0, a 100 us clear; the host sets up until 80, then sends a span
    // (5 us) and ends at 90. The clear crosses 0-1 and runs 1-101, the span crosses 80-81 and
    // runs 101-106: a frame of 106 us where host + controller would be 90 + 105.
    TimedPipeline p;
    p.push({0, 10, 1, 100});
    EXPECT_EQ(p.push({80, 10, 1, 5}), 106);
    const PipelineFigures f = p.finish(90);
    EXPECT_EQ(f.frame_us, 106);
    EXPECT_EQ(f.host_us, 90);
    EXPECT_EQ(f.controller_idle_us, 1);
}

TEST(TimedPipeline, AMixedFrame) {
    // a 25-byte buffer: a 20-byte command (send 0, bus 2, exec 10) then three 10-byte ones
    // at 3, 4 and 30 (bus 1, exec 4), the host ending at 32. c0 crosses 0-2, runs 2-12. c1 at
    // 3: room is 5, so it waits for c0 (done 12): a 9 us stall, crosses 12-13, runs 13-17. c2
    // is ready at 4 + 9 = 13, the bus is free at 13, room 15: crosses 13-14, runs 17-21. c3
    // is ready at 39: crosses 39-40, runs 40-44. The host ends at 32 + 9 = 41.
    TimedPipeline p(25);
    EXPECT_EQ(p.push({0, 20, 2, 10}), 12);
    EXPECT_EQ(p.push({3, 10, 1, 4}), 17);
    EXPECT_EQ(p.push({4, 10, 1, 4}), 21);
    EXPECT_EQ(p.push({4, 0, 0, 0}), 21);  // a marker: not sent
    EXPECT_EQ(p.push({30, 10, 1, 4}), 44);
    const PipelineFigures f = p.finish(32);
    EXPECT_EQ(f.host_stalled_us, 9);
    EXPECT_EQ(f.stalls, 1u);
    EXPECT_EQ(f.frame_us, 44);
    EXPECT_EQ(f.host_us, 32);
    EXPECT_EQ(f.bus_busy_us, 5);
    EXPECT_EQ(f.controller_busy_us, 22);
    EXPECT_EQ(f.high_water_bytes, 20u);
    // the next frame starts from 0 again
    EXPECT_EQ(p.push({0, 10, 1, 1}), 2);
}

// The bound docs/COST_MODEL.md states for the pipeline in time: a frame never takes less
// than the larger of the host's own work and the controller alone (every command waiting at
// 0, through the same buffer), nor more than their sum -- whatever the send times, costs and
// buffer. Two thousand random frames, small buffers among them, so that most stall.
TEST(TimedPipeline, AFrameLiesBetweenTheLargerSideAndTheSumOfTheHostAndTheControllerAlone) {
    std::mt19937 rng(89);
    std::uniform_int_distribution<int> count(1, 60), bytes(0, 24), cost(0, 40), gap(0, 30),
        capacity(24, 120);
    int stalled = 0, bounded_slower = 0;
    for (int frame = 0; frame < 2000; ++frame) {
        const uint64_t buffer = frame % 4 == 0 ? kUnboundedBuffer : capacity(rng);
        TimedPipeline timed(buffer), alone(buffer), unbounded;
        double send = 0;
        for (int i = count(rng); i > 0; --i) {
            send += gap(rng);
            const uint32_t b = static_cast<uint32_t>(bytes(rng));
            const double bus = b ? cost(rng) / 4.0 : 0, exec = b ? cost(rng) : 0;
            timed.push({send, b, bus, exec});
            alone.push({0, b, bus, exec});
            unbounded.push({0, b, bus, exec});
        }
        const double host_end = send + gap(rng);
        const PipelineFigures f = timed.finish(host_end);
        const double alone_us = alone.finish(0).frame_us;
        const double unbounded_us = unbounded.finish(0).frame_us;
        ASSERT_EQ(f.host_us, host_end) << frame;  // its own work, stalls apart
        ASSERT_GE(f.frame_us, std::max(f.host_us, alone_us)) << frame;
        ASSERT_LE(f.frame_us, f.host_us + alone_us) << frame;
        ASSERT_GE(alone_us, unbounded_us) << frame;  // a bound can only slow the controller
        if (buffer == kUnboundedBuffer) {
            ASSERT_EQ(alone_us, unbounded_us) << frame;
        }
        stalled += f.stalls > 0;
        bounded_slower += alone_us > unbounded_us;
    }
    // the frames did exercise stalls and buffers that slow the controller alone
    EXPECT_GT(stalled, 500);
    EXPECT_GT(bounded_slower, 300);
}

TEST(TimedPipeline, RefusesWhatCannotBe) {
    EXPECT_THROW(TimedPipeline(0), std::invalid_argument);
    TimedPipeline p(8);
    EXPECT_THROW(p.push({0, 10, 1, 1}), std::invalid_argument);  // bigger than the buffer
    p.push({5, 4, 1, 1});
    EXPECT_THROW(p.push({4, 4, 1, 1}), std::invalid_argument);  // back in time
}

}  // namespace
}  // namespace fb89::controller
