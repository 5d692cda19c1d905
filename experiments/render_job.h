// One render job, below the command line: a scene, the methods to render it with, the host
// they are timed on -- this machine, in interleaved rounds, or a 1989 host, each method
// emulated once and priced -- and the controller that tiles their commands. Out come the
// scene, and per method its renderer (set up, for the id pass and the beam mask), its
// command stream, its host statistics, its 1989-host run, the controller's figures and the
// split. `fb89 render` runs a job of one method, `fb89 compare` one of every method; the
// experiments time their settings through the same engine (measure_settings()).
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "controller_sim/profile.h"
#include "controller_sim/timed_pipeline.h"
#include "experiments/measure.h"
#include "experiments/settings.h"
#include "host/methods.h"
#include "host/raster/screen_scene.h"
#include "host/scene/scene.h"
#include "host/stats.h"
#include "period/host_cost.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_writer.h"

namespace fb89::experiments {

class PeriodRuns;

struct RenderJob {
    std::string scene;                         // a scene file
    std::vector<host::MethodOptions> methods;  // one or more
    ImageSize size;                            // 0 x 0: the scene's own
    int repeat = 1;  // native: timed rounds, the hidden-surface time their median (0: untimed)
    std::string controller = std::string(controller::kDefaultProfile);
    bool progress = false;
    // A 1989 host (period_runs.h): each method's set-up and hidden-surface times are
    // modelled from one emulated run; the native run gives the commands. Null: this machine.
    std::shared_ptr<PeriodRuns> period;
    // On a 1989 host: set each emulated run's frame against the native one's, pixel for pixel.
    bool check_frames = false;
    // The controller's command buffer in the pipeline in time: none given, the profile's.
    std::optional<uint64_t> buffer_bytes;
};

// A method's run on the 1989 host.
struct PeriodFrame {
    period::HostCost cost;
    std::string cpu, fpu;  // the profile's chips
    uint64_t guest_instructions = 0;
    double emulated_seconds = 0;  // 0: answered from a results folder
    bool checked = false;         // the frames were compared (an emulated run, check_frames)
    bool same_frame = false;      // the emulated frame's checksum is the native one's
    uint64_t differing_pixels = 0;
};

struct MethodRun {
    host::MethodOptions options;
    std::unique_ptr<host::Renderer> renderer;  // set up on the job's screen
    protocol::MemoryBuffer commands;           // the frame (the last round's, natively)
    // natively: load (the job's), set-up (projection + the method's own), hidden-surface
    // (the median), its samples, end to end; the last frame's counters
    host::HostStats stats;
    std::optional<PeriodFrame> period;
    ControllerFigures controller;
    double host_frame_ms = 0;  // set-up + hidden-surface on the job's host (CPU ms natively)
    FrameSplit split;          // host_frame_ms against the controller's frame time
    // Natively: the frame through the pipeline in time (controller_sim/timed_pipeline.h) from
    // the commands' measured send times -- the set-up's time, then each command's packet's
    // time in the last hidden-surface round, or on a 1989 host the priced instructions up to
    // its packet's send mark; FRAME_BEGIN sent as the set-up starts, so that the clear
    // overlaps it -- with the job's command buffer. None when the 1989 host's counts have no
    // send marks (a results folder from before them).
    std::optional<FramePipeline> pipeline;
    // What it came from: each command's send time in microseconds from the start of the
    // set-up (FRAME_BEGIN's 0), the set-up's end, the host's end; empty without a pipeline.
    std::vector<double> send_us;
    double setup_end_us = 0;
    uint64_t buffer_bytes = controller::kUnboundedBuffer;  // the pipeline's command buffer
};

struct RenderResult {
    host::Scene scene;
    host::ScreenScene screen;  // projected, shaded
    std::vector<MethodRun> runs;
};

// Throws what loading the scene or the controller profile throws, and period::EmulatorError
// when an emulated run fails.
RenderResult run_render_job(const RenderJob& job);

// A frame's commands through the pipeline in time under `profile`: command i sent at
// send_us[i], the host's own work ending at host_end_us, a buffer of `buffer_bytes`, and the
// controller alone through the same buffer; what the controller made of the frame
// (controller_figures(), from the same pass) in `controller`
// and where each command went in `timings`, when given. Throws std::invalid_argument for a
// buffer smaller than the profile's largest command and as TimedPipeline::push does.
FramePipeline pipeline_figures(const protocol::MemoryBuffer& commands,
                               const std::vector<double>& send_us, double host_end_us,
                               const controller::CostProfile& profile,
                               uint64_t buffer_bytes = controller::kUnboundedBuffer,
                               ControllerFigures* controller = nullptr,
                               std::vector<controller::CommandTiming>* timings = nullptr);

// Writes a run's commands to `writer`; a timed writer (a version-2 stream) also gets their
// send times and the host's end, in whole nanoseconds (each SEND_TIME where the time changes,
// HOST_END before FRAME_END), when the run has them.
void write_commands(protocol::StreamWriter& writer, const MethodRun& run);

// A frame's send times from the start of the set-up: `hs_us`, counted from the start of the
// hidden-surface pass, moved by the set-up's `setup_us`, with FRAME_BEGIN sent as the set-up
// starts (so that the clear overlaps it). Empty unless there is one for each of `commands`.
std::vector<double> frame_send_times(std::vector<double> hs_us, double setup_us,
                                     std::size_t commands);

// Each of a frame's `commands` commands' send time on a 1989 host in microseconds from the
// start of the hidden-surface phase: the time of the send mark that closed its packet
// (period/guest), priced as `cost` prices the phase. Empty when the counts have no send
// marks (counted before there were any) or they do not cover exactly `commands` commands.
std::vector<double> period_send_times_us(const period::HostCost& cost, std::size_t commands);

// The rows of the job's frame check: the frame `commands` leave, and how many pixels differ
// between two such frames (all of them when the sizes differ).
uint64_t frames_differing(const protocol::MemoryBuffer& a, const protocol::MemoryBuffer& b,
                          bool* same_checksum);

}  // namespace fb89::experiments
