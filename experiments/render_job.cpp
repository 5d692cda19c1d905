#include "experiments/render_job.h"

#include <cmath>

#include "controller_sim/controller.h"
#include "experiments/period_runs.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "period/host_profile.h"
#include "protocol/stream_reader.h"

namespace fb89::experiments {

namespace {

// The frame `commands` leave in a controller (pixels do not depend on its profile).
struct Frame {
    bool complete = false;
    uint64_t checksum = 0;
    std::vector<uint8_t> pixels;
};

Frame frame_of(const protocol::MemoryBuffer& commands) {
    controller::Controller ctl(controller::load_profile("ideal"));
    commands.replay_into(ctl);
    Frame f;
    f.complete = !ctl.frames().empty();
    if (f.complete) f.checksum = ctl.frames().at(0).checksum;
    const auto px = ctl.framebuffer().pixels();
    f.pixels.assign(px.begin(), px.end());
    return f;
}

protocol::MemoryBuffer decoded(const std::vector<uint8_t>& stream) {
    protocol::StreamReader reader(stream, "the guest's stream");
    protocol::MemoryBuffer commands;
    protocol::Command c;
    while (reader.next(c))
        commands.submit(c);
    return commands;
}

PeriodFrame period_frame(GuestOutcome&& outcome, const period::HostProfile& profile,
                         const protocol::MemoryBuffer& native, bool check) {
    PeriodFrame f;
    f.cost = std::move(outcome.cost);
    f.cpu = profile.cpu;
    f.fpu = profile.fpu;
    f.guest_instructions = outcome.instructions;
    f.emulated_seconds = outcome.emulated_seconds;
    if (check && outcome.emulated) {
        f.checked = true;
        f.differing_pixels = frames_differing(native, decoded(outcome.stream), &f.same_frame);
    }
    return f;
}

constexpr int kSetup = static_cast<int>(period::Phase::Setup);
constexpr int kHiddenSurface = static_cast<int>(period::Phase::HiddenSurface);

}  // namespace

std::vector<double> period_send_times_us(const period::HostCost& cost, std::size_t commands) {
    std::vector<double> out;
    for (const period::SendTime& s : cost.sends) {
        if (s.phase != kHiddenSurface) continue;
        if (s.commands < out.size() || s.commands > commands) return {};
        out.resize(s.commands, s.ms * 1e3);
    }
    if (out.size() != commands) return {};
    return out;
}

FramePipeline pipeline_figures(const protocol::MemoryBuffer& commands,
                               const std::vector<double>& send_us, double host_end_us,
                               const controller::CostProfile& profile, uint64_t buffer_bytes,
                               ControllerFigures* controller,
                               std::vector<controller::CommandTiming>* timings) {
    controller::Controller ctl(profile);
    controller::TimedPipeline pipe(buffer_bytes);
    controller::TimedPipeline alone(buffer_bytes);  // every command waiting at 0
    if (const uint32_t bytes = profile.largest_tiling_bytes(); bytes > buffer_bytes)
        throw std::invalid_argument("--buffer: " + std::to_string(buffer_bytes) +
                                    " bytes is less than a command of " + profile.name +
                                    " (up to " + std::to_string(bytes) + " bytes)");
    const auto& all = commands.commands();
    if (send_us.size() != all.size())
        throw std::invalid_argument(std::to_string(send_us.size()) + " send times for " +
                                    std::to_string(all.size()) + " commands");
    if (timings) timings->resize(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        ctl.execute(all[i]);
        const auto& cost = ctl.last_cost();
        pipe.push({controller::whole_ns(send_us[i]), cost.bytes, cost.bus_us, cost.exec_us},
                  timings ? &(*timings)[i] : nullptr);
        alone.push({0, cost.bytes, cost.bus_us, cost.exec_us});
    }
    if (controller) *controller = controller_figures(ctl);
    return {pipe.finish(controller::whole_ns(host_end_us)), alone.finish(0).frame_us};
}

void write_commands(protocol::StreamWriter& writer, const MethodRun& run) {
    const auto& all = run.commands.commands();
    if (!writer.timed() || run.send_us.size() != all.size()) {
        for (const protocol::Command& c : all)
            writer.submit(c);
        return;
    }
    // whole nanoseconds, as the pipeline takes them; FRAME_BEGIN is sent at 0 by definition
    using controller::to_ns;
    int64_t last = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const bool begin = std::holds_alternative<protocol::FrameBegin>(all[i]);
        if (!begin) writer.send_time(last = std::max(last, to_ns(run.send_us[i])));
        if (std::holds_alternative<protocol::FrameEnd>(all[i]))
            writer.host_end(std::max(last, to_ns(run.host_frame_ms * 1e3)));
        writer.submit(all[i]);
        if (begin) last = 0;
    }
}

std::vector<double> frame_send_times(std::vector<double> hs_us, double setup_us,
                                     std::size_t commands) {
    if (hs_us.empty() || hs_us.size() != commands) return {};
    for (double& t : hs_us)
        t += setup_us;
    hs_us.front() = 0;  // FRAME_BEGIN: the clear starts as the host sets up
    return hs_us;
}

