#include "host/trace/beam_ray_hybrid.h"

#include <algorithm>
#include <cmath>

#include "host/model/analytic_model.h"

#include "host/raster/scene_measures.h"

namespace fb89::host {

// What one frame carries through the recursion; counts are published once at its end.
struct BeamRayHybrid::Frame {
    protocol::CommandSink& sink;
    TraceCounts rays;
    BeamCounts beams;
    uint64_t fills = 0, pixels_by_beams = 0, pixels_by_rays = 0, windows_to_rays = 0;
    uint64_t level = 0, max_depth = 0;  // the current window's recursion level; the deepest
};

namespace {

struct PixelTrace {
    int x, y;
    const RayTrace* trace;
};

// The window's corner pixels in the order the beam tracer takes them.
void corner_pixels(const PixelRect& w, int xs[4], int ys[4]) {
    xs[0] = w.x0, ys[0] = w.y0;
    xs[1] = w.x1 - 1, ys[1] = w.y0;
    xs[2] = w.x1 - 1, ys[2] = w.y1 - 1;
    xs[3] = w.x0, ys[3] = w.y1 - 1;
}

}  // namespace

void BeamRayHybrid::setup(const ScreenScene& scene) {
    // the beams query what the rays walk: the BVH, or the paper's grid (no grid otherwise)
    const bool grid = m_trace_options.accel == Accel::Grid;
    m_trace.build(scene, m_trace_options.max_reflections, grid ? m_options.grid_density : 0,
                  m_trace_options.accel);
    m_beams = grid ? std::make_unique<BeamTracer>(*m_trace.scene, *m_trace.grid)
                   : std::make_unique<BeamTracer>(*m_trace.scene, m_trace.tracer->bvh());
    m_depth = std::max(1.0, measure_scene(scene).depth_complexity);
    m_width = scene.width;
    m_height = scene.height;
    m_pixels.assign(static_cast<size_t>(scene.width) * scene.height, 0);
    m_row_from.assign(static_cast<size_t>(scene.height), scene.width);
    m_row_to.assign(static_cast<size_t>(scene.height), 0);
    m_pixels_clean = true;
    m_beam_windows.clear();
}

const std::vector<uint8_t>& BeamRayHybrid::beam_mask() const {
    m_beam_mask.assign(static_cast<size_t>(m_width) * m_height, 0);
    for (const PixelRect& w : m_beam_windows)
        for (int y = w.y0; y < w.y1; ++y)
            std::fill_n(&m_beam_mask[static_cast<size_t>(y) * m_width + w.x0], w.width(), 1);
    return m_beam_mask;
}

void BeamRayHybrid::render(const ScreenScene& scene, protocol::CommandSink& sink,
                           HostStats& stats) {
    if (!m_pixels_clean) {  // an earlier frame was cut short (its sink threw)
        std::fill(m_pixels.begin(), m_pixels.end(), 0);
        std::fill(m_row_from.begin(), m_row_from.end(), m_width);
        std::fill(m_row_to.begin(), m_row_to.end(), 0);
    }
    m_pixels_clean = false;
    m_beam_windows.clear();
    Frame frame{sink, {}, {}};
    const PixelRect screen = scene.screen();
    if (!screen.empty()) {
        int xs[4], ys[4];
        corner_pixels(screen, xs, ys);
        RayTrace traces[4];
        const RayTrace* corners[4];
        for (int i = 0; i < 4; ++i) {
            corners[i] = &traces[i];
            for (int j = 0; j < i; ++j)
                if (xs[j] == xs[i] && ys[j] == ys[i]) corners[i] = corners[j];
            if (corners[i] == &traces[i])
                m_trace.tracer->trace_pixel(xs[i], ys[i], traces[i], frame.rays);
        }
        window(frame, screen, corners);
    }
    // ray-traced pixels leave as spans, row by row; the rest of each row is 0 (sends nothing)
    uint64_t spans = 0;
    for (int y = 0; y < scene.height; ++y) {
        const int from = m_row_from[y], to = m_row_to[y];
        if (from >= to) continue;
        uint32_t* row = &m_pixels[static_cast<size_t>(y) * m_width];
        spans += emit_packed_row(row, y, from, to, sink);
        std::fill(row + from, row + to, 0);
        m_row_from[y] = m_width;
        m_row_to[y] = 0;
    }
    m_pixels_clean = true;

    frame.rays.publish(stats.counters);
    frame.beams.publish(stats.counters);
    stats.counters.add("windows_to_rays", frame.windows_to_rays);
    stats.counters.add("pixels_by_beams", frame.pixels_by_beams);
    stats.counters.add("pixels_by_rays", frame.pixels_by_rays);
    stats.counters.add("fills", frame.fills);
    stats.counters.add("spans", spans);
    stats.counters.set("max_depth", frame.max_depth);
}

uint32_t BeamRayHybrid::distinct_first_faces(const RayTrace* const corners[4]) const {
    uint32_t ids[4];
    uint32_t n = 0;
    for (int i = 0; i < 4; ++i) {
        if (corners[i]->count == 0) continue;
        const uint32_t id = m_trace.scene->faces()[corners[i]->hits[0].piece].id;
        if (std::find(ids, ids + n, id) == ids + n) ids[n++] = id;
    }
    return n;
}

void BeamRayHybrid::window(Frame& frame, const PixelRect& w, const RayTrace* const corners[4]) {
    frame.max_depth = std::max(frame.max_depth, frame.level);
    if (w.area() == 1) {  // a single pixel: its ray is its corner's
        rays_for_window(frame, w, corners);
        return;
    }
    // classify the window's beam
    if (m_beams->classify(corners, frame.beams) == BeamClass::Hit) {
        const RayTrace& path = *corners[0];
        if (path.count > 0) {
            frame.sink.fill_rect({w.x0, w.y0, static_cast<uint32_t>(w.width()),
                                  static_cast<uint32_t>(w.height()), path.color});
            ++frame.fills;
        }
        m_beam_windows.push_back(w);
        frame.pixels_by_beams += static_cast<uint64_t>(w.area());
        return;
    }
    // A window at most 4 pixels each way whose own beam failed: its children are at most 2
    // each way, every pixel of theirs a corner whose ray is traced anyway, so their beams
    // could fill no pixel without its ray. Rays for all of it trace the same rays, without
    // the children's beams (or an F_w query to decide so).
    if (w.width() <= 4 && w.height() <= 4) {
        rays_for_window(frame, w, corners);
        return;
    }
    // Expr. 2.7: go on with beams, or hand the window to the ray tracer
    if (std::isfinite(m_options.threshold)) {
        // the cost exceeds the threshold once F_w exceeds this; count no further than that,
        // and not at all when even every face of the scene could not exceed it
        const double scene_faces = m_trace.scene->face_count();
        const double area = static_cast<double>(w.area());
        const double enough =
            model::expr_2_7_faces_at(m_options.threshold, scene_faces, m_depth, area);
        if (enough < scene_faces) {
            // the faces the corner rays hit first lie in the beam: when they already number
            // more than `most`, so would the query's count, which stops at most + 1
            const auto most = static_cast<uint32_t>(std::max(0.0, std::floor(enough)));
            const double faces = distinct_first_faces(corners) > most
                                     ? most + 1.0
                                     : m_beams->faces_in_beam(corners, frame.beams, most);
            if (model::expr_2_7_area(scene_faces, faces, m_depth, area) > m_options.threshold) {
                rays_for_window(frame, w, corners);
                return;
            }
        }
    }
    // subdivide into four, reusing every corner ray already traced
    const int xm = w.width() > 1 ? w.x0 + w.width() / 2 : w.x1;
    const int ym = w.height() > 1 ? w.y0 + w.height() / 2 : w.y1;
    const PixelRect children[4] = {
        {w.x0, w.y0, xm, ym}, {xm, w.y0, w.x1, ym}, {w.x0, ym, xm, w.y1}, {xm, ym, w.x1, w.y1}};
    PixelTrace known[16];
    int known_count = 0;
    int xs[4], ys[4];
    corner_pixels(w, xs, ys);
    for (int i = 0; i < 4; ++i)
        known[known_count++] = {xs[i], ys[i], corners[i]};
    RayTrace traced[12];
    int traced_count = 0;
    for (const PixelRect& child : children) {
        if (child.empty()) continue;
        corner_pixels(child, xs, ys);
        const RayTrace* child_corners[4];
        for (int i = 0; i < 4; ++i) {
            const PixelTrace* found = nullptr;
            for (int k = 0; k < known_count && !found; ++k)
                if (known[k].x == xs[i] && known[k].y == ys[i]) found = &known[k];
            if (!found) {
                RayTrace& t = traced[traced_count++];
                m_trace.tracer->trace_pixel(xs[i], ys[i], t, frame.rays);
                known[known_count] = {xs[i], ys[i], &t};
                found = &known[known_count++];
            }
            child_corners[i] = found->trace;
        }
        ++frame.level;
        window(frame, child, child_corners);
        --frame.level;
    }
}

void BeamRayHybrid::rays_for_window(Frame& frame, const PixelRect& w,
                                    const RayTrace* const corners[4]) {
    int xs[4], ys[4];
    corner_pixels(w, xs, ys);
    RayTrace path;
    for (int y = w.y0; y < w.y1; ++y) {
        m_row_from[y] = std::min(m_row_from[y], w.x0);
        m_row_to[y] = std::max(m_row_to[y], w.x1);
    }
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x) {
            const RayTrace* t = nullptr;
            for (int i = 0; i < 4 && !t; ++i)
                if (xs[i] == x && ys[i] == y) t = corners[i];
            m_pixels[static_cast<size_t>(y) * m_width + x] =
                t ? (t->count > 0 ? packed_pixel(t->color) : 0)
                  : m_trace.tracer->pixel_color(x, y, path, frame.rays);
        }
    frame.pixels_by_rays += static_cast<uint64_t>(w.area());
    ++frame.windows_to_rays;
}

}  // namespace fb89::host
