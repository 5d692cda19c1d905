// After the paper (issue 53): the methods that came next, on the paper's scenes, beside the
// plain method and the paper's own hybrid, timed interleaved.
//   successors: the hierarchical Z-buffer (hzb.h) against the Z-buffer and the §3 hybrid at
//     the paper's threshold, on A-F and on the ideal scene (§2, Fig. 2.3) at depth
//     complexities 1 to 64;
//   successors-rays: multi-level ray tracing (mlrta.h) against the ray tracer and the §4
//     beam-ray hybrid, on G, H, I and the Cornell boxes at each size; the ray tracer on the
//     kd-tree as well, so that the tree's share of the gain and the beams' stand apart, and
//     mlrta with its rays one by one (mlrta-scalar), so that the packets' share does too.
#include <fmt/format.h>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "controller_sim/controller.h"
#include "experiments/experiments.h"
#include "experiments/measure.h"
#include "host/raster/scene_measures.h"
#include "host/raster/screen_setup.h"
#include "host/scene/generators.h"
#include "protocol/output_file.h"

namespace fb89::experiments {

namespace {

// The ideal scene at the settings' size (1024 x 780 when none is given): `layers` layers of
// 16 x 16-pixel squares, a ½-pixel gap between them, layer k at depth (k + 1) / (layers + 1).
host::ScreenScene ideal_ladder_screen(const ExperimentSettings& s, int layers, host::Scene& scene) {
    scene = host::ideal_scene(s.size.width > 0 ? s.size.width : 1024,
                              s.size.height > 0 ? s.size.height : 780, layers, 16, 16, 0.5);
    host::Counters counters;
    return host::project_scene(scene, host::ColorMode::Shaded, counters);
}

// The frame a frame's commands leave in the controller, as a checksum.
uint64_t frame_checksum(const protocol::MemoryBuffer& commands) {
    controller::Controller ctl(controller::load_profile("ideal"));
    commands.replay_into(ctl);
    return ctl.framebuffer().checksum();
}

}  // namespace

// On a 1989 host the guest reads its scene from a file: the ideal ladder's rungs are written
// as scene files (the `ideal` generator, screen space, the same squares) into a scratch folder
// of the system's temporary folder, removed when the experiment ends.
class ScratchScenes {
  public:
    ScratchScenes()
        : m_dir(std::filesystem::temp_directory_path() /
                fmt::format("fb89-successors-{}-{}", ::getpid(),
                            std::chrono::steady_clock::now().time_since_epoch().count())) {
        std::filesystem::create_directories(m_dir);
    }
    ~ScratchScenes() {
        std::error_code ignored;
        std::filesystem::remove_all(m_dir, ignored);
    }
    ScratchScenes(const ScratchScenes&) = delete;
    ScratchScenes& operator=(const ScratchScenes&) = delete;

    std::string ideal(int width, int height, int layers) const {
        const std::filesystem::path path = m_dir / fmt::format("ideal-{}.json", layers);
        const nlohmann::json scene = {
            {"camera", {{"projection", "screen"}}},
            {"image", {{"width", width}, {"height", height}}},
            {"objects",
             {{{"generator", "ideal"}, {"layers", layers}, {"cell", 16}, {"gap", 0.5}}}}};
        protocol::write_output(path, scene.dump(2) + "\n", protocol::Publish::Now);
        return path.string();
    }

