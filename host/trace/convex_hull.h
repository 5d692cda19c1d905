// Convex hulls against face pieces: the question that the beam segments of §4 (Fig. 4.1,
// beam_tracer.cpp) and the decahedra of §5 (Fig. 5.3, host/radiosity/decahedron.cpp) both
// ask of the uniform grid, "which pieces meet this convex volume?".
//
// - A hull is its points, their bounding box, its bounding planes with the points' extent
//   along each, and its edge directions. Each caller builds its own (a beam segment from two
//   quadrilaterals, a decahedron by gift wrapping two outlines).
// - A piece is apart from the hull when some axis separates their extents (the separating-
//   axis theorem): the hull's planes, the piece's plane, then the cross products of the
//   piece's edges with the hull's.
// - The culled scan takes the grid cells in the hull's box, grown by the scene's tolerance,
//   drops those that one of the hull's planes separates from it, and hands each piece
//   listed in the cells left to the caller once (a Mailbox round).
// - The BVH walk (the beam tracer's, unless its rays walk the grid) goes down the ray
//   tracer's BVH (bvh.h) instead, into the boxes that neither the hull's box nor one of its
//   planes separates from it, and hands over the pieces of the leaves it reaches. Each piece
//   sits in one leaf, so it needs no mailbox, and the boxes hug the pieces where a grid's
//   cells are the same size everywhere: a beam down a room's length tests the few pieces near
//   it, not every piece of every cell its box reaches.
//
// The touching rule is a parameter. TouchingBlocks (the beam tracer): only a gap wider than
// the tolerance separates, so "empty" is always true and faces that touch a segment block
// it. TouchingIsApart (the decahedra): extents overlapping by no more than the tolerance are
// apart, so only the hull's open interior counts as occupied (docs/DECAHEDRA.md says why δ
// is still exact).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "host/trace/bvh.h"
#include "host/trace/grid.h"
#include "host/trace/mailbox.h"

namespace fb89::host {

// A convex volume made ready for separating-axis tests. A beam segment fills 8 points, 6
// planes and 12 edges at most; a decahedron up to 24 planes and 40 edges.
struct ConvexHull {
    static constexpr int kMaxPoints = 8, kMaxPlanes = 24, kMaxEdges = 40;
    glm::dvec3 points[kMaxPoints];
    int point_count = 0;
    glm::dvec3 lo{0}, hi{0};                            // the points' bounding box (fit_box)
    glm::dvec3 planes[kMaxPlanes];                      // unit
    double plane_lo[kMaxPlanes], plane_hi[kMaxPlanes];  // the points' extent along each
    int plane_count = 0;
    glm::dvec3 edges[kMaxEdges];  // unit
    int edge_count = 0;

