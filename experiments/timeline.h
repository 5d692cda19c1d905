// A frame through the pipeline in time, as a timeline to look at: Chrome's trace-event JSON
// (the "JSON Object Format" that Perfetto's UI and chrome://tracing open). One process, the
// frame; a lane (thread) each for the host, the bus and the controller:
//
//   host        "set-up" and "hidden-surface" slices, a "stall" slice inside them for every
//               wait on the bus or the buffer, and an instant mark per command sent, named
//               by its opcode;
//   bus         a slice per command crossing it, named by opcode;
//   controller  a slice per command executing, named by opcode (args: its number, bytes);
//
// and a counter, "command buffer", of the bytes held. Times are microseconds from the start
// of the host's set-up ("ts" is in microseconds in that format). The pipeline's figures,
// the title and the buffer go in "otherData". docs/COST_MODEL.md, "The pipeline in time".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/profile.h"
#include "controller_sim/timed_pipeline.h"
#include "protocol/memory_buffer.h"

namespace fb89::experiments {

struct TimelineFrame {
    std::string title;        // what the frame is: scene, method, host, controller
    double setup_end_us = 0;  // the host's set-up ends (no stall can come before it)
    double host_end_us = 0;   // the host's own work ends (without stalls)
    // how the send times were had: "measured" (natively), "counted" (a 1989 host), or ""
    // (none: a stream without times, every command ready at 0; no host phases are drawn)
    std::string send_times = "measured";
};

// The frame `commands`, command i sent at send_us[i], through the pipeline under `profile`
// with a buffer of `buffer_bytes`, as trace-event JSON text; its figures in `figures` when
// given. Throws std::invalid_argument as TimedPipeline does (a send time that goes back, a
// command too large for the buffer).
// A frame's figures through the pipeline as JSON, in the names and units every output uses
// (--stats' "pipeline", the timeline's summary, Python): frame_ms, host_ms, host_stalled_ms,
// host_stalls, bus_busy_ms, controller_busy_ms, controller_idle_ms, buffer_high_water_bytes,
// buffer_bytes, host_utilization, controller_utilization.
nlohmann::json pipeline_figures_json(const controller::PipelineFigures& p);

std::string timeline_json(const protocol::MemoryBuffer& commands,
                          const std::vector<double>& send_us, const TimelineFrame& frame,
                          const controller::CostProfile& profile, uint64_t buffer_bytes,
                          controller::PipelineFigures* figures = nullptr);

}  // namespace fb89::experiments