  private:
    std::filesystem::path m_dir;
};

Table experiment_successors(const ExperimentSettings& s) {
    Table table({"scene", "method", "faces", "depth_complexity", "hs_cpu_ms", "speedup",
                 "depth_tests", "faces_rasterised", "nodes_culled", "faces_culled", "pyramid_tests",
                 "commands", "controller_ms", "frame_ms"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    host::MethodOptions paper(host::Method::Hybrid);
    paper.hybrid.threshold = host::kPaperThreshold;
    const std::vector<host::MethodOptions> settings{host::Method::ZBuffer, paper,
                                                    host::Method::Hzb};
    const char* const labels[] = {"zbuffer", "hybrid-0.04", "hzb"};
    const auto add_rows = [&](const std::string& label, const host::ScreenScene& screen,
                              uint32_t faces, std::vector<Measured> r) {
        const host::SceneMeasures m = host::measure_scene(screen);
        const double z = r[0].median.cpu_ms;
        for (std::size_t k = 0; k < r.size(); ++k) {
            const host::Counters& c = r[k].counters;
            // a counter the method does not keep is left empty, not 0
            const auto counted = [&](std::string_view name) {
                for (const auto& [key, value] : c.items())
                    if (key == name) return std::to_string(value);
                return std::string();
            };
            const ControllerFigures ctl = controller_figures(r[k].commands, profile);
            const double ms = r[k].median.cpu_ms;
            table.add({label, labels[k], std::to_string(faces), fixed(m.depth_complexity, 3),
                       fixed(ms, 3), fixed(ms > 0 ? z / ms : 0.0, 3), counted("depth_tests"),
                       counted("faces_rasterised"), counted("hzb_nodes_culled"),
                       counted("hzb_faces_culled"), counted("hzb_pyramid_tests"),
                       std::to_string(ctl.commands), fixed(ctl.controller_ms, 3),
                       fixed(ctl.frame_ms, 3)});
        }
    };
    for (const auto& file : s.scenes) {
        host::Scene scene;
        const host::ScreenScene screen = load_screen(file, s, scene);
        add_rows(file, screen, scene.face_count, measure_settings(file, screen, settings, s));
    }
    std::optional<ScratchScenes> scratch;
    if (s.period) scratch.emplace();
    for (int layers : {1, 2, 4, 8, 16, 32, 64}) {
        host::Scene scene;
        const std::string label = fmt::format("ideal-{}", layers);
        if (s.period) {
            const std::string file =
                scratch->ideal(s.size.width > 0 ? s.size.width : 1024,
                               s.size.height > 0 ? s.size.height : 780, layers);
            const host::ScreenScene screen = load_screen(file, s, scene);
            add_rows(label, screen, scene.face_count, measure_settings(file, screen, settings, s));
            continue;
        }
        const host::ScreenScene screen = ideal_ladder_screen(s, layers, scene);
        add_rows(label, screen, scene.face_count,
                 measure_interleaved(screen, settings, s.repeat, label, s.progress));
    }
    return table;
}

Table experiment_successors_rays(const ExperimentSettings& s, const std::vector<ImageSize>& sizes,
                                 double beam_threshold) {
    Table table({"scene", "width", "height", "method", "hs_cpu_ms", "speedup", "rays",
                 "pixels_by_beams", "beams", "entry_points", "mean_entry_depth", "nodes_visited",
                 "ray_face_tests", "commands", "controller_ms", "frame_ms", "same_frame"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    host::MethodOptions kd(host::Method::RayTrace), beam(host::Method::Beam),
        scalar(host::Method::Mlrta);
    kd.trace.accel = host::Accel::Kd;
    beam.beam.threshold = beam_threshold;
    scalar.trace.packets = false;
    const std::vector<host::MethodOptions> settings{host::Method::RayTrace, kd, beam,
                                                    host::Method::Mlrta, scalar};
    const char* const labels[] = {"raytrace", "raytrace-kd", "beam", "mlrta", "mlrta-scalar"};
    for (const auto& file : s.scenes)
        for (const ImageSize& size : sizes) {
            ExperimentSettings at = s;
            at.size = size;
            host::Scene scene;
            const host::ScreenScene screen = load_screen(file, at, scene);
            auto r = measure_settings(file, screen, settings, at);
            const double rays_ms = r[0].median.cpu_ms;
            const uint64_t reference = frame_checksum(r[0].commands);
            for (std::size_t k = 0; k < r.size(); ++k) {
                const host::Counters& c = r[k].counters;
                const ControllerFigures ctl = controller_figures(r[k].commands, profile);
                const double ms = r[k].median.cpu_ms;
                const uint64_t nodes = c.get("bvh_nodes_visited") + c.get("kd_nodes_visited") +
                                       c.get("cells_visited") + c.get("beam_nodes_visited") +
                                       c.get("packet_nodes_visited");
                const uint64_t entries = c.get("entry_points");
                // the beam method fills windows where the others send spans: the frames compared
                const bool same = frame_checksum(r[k].commands) == reference;
                table.add({file, std::to_string(size.width), std::to_string(size.height), labels[k],
                           fixed(ms, 3), fixed(ms > 0 ? rays_ms / ms : 0.0, 3),
                           std::to_string(c.get("rays")), std::to_string(c.get("pixels_by_beams")),
                           std::to_string(c.get("beams")), std::to_string(entries),
                           entries > 0 ? fixed(static_cast<double>(c.get("entry_depth_total")) /
                                                   static_cast<double>(entries),
                                               2)
                                       : std::string(),
                           std::to_string(nodes), std::to_string(c.get("ray_face_tests")),
                           std::to_string(ctl.commands), fixed(ctl.controller_ms, 3),
                           fixed(ctl.frame_ms, 3), same ? "yes" : "NO"});
            }
        }
    return table;
}

}  // namespace fb89::experiments