    void fit_box() {
        lo = hi = points[0];
        for (int k = 1; k < point_count; ++k) {
            lo = glm::min(lo, points[k]);
            hi = glm::max(hi, points[k]);
        }
    }
};

// The extent of `count` points along `axis`.
inline void project(const glm::dvec3* p, int count, const glm::dvec3& axis, double& lo,
                    double& hi) {
    lo = hi = glm::dot(p[0], axis);
    for (int i = 1; i < count; ++i) {
        const double d = glm::dot(p[i], axis);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
}

// The beam tracer's rule: extents a and b on one axis are apart only when a gap wider than
// `tol` lies between them.
struct TouchingBlocks {
    static bool apart(double lo_a, double hi_a, double lo_b, double hi_b, double tol) {
        return hi_a + tol < lo_b || hi_b + tol < lo_a;
    }
    // Boxes: b grown by tol.
    static bool boxes_apart(const glm::dvec3& lo_a, const glm::dvec3& hi_a, const glm::dvec3& lo_b,
                            const glm::dvec3& hi_b, double tol) {
        return glm::any(glm::lessThan(hi_a, lo_b - tol)) ||
               glm::any(glm::greaterThan(lo_a, hi_b + tol));
    }
    // Two edges give no axis only when rounding made their cross product (1e-18 of an edge).
    static bool parallel(double axis_length, double edge_length) {
        return !(axis_length > edge_length * 1e-6 * 1e-12);
    }
};

// The decahedra's rule: extents overlapping by no more than `tol` are apart.
struct TouchingIsApart {
    static bool apart(double lo_a, double hi_a, double lo_b, double hi_b, double tol) {
        return hi_a - lo_b <= tol || hi_b - lo_a <= tol;
    }
    static bool boxes_apart(const glm::dvec3& lo_a, const glm::dvec3& hi_a, const glm::dvec3& lo_b,
                            const glm::dvec3& hi_b, double tol) {
        for (int a = 0; a < 3; ++a)
            if (apart(lo_a[a], hi_a[a], lo_b[a], hi_b[a], tol)) return true;
        return false;
    }
    // Edges within 1e-9 of parallel give no axis: their cross product is rounding.
    static bool parallel(double axis_length, double edge_length) {
        return !(axis_length > 1e-9 * edge_length);
    }
};

// True when one of the hull's planes or the piece's own plane (`normal`) separates the
// piece (n vertices from v) from the hull.
template <class Rule>
bool planes_separate(const ConvexHull& h, const glm::dvec3* v, int n, const glm::dvec3& normal,
                     double tol) {
    double lo_p, hi_p, lo_h, hi_h;
    for (int k = 0; k < h.plane_count; ++k) {
        project(v, n, h.planes[k], lo_p, hi_p);
        if (Rule::apart(lo_p, hi_p, h.plane_lo[k], h.plane_hi[k], tol)) return true;
    }
    project(v, n, normal, lo_p, hi_p);
    project(h.points, h.point_count, normal, lo_h, hi_h);
    return Rule::apart(lo_p, hi_p, lo_h, hi_h, tol);
}

// True when the cross product of an edge of the piece and one of the hull separates them.
template <class Rule>
bool edges_separate(const ConvexHull& h, const glm::dvec3* v, int n, double tol) {
    double lo_p, hi_p, lo_h, hi_h;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 edge = v[(i + 1) % n] - v[i];
        const double edge_length = glm::length(edge);
        for (int k = 0; k < h.edge_count; ++k) {
            glm::dvec3 axis = glm::cross(edge, h.edges[k]);
            const double length = glm::length(axis);
            if (Rule::parallel(length, edge_length)) continue;
            axis /= length;
            project(v, n, axis, lo_p, hi_p);
            project(h.points, h.point_count, axis, lo_h, hi_h);
            if (Rule::apart(lo_p, hi_p, lo_h, hi_h, tol)) return true;
        }
    }
    return false;
}

// True when one of the hull's planes separates the box centre ± half from the hull.
template <class Rule>
bool culls(const ConvexHull& h, const double* reach, const glm::dvec3& centre, double tol) {
    for (int k = 0; k < h.plane_count; ++k) {
        const double c = glm::dot(h.planes[k], centre);
        if (Rule::apart(c - reach[k], c + reach[k], h.plane_lo[k], h.plane_hi[k], tol)) return true;
    }
    return false;
}

// The culled scan: calls visit(piece) once for each piece listed in a cell of `grid` that
// the hull's box grown by `tol` reaches and no plane of the hull culls; stops when visit
// returns true. A crowded cell's own grid is not used: culling its many small cells costs
// more than visiting the cell's pieces. Returns the cells not culled.
template <class Rule, class Visit>
uint64_t scan_hull_cells(const UniformGrid& grid, const ConvexHull& h, double tol, Mailbox& mailbox,
                         Visit&& visit) {
    Mailbox::Round round = mailbox.begin();
    glm::ivec3 first, last;
    if (!grid.cell_range(h.lo - tol, h.hi + tol, first, last)) return 0;
    // a cell's half-extent along each plane's normal
    const glm::dvec3 half = grid.cell_size() * 0.5;
    double reach[ConvexHull::kMaxPlanes];
    for (int k = 0; k < h.plane_count; ++k)
        reach[k] = glm::dot(glm::abs(h.planes[k]), half);
    uint64_t cells = 0;
    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) {
                // cull cells
                if (culls<Rule>(h, reach, grid.cell_lo(x, y, z) + half, tol)) continue;
                ++cells;
                // visit each piece once
                for (uint32_t piece : grid.cell(grid.index(x, y, z)))
                    if (round.first_visit(piece) && visit(piece)) return cells;
            }
    return cells;
}

