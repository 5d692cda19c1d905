// The pipeline in time (controller_sim/timed_pipeline.h) as the front ends report it: a
// rendered frame as a timeline (render --timeline, Python's Render.timeline()), and each
// complete frame of a replayed stream followed through the pipeline (replay --buffer and
// --timeline, Python's replay(buffer=, timeline=)), so that both front ends give the same
// figures and the same trace-event JSON, byte for byte.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"
#include "controller_sim/timed_pipeline.h"
#include "experiments/render_job.h"
#include "experiments/timeline.h"
#include "protocol/command.h"
#include "protocol/memory_buffer.h"

namespace fb89::frontend {

// The frame of `run` (one method of a render job on `scene_file`, timed on `host`) through
// the pipeline under `profile`, as trace-event JSON (experiments/timeline.h). Throws
// std::runtime_error naming `option` when the frame has no send times.
std::string render_timeline(const experiments::MethodRun& run, const std::string& scene_file,
                            const std::string& method, const std::string& host,
                            const controller::CostProfile& profile, const std::string& option);

// One replayed frame's figures as JSON: experiments::pipeline_figures_json (timeline.h).
using experiments::pipeline_figures_json;

// Each complete frame of a stream through the pipeline with a command buffer of
// `buffer_bytes`, from the send times the stream carries (none: every command ready at 0).
// A frame starts at its FRAME_BEGIN; commands before the first are not followed.
class FramePipelines {
  public:
    // `keep_last_frame`: keep the last complete frame's commands and send times, for
    // last_frame_timeline().
    FramePipelines(uint64_t buffer_bytes, bool keep_last_frame);

    // Command `c`, just executed at `cost` (what the controller said it cost), sent at
    // `send_ns`; at a FRAME_END, `host_end_ns` is when the host's work on the frame ended
    // (its HOST_END, or without one its last send time).
    void follow(const protocol::Command& c, int64_t send_ns,
                const controller::Controller::CommandCost& cost, int64_t host_end_ns);

    uint64_t buffer_bytes() const { return m_buffer; }
    // One entry per complete frame, in order.
    const std::vector<controller::PipelineFigures>& frames() const { return m_frames; }

    // The last complete frame as trace-event JSON, titled "<stream>, frame N, controller
    // <profile>"; `send_times` says where the stream's times came from ("" for none).
    // Throws std::runtime_error "<stream>: no complete frame; <output> not written" when
    // there is none.
    std::string last_frame_timeline(const std::string& stream, const std::string& output,
                                    const std::string& send_times,
                                    const controller::CostProfile& profile) const;

  private:
    uint64_t m_buffer;
    bool m_keep;
    std::optional<controller::TimedPipeline> m_pipe;
    std::vector<controller::PipelineFigures> m_frames;
    protocol::MemoryBuffer m_frame, m_last_frame;
    std::vector<double> m_frame_send_us, m_last_send_us;
    double m_last_host_end_us = 0;
};

}  // namespace fb89::frontend