uint64_t frames_differing(const protocol::MemoryBuffer& a, const protocol::MemoryBuffer& b,
                          bool* same_checksum) {
    const Frame fa = frame_of(a), fb = frame_of(b);
    if (same_checksum) *same_checksum = fa.complete && fb.complete && fa.checksum == fb.checksum;
    if (fa.pixels.size() != fb.pixels.size())
        return std::max(fa.pixels.size(), fb.pixels.size()) / 3;
    uint64_t n = 0;
    for (size_t i = 0; i + 2 < fa.pixels.size(); i += 3)
        n += fa.pixels[i] != fb.pixels[i] || fa.pixels[i + 1] != fb.pixels[i + 1] ||
             fa.pixels[i + 2] != fb.pixels[i + 2];
    return n;
}

RenderResult run_render_job(const RenderJob& job) {
    RenderResult result;
    const controller::CostProfile profile = controller::load_profile(job.controller);

    // load and set-up, as the paper times them: the scene once, each method's own set-up
    host::Stopwatch stage;
    result.scene = host::load_scene(job.scene);
    if (job.size.width > 0) {
        result.scene.width = job.size.width;
        result.scene.height = job.size.height;
    }
    const host::Timing load = stage.elapsed();
    stage.restart();
    host::Counters projection_counters;
    result.screen = host::project_scene(result.scene, host::ColorMode::Shaded, projection_counters);
    const host::Timing projection = stage.elapsed();

    std::vector<host::Renderer*> renderers;
    for (const host::MethodOptions& o : job.methods) {
        MethodRun run;
        run.options = o;
        run.renderer = host::make_renderer(o);
        host::Stopwatch clock;
        run.renderer->setup(result.screen);
        run.stats.load = load;
        run.stats.setup = projection;
        run.stats.setup += clock.elapsed();
        for (const auto& [name, value] : projection_counters.items())
            run.stats.counters.add(name, value);
        renderers.push_back(run.renderer.get());
        result.runs.push_back(std::move(run));
    }

    // hidden-surface: interleaved rounds here (the commands are the last round's)
    std::vector<Measured> measured = time_renderers(result.screen, renderers, job.repeat, job.scene,
                                                    job.progress && !job.period);
    std::vector<std::vector<double>> send_us(result.runs.size());
    for (size_t m = 0; m < result.runs.size(); ++m) {
        MethodRun& run = result.runs[m];
        send_us[m] = measured[m].host_send_times_us();
        run.commands = std::move(measured[m].commands);
        run.stats.hidden_surface = measured[m].median;
        run.stats.hidden_surface_samples = std::move(measured[m].samples);
        for (const auto& [name, value] : measured[m].counters.items())
            run.stats.counters.add(name, value);
        run.stats.end_to_end = run.stats.load;
        run.stats.end_to_end += run.stats.setup;
        run.stats.end_to_end += run.stats.hidden_surface;
        run.host_frame_ms = run.stats.setup.cpu_ms + run.stats.hidden_surface.cpu_ms;
    }

    // on a 1989 host: each method emulated once, priced, and (asked) its frame checked
    if (job.period) {
        std::vector<GuestOutcome> outcomes =
            run_on_period_host(job.scene, job.methods, job.size, *job.period, job.progress);
        for (size_t m = 0; m < result.runs.size(); ++m) {
            MethodRun& run = result.runs[m];
            run.period = period_frame(std::move(outcomes[m]), job.period->profile(), run.commands,
                                      job.check_frames);
            const auto& phases = run.period->cost.phases;
            run.host_frame_ms = phases[static_cast<int>(period::Phase::Setup)].ms +
                                phases[static_cast<int>(period::Phase::HiddenSurface)].ms;
        }
    }

    // the controller tiles what the host decided; its cost is modelled, never timed
    for (size_t m = 0; m < result.runs.size(); ++m) {
        MethodRun& run = result.runs[m];
        // the pipeline in time from the send times: measured natively (a job of 0 rounds
        // renders once, untimed, and has none), counted on a 1989 host; the controller's
        // figures come from the same pass
        const std::size_t n = run.commands.size();
        const double setup_us =
            run.period ? run.period->cost.phases[kSetup].ms * 1e3 : run.stats.setup.cpu_ms * 1e3;
        run.send_us = frame_send_times(
            run.period ? period_send_times_us(run.period->cost, n) : std::move(send_us[m]),
            setup_us, n);
        if (run.send_us.empty()) {
            run.controller = controller_figures(run.commands, profile);
        } else {
            run.buffer_bytes = job.buffer_bytes.value_or(profile.command_buffer_bytes);
            run.pipeline = pipeline_figures(run.commands, run.send_us, run.host_frame_ms * 1e3,
                                            profile, run.buffer_bytes, &run.controller);
            run.setup_end_us = setup_us;
        }
        run.split = frame_split(run.host_frame_ms, run.controller.frame_ms);
    }
    return result;
}

}  // namespace fb89::experiments
