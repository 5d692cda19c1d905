#include "host/scene/projection.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "host/raster/coverage.h"
#include "host/scene/clip.h"
#include "host/scene/polygon.h"

namespace fb89::host {

namespace {

struct ProjectedVertex {
    double x, y, z;  // pixels, pixels, window depth in [0, 1]
};

uint8_t to_byte(double v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

protocol::Rgb shade(const Scene& scene, const Face& face, ColorMode mode) {
    if (mode == ColorMode::FaceId) return face_id_color(face.id);
    glm::dvec3 c = face.material.color;
    if (scene.projection == Projection::Perspective) {
        glm::dvec3 n = glm::normalize(newell_normal(face.vertices));
        if (glm::dot(n, scene.camera.eye - face.vertices[0]) < 0) n = -n;  // two-sided
        double diffuse = std::max(0.0, glm::dot(n, -scene.light.direction));
        c = c * (scene.light.ambient + (1.0 - scene.light.ambient) * diffuse);
    }
    c += face.material.emission;
    return {to_byte(c.r), to_byte(c.g), to_byte(c.b)};
}

// Depth plane through the projected (unsnapped) vertices: exact for a planar face.
DepthPlane depth_plane(const std::vector<ProjectedVertex>& v) {
    double nx = 0, ny = 0, nz = 0;
    if (v.size() == 3) {
        double ux = v[1].x - v[0].x, uy = v[1].y - v[0].y, uz = v[1].z - v[0].z;
        double wx = v[2].x - v[0].x, wy = v[2].y - v[0].y, wz = v[2].z - v[0].z;
        nx = uy * wz - uz * wy;
        ny = uz * wx - ux * wz;
        nz = ux * wy - uy * wx;
    } else {
        for (size_t i = 0; i < v.size(); ++i) {
            const auto& a = v[i];
            const auto& b = v[(i + 1) % v.size()];
            nx += (a.y - b.y) * (a.z + b.z);
            ny += (a.z - b.z) * (a.x + b.x);
            nz += (a.x - b.x) * (a.y + b.y);
        }
    }
    if (nz == 0) return {0, 0, v[0].z};  // edge-on: covers no pixel centre anyway
    DepthPlane p;
    p.a = -nx / nz;
    p.b = -ny / nz;
    p.c = v[0].z - p.a * v[0].x - p.b * v[0].y;
    return p;
}

int64_t cross(const SnappedPoint& o, const SnappedPoint& a, const SnappedPoint& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Snapped polygon in positive orientation with no repeated points; empty if it has no area.
std::vector<SnappedPoint> snap(const std::vector<ProjectedVertex>& v) {
    std::vector<SnappedPoint> s;
    for (const auto& p : v) {
        SnappedPoint q{std::llround(p.x * kSubpixel), std::llround(p.y * kSubpixel)};
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

bool is_convex(const std::vector<SnappedPoint>& s) {
    for (size_t i = 0; i < s.size(); ++i)
        if (cross(s[i], s[(i + 1) % s.size()], s[(i + 2) % s.size()]) < 0) return false;
    return true;
}

// Snapping can bend a near-degenerate convex polygon; cut it into triangles by ear clipping.
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
    auto first = [](int64_t lo) { return (lo - kSubpixel / 2 + kSubpixel - 1) >> kSubpixelBits; };
    auto last = [](int64_t hi) { return (hi - kSubpixel / 2) >> kSubpixelBits; };
    PixelRect r;
    r.x0 = static_cast<int>(std::clamp<int64_t>(first(lx), 0, width));
    r.y0 = static_cast<int>(std::clamp<int64_t>(first(ly), 0, height));
    r.x1 = static_cast<int>(std::clamp<int64_t>(last(hx) + 1, 0, width));
    r.y1 = static_cast<int>(std::clamp<int64_t>(last(hy) + 1, 0, height));
    return r;
}

}  // namespace

protocol::Rgb face_id_color(uint32_t id) {
    uint32_t v = id + 1;
    return {static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

uint32_t face_id_from_color(protocol::Rgb c) {
    return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | uint32_t{c.b};
}

ScreenScene project_scene(const Scene& scene, ColorMode mode, Counters& counters) {
    ScreenScene out;
    out.width = scene.width;
    out.height = scene.height;
    // in the face-id pass the background is id + 1 = 0, whatever the scene's colour
    out.background = mode == ColorMode::FaceId
                         ? protocol::Rgb{0, 0, 0}
                         : protocol::Rgb{to_byte(scene.background.r), to_byte(scene.background.g),
                                         to_byte(scene.background.b)};
    out.face_count = scene.face_count;
    out.world = &scene;
    out.id_colors = mode == ColorMode::FaceId;
    const double w = scene.width, h = scene.height;
    const bool perspective = scene.projection == Projection::Perspective;

    // clip planes: dot(plane, p) >= 0 keeps p
    std::vector<glm::dvec4> planes;
    glm::dmat4 clip_from_world(1.0);
    if (perspective) {
        const Camera& cam = scene.camera;
        clip_from_world =
            glm::perspective(glm::radians(cam.fovy_degrees), w / h, cam.near, cam.far) *
            glm::lookAt(cam.eye, cam.look_at, cam.up);
        double gx = 1 + 2 * kGuardBandPixels / w, gy = 1 + 2 * kGuardBandPixels / h;
        planes = {{0, 0, 1, 1},   {0, 0, -1, 1}, {1, 0, 0, gx},
                  {-1, 0, 0, gx}, {0, 1, 0, gy}, {0, -1, 0, gy}};
    } else {
        const double g = kGuardBandPixels;
        planes = {{0, 0, 1, 0},      {0, 0, -1, 1}, {1, 0, 0, g},
                  {-1, 0, 0, w + g}, {0, 1, 0, g},  {0, -1, 0, h + g}};
    }

    uint64_t clipped = 0, outside = 0, no_area = 0, split = 0;
    std::vector<glm::dvec4> poly, scratch;
    std::vector<ProjectedVertex> projected;
    for (const Face& face : scene.faces) {
        // to clip space, then clip
        poly.clear();
        for (const auto& v : face.vertices)
            poly.push_back(perspective ? clip_from_world * glm::dvec4(v, 1.0) : glm::dvec4(v, 1.0));
        size_t before = poly.size();
        std::vector<glm::dvec4> original = poly;
        if (!clip_polygon(poly, planes, scratch)) {
            ++outside;
            continue;
        }
        if (poly != original || poly.size() != before) ++clipped;

        // divide and viewport: x right, y down
        projected.clear();
        for (const auto& p : poly) {
            if (perspective)
                projected.push_back(
                    {(p.x / p.w + 1) * 0.5 * w, (1 - p.y / p.w) * 0.5 * h, (p.z / p.w + 1) * 0.5});
            else
                projected.push_back({p.x, p.y, p.z});
        }
        DepthPlane depth = depth_plane(projected);
        std::vector<SnappedPoint> snapped = snap(projected);
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
        protocol::Rgb color = shade(scene, face, mode);
        for (auto& piece : pieces) {
            PixelRect bounds = pixel_bounds(piece, scene.width, scene.height);
            if (bounds.empty()) continue;
            ScreenFace f;
            f.id = face.id;
            f.color = color;
            f.depth = depth;
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
    counters.add("faces_clipped", clipped);
    counters.add("faces_outside_frustum", outside);
    counters.add("faces_without_area", no_area);
    counters.add("faces_split_after_snapping", split);
    counters.add("screen_faces", out.faces.size());
    return out;
}

}  // namespace fb89::host
