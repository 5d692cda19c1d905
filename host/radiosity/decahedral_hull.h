// The decahedron of the paper's §5 (Fig. 5.3): the convex hull of two patch regions'
// outlines, and whether a face piece reaches into its open interior.
//
// Ours takes any two convex outlines (a triangle's apex counted once) and builds their hull
// by gift wrapping: each facet is one outline's plane, or holds an edge of one outline and a
// corner of the other. A piece occupies the hull when no axis (the boxes', the hull's
// facets, the piece's plane, the cross products of their edges) sees the two overlap by no
// more than the scene's tolerance: touching is apart (convex_hull.h, TouchingIsApart).
// docs/DECAHEDRA.md says why that leaves δ exactly as flux tracing finds it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "host/trace/convex_hull.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {

struct DecahedralHull : ConvexHull {
    int na = 0;                // points[0, na) are the first outline's corners
    uint32_t on[kMaxPlanes];   // the points on each facet, as bits
    bool edges_found = false;  // find_edges has run
};

// The hull of two outlines; false when it is flat (every point within tol of one plane).
bool make_decahedral_hull(const std::array<glm::dvec3, 4>& a, const std::array<glm::dvec3, 4>& b,
                          double tol, DecahedralHull& h);

// The scene's pieces as the decahedra test them, their bounding boxes first.
class HullPieces {
  public:
    explicit HullPieces(const TraceScene& scene);
    // True when the piece's box and [lo, hi] overlap by no more than the tolerance on an axis.
    bool box_apart(uint32_t piece, const glm::dvec3& lo, const glm::dvec3& hi) const;
    // True when the piece reaches deeper than the tolerance into the hull (finds the hull's
    // edges the first time they are needed).
    bool occupies(DecahedralHull& h, uint32_t piece) const;

  private:
    const TraceScene& m_scene;
    double m_tol;
};

}  // namespace fb89::host
