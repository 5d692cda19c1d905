// The paper's §2 and §3 experiments on the raster methods: Figs. 2.1, 2.4 and 3.1, the
// hybrid against the Z-buffer, the threshold sweep, and speed against accuracy.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <fmt/format.h>

#include "experiments/compare.h"
#include "experiments/depth_agreement.h"
#include "experiments/experiments.h"
#include "experiments/id_pass.h"
#include "experiments/measure.h"
#include "host/model/analytic_model.h"
#include "host/raster/scene_measures.h"
#include "host/raster/screen_setup.h"
#include "host/raster/warnock.h"
#include "host/scene/generators.h"
#include "protocol/memory_buffer.h"

namespace fb89::experiments {

namespace {

struct Setting {
    std::string label;
    host::MethodOptions options;
};

host::MethodOptions warnock_with(host::WindowTest test) {
    host::MethodOptions o(host::Method::Warnock);
    o.warnock.window_test = test;
    return o;
}

const std::vector<Setting>& fig2_1_methods() {
    static const std::vector<Setting> methods{
        {"zbuffer", host::Method::ZBuffer},
        {"scanline", host::Method::ScanLine},
        {"warnock-area", warnock_with(host::WindowTest::Area)},
        {"warnock-centres", warnock_with(host::WindowTest::Centres)}};
    return methods;
}

}  // namespace

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
        std::vector<host::MethodOptions> settings;
        for (const auto& m : methods)
            settings.push_back(m.options);
        std::vector<Measured> results = measure_settings(file, screen, settings, s);
        const double zbuffer_ms = results[0].median.cpu_ms;
        for (size_t m = 0; m < methods.size(); ++m) {
            const ControllerFigures ctl = controller_figures(results[m].commands, profile);
            const auto& c = results[m].counters;
            const host::Timing med = results[m].median;
            table.add(
                {file, methods[m].label, std::to_string(scene.face_count),
                 fixed(measures.depth_complexity, 3), fixed(med.wall_ms, 3), fixed(med.cpu_ms, 3),
                 fixed(med.cpu_ms / zbuffer_ms, 3), std::to_string(c.get("window_samples")),
                 std::to_string(c.get("face_computations")), std::to_string(c.get("depth_tests")),
                 std::to_string(ctl.commands), std::to_string(ctl.fills), std::to_string(ctl.spans),
                 fixed(ctl.controller_ms, 3), fixed(ctl.bus_ms, 3), fixed(ctl.frame_ms, 3)});
        }
    }
    return table;
}

namespace {

uint64_t warnock_samples(const host::ScreenScene& screen, host::WindowTest test,
                         uint64_t* sorts = nullptr) {
    host::Warnock warnock({test, {}});
    protocol::MemoryBuffer discard;
    host::HostStats stats;
    warnock.render(screen, discard, stats);
    if (sorts) *sorts = stats.counters.get("face_sorts");
    return stats.counters.get("window_samples");
}

host::ScreenScene ideal_screen(int e_s, int layers, uint64_t f_v) {
    const double cell = e_s / std::sqrt(static_cast<double>(f_v));
    const host::Scene scene = host::ideal_scene(e_s, e_s, layers, cell, cell, 0.5);
    host::Counters counters;
    return host::project_scene(scene, host::ColorMode::Shaded, counters);
}

}  // namespace