// True when the hull's box, grown by `tol`, or one of its planes separates the box [lo, hi]
// from the hull.
template <class Rule>
bool box_culled(const ConvexHull& h, const glm::dvec3& lo, const glm::dvec3& hi, double tol) {
    if (Rule::boxes_apart(lo, hi, h.lo, h.hi, tol)) return true;
    const glm::dvec3 half = (hi - lo) * 0.5;
    double reach[ConvexHull::kMaxPlanes];
    for (int k = 0; k < h.plane_count; ++k)
        reach[k] = glm::dot(glm::abs(h.planes[k]), half);
    return culls<Rule>(h, reach, lo + half, tol);
}

// The BVH walk: calls visit(piece) for each piece of each leaf whose box box_culled keeps,
// once each (a piece sits in one leaf); stops when visit returns true. The boxes are the
// ray tracer's, rounded outward to float and padded (bvh.h), so a box holds its pieces with
// room to spare for the rounding of this test. On x86-64 it walks the 8-wide tree, a box at
// a time, elsewhere the binary one. Returns the boxes tested.
template <class Rule, class Visit>
uint64_t scan_hull_bvh(const RayBvh& bvh, const ConvexHull& h, double tol, Visit&& visit) {
    const std::vector<RayBvh::Node>& nodes = bvh.nodes();
    const std::vector<uint32_t>& pieces = bvh.pieces();
    if (nodes.empty()) return 0;
    auto leaf = [&](uint32_t first, uint32_t count) {
        for (uint32_t i = first; i < first + count; ++i)
            if (visit(pieces[i])) return true;
        return false;
    };
    auto culled = [&](const RayBvh::Node& n) {
        return box_culled<Rule>(h, {n.bounds[0], n.bounds[1], n.bounds[2]},
                                {n.bounds[3], n.bounds[4], n.bounds[5]}, tol);
    };
    uint64_t tested = 1;
    if (culled(nodes[0])) return tested;
    if (nodes[0].count > 0) {  // the whole tree one leaf
        leaf(nodes[0].index, nodes[0].count);
        return tested;
    }
    uint32_t stack[RayBvh::kMaxDepth * (RayBvh::kWidth - 1) + RayBvh::kWidth];
    int top = 0;
    if constexpr (RayBvh::kWide) {
        const std::vector<RayBvh::WideNode>& wide = bvh.wide();
        stack[top++] = 0;
        while (top > 0) {
            const RayBvh::WideNode& n = wide[stack[--top]];
            tested += n.used;
            for (uint32_t k = 0; k < n.used; ++k) {
                if (box_culled<Rule>(h, {n.lo[0][k], n.lo[1][k], n.lo[2][k]},
                                     {n.hi[0][k], n.hi[1][k], n.hi[2][k]}, tol))
                    continue;
                if (n.count[k] == 0)
                    stack[top++] = n.child[k];
                else if (leaf(n.child[k], n.count[k]))
                    return tested;
            }
        }
    } else {
        // an inner node's children: the node after it and its `index`
        stack[top++] = 1;
        stack[top++] = nodes[0].index;
        while (top > 0) {
            const RayBvh::Node& n = nodes[stack[--top]];
            ++tested;
            if (culled(n)) continue;
            if (n.count > 0) {
                if (leaf(n.index, n.count)) return tested;
                continue;
            }
            stack[top++] = static_cast<uint32_t>(&n - nodes.data()) + 1;
            stack[top++] = n.index;
        }
    }
    return tested;
}

}  // namespace fb89::host
