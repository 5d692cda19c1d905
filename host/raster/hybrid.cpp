#include "host/raster/hybrid.h"

#include <algorithm>
#include <cmath>

#include "host/model/analytic_model.h"

namespace fb89::host {

double expr_3_1_cost(double faces, double depth, double area) {
    if (faces <= 0 || area <= 0) return 0;
    // F_w <= D: log4(F_w / D) taken as 0, which is Expr. 3.1 with D = F_w
    return model::expr_3_1_area(faces, std::min(depth, faces), area);
}

Hybrid::Hybrid(HybridOptions options, WarnockOptions warnock)
    : m_options(options), m_warnock(warnock) {}

void Hybrid::setup(const ScreenScene& scene) {
    m_warnock.setup(scene);
    m_zbuffer.setup(scene);
    // each face's screen area and box, for the depth-complexity estimates
    m_areas.resize(scene.faces.size());
    for (size_t i = 0; i < scene.faces.size(); ++i) {
        const ScreenFace& f = scene.faces[i];
        const SnappedPoint* p = scene.points_of(f);
        double twice = 0;
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for (uint32_t k = 0; k < f.point_count; ++k) {
            const SnappedPoint& a = p[k];
            const SnappedPoint& b = p[(k + 1) % f.point_count];
            twice += static_cast<double>(a.x * b.y - b.x * a.y);
            const double x = static_cast<double>(a.x) / kSubpixel;
            const double y = static_cast<double>(a.y) / kSubpixel;
            x0 = std::min(x0, x), x1 = std::max(x1, x);
            y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
        m_areas[i] = {std::abs(twice) / (2.0 * kSubpixel * kSubpixel), x0, y0, x1, y1};
    }
    m_all.resize(scene.faces.size());
    for (uint32_t i = 0; i < m_all.size(); ++i)
        m_all[i] = i;
    m_scene_depth = window_depth(scene.screen(), m_all);
    m_setup_for = &scene;
}

// Faces' area inside the window over the window's area, at least 1.
double Hybrid::window_depth(const PixelRect& w, std::span<const uint32_t> faces) const {
    double covered = 0;
    for (uint32_t i : faces) {
        const FaceArea& a = m_areas[i];
        const double bw = a.x1 - a.x0, bh = a.y1 - a.y0;
        const double iw = std::min<double>(a.x1, w.x1) - std::max<double>(a.x0, w.x0);
        const double ih = std::min<double>(a.y1, w.y1) - std::max<double>(a.y0, w.y0);
        if (iw <= 0 || ih <= 0 || bw <= 0 || bh <= 0) continue;
        covered += a.area * (iw * ih) / (bw * bh);
    }
    return std::max(1.0, covered / static_cast<double>(w.area()));
}

void Hybrid::render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) {
    if (m_setup_for != &scene || m_areas.size() != scene.faces.size()) setup(scene);
    m_zcounts = {};
    m_zbuffer_pixels = 0;
    // the looker's first window is the screen with every face: when the Z-buffer takes it,
    // Warnock need not even sort the faces into their first list
    if (take(scene, scene.screen(), m_all, sink)) {
        stats.counters.add("windows_handed_over", 1);
    } else {
        m_warnock.set_handoff(this);
        m_warnock.render(scene, sink, stats);
    }
    const uint64_t total = static_cast<uint64_t>(scene.screen().area());
    stats.counters.add("hybrid_pixels_zbuffer", m_zbuffer_pixels);
    stats.counters.add("hybrid_pixels_warnock", total - m_zbuffer_pixels);
    stats.counters.add("depth_tests", m_zcounts.depth_tests);
    stats.counters.add("pixels_written", m_zcounts.pixels_written);
    stats.counters.add("spans", m_zcounts.spans);
}

// The looker's test: hand the window to the Z-buffer when Expr. 3.1 exceeds the threshold.
bool Hybrid::take(const ScreenScene& scene, const PixelRect& w, std::span<const uint32_t> faces,
                  protocol::CommandSink& sink) {
    if (faces.empty()) return false;
    const double depth =
        m_options.depth == DepthEstimate::Scene ? m_scene_depth : window_depth(w, faces);
    const double cost =
        expr_3_1_cost(static_cast<double>(faces.size()), depth, static_cast<double>(w.area()));
    if (!(cost > m_options.threshold)) return false;
    m_zbuffer.render_window(scene, faces, w, sink, m_zcounts);
    m_zbuffer_pixels += static_cast<uint64_t>(w.area());
    return true;
}

}  // namespace fb89::host
