// Tests of the render job's pipeline in time (experiments/render_job.h): natively, from the
// commands' measured send times.
#include <gtest/gtest.h>

#include <string>

#include "experiments/render_job.h"

namespace fb89::experiments {
namespace {

TEST(RenderJobPipeline, NativelyTheFrameLiesBetweenTheLargerSideAndTheirSum) {
    RenderJob job;
    job.scene = std::string(FB89_SCENES_DIR) + "/A.json";
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

}  // namespace
}  // namespace fb89::experiments
