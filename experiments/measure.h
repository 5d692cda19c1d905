// How the experiments measure: the one interleaved-timing loop, a method's frame timed
// through it, and what the controller makes of a frame's commands.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "controller_sim/controller.h"
#include "controller_sim/profile.h"
#include "controller_sim/timed_pipeline.h"
#include "experiments/progress.h"
#include "experiments/settings.h"
#include "host/methods.h"
#include "host/raster/screen_scene.h"
#include "host/scene/scene.h"
#include "host/stats.h"
#include "period/stop.h"
#include "protocol/memory_buffer.h"

namespace fb89::experiments {

class PeriodRuns;
struct GuestOutcome;

// The one interleaved-timing loop: a warm-up round, then `repeat` rounds; each round runs
// every one of `count` settings once, in an order rotated by one from round to round, so
// that slow drifts of the machine fall on all settings alike. run(m, timed) runs setting m;
// `timed` is false in the warm-up round, whose figures are not kept.
// With `progress`, the rounds done show on stderr ("label: 3/11 rounds, about 12 s left").
// A stop asked for (period/stop.h) ends it between rounds.
template <class Run>
void interleave(size_t count, int repeat, const std::string& label, bool progress, Run&& run) {
    ProgressLine line(progress);
    line.start(label);
    const auto rounds = static_cast<uint64_t>(repeat + 1);
    for (int round = -1; round < repeat; ++round) {
        period::throw_if_stopped();
        line.step(static_cast<uint64_t>(round + 1), rounds, "rounds");
        for (size_t k = 0; k < count; ++k)
            run((k + static_cast<size_t>(round + 1)) % count, round >= 0);
    }
}

// One setting's result of interleaved timing: the median time, the counters and commands
// of its last frame (every frame is the same).
struct Measured {
    host::Timing median;
    std::vector<host::Timing> samples;  // every timed round's
    host::Timing setup;  // the whole set-up stage, once: projection and the method's own
    host::Counters counters;
    protocol::MemoryBuffer commands;
    host::Timing last;  // the frame whose commands these are: its time
    // That frame's send times in microseconds from its start, on the clock of the reported
    // hidden-surface time (median.cpu_ms): read on the wall clock, then scaled by median.cpu_ms
    // over the frame's wall time, so that on a loaded machine, where wall time runs ahead of
    // CPU time, no send falls after the host's end. As read when either time is zero.
    std::vector<double> host_send_times_us();
    // measure_settings(): each command's send time in microseconds from the set-up's start
    // (FRAME_BEGIN's 0): measured natively, counted on a 1989 host; empty when there are none
    std::vector<double> send_us;
};
// The interleaved rounds over renderers already set up on `screen`: each one's median
// hidden-surface time, last frame and counters (setup left at zero).
std::vector<Measured> time_renderers(const host::ScreenScene& screen,
                                     const std::vector<host::Renderer*>& renderers, int repeat,
                                     const std::string& label, bool progress);
// Every setting's hidden-surface time on one screen scene, set up once, timed interleaved.
std::vector<Measured> measure_interleaved(const host::ScreenScene& screen,
                                          const std::vector<host::MethodOptions>& settings,
                                          int repeat, const std::string& label, bool progress);
// The same on the experiment's host: here, measure_interleaved(); on a 1989 host
// (s.period), each setting rendered once here for its commands and counts and its time the
// modelled hidden-surface time of its emulated run of `file` (wall = CPU).
std::vector<Measured> measure_settings(const std::string& file, const host::ScreenScene& screen,
                                       const std::vector<host::MethodOptions>& settings,
                                       const ExperimentSettings& s);

// Each setting of `file` (at `size`, 0 x 0 for the scene's own) emulated once on the 1989
// host and priced, with progress shown as "LABEL: i/n emulated runs" (LABEL: `label`, else
// the file).
std::vector<GuestOutcome> run_on_period_host(const std::string& file,
                                             const std::vector<host::MethodOptions>& settings,
                                             ImageSize size, PeriodRuns& period, bool progress,
                                             const std::string& label = {});

// Every method, each with its default options.
std::vector<host::MethodOptions> every_method();

// The two-stage pipeline: the host makes frame n + 1 while the controller tiles frame n, so
// the frame time is the larger of the two and that side bounds it; `ratio` is frame time
// over the other side's (0 when that side takes no time).
struct FrameSplit {
    double frame_ms = 0;
    bool host_bounds = false;
    double ratio = 0;
};
FrameSplit frame_split(double host_ms, double controller_ms);

// What the controller makes of one frame's commands under a profile.
struct ControllerFigures {
    uint64_t commands = 0, fills = 0, spans = 0;
    uint64_t depth_spans = 0, faces = 0;  // the depth commands (zspans, faces)
    uint64_t bus_bytes = 0;               // the frame's commands on the host port
    double controller_ms = 0, bus_ms = 0, frame_ms = 0;
};
ControllerFigures controller_figures(const protocol::MemoryBuffer& commands,
                                     const controller::CostProfile& profile);
// The same of a controller that has run one frame.
ControllerFigures controller_figures(const controller::Controller& ctl);

// A frame through the pipeline in time, and the two sides it is judged against: the host's
// own work (host_us) and the controller alone -- every command waiting at the bus at 0,
// through the same command buffer. A bounded buffer can make the controller alone slower
// than the split's unbounded pipeline (a command crosses the bus only once the buffer has
// room for it, so bus and execution take turns); unbounded, the two are the same. The frame
// never takes less than the larger side or more than their sum (docs/COST_MODEL.md, "The
// pipeline in time"), so overlap() lies in [0, 1].
struct FramePipeline : controller::PipelineFigures {
    double controller_alone_us = 0;
    double max_us() const { return std::max(host_us, controller_alone_us); }
    double sum_us() const { return host_us + controller_alone_us; }
    // The share of the smaller side the pipeline hides: 0 when the frame takes the sum (no
    // overlap), 1 when it takes the max. (Clamped: outside [0, 1] only by rounding.)
    double overlap() const {
        const double smaller = std::min(host_us, controller_alone_us);
        return smaller > 0 ? std::clamp((sum_us() - frame_us) / smaller, 0.0, 1.0) : 1;
    }
};

// Loads a scene file (into `scene`, which the result points into), at the settings' size
// when one is given, and projects it shaded.
host::ScreenScene load_screen(const std::string& file, const ExperimentSettings& s,
                              host::Scene& scene);

}  // namespace fb89::experiments
