#include "host/raster/warnock.h"

#include <algorithm>
#include <cmath>

#include "host/raster/coverage.h"
#include "host/raster/depth.h"

namespace fb89::host {

namespace {

// Edge function at the pixel corner (cx, cy), in the same units as at centres.
inline int64_t at_corner(const EdgeFunction& e, int64_t cx, int64_t cy) {
    return e.nx * kSubpixel * cx + e.ny * kSubpixel * cy + e.k0 - (kSubpixel / 2) * (e.nx + e.ny);
}

// Largest |z| term of a plane over a window: bounds depth_at's rounding error.
inline double magnitude(const DepthPlane& p, const PixelRect& w) {
    return std::abs(p.a) * std::max(std::abs(w.x0 + 0.5), std::abs(w.x1 - 0.5)) +
           std::abs(p.b) * std::max(std::abs(w.y0 + 0.5), std::abs(w.y1 - 0.5)) + std::abs(p.c);
}

int side_class(int side) {
    int k = 0;
    while (side >= 2 && k < 15)
        side >>= 1, ++k;
    return k;
}

}  // namespace

const char* to_string(WindowTest t) {
    return t == WindowTest::Area ? "area" : "centres";
}

void WarnockCounts::publish(Counters& c) const {
    c.add("window_samples", samples);
    c.add("face_computations", face_sorts + face_splits);
    c.add("face_sorts", face_sorts);
    c.add("face_splits", face_splits);
    c.add("face_drops", face_drops);
    c.add("empty_windows", empty_windows);
    c.add("surrounded_windows", surrounded);
    c.add("pixel_windows", pixel_windows);
    c.add("fills", fills);
    c.add("filled_pixels", filled_pixels);
    c.add("front_tests", front_tests);
    c.set("max_depth", max_depth);
    if (handed_over) c.add("windows_handed_over", handed_over);
    if (approximate_fills) c.add("approximate_fills", approximate_fills);
    for (size_t k = 0; k < fills_by_side.size(); ++k)
        if (fills_by_side[k])
            c.add("fills_side_" + std::to_string(1u << k) + "+", fills_by_side[k]);
}

void Warnock::setup(const ScreenScene& scene) {
    m_boxes.resize(scene.faces.size());
    for (size_t i = 0; i < scene.faces.size(); ++i) {
        const ScreenFace& f = scene.faces[i];
        const SnappedPoint* p = scene.points_of(f);
        Box b{p[0].x, p[0].y, p[0].x, p[0].y};
        for (uint32_t k = 1; k < f.point_count; ++k) {
            b.x0 = std::min(b.x0, p[k].x), b.x1 = std::max(b.x1, p[k].x);
            b.y0 = std::min(b.y0, p[k].y), b.y1 = std::max(b.y1, p[k].y);
        }
        m_boxes[i] = b;
    }
}

void Warnock::render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) {
    if (m_boxes.size() != scene.faces.size()) setup(scene);
    m_scene = &scene;
    m_sink = &sink;
    m_counts = {};
    m_arena.clear();
    const PixelRect screen = scene.screen();
    for (uint32_t i = 0; i < scene.faces.size(); ++i)
        if (belongs(i, screen)) m_arena.push_back(i);
    if (!screen.empty()) look(screen, 0, m_arena.size(), 0);
    m_counts.publish(stats.counters);
}

// The looker: sample the window; if the thinker fails, split it and look at each part.
void Warnock::look(const PixelRect& w, size_t begin, size_t end, uint64_t depth) {
    m_counts.max_depth = std::max(m_counts.max_depth, depth);
    if (m_handoff && m_handoff->take(*m_scene, w, {m_arena.data() + begin, end - begin}, *m_sink)) {
        ++m_counts.handed_over;
        return;
    }
    if (think(w, begin, end)) return;

    // split evenly into (up to) four: no empty sub-window
    int xs[3] = {w.x0, w.x0 + w.width() / 2, w.x1};
    int ys[3] = {w.y0, w.y0 + w.height() / 2, w.y1};
    PixelRect kids[4];
    int n = 0;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c)
            if (xs[c + 1] > xs[c] && ys[r + 1] > ys[r])
                kids[n++] = {xs[c], ys[r], xs[c + 1], ys[r + 1]};

    // sort each face into the sub-windows it reaches
    const size_t count = end - begin, base = m_arena.size();
    m_arena.resize(base + static_cast<size_t>(n) * count);
    size_t filled[4] = {0, 0, 0, 0};
    for (size_t i = begin; i < end; ++i) {
        const uint32_t f = m_arena[i];
        int hits = 0;
        for (int k = 0; k < n; ++k) {
            if (!belongs(f, kids[k])) continue;
            m_arena[base + static_cast<size_t>(k) * count + filled[k]++] = f;
            ++hits;
        }
        if (hits == 1)
            ++m_counts.face_sorts;
        else if (hits > 1)
            ++m_counts.face_splits;
        else
            ++m_counts.face_drops;
    }
    for (int k = 0; k < n; ++k) {
        const size_t first = base + static_cast<size_t>(k) * count;
        look(kids[k], first, first + filled[k], depth + 1);
    }
    m_arena.resize(base);
}

