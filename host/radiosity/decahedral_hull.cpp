#include "host/radiosity/decahedral_hull.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace fb89::host {

namespace {

// An outline's distinct corners in order (a triangle's apex once): 3 or 4.
int distinct_corners(const std::array<glm::dvec3, 4>& r, double tol, glm::dvec3* out) {
    int n = 0;
    for (const glm::dvec3& p : r)
        if (n == 0 || glm::length(p - out[n - 1]) > tol) out[n++] = p;
    if (n > 1 && glm::length(out[n - 1] - out[0]) <= tol) --n;
    return n;
}

// Adds the plane of unit outward `normal` through `through` to the hull, unless it is
// known; its extent comes from projecting every point, and it is dropped when `through` is
// not on the hull's side of it (a plane that supports nothing).
void add_plane(DecahedralHull& h, const glm::dvec3& normal, const glm::dvec3& through, double tol) {
    for (int k = 0; k < h.plane_count; ++k)
        if (glm::dot(h.planes[k], normal) > 1 - 1e-9) return;
    if (h.plane_count == DecahedralHull::kMaxPlanes) return;  // fewer axes: more conservative
    const int k = h.plane_count;
    const double at = glm::dot(normal, through);
    double lo = at, hi = at;
    uint32_t on = 0;
    for (int m = 0; m < h.point_count; ++m) {
        const double s = glm::dot(normal, h.points[m]);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
        if (std::abs(s - at) <= tol) on |= 1u << m;
    }
    if (hi - at > tol) return;
    h.planes[k] = normal;
    h.plane_lo[k] = lo;
    h.plane_hi[k] = hi;
    h.on[k] = on;
    ++h.plane_count;
}

// The facets through each edge of polygon P (n corners from p) towards polygon Q (m corners
// from q), by gift wrapping: seen along the edge, P lies at angle 0 (inwards) and each corner
// of Q at some angle around it; the hull's facets through the edge are the two extreme
// angles either side (P's own plane when Q has no corner on that side).
void wrap_edges(DecahedralHull& h, const glm::dvec3* p, int n, const glm::dvec3& up,
                const glm::dvec3* q, int m, double tol) {
    for (int i = 0; i < n; ++i) {
        const glm::dvec3& p0 = p[i];
        const glm::dvec3 edge = p[(i + 1) % n] - p0;
        const glm::dvec3 out = glm::normalize(glm::cross(edge, up));  // in P's plane
        double ux = 0, uz = 0, lx = 0, lz = 0;  // the extreme corners above and below
        bool upper = false, lower = false;
        for (int k = 0; k < m; ++k) {
            const glm::dvec3 d = q[k] - p0;
            const double x = -glm::dot(d, out), z = glm::dot(d, up);
            if (z > tol || (z >= -tol && x < -tol)) {
                if (!upper || ux * z - uz * x > 0) ux = x, uz = z;
                upper = true;
            } else if (z < -tol) {
                if (!lower || lx * z - lz * x < 0) lx = x, lz = z;
                lower = true;
            }
        }
        if (upper) add_plane(h, glm::normalize(uz * out + ux * up), p0, tol);
        if (lower) add_plane(h, glm::normalize(-lz * out - lx * up), p0, tol);
    }
}

// The hull's edge directions, once a piece needs them: the outlines' and those between the
// two on two facets at once.
void find_edges(DecahedralHull& h) {
    h.edges_found = true;
    const int na = h.na, nb = h.point_count - h.na;
    const glm::dvec3* a = h.points;
    const glm::dvec3* b = h.points + na;
    auto add_edge = [&](const glm::dvec3& from, const glm::dvec3& to) {
        const glm::dvec3 e = glm::normalize(to - from);
        for (int k = 0; k < h.edge_count; ++k)
            if (std::abs(glm::dot(h.edges[k], e)) > 1 - 1e-9) return;
        if (h.edge_count < DecahedralHull::kMaxEdges) h.edges[h.edge_count++] = e;
    };
    for (int i = 0; i < na; ++i)
        add_edge(a[i], a[(i + 1) % na]);
    for (int i = 0; i < nb; ++i)
        add_edge(b[i], b[(i + 1) % nb]);
    for (int i = 0; i < na; ++i)
        for (int j = 0; j < nb; ++j) {
            const uint32_t both = (1u << i) | (1u << (na + j));
            int shared = 0;
            for (int k = 0; k < h.plane_count; ++k)
                shared += (h.on[k] & both) == both;
            if (shared >= 2 && glm::any(glm::notEqual(a[i], b[j]))) add_edge(a[i], b[j]);
        }
}

}  // namespace

// A facet of the hull of two convex polygons is one's plane, or holds an edge of one and a
// corner of the other, found by wrapping each edge.
bool make_decahedral_hull(const std::array<glm::dvec3, 4>& ra, const std::array<glm::dvec3, 4>& rb,
                          double tol, DecahedralHull& h) {
    const int na = distinct_corners(ra, tol, h.points);
    const int nb = distinct_corners(rb, tol, h.points + na);
    const int n = h.point_count = na + nb;
    h.na = na;
    h.fit_box();
    if (na < 3 || nb < 3) return false;
    const glm::dvec3* a = h.points;
    const glm::dvec3* b = h.points + na;
    const glm::dvec3 up_a = glm::normalize(glm::cross(a[1] - a[0], a[2] - a[0]));
    const glm::dvec3 up_b = glm::normalize(glm::cross(b[1] - b[0], b[2] - b[0]));

    // each polygon's plane, when the other lies on one side of it
    bool flat = false;
    for (int k = 0; k < 2; ++k) {
        const glm::dvec3& up = k == 0 ? up_a : up_b;
        const glm::dvec3& at = k == 0 ? a[0] : b[0];
        bool above = false, below = false;
        for (int j = 0; j < n; ++j) {
            const double s = glm::dot(up, h.points[j] - at);
            above |= s > tol;
            below |= s < -tol;
        }
        flat |= !above && !below;
        if (above != below) add_plane(h, above ? -up : up, at, tol);
    }
    if (flat) return false;
    // the facets through each outline's edges
    wrap_edges(h, a, na, up_a, b, nb, tol);
    wrap_edges(h, b, nb, up_b, a, na, tol);
    return h.plane_count >= 4;
}

HullPieces::HullPieces(const TraceScene& scene) : m_scene(scene), m_tol(scene.tolerance()) {}

bool HullPieces::box_apart(uint32_t piece, const glm::dvec3& lo, const glm::dvec3& hi) const {
    const PieceBox& box = m_scene.box(piece);
    return TouchingIsApart::boxes_apart(box.lo, box.hi, lo, hi, m_tol);
}

bool HullPieces::occupies(DecahedralHull& h, uint32_t piece) const {
    if (box_apart(piece, h.lo, h.hi)) return false;  // bounding boxes first
    const TraceFace& f = m_scene.faces()[piece];
    const glm::dvec3* v = m_scene.vertices_of(f);
    const int n = static_cast<int>(f.vertex_count);
    // a corner deeper than tol inside every facet: certainly in
    for (int i = 0; i < n; ++i) {
        int k = 0;
        while (k < h.plane_count && glm::dot(h.planes[k], v[i]) < h.plane_hi[k] - m_tol)
            ++k;
        if (k == h.plane_count) return true;
    }
    // the hull's facets, the piece's plane, then edge against edge
    if (planes_separate<TouchingIsApart>(h, v, n, f.normal, m_tol)) return false;
    if (!h.edges_found) find_edges(h);
    return !edges_separate<TouchingIsApart>(h, v, n, m_tol);
}

}  // namespace fb89::host
