#include "host/raster/screen_setup.h"

#include <algorithm>
#include <cmath>

#include "host/raster/coverage.h"

namespace fb89::host {

namespace {

int64_t cross(const SnappedPoint& o, const SnappedPoint& a, const SnappedPoint& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool is_convex(const std::vector<SnappedPoint>& s) {
    for (size_t i = 0; i < s.size(); ++i)
        if (cross(s[i], s[(i + 1) % s.size()], s[(i + 2) % s.size()]) < 0) return false;
    return true;
}

}  // namespace

std::vector<SnappedPoint> snap(const ProjectedVertex* v, uint32_t count) {
    std::vector<SnappedPoint> s;
    for (uint32_t i = 0; i < count; ++i) {
        SnappedPoint q{std::llround(v[i].x * kSubpixel), std::llround(v[i].y * kSubpixel)};
        if (s.empty() || s.back().x != q.x || s.back().y != q.y) s.push_back(q);
    }
    while (s.size() > 1 && s.front().x == s.back().x && s.front().y == s.back().y)
        s.pop_back();
    if (s.size() < 3) return {};
    int64_t area2 = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        const auto& a = s[i];
        const auto& b = s[(i + 1) % s.size()];
        area2 += a.x * b.y - b.x * a.y;
    }
    if (area2 == 0) return {};
    if (area2 < 0) std::reverse(s.begin(), s.end());
    return s;
}

std::vector<std::vector<SnappedPoint>> convex_pieces(std::vector<SnappedPoint> s) {
    std::vector<std::vector<SnappedPoint>> out;
    size_t guard = s.size() * s.size() + 8, i = 0;
    while (s.size() > 3 && guard-- > 0) {
        size_t n = s.size();
        const auto &a = s[(i + n - 1) % n], &b = s[i % n], &c = s[(i + 1) % n];
        bool ear = cross(a, b, c) > 0;
        for (size_t k = 0; ear && k < n; ++k) {
            const auto& p = s[k];
            if (k == i % n || k == (i + 1) % n || k == (i + n - 1) % n) continue;
            ear = !(cross(a, b, p) >= 0 && cross(b, c, p) >= 0 && cross(c, a, p) >= 0);
        }
        if (ear) {
            out.push_back({a, b, c});
            s.erase(s.begin() + static_cast<long>(i % n));
        } else {
            ++i;
        }
    }
    if (s.size() == 3 && cross(s[0], s[1], s[2]) > 0) out.push_back(s);
    return out;
}

PixelRect pixel_bounds(const std::vector<SnappedPoint>& s, int width, int height) {
    int64_t lx = s[0].x, hx = s[0].x, ly = s[0].y, hy = s[0].y;
    for (const auto& p : s) {
        lx = std::min(lx, p.x), hx = std::max(hx, p.x);
        ly = std::min(ly, p.y), hy = std::max(hy, p.y);
    }
    // the first and last pixel centres (at +0.5) within [lo, hi]
    auto first = [](int64_t lo) { return (lo - kSubpixel / 2 + kSubpixel - 1) >> kSubpixelBits; };
    auto last = [](int64_t hi) { return (hi - kSubpixel / 2) >> kSubpixelBits; };
    PixelRect r;
    r.x0 = static_cast<int>(std::clamp<int64_t>(first(lx), 0, width));
    r.y0 = static_cast<int>(std::clamp<int64_t>(first(ly), 0, height));
    r.x1 = static_cast<int>(std::clamp<int64_t>(last(hx) + 1, 0, width));
    r.y1 = static_cast<int>(std::clamp<int64_t>(last(hy) + 1, 0, height));
    return r;
}

ScreenScene setup_screen(const ProjectedScene& in, Counters& counters) {
    ScreenScene out;
    out.width = in.width;
    out.height = in.height;
    out.background = in.background;
    out.face_count = in.face_count;
    out.world = in.world;
    out.id_colors = in.id_colors;
    uint64_t no_area = 0, split = 0;
    for (const ProjectedFace& face : in.faces) {
        // snap, then cut where snapping bent the polygon
        std::vector<SnappedPoint> snapped = snap(in.vertices_of(face), face.vertex_count);
        if (snapped.empty()) {
            ++no_area;
            continue;
        }
        std::vector<std::vector<SnappedPoint>> pieces;
        if (is_convex(snapped)) {
            pieces.push_back(std::move(snapped));
        } else {
            pieces = convex_pieces(std::move(snapped));
            ++split;
        }
        // bounds and edge functions per piece
        for (auto& piece : pieces) {
            PixelRect bounds = pixel_bounds(piece, in.width, in.height);
            if (bounds.empty()) continue;
            ScreenFace f;
            f.id = face.id;
            f.color = face.color;
            f.depth = face.depth;
            f.first_point = static_cast<uint32_t>(out.points.size());
            f.point_count = static_cast<uint32_t>(piece.size());
            f.bounds = bounds;
            out.points.insert(out.points.end(), piece.begin(), piece.end());
            out.edges.resize(out.points.size());
            setup_edges(piece.data(), f.point_count, &out.edges[f.first_point]);
            out.faces.push_back(f);
        }
    }
    std::stable_sort(out.faces.begin(), out.faces.end(),
                     [](const ScreenFace& a, const ScreenFace& b) { return a.id < b.id; });
    counters.add("faces_without_area", no_area);
    counters.add("faces_split_after_snapping", split);
    counters.add("screen_faces", out.faces.size());
    return out;
}

ScreenScene project_scene(const Scene& scene, ColorMode mode, Counters& counters) {
    return setup_screen(project_faces(scene, mode, counters), counters);
}

}  // namespace fb89::host
