// After the paper (issue 53): the methods that came next, on the paper's scenes, beside the
// plain method and the paper's own hybrid. This part: the hierarchical Z-buffer (hzb.h)
// against the Z-buffer and the §3 hybrid at the paper's threshold, on A-F and on the ideal
// scene (§2, Fig. 2.3) at depth complexities 1 to 64, natively and timed interleaved.
#include <fmt/format.h>

#include <stdexcept>

#include "experiments/experiments.h"
#include "experiments/measure.h"
#include "host/raster/scene_measures.h"
#include "host/raster/screen_setup.h"
#include "host/scene/generators.h"

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

}  // namespace

Table experiment_successors(const ExperimentSettings& s) {
    if (s.period)
        throw std::invalid_argument(
            "experiment successors: on a 1989 host not yet: natively only (drop --host)");
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
    for (int layers : {1, 2, 4, 8, 16, 32, 64}) {
        host::Scene scene;
        const host::ScreenScene screen = ideal_ladder_screen(s, layers, scene);
        const std::string label = fmt::format("ideal-{}", layers);
        add_rows(label, screen, scene.face_count,
                 measure_interleaved(screen, settings, s.repeat, label, s.progress));
    }
    return table;
}

}  // namespace fb89::experiments
