// Tests of the render job's pipeline in time (experiments/render_job.h): natively, from the
// commands' measured send times.
#include <gtest/gtest.h>

#include <string>

#include "experiments/render_job.h"
#include "protocol/stream_reader.h"

namespace fb89::experiments {
namespace {

TEST(RenderJobPipeline, NativelyTheFrameLiesBetweenTheLargerSideAndTheirSum) {
    RenderJob job;
    job.scene = FB89_SCENES_DIR "/A.json";
    job.size = {256, 195};
    job.repeat = 1;
    for (const host::Method m : {host::Method::ZBuffer, host::Method::Warnock})
        job.methods.emplace_back(m);
    const RenderResult result = run_render_job(job);
    for (const MethodRun& run : result.runs) {
        ASSERT_TRUE(run.pipeline.has_value());
        const controller::PipelineFigures& p = *run.pipeline;
        const double host_us = run.host_frame_ms * 1e3;
        // the same controller model, command by command
        EXPECT_NEAR(p.controller_busy_us, run.controller.controller_ms * 1e3, 1e-6);
        EXPECT_NEAR(p.bus_busy_us, run.controller.bus_ms * 1e3, 1e-6);
        // overlap can only help: never below the larger side, never above the two in turn
        // the host's own work: its set-up and hidden-surface time, or its last send when the
        // last (timed) round ran longer than the median
        EXPECT_GE(p.host_us + 1e-9, host_us);
        EXPECT_GE(p.frame_us + 1e-9, std::max(p.host_us, p.controller_busy_us));
        EXPECT_LE(p.frame_us,
                  p.host_us + p.host_stalled_us + p.bus_busy_us + p.controller_busy_us + 1e-6);
        EXPECT_NEAR(p.controller_idle_us, p.frame_us - p.controller_busy_us, 1e-9);
        EXPECT_GT(p.controller_utilization(), 0);
        EXPECT_LE(p.controller_utilization(), 1 + 1e-12);
    }
}

// A bounded buffer the bus and the controller must take turns through (12 bytes, one
// FILL_RECT, on the ISA bus's slow profile): the controller alone is slower than the split's
// unbounded pipeline, and the frame, taken against it, still lies between max and sum -- the
// overlap a share in [0, 1], not the negative one host + the unbounded controller would give.
TEST(RenderJobPipeline, ABufferThatSlowsTheControllerIsCountedOnTheControllersSide) {
    RenderJob job;
    job.scene = FB89_SCENES_DIR "/A.json";
    job.size = {256, 195};
    job.repeat = 1;
    job.controller = "tms34010-isa";
    job.methods.emplace_back(host::Method::Warnock);
    for (const uint64_t buffer : {uint64_t{12}, controller::kUnboundedBuffer}) {
        job.buffer_bytes = buffer;
        const RenderResult result = run_render_job(job);
        const MethodRun& run = result.runs.front();
        ASSERT_TRUE(run.pipeline.has_value());
        const FramePipeline& p = *run.pipeline;
        const double unbounded_us = run.controller.frame_ms * 1e3;
        if (buffer == controller::kUnboundedBuffer) {
            EXPECT_NEAR(p.controller_alone_us, unbounded_us, 1e-6);
        } else {
            // bus and execution in turn: the controller alone takes longer than the frame
            // the split allows the host and controller together
            EXPECT_GT(p.controller_alone_us, unbounded_us + 0.05 * unbounded_us);
            EXPECT_GT(p.frame_us, p.host_us + unbounded_us);
        }
        EXPECT_GE(p.frame_us + 1e-6, p.max_us());
        EXPECT_LE(p.frame_us, p.sum_us() + 1e-6);
        EXPECT_GE(p.overlap(), 0);
        EXPECT_LE(p.overlap(), 1);
    }
}

// A frame's stream keeps its send times (a version-2 stream, whole nanoseconds): through the
// pipeline from the stream alone, without the host, the frame's figures are the render's,
// exactly -- the replay `fb89 replay --buffer` does.
TEST(RenderJobPipeline, TheFramesStreamReplaysThroughThePipelineAsItWasRendered) {
    RenderJob job;
    job.scene = FB89_SCENES_DIR "/A.json";
    job.size = {256, 195};
    job.repeat = 1;
    job.buffer_bytes = 2048;  // small enough to stall the host
    job.methods.emplace_back(host::Method::ScanLine);
    const RenderResult result = run_render_job(job);
    const MethodRun& run = result.runs.front();
    ASSERT_TRUE(run.pipeline.has_value());

    protocol::StreamWriter writer(protocol::Properties{}, protocol::Timing::Timed);
    write_commands(writer, run);
    writer.close();
    protocol::StreamReader reader(writer.bytes());
    protocol::MemoryBuffer frame;
    std::vector<double> send_us;
    protocol::Command c;
    while (reader.next(c)) {
        frame.submit(c);
        send_us.push_back(static_cast<double>(reader.send_time_ns()) / 1e3);
    }
    ASSERT_EQ(frame.size(), run.commands.size());
    ASSERT_TRUE(reader.host_end_ns().has_value());
    // monotone within the frame, FRAME_BEGIN at 0, each within half a nanosecond of the render's
    EXPECT_EQ(send_us.front(), 0);
    for (std::size_t i = 0; i < send_us.size(); ++i) {
        if (i > 0) {
            EXPECT_GE(send_us[i], send_us[i - 1]);
        }
        EXPECT_NEAR(send_us[i], run.send_us[i], 0.5e-3) << i;
    }
    const controller::PipelineFigures p =
        pipeline_figures(frame, send_us, static_cast<double>(*reader.host_end_ns()) / 1e3,
                         controller::load_profile("tms34010-50mhz"), 2048);
    const controller::PipelineFigures& r = *run.pipeline;
    EXPECT_EQ(p.frame_us, r.frame_us);
    EXPECT_EQ(p.host_us, r.host_us);
    EXPECT_EQ(p.host_stalled_us, r.host_stalled_us);
    EXPECT_EQ(p.stalls, r.stalls);
    EXPECT_EQ(p.controller_idle_us, r.controller_idle_us);
    EXPECT_EQ(p.high_water_bytes, r.high_water_bytes);
    EXPECT_GT(r.stalls, 0u);  // the buffer did bind
}

}  // namespace
}  // namespace fb89::experiments