// The thinker: empty, a 1-pixel window, or a surrounder in front; otherwise fail.
bool Warnock::think(const PixelRect& w, size_t begin, size_t end) {
    ++m_counts.samples;
    if (begin == end) {
        ++m_counts.empty_windows;
        return true;
    }
    if (w.width() == 1 && w.height() == 1) return resolve_pixel(w, begin, end);
    for (size_t i = begin; i < end; ++i) {
        const uint32_t s = m_arena[i];
        if (surrounds(s, w) && in_front(s, w, begin, end)) {
            ++m_counts.surrounded;
            fill(w, m_scene->faces[s].color);
            return true;
        }
    }
    // approximate: a large window nearly covered by a face in front of the others
    if (m_approx.min_side > 0 && std::min(w.width(), w.height()) >= m_approx.min_side) {
        for (size_t i = begin; i < end; ++i) {
            const uint32_t s = m_arena[i];
            if (nearly_surrounds(s, w) && in_front(s, w, begin, end)) {
                ++m_counts.approximate_fills;
                fill(w, m_scene->faces[s].color);
                return true;
            }
        }
    }
    return false;
}

// Point sampling at the pixel's centre with the shared coverage and depth rule.
bool Warnock::resolve_pixel(const PixelRect& w, size_t begin, size_t end) {
    ++m_counts.pixel_windows;
    const ScreenFace* best = nullptr;
    double best_z = 0;
    for (size_t i = begin; i < end; ++i) {
        const ScreenFace& f = m_scene->faces[m_arena[i]];
        if (!covers(m_scene->edges_of(f), f.point_count, w.x0, w.y0)) continue;
        double z = depth_at(f.depth, w.x0, w.y0);
        if (!best || nearer(z, f.id, best_z, best->id)) {
            best = &f;
            best_z = z;
        }
    }
    if (best)
        fill(w, best->color);
    else
        ++m_counts.empty_windows;
    return true;
}

// Is face s nearer than every other face of the window at every pixel centre? The planes
// differ linearly, so the corner centres bound the window; the margin covers rounding.
bool Warnock::in_front(uint32_t s, const PixelRect& w, size_t begin, size_t end) {
    const ScreenFace& S = m_scene->faces[s];
    const int cx[2] = {w.x0, w.x1 - 1}, cy[2] = {w.y0, w.y1 - 1};
    double zs[4];
    for (int k = 0; k < 4; ++k)
        zs[k] = depth_at(S.depth, cx[k & 1], cy[k >> 1]);
    const double mag_s = magnitude(S.depth, w);
    uint64_t tests = 0;
    bool ok = true;
    for (size_t i = begin; i < end && ok; ++i) {
        const ScreenFace& G = m_scene->faces[m_arena[i]];
        if (G.id == S.id) continue;  // another piece of the same face
        ++tests;
        if (G.depth.a == S.depth.a && G.depth.b == S.depth.b && G.depth.c == S.depth.c) {
            ok = S.id < G.id;  // identical planes tie everywhere: the lower id wins
            continue;
        }
        const double margin = 0x1p-50 * (mag_s + magnitude(G.depth, w));
        for (int k = 0; k < 4 && ok; ++k)
            ok = depth_at(G.depth, cx[k & 1], cy[k >> 1]) - zs[k] > margin;
    }
    m_counts.front_tests += tests;
    return ok;
}

