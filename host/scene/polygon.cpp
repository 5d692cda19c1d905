// Polygon preparation: validation, planarity and convexity checks, ear-clipping
// triangulation for polygons that are not planar convex faces.
#include "host/scene/polygon.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace fb89::host {

namespace {

double extent_of(const std::vector<glm::dvec3>& v) {
    glm::dvec3 lo = v[0], hi = v[0];
    for (const auto& p : v) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

std::vector<glm::dvec3> without_repeats(const std::vector<glm::dvec3>& in) {
    std::vector<glm::dvec3> out;
    for (const auto& p : in)
        if (out.empty() || out.back() != p) out.push_back(p);
    while (out.size() > 1 && out.front() == out.back())
        out.pop_back();
    return out;
}

// 2D coordinates in the plane with normal n, keeping the polygon's orientation positive.
std::vector<glm::dvec2> to_plane(const std::vector<glm::dvec3>& v, const glm::dvec3& n) {
    glm::dvec3 a = glm::abs(n);
    int drop = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    bool flip = n[drop] < 0;
    std::vector<glm::dvec2> out;
    out.reserve(v.size());
    for (const auto& p : v)
        out.emplace_back(p[u], flip ? -p[w] : p[w]);
    return out;
}

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

bool inside_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b,
                     const glm::dvec2& c) {
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// Ear clipping on a counter-clockwise 2D polygon; returns index triples.
std::vector<std::array<size_t, 3>> ear_clip(const std::vector<glm::dvec2>& p) {
    std::vector<size_t> ring(p.size());
    for (size_t i = 0; i < ring.size(); ++i)
        ring[i] = i;
    std::vector<std::array<size_t, 3>> tris;
    size_t guard = ring.size() * ring.size() + 8;
    size_t i = 0;
    while (ring.size() > 3 && guard-- > 0) {
        size_t n = ring.size();
        size_t ia = ring[(i + n - 1) % n], ib = ring[i % n], ic = ring[(i + 1) % n];
        bool ear = cross2(p[ia], p[ib], p[ic]) > 0;
        for (size_t k = 0; ear && k < n; ++k) {
            size_t j = ring[k];
            if (j != ia && j != ib && j != ic && inside_triangle(p[j], p[ia], p[ib], p[ic]))
                ear = false;
        }
        if (ear) {
            tris.push_back({ia, ib, ic});
            ring.erase(ring.begin() + static_cast<long>(i % n));
        } else {
            ++i;
        }
    }
    if (ring.size() > 3) {  // self-intersecting: fall back to a fan over what is left
        for (size_t k = 1; k + 1 < ring.size(); ++k)
            tris.push_back({ring[0], ring[k], ring[k + 1]});
    } else if (ring.size() == 3) {
        tris.push_back({ring[0], ring[1], ring[2]});
    }
    return tris;
}

}  // namespace

glm::dvec3 newell_normal(const std::vector<glm::dvec3>& v) {
    glm::dvec3 n{0, 0, 0};
    for (size_t i = 0; i < v.size(); ++i) {
        const glm::dvec3& a = v[i];
        const glm::dvec3& b = v[(i + 1) % v.size()];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

PolygonResult prepare_polygon(const std::vector<glm::dvec3>& input) {
    PolygonResult result;
    for (const auto& p : input) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            result.verdict = PolygonVerdict::NotFinite;
            result.reason = "a vertex coordinate is NaN or infinite";
            return result;
        }
        if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate) {
            result.verdict = PolygonVerdict::NotFinite;
            result.reason =
                "a vertex coordinate is beyond ±1e12 (clipping such a face in double "
                "precision would lose it)";
            return result;
        }
    }
    std::vector<glm::dvec3> v = without_repeats(input);
    glm::dvec3 n = v.size() >= 3 ? newell_normal(v) : glm::dvec3(0);
    double extent = v.size() >= 3 ? extent_of(v) : 0;
    double len = glm::length(n);
    if (v.size() < 3 || !(len > 1e-12 * extent * extent) || !std::isfinite(len)) {
        result.verdict = PolygonVerdict::Degenerate;
        result.reason = v.size() < 3 ? "fewer than 3 distinct vertices" : "zero area";
        return result;
    }

    // planarity: every vertex within a relative tolerance of the best-fit plane
    glm::dvec3 u = n / len;
    glm::dvec3 centroid{0};
    for (const auto& p : v)
        centroid += p;
    centroid /= static_cast<double>(v.size());
    double worst = 0;
    for (const auto& p : v)
        worst = std::max(worst, std::abs(glm::dot(u, p - centroid)));
    bool planar = worst <= 1e-6 * extent;

    // convexity: every turn the same way as the polygon (collinear vertices allowed)
    std::vector<glm::dvec2> flat = to_plane(v, n);
    bool convex = true;
    for (size_t i = 0; i < flat.size() && convex; ++i) {
        const auto& a = flat[i];
        const auto& b = flat[(i + 1) % flat.size()];
        const auto& c = flat[(i + 2) % flat.size()];
        if (cross2(a, b, c) < -1e-12 * extent * extent) convex = false;
    }

    if (planar && convex) {
        result.pieces.push_back(std::move(v));
        return result;
    }
    result.verdict = PolygonVerdict::Triangulated;
    result.reason = !planar ? fmt::format("not planar (a vertex lies {:.3g} off its plane)", worst)
                            : std::string("not convex");
    for (const auto& t : ear_clip(flat)) {
        std::vector<glm::dvec3> tri{v[t[0]], v[t[1]], v[t[2]]};
        if (glm::length(newell_normal(tri)) > 1e-12 * extent * extent)
            result.pieces.push_back(std::move(tri));
    }
    if (result.pieces.empty()) {
        result.verdict = PolygonVerdict::Degenerate;
        result.reason = "zero area after triangulation";
    }
    return result;
}

}  // namespace fb89::host