// Eq. 2.4 against the counts. For A-F, as in the paper: E_s = sqrt(W H), D the measured
// depth complexity, F_v = F / D. For ideal scenes the model is exact.
Table experiment_fig2_4(const ExperimentSettings& s) {
    Table table({"scene", "e_s", "faces_on_screen", "depth_complexity", "f_v", "predicted",
                 "measured_area", "measured_centres", "area_over_predicted", "sort_computations",
                 "predicted_sort_computations"});
    // the scenes given, then 3 depths x 7 F_v of ideal scenes (F_v = 4, 16, ..., 16384)
    const std::array<int, 3> all_layers = {1, 2, 4};
    const uint64_t total = s.scenes.size() + all_layers.size() * 7;
    uint64_t done = 0;
    ProgressLine line(s.progress);
    line.start("fig2.4");
    for (const auto& file : s.scenes) {
        line.step(done++, total, "scenes");
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
    for (int layers : all_layers) {
        for (uint64_t f_v = 4; f_v <= 16384; f_v *= 4) {
            line.step(done++, total, "scenes");
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
    return table;
}

std::vector<double> threshold_ramp(double from, double to, int steps) {
    std::vector<double> out;
    if (steps <= 1) return {from};
    for (int i = 0; i < steps; ++i)
        out.push_back(from * std::pow(to / from, static_cast<double>(i) / (steps - 1)));
    return out;
}

// The hybrid at each threshold (plus 0 = pure Z-buffer and inf = pure Warnock), timed
// interleaved per scene.
Table sweep_threshold(const ExperimentSettings& s, const std::vector<double>& thresholds,
                      const host::MethodOptions& base) {
    Table table({"scene", "threshold", "hs_wall_ms", "hs_cpu_ms", "ratio_to_zbuffer",
                 "window_samples", "face_computations", "windows_handed_over", "pixels_zbuffer",
                 "pixels_warnock", "depth_tests", "commands", "fills", "spans", "controller_ms",
                 "bus_ms", "frame_ms"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    std::vector<host::MethodOptions> settings;
    for (double t : thresholds) {
        host::MethodOptions o = base;
        o.method = host::Method::Hybrid;
        o.hybrid.threshold = t;
        settings.push_back(o);
    }
    for (const auto& file : s.scenes) {
        host::Scene scene;
        host::ScreenScene screen = load_screen(file, s, scene);
        std::vector<Measured> results = measure_settings(file, screen, settings, s);
        double zbuffer_ms = 0;
        for (size_t i = 0; i < thresholds.size(); ++i)
            if (thresholds[i] == 0) zbuffer_ms = results[i].median.cpu_ms;
        for (size_t i = 0; i < thresholds.size(); ++i) {
            const ControllerFigures ctl = controller_figures(results[i].commands, profile);
            const auto& c = results[i].counters;
            const host::Timing med = results[i].median;
            table.add({file,
                       std::isinf(thresholds[i]) ? "inf" : fmt::format("{:.6g}", thresholds[i]),
                       fixed(med.wall_ms, 3), fixed(med.cpu_ms, 3),
                       zbuffer_ms > 0 ? fixed(med.cpu_ms / zbuffer_ms, 3) : "",
                       std::to_string(c.get("window_samples")),
                       std::to_string(c.get("face_computations")),
                       std::to_string(c.get("windows_handed_over")),
                       std::to_string(c.get("hybrid_pixels_zbuffer")),
                       std::to_string(c.get("hybrid_pixels_warnock")),
                       std::to_string(c.get("depth_tests")), std::to_string(ctl.commands),
                       std::to_string(ctl.fills), std::to_string(ctl.spans),
                       fixed(ctl.controller_ms, 3), fixed(ctl.bus_ms, 3), fixed(ctl.frame_ms, 3)});
        }
    }
    return table;
}

namespace {

// The face-id buffer a setting produces, through its commands and the controller (with a
// depth word of `depth_bits` for the depth commands).
controller::Framebuffer id_frame(const host::Scene& scene, const host::MethodOptions& o,
                                 uint32_t depth_bits) {
    auto renderer = host::make_renderer(o);
    return id_framebuffer(scene, *renderer, depth_bits);
}

}  // namespace

// Speed against accuracy: exact settings beside approximate ones (the thinker may fill a
// window of side >= k with a face in front that misses up to a fraction eps of its
// centres), and the two methods whose controller tests depth itself; pixels wrong are
// counted against the Z-buffer's face-id buffer, in the frame the profile's controller
// draws: for the depth commands with its depth word, whose ties (two faces within its step,
// either kept) are counted apart in pixels_ties.
Table experiment_accuracy(const ExperimentSettings& s, double threshold) {
    Table table({"scene", "setting", "method", "threshold", "approx_min_side", "approx_epsilon",
                 "hs_cpu_ms", "ratio_to_zbuffer", "commands", "controller_ms", "pixels_wrong",
                 "fraction_wrong", "pixels_ties", "depth_bits"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    std::vector<Setting> settings{{"zbuffer", host::Method::ZBuffer}};
    for (host::Method method : {host::Method::DepthSpans, host::Method::Faces})
        settings.push_back({std::string(host::method_info(method).name), method});
    for (host::Method method : {host::Method::Warnock, host::Method::Hybrid}) {
        for (auto [k, eps] : {std::pair{0, 0.0}, {32, 0.01}, {16, 0.02}, {8, 0.05}, {4, 0.1}}) {
            host::MethodOptions o(method);
            o.hybrid.threshold = threshold;
            o.warnock.approx = {k, eps};
            const std::string_view name = host::method_info(method).name;
            settings.push_back(
                {fmt::format("{}{}", name, k ? fmt::format(" k={} eps={}", k, eps) : " exact"), o});
        }
    }
    for (const auto& file : s.scenes) {
        host::Scene scene;
        host::ScreenScene screen = load_screen(file, s, scene);
        std::vector<host::MethodOptions> options;
        for (const auto& st : settings)
            options.push_back(st.options);
        std::vector<Measured> results = measure_settings(file, screen, options, s);
        const controller::Framebuffer truth = id_frame(scene, settings[0].options, 32);
        host::Counters counters;
        const host::ScreenScene id_screen =
            host::project_scene(scene, host::ColorMode::FaceId, counters);
        const double zbuffer_ms = results[0].median.cpu_ms;
        for (size_t i = 0; i < settings.size(); ++i) {
            const auto& o = settings[i].options;
            const ControllerFigures ctl = controller_figures(results[i].commands, profile);
            const bool depth = host::method_info(o.method).depth_commands;
            const controller::Framebuffer ids =
                i == 0 ? truth : id_frame(scene, o, profile.depth_bits);
            const uint64_t wrong = id_differences(truth, ids).total();
            std::string ties, bits;  // the depth commands' ties of the profile's word
            if (depth) {
                ties =
                    std::to_string(depth_agreement(id_screen, truth, ids, profile.depth_bits).ties);
                bits = std::to_string(profile.depth_bits);
            }
            table.add(
                {file, settings[i].label, std::string(host::method_info(o.method).name),
                 o.method == host::Method::Hybrid ? fmt::format("{:.6g}", o.hybrid.threshold) : "",
                 std::to_string(o.warnock.approx.min_side),
                 fmt::format("{}", o.warnock.approx.epsilon), fixed(results[i].median.cpu_ms, 3),
                 fixed(results[i].median.cpu_ms / zbuffer_ms, 3), std::to_string(ctl.commands),
                 fixed(ctl.controller_ms, 3), std::to_string(wrong),
                 fmt::format("{:.6f}", static_cast<double>(wrong) /
                                           static_cast<double>(screen.width * screen.height)),
                 ties, bits});
        }
    }
    return table;
}

Table experiment_fig3_1(const ExperimentSettings& s, double chosen) {
    std::vector<double> thresholds{0.0, host::kPaperThreshold, chosen};
    for (double t : threshold_ramp(0.0002, 2.0, 13))
        thresholds.push_back(t);
    thresholds.push_back(std::numeric_limits<double>::infinity());
    std::sort(thresholds.begin(), thresholds.end());
    thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());
    return sweep_threshold(s, thresholds, host::MethodOptions(host::Method::Hybrid));
}

// The headline of §3: the hybrid at the calibrated and at the paper's threshold against
// the pure Z-buffer, interleaved, on each scene.
Table experiment_hybrid(const ExperimentSettings& s, double chosen) {
    Table table({"scene", "faces", "zbuffer_ms", "hybrid_ms", "hybrid_over_zbuffer", "speedup_pct",
                 "paper_hybrid_ms", "paper_over_zbuffer", "threshold", "pixels_zbuffer_pct",
                 "zbuffer_commands", "hybrid_commands", "zbuffer_controller_ms",
                 "hybrid_controller_ms"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    host::MethodOptions zbuffer(host::Method::ZBuffer), hybrid(host::Method::Hybrid),
        paper(host::Method::Hybrid);
    hybrid.hybrid.threshold = chosen;
    paper.hybrid.threshold = host::kPaperThreshold;
    for (const auto& file : s.scenes) {
        host::Scene scene;
        host::ScreenScene screen = load_screen(file, s, scene);
        auto r = measure_settings(file, screen, {zbuffer, hybrid, paper}, s);
        const double z = r[0].median.cpu_ms, h = r[1].median.cpu_ms, p = r[2].median.cpu_ms;
        const ControllerFigures cz = controller_figures(r[0].commands, profile);
        const ControllerFigures ch = controller_figures(r[1].commands, profile);
        const double share = 100.0 *
                             static_cast<double>(r[1].counters.get("hybrid_pixels_zbuffer")) /
                             (static_cast<double>(screen.width) * screen.height);
        table.add({file, std::to_string(scene.face_count), fixed(z, 3), fixed(h, 3),
                   fixed(h / z, 3), fixed(100.0 * (z - h) / z, 1), fixed(p, 3), fixed(p / z, 3),
                   fmt::format("{:.6g}", chosen), fixed(share, 1), std::to_string(cz.commands),
                   std::to_string(ch.commands), fixed(cz.controller_ms, 3),
                   fixed(ch.controller_ms, 3)});
    }
    return table;
}

}  // namespace fb89::experiments