bool Warnock::surrounds(uint32_t face, const PixelRect& w) const {
    const ScreenFace& f = m_scene->faces[face];
    const EdgeFunction* edges = m_scene->edges_of(f);
    if (m_test == WindowTest::Centres) {
        if (f.bounds.x0 > w.x0 || f.bounds.x1 < w.x1 || f.bounds.y0 > w.y0 || f.bounds.y1 < w.y1)
            return false;
        for (int y = w.y0; y < w.y1; ++y) {
            int xb = 0, xe = 0;
            if (!row_span(edges, f.point_count, y, w.x0, w.x1, xb, xe) || xb != w.x0 || xe != w.x1)
                return false;
        }
        return true;
    }
    // area: the face contains the closed window, i.e. all four corners
    const Box& b = m_boxes[face];
    if (b.x0 > w.x0 * kSubpixel || b.x1 < w.x1 * kSubpixel || b.y0 > w.y0 * kSubpixel ||
        b.y1 < w.y1 * kSubpixel)
        return false;
    for (uint32_t i = 0; i < f.point_count; ++i) {
        const EdgeFunction& e = edges[i];
        if (at_corner(e, w.x0, w.y0) < 0 || at_corner(e, w.x1, w.y0) < 0 ||
            at_corner(e, w.x0, w.y1) < 0 || at_corner(e, w.x1, w.y1) < 0)
            return false;
    }
    return true;
}

// Covers all but a fraction epsilon of the window's pixel centres.
bool Warnock::nearly_surrounds(uint32_t face, const PixelRect& w) const {
    const ScreenFace& f = m_scene->faces[face];
    const EdgeFunction* edges = m_scene->edges_of(f);
    const double allowed = m_approx.epsilon * static_cast<double>(w.area());
    double missed = 0;
    for (int y = w.y0; y < w.y1 && missed <= allowed; ++y) {
        int xb = 0, xe = 0;
        missed += row_span(edges, f.point_count, y, w.x0, w.x1, xb, xe) ? w.width() - (xe - xb)
                                                                        : w.width();
    }
    return missed <= allowed;
}

bool Warnock::belongs(uint32_t face, const PixelRect& w) const {
    return m_test == WindowTest::Area ? interiors_overlap(face, w) : covers_a_centre(face, w);
}

// Separating axes of a convex polygon and a rectangle: the box axes, then the edges.
bool Warnock::interiors_overlap(uint32_t face, const PixelRect& w) const {
    const Box& b = m_boxes[face];
    if (b.x1 <= w.x0 * kSubpixel || b.x0 >= w.x1 * kSubpixel || b.y1 <= w.y0 * kSubpixel ||
        b.y0 >= w.y1 * kSubpixel)
        return false;
    const ScreenFace& f = m_scene->faces[face];
    const EdgeFunction* edges = m_scene->edges_of(f);
    for (uint32_t i = 0; i < f.point_count; ++i) {
        const EdgeFunction& e = edges[i];
        // the window corner furthest into the face's side of this edge
        if (at_corner(e, e.nx > 0 ? w.x1 : w.x0, e.ny > 0 ? w.y1 : w.y0) <= 0) return false;
    }
    return true;
}

bool Warnock::covers_a_centre(uint32_t face, const PixelRect& w) const {
    const ScreenFace& f = m_scene->faces[face];
    const int y0 = std::max(w.y0, f.bounds.y0), y1 = std::min(w.y1, f.bounds.y1);
    const int x0 = std::max(w.x0, f.bounds.x0), x1 = std::min(w.x1, f.bounds.x1);
    if (x0 >= x1) return false;
    const EdgeFunction* edges = m_scene->edges_of(f);
    for (int y = y0; y < y1; ++y) {
        int xb = 0, xe = 0;
        if (row_span(edges, f.point_count, y, x0, x1, xb, xe)) return true;
    }
    return false;
}

void Warnock::fill(const PixelRect& w, protocol::Rgb color) {
    m_sink->fill_rect(
        {w.x0, w.y0, static_cast<uint32_t>(w.width()), static_cast<uint32_t>(w.height()), color});
    ++m_counts.fills;
    m_counts.filled_pixels += static_cast<uint64_t>(w.area());
    ++m_counts.fills_by_side[static_cast<size_t>(side_class(std::min(w.width(), w.height())))];
}

}  // namespace fb89::host
