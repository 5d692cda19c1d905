#include "cli/experiments.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "controller_sim/controller.h"
#include "host/model/analytic_model.h"
#include "host/raster/renderer.h"
#include "host/raster/scene_measures.h"
#include "host/raster/warnock.h"
#include "host/scene/generators.h"
#include "host/scene/projection.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"

namespace fb89::cli {

std::string Table::csv() const {
    std::string out;
    auto line = [&out](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i)
            out += (i ? "," : "") + cells[i];
        out += "\n";
    };
    line(m_columns);
    for (const auto& r : m_rows)
        line(r);
    return out;
}

std::string Table::text() const {
    std::vector<size_t> width(m_columns.size());
    for (size_t i = 0; i < m_columns.size(); ++i)
        width[i] = m_columns[i].size();
    for (const auto& r : m_rows)
        for (size_t i = 0; i < r.size() && i < width.size(); ++i)
            width[i] = std::max(width[i], r[i].size());
    std::string out;
    auto line = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i)
            out += fmt::format("{:>{}}  ", cells[i], width[i]);
        out += "\n";
    };
    line(m_columns);
    for (const auto& r : m_rows)
        line(r);
    return out;
}

namespace {

struct Method {
    std::string label;
    host::RenderOptions options;
};

const std::vector<Method>& fig2_1_methods() {
    static const std::vector<Method> methods{{"zbuffer", {"zbuffer", "area"}},
                                             {"scanline", {"scanline", "area"}},
                                             {"warnock-area", {"warnock", "area"}},
                                             {"warnock-centres", {"warnock", "centres"}}};
    return methods;
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

std::string fixed(double v, int digits) {
    return fmt::format("{:.{}f}", v, digits);
}

}  // namespace

// Interleaved timing: every round renders each method once, in a rotating order, so
// slow drifts of the machine fall on all methods alike; medians per method.
Table experiment_fig2_1(const ExperimentSettings& s) {
    Table table({"scene", "method", "faces", "depth_complexity", "hs_wall_ms", "hs_cpu_ms",
                 "ratio_to_zbuffer", "window_samples", "face_computations", "depth_tests",
                 "commands", "fills", "spans", "controller_ms", "bus_ms", "frame_ms"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    for (const auto& file : s.scenes) {
        host::Scene scene;
        host::ScreenScene screen = load_screen(file, s, scene);
        host::SceneMeasures measures = host::measure_scene(screen);
        const auto& methods = fig2_1_methods();
        std::vector<std::unique_ptr<host::Renderer>> renderers;
        std::vector<std::vector<host::Timing>> times(methods.size());
        std::vector<host::HostStats> last(methods.size());
        std::vector<protocol::MemoryBuffer> buffers(methods.size());
        for (const auto& m : methods) {
            renderers.push_back(host::make_renderer(m.options));
            renderers.back()->setup(screen);
        }
        for (int round = -1; round < s.repeat; ++round) {  // round -1 warms up
            if (s.progress)
                std::cerr << fmt::format("\r{}: round {}/{}   ", file, round + 1, s.repeat);
            for (size_t k = 0; k < methods.size(); ++k) {
                size_t m = (k + static_cast<size_t>(round + 1)) % methods.size();
                buffers[m].clear();
                host::HostStats stats;
                host::Timing t = host::render_frame(*renderers[m], screen, buffers[m], stats);
                if (round >= 0) times[m].push_back(t);
                last[m] = stats;
            }
        }
        if (s.progress) std::cerr << "\r" << std::string(60, ' ') << "\r";
        const double zbuffer_ms = host::median(times[0]).cpu_ms;
        for (size_t m = 0; m < methods.size(); ++m) {
            controller::Controller ctl(profile);
            buffers[m].replay_into(ctl);
            const auto& frame = ctl.frames().at(0);
            const auto& c = last[m].counters;
            host::Timing med = host::median(times[m]);
            table.add({file, methods[m].label, std::to_string(scene.face_count),
                       fixed(measures.depth_complexity, 3), fixed(med.wall_ms, 3),
                       fixed(med.cpu_ms, 3), fixed(med.cpu_ms / zbuffer_ms, 3),
                       std::to_string(c.get("window_samples")),
                       std::to_string(c.get("face_computations")),
                       std::to_string(c.get("depth_tests")), std::to_string(frame.total().commands),
                       std::to_string(
                           frame.ops[protocol::opcode_index(protocol::Opcode::FillRect)].commands),
                       std::to_string(
                           frame.ops[protocol::opcode_index(protocol::Opcode::DrawSpan)].commands),
                       fixed(frame.controller_busy_us / 1e3, 3), fixed(frame.bus_busy_us / 1e3, 3),
                       fixed(frame.end_us / 1e3, 3)});
        }
    }
    return table;
}

namespace {

uint64_t warnock_samples(const host::ScreenScene& screen, host::WindowTest test,
                         uint64_t* sorts = nullptr) {
    host::Warnock warnock(test);
    protocol::MemoryBuffer discard;
    host::HostStats stats;
    warnock.render(screen, discard, stats);
    if (sorts) *sorts = stats.counters.get("face_sorts");
    return stats.counters.get("window_samples");
}

host::ScreenScene ideal_screen(int e_s, int layers, uint64_t f_v) {
    host::Scene scene;
    scene.projection = host::Projection::Screen;
    scene.width = scene.height = e_s;
    const double cell = e_s / std::sqrt(static_cast<double>(f_v));
    for (auto& p : host::generate_ideal(e_s, e_s, layers, cell, cell, 0.5)) {
        host::Face f;
        f.vertices = std::move(p.vertices);
        f.id = scene.face_count++;
        scene.faces.push_back(std::move(f));
    }
    host::Counters counters;
    return host::project_scene(scene, host::ColorMode::Shaded, counters);
}

}  // namespace

// Eq. 2.4 against the counts. For A-F, as in the paper: E_s = sqrt(W H), D the measured
// depth complexity, F_v = F / D. For ideal scenes the model is exact.
Table experiment_fig2_4(const ExperimentSettings& s) {
    Table table({"scene", "e_s", "faces", "depth_complexity", "f_v", "predicted", "measured_area",
                 "measured_centres", "area_over_predicted", "sort_computations",
                 "predicted_sort_computations"});
    for (const auto& file : s.scenes) {
        host::Scene scene;
        host::ScreenScene screen = load_screen(file, s, scene);
        host::SceneMeasures m = host::measure_scene(screen);
        const double e_s = std::sqrt(static_cast<double>(screen.width) * screen.height);
        const double d = m.depth_complexity, f_v = static_cast<double>(m.faces) / d;
        const double predicted = host::model::window_samples(e_s, f_v);
        uint64_t sorts = 0;
        const uint64_t area = warnock_samples(screen, host::WindowTest::Area, &sorts);
        const uint64_t centres = warnock_samples(screen, host::WindowTest::Centres);
        table.add({file, fixed(e_s, 1), std::to_string(m.faces), fixed(d, 3), fixed(f_v, 1),
                   fixed(predicted, 0), std::to_string(area), std::to_string(centres),
                   fixed(static_cast<double>(area) / predicted, 3), std::to_string(sorts),
                   fixed(host::model::sort_face_computations(static_cast<double>(m.faces), d), 0)});
    }
    const int e_s = 512;
    for (int layers : {1, 2, 4}) {
        for (uint64_t f_v = 4; f_v <= 16384; f_v *= 4) {
            if (s.progress) std::cerr << fmt::format("\rideal D={} F_v={}   ", layers, f_v);
            host::ScreenScene screen = ideal_screen(e_s, layers, f_v);
            uint64_t sorts = 0;
            const uint64_t area = warnock_samples(screen, host::WindowTest::Area, &sorts);
            const uint64_t centres = warnock_samples(screen, host::WindowTest::Centres);
            const double predicted = host::model::window_samples(e_s, static_cast<double>(f_v));
            table.add(
                {fmt::format("ideal-D{}-Fv{}", layers, f_v), std::to_string(e_s),
                 std::to_string(layers * f_v), std::to_string(layers), std::to_string(f_v),
                 fixed(predicted, 0), std::to_string(area), std::to_string(centres),
                 fixed(static_cast<double>(area) / predicted, 3), std::to_string(sorts),
                 fixed(host::model::scene_sort_face_computations(static_cast<double>(f_v), layers),
                       0)});
        }
    }
    if (s.progress) std::cerr << "\r" << std::string(40, ' ') << "\r";
    return table;
}

}  // namespace fb89::cli
