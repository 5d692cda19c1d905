#include "experiments/measure.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "controller_sim/controller.h"
#include "experiments/period_runs.h"
#include "experiments/render_job.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"

namespace fb89::experiments {

std::vector<Measured> time_renderers(const host::ScreenScene& screen,
                                     const std::vector<host::Renderer*>& renderers, int repeat,
                                     const std::string& label, bool progress) {
    std::vector<std::vector<host::Timing>> times(renderers.size());
    std::vector<Measured> out(renderers.size());
    interleave(renderers.size(), repeat, label, progress, [&](size_t m, bool timed) {
        out[m].commands.clear();
        out[m].commands.time_packets(protocol::kSendPacketCommands);  // send times, by packet
        host::HostStats stats;
        host::Timing t = host::render_frame(*renderers[m], screen, out[m].commands, stats);
        out[m].last = t;
        if (timed) {
            times[m].push_back(t);
            out[m].samples.push_back(t);
        }
        out[m].counters = stats.counters;
    });
    for (size_t m = 0; m < renderers.size(); ++m)
        out[m].median = host::median(times[m]);
    return out;
}

std::vector<double> Measured::host_send_times_us() {
    std::vector<double> us = commands.send_times_us();
    const double hs_us = median.cpu_ms * 1e3;
    if (hs_us <= 0 || last.wall_ms <= 0) return us;
    const double scale = hs_us / (last.wall_ms * 1e3);
    for (double& t : us)
        t = std::min(t * scale, hs_us);
    return us;
}

std::vector<Measured> measure_interleaved(const host::ScreenScene& screen,
                                          const std::vector<host::MethodOptions>& settings,
                                          int repeat, const std::string& label, bool progress) {
    std::vector<std::unique_ptr<host::Renderer>> renderers;
    std::vector<host::Renderer*> pointers;
    std::vector<host::Timing> setups;
    for (const host::MethodOptions& o : settings) {
        renderers.push_back(host::make_renderer(o));
        pointers.push_back(renderers.back().get());
        host::Stopwatch clock;
        renderers.back()->setup(screen);
        setups.push_back(clock.elapsed());
    }
    std::vector<Measured> out = time_renderers(screen, pointers, repeat, label, progress);
    for (size_t m = 0; m < settings.size(); ++m)
        out[m].setup = setups[m];
    return out;
}

std::vector<GuestOutcome> run_on_period_host(const std::string& file,
                                             const std::vector<host::MethodOptions>& settings,
                                             ImageSize size, PeriodRuns& period, bool progress,
                                             const std::string& label) {
    const std::string wh = size.width > 0 ? fmt::format("{}x{}", size.width, size.height) : "";
    std::vector<GuestJob> jobs;
    for (const host::MethodOptions& o : settings)
        jobs.push_back({file, guest_options(o, wh)});
    period.set_progress(progress, label.empty() ? file : label);
    return period.run_outcomes(jobs);
}

namespace {

// "A.json (scene 3 of 14)": the scene's file name and, among several, where it stands.
std::string progress_label(const ExperimentSettings& s, const std::string& file) {
    std::string label = std::filesystem::path(file).filename().string();
    const auto at = std::find(s.scenes.begin(), s.scenes.end(), file);
    if (s.scenes.size() > 1 && at != s.scenes.end())
        label += fmt::format(" (scene {} of {})", at - s.scenes.begin() + 1, s.scenes.size());
    return label;
}

}  // namespace

std::vector<Measured> measure_settings(const std::string& file, const host::ScreenScene& screen,
                                       const std::vector<host::MethodOptions>& settings,
                                       const ExperimentSettings& s) {
    const std::string label = progress_label(s, file);
    if (!s.period) {
        std::vector<Measured> out =
            measure_interleaved(screen, settings, s.repeat, label, s.progress);
        // the set-up stage is the projection (timed once here) and the method's own
        if (screen.world) {
            host::Counters counters;
            host::Stopwatch clock;
            host::project_scene(*screen.world, host::ColorMode::Shaded, counters);
            const host::Timing projection = clock.elapsed();
            for (Measured& m : out)
                m.setup += projection;
        }
        for (Measured& m : out)
            m.send_us =
                frame_send_times(m.host_send_times_us(), m.setup.cpu_ms * 1e3, m.commands.size());
        return out;
    }
    // commands and counts from one frame here, untimed
    std::vector<Measured> out = measure_interleaved(screen, settings, 0, label, false);
    const std::vector<GuestOutcome> runs =
        run_on_period_host(file, settings, s.size, *s.period, s.progress, label);
    for (size_t m = 0; m < settings.size(); ++m) {
        const auto& phases = runs[m].cost.phases;
        const double ms = phases[static_cast<int>(period::Phase::HiddenSurface)].ms;
        out[m].median = {ms, ms};
        // the whole set-up stage: projection and the method's own
        const double setup = phases[static_cast<int>(period::Phase::Setup)].ms;
        out[m].setup = {setup, setup};
        out[m].send_us =
            frame_send_times(period_send_times_us(runs[m].cost, out[m].commands.size()),
                             setup * 1e3, out[m].commands.size());
    }
    return out;
}

std::vector<host::MethodOptions> every_method() {
    std::vector<host::MethodOptions> settings;
    for (const host::MethodInfo& m : host::methods())
        settings.emplace_back(m.method);
    return settings;
}

FrameSplit frame_split(double host_ms, double controller_ms) {
    FrameSplit f;
    f.host_bounds = host_ms >= controller_ms;
    f.frame_ms = std::max(host_ms, controller_ms);
    const double other = std::min(host_ms, controller_ms);
    f.ratio = other > 0 ? f.frame_ms / other : 0;
    return f;
}

ControllerFigures controller_figures(const protocol::MemoryBuffer& commands,
                                     const controller::CostProfile& profile) {
    controller::Controller ctl(profile);
    commands.replay_into(ctl);
    return controller_figures(ctl);
}

ControllerFigures controller_figures(const controller::Controller& ctl) {
    const auto& frame = ctl.frames().at(0);
    ControllerFigures f;
    f.commands = frame.total().commands;
    f.bus_bytes = frame.total().bytes;
    f.fills = frame.ops[protocol::opcode_index(protocol::Opcode::FillRect)].commands;
    f.spans = frame.ops[protocol::opcode_index(protocol::Opcode::DrawSpan)].commands;
    f.depth_spans = frame.ops[protocol::opcode_index(protocol::Opcode::DepthSpan)].commands;
    f.faces = frame.ops[protocol::opcode_index(protocol::Opcode::Face)].commands;
    f.controller_ms = frame.controller_busy_us / 1e3;
    f.bus_ms = frame.bus_busy_us / 1e3;
    f.frame_ms = frame.end_us / 1e3;
    return f;
}

host::ScreenScene load_screen(const std::string& file, const ExperimentSettings& s,
                              host::Scene& scene) {
    scene = host::load_scene(file);
    if (s.size.width > 0) {
        scene.width = s.size.width;
        scene.height = s.size.height;
    }
    host::Counters counters;
    return host::project_scene(scene, host::ColorMode::Shaded, counters);
}

}  // namespace fb89::experiments
