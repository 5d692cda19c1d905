// The paper's §4 experiments: the beam-ray hybrid against the ray tracer alone.
//   fig4.8 / fig4.11 / fig4.12: time against resolution, whole process from reading the
//     scene to the last command delivered (as the paper timed it), interleaved;
//   fig4.7 / fig4.10: the frames with every ray-traced pixel blacked out, and the share of
//     pixels beams decided;
//   beam-threshold: time and pixels by beams against the Expr. 2.7 threshold, with the
//     check that every threshold shows the ray tracer's frame.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include <fmt/format.h>

#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "experiments/beam_mask.h"
#include "experiments/experiments.h"
#include "experiments/measure.h"
#include "experiments/period_runs.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "host/trace/beam_ray_hybrid.h"

namespace fb89::experiments {

namespace {

// One run of the whole process for one setting: load, project, set up, render.
struct EndToEnd {
    host::Timing end_to_end, hidden_surface;
    host::Counters counters;
    protocol::MemoryBuffer commands;
    std::vector<uint8_t> beam_mask;
};

EndToEnd run_end_to_end(const std::string& file, ImageSize size,
                        const host::MethodOptions& options) {
    EndToEnd out;
    host::Stopwatch clock;
    host::Scene scene = host::load_scene(file);
    if (size.width > 0) {
        scene.width = size.width;
        scene.height = size.height;
    }
    host::HostStats stats;
    host::ScreenScene screen = host::project_scene(scene, host::ColorMode::Shaded, stats.counters);
    auto renderer = host::make_renderer(options);
    renderer->setup(screen);
    out.hidden_surface = host::render_frame(*renderer, screen, out.commands, stats);
    out.end_to_end = clock.elapsed();
    out.counters = stats.counters;
    if (auto* beam = dynamic_cast<host::BeamRayHybrid*>(renderer.get()))
        out.beam_mask = beam->beam_mask();
    return out;
}

// Interleaved rounds of the whole process, one per setting each round; medians.
struct EndToEndMedians {
    host::Timing end_to_end, hidden_surface;
    EndToEnd last;
};
std::vector<EndToEndMedians> measure_end_to_end(const std::string& file, ImageSize size,
                                                const std::vector<host::MethodOptions>& settings,
                                                int repeat, bool progress) {
    std::vector<std::vector<host::Timing>> e2e(settings.size()), hs(settings.size());
    std::vector<EndToEndMedians> out(settings.size());
    const std::string label = fmt::format("{} {}x{}", file, size.width, size.height);
    interleave(settings.size(), repeat, label, progress, [&](size_t m, bool timed) {
        out[m].last = run_end_to_end(file, size, settings[m]);
        if (!timed) return;
        e2e[m].push_back(out[m].last.end_to_end);
        hs[m].push_back(out[m].last.hidden_surface);
    });
    for (size_t m = 0; m < settings.size(); ++m) {
        out[m].end_to_end = host::median(e2e[m]);
        out[m].hidden_surface = host::median(hs[m]);
    }
    return out;
}

host::MethodOptions trace_setting(host::Method method, double threshold, host::Accel accel) {
    host::MethodOptions o(method);
    o.beam.threshold = threshold;
    o.trace.accel = accel;
    return o;
}

double beam_share(const host::Counters& c) {
    const double all = static_cast<double>(c.get("pixels_by_beams") + c.get("pixels_by_rays"));
    return all > 0 ? 100.0 * static_cast<double>(c.get("pixels_by_beams")) / all : 0;
}

uint64_t trace_frame_checksum(const protocol::MemoryBuffer& commands) {
    controller::Controller ctl(controller::load_profile("ideal"));
    commands.replay_into(ctl);
    return ctl.framebuffer().checksum();
}

}  // namespace

Table experiment_beam_resolution(const ExperimentSettings& s, const std::vector<ImageSize>& sizes,
                                 double threshold) {
    Table table({"scene", "width", "height", "method", "e2e_wall_ms", "e2e_cpu_ms", "hs_cpu_ms",
                 "ratio_to_raytrace", "speedup_pct", "pixels_by_beams_pct", "rays", "beams",
                 "beam_queries", "fills", "spans", "controller_ms", "same_frame"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    for (const auto& file : s.scenes)
        for (const ImageSize& size : sizes) {
            const std::vector<host::MethodOptions> methods{
                trace_setting(host::Method::RayTrace, 0, s.accel),
                trace_setting(host::Method::Beam, threshold, s.accel)};
            auto r = measure_end_to_end(file, size, methods, s.period ? 0 : s.repeat,
                                        s.progress && !s.period);
            if (s.period) {
                // on a 1989 host: each counted once, load + set-up + hidden-surface priced
                const std::string wxh = fmt::format("{}x{}", size.width, size.height);
                s.period->set_progress(s.progress, fmt::format("{} {}", file, wxh));
                const auto costs = s.period->run({{file, guest_options(methods[0], wxh)},
                                                  {file, guest_options(methods[1], wxh)}});
                for (size_t m = 0; m < 2; ++m) {
                    const double e2e = costs[m].end_to_end_ms();
                    const double hs =
                        costs[m].phases[static_cast<int>(period::Phase::HiddenSurface)].ms;
                    r[m].end_to_end = {e2e, e2e};
                    r[m].hidden_surface = {hs, hs};
                }
            }
            const double rays_ms = r[0].end_to_end.cpu_ms;
            const bool same = trace_frame_checksum(r[0].last.commands) ==
                              trace_frame_checksum(r[1].last.commands);
            for (size_t m = 0; m < 2; ++m) {
                const auto& c = r[m].last.counters;
                const ControllerFigures ctl = controller_figures(r[m].last.commands, profile);
                const double ms = r[m].end_to_end.cpu_ms;
                table.add({file, std::to_string(size.width), std::to_string(size.height),
                           m == 0 ? "raytrace" : "beam", fixed(r[m].end_to_end.wall_ms, 2),
                           fixed(ms, 2), fixed(r[m].hidden_surface.cpu_ms, 2),
                           fixed(ms / rays_ms, 3), fixed(100.0 * (rays_ms - ms) / rays_ms, 1),
                           fixed(beam_share(c), 1), std::to_string(c.get("rays")),
                           std::to_string(c.get("beams")), std::to_string(c.get("beam_queries")),
                           std::to_string(ctl.fills), std::to_string(ctl.spans),
                           fixed(ctl.controller_ms, 2), same ? "yes" : "NO"});
            }
        }
    return table;
}

Table experiment_beam_masks(const ExperimentSettings& s, double threshold,
                            const std::string& out_dir) {
    Table table({"scene", "width", "height", "pixels_by_beams_pct", "beams", "beam_hits",
                 "windows_to_rays", "image", "mask"});
    std::filesystem::create_directories(out_dir);
    for (const auto& file : s.scenes) {
        EndToEnd run =
            run_end_to_end(file, s.size, trace_setting(host::Method::Beam, threshold, s.accel));
        controller::Controller ctl(controller::load_profile("ideal"));
        run.commands.replay_into(ctl);
        const std::string stem = std::filesystem::path(file).stem().string();
        const std::string image = out_dir + "/" + stem + "_beam.png";
        const std::string mask = out_dir + "/" + stem + "_mask.png";
        controller::write_png(image, ctl.framebuffer());
        controller::write_png(mask, masked_by_beams(ctl.framebuffer(), run.beam_mask));
        const auto& c = run.counters;
        table.add({file, std::to_string(ctl.framebuffer().width()),
                   std::to_string(ctl.framebuffer().height()), fixed(beam_share(c), 1),
                   std::to_string(c.get("beams")), std::to_string(c.get("beam_hits")),
                   std::to_string(c.get("windows_to_rays")), image, mask});
    }
    return table;
}

std::vector<double> beam_threshold_ramp() {
    std::vector<double> out{0.0};
    for (double t : threshold_ramp(0.01, 1000.0, 16))
        out.push_back(t);
    out.push_back(std::numeric_limits<double>::infinity());
    return out;
}

Table experiment_beam_threshold(const ExperimentSettings& s, const std::vector<double>& ramp) {
    Table table({"scene", "threshold", "hs_wall_ms", "hs_cpu_ms", "ratio_to_raytrace",
                 "pixels_by_beams_pct", "rays", "beams", "beam_queries", "window_face_counts",
                 "query_face_tests", "same_frame_as_raytrace"});
    for (const auto& file : s.scenes) {
        host::Scene scene;
        host::ScreenScene screen = load_screen(file, s, scene);
        std::vector<host::MethodOptions> settings{
            trace_setting(host::Method::RayTrace, 0, s.accel)};
        for (double t : ramp)
            settings.push_back(trace_setting(host::Method::Beam, t, s.accel));
        auto r = measure_settings(file, screen, settings, s);
        const double rays_ms = r[0].median.cpu_ms;
        const uint64_t rays_frame = trace_frame_checksum(r[0].commands);
        for (size_t m = 0; m < settings.size(); ++m) {
            const auto& c = r[m].counters;
            const std::string threshold =
                m == 0 ? "raytrace" : fmt::format("{:.6g}", settings[m].beam.threshold);
            table.add({file, threshold, fixed(r[m].median.wall_ms, 3), fixed(r[m].median.cpu_ms, 3),
                       fixed(r[m].median.cpu_ms / rays_ms, 3), fixed(beam_share(c), 1),
                       std::to_string(c.get("rays")), std::to_string(c.get("beams")),
                       std::to_string(c.get("beam_queries")),
                       std::to_string(c.get("window_face_counts")),
                       std::to_string(c.get("query_face_tests")),
                       trace_frame_checksum(r[m].commands) == rays_frame ? "yes" : "NO"});
        }
    }
    return table;
}

}  // namespace fb89::experiments
