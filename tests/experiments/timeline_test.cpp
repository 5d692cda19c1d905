// Tests of the timeline (experiments/timeline.h): the trace-event JSON parses, has its three
// lanes, and adds up to the pipeline's own figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "controller_sim/profile.h"
#include "experiments/render_job.h"
#include "experiments/timeline.h"

namespace fb89::experiments {
namespace {

TEST(Timeline, ItsLanesAddUpToThePipelinesFigures) {
    RenderJob job;
    job.scene = std::string(FB89_SCENES_DIR) + "/A.json";
    job.size = {128, 98};
    job.repeat = 1;
    job.methods.emplace_back(host::Method::ScanLine);
    const RenderResult result = run_render_job(job);
    const MethodRun& run = result.runs.front();
    ASSERT_EQ(run.send_us.size(), run.commands.size());
    const controller::CostProfile profile = controller::load_profile(job.controller);
    // unbounded, and a buffer of 64 bytes that stalls the host
    for (const uint64_t buffer : {controller::kUnboundedBuffer, uint64_t{64}}) {
        TimelineFrame frame{"scene A, scanline", run.setup_end_us, run.host_frame_ms * 1e3};
        controller::PipelineFigures f;
        const nlohmann::json j = nlohmann::json::parse(
            timeline_json(run.commands, run.send_us, frame, profile, buffer, &f));
        EXPECT_EQ(j.at("otherData").at("frame_ms").get<double>(), f.frame_us / 1e3);
        std::map<std::string, int> lanes;  // thread name -> tid
        double controller_us = 0, bus_us = 0, stalled_us = 0, host_end = 0, last_send = 0;
        uint64_t sends = 0, high = 0, held = 1, executed = 0;
        for (const nlohmann::json& e : j.at("traceEvents")) {
            const std::string ph = e.at("ph");
            if (ph == "M" && e.at("name") == "thread_name")
                lanes[e.at("args").at("name")] = e.at("tid");
            if (ph == "C") {
                held = e.at("args").at("bytes");
                high = std::max(high, held);
            }
            if (ph == "i") {
                EXPECT_GE(e.at("ts").get<double>(), last_send);  // sends in time order
                last_send = e.at("ts");
                ++sends;
            }
            if (ph != "X") continue;
            const double dur = e.at("dur");
            EXPECT_GE(dur, 0);
            const int tid = e.at("tid");
            if (tid == 3) controller_us += dur, ++executed;
            if (tid == 2) bus_us += dur;
            if (tid == 1 && e.at("name") == "stall") stalled_us += dur;
            if (tid == 1 && e.at("name") == "hidden-surface")
                host_end = e.at("ts").get<double>() + dur;
        }
        EXPECT_EQ(lanes, (std::map<std::string, int>{{"host", 1}, {"bus", 2}, {"controller", 3}}));
        EXPECT_EQ(sends, run.commands.size());  // a mark per command
        EXPECT_NEAR(controller_us, f.controller_busy_us, 1e-6 * f.controller_busy_us);
        EXPECT_NEAR(bus_us, f.bus_busy_us, 1e-6 * f.bus_busy_us);
        EXPECT_NEAR(stalled_us, f.host_stalled_us, 1e-6 * (1 + f.host_stalled_us));
        EXPECT_NEAR(host_end, f.host_us + f.host_stalled_us, 1e-6 * host_end);
        EXPECT_EQ(high, f.high_water_bytes);
        EXPECT_EQ(held, 0u);  // the frame ends with the buffer empty
        EXPECT_GT(executed, 0u);
        if (buffer == 64) {
            EXPECT_LE(high, 64u);
            EXPECT_GT(f.host_stalled_us, 0);
        }
    }
}

TEST(Timeline, ASendTimeThatGoesBackIsRefused) {
    RenderJob job;
    job.scene = std::string(FB89_SCENES_DIR) + "/A.json";
    job.size = {64, 49};
    job.methods.emplace_back(host::Method::ZBuffer);
    const RenderResult result = run_render_job(job);
    const MethodRun& run = result.runs.front();
    std::vector<double> sends = run.send_us;
    ASSERT_GT(sends.size(), 3u);
    sends[2] = sends[1] + 5;
    sends[3] = sends[1] + 1;  // back
    EXPECT_THROW(timeline_json(run.commands, sends, {}, controller::load_profile(job.controller),
                               controller::kUnboundedBuffer),
                 std::invalid_argument);
    sends.pop_back();  // one short
    EXPECT_THROW(timeline_json(run.commands, sends, {}, controller::load_profile(job.controller),
                               controller::kUnboundedBuffer),
                 std::invalid_argument);
}

}  // namespace
}  // namespace fb89::experiments
