// Beam classification of the paper's §4 (Fig. 4.1): a window's beam is the volume of the
// rays through it, bounded by its four lateral rays; following the lateral rays' common path
// (mirror to mirror) cuts it into beam segments. The window is
//   - a hit when every lateral ray has the same path (the same faces, seen from the same
//     sides) and every beam segment is empty of other faces: every pixel of the window
//     then sees that path, and the window is filled with one colour;
//   - a partial hit when the lateral rays' paths differ (or a face lies in a beam that the
//     lateral rays leave through without hitting anything);
//   - a blocked hit when the paths agree but a segment holds another face.
//
// How ours differs from the paper, to make a hit exact under the ray tracer's own rules:
// - the lateral rays are the rays of the window's corner *pixels* (through their centres),
//   so every pixel ray of the window lies inside the beam and the corner classifications are
//   those of the ray tracer itself;
// - the lateral hits must lie inside their face by a margin (four tolerances), so that a
//   pixel ray between them can never slip off it through rounding;
// - the emptiness query is exact and conservative: a segment is the convex hull of its
//   start and end quadrilaterals (the eye's point for a first segment); the pieces that may
//   meet it are found through the ray tracer's BVH (its boxes culled against the hull's box
//   and planes) or, when the rays walk the paper's uniform grid, through that grid (its
//   cells in the hull's box culled against its planes); each piece found is checked by the
//   separating-axis theorem (the hull's planes, the piece's plane, and the cross products of
//   their edges) with the scene's tolerance (convex_hull.h, TouchingBlocks): only a
//   separation wider than the tolerance counts as empty. A false "occupied" costs a
//   subdivision; "empty" is always true, so faces that touch the segment (sharing an edge
//   with the hit face, coplanar overlaps, exact ties) block it. Either structure gives the
//   same answers: only the pieces tested on the way differ.
#pragma once

#include <cstdint>
#include <vector>

#include "host/trace/convex_hull.h"
#include "host/trace/grid.h"
#include "host/trace/mailbox.h"
#include "host/trace/ray_tracer.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {

enum class BeamClass { Hit, Partial, Blocked };

struct BeamCounts {
    uint64_t beams = 0;  // windows classified
    uint64_t hits = 0, partial = 0, blocked = 0;
    uint64_t queries = 0;           // segment emptiness queries
    uint64_t face_counts = 0;       // F_w queries (faces in a window's beam)
    uint64_t query_cells = 0;       // grid cells a query looked at (queries through the grid)
    uint64_t query_nodes = 0;       // BVH boxes a query tested (queries through the BVH)
    uint64_t query_face_tests = 0;  // separating-axis tests of a piece against a segment
    void publish(Counters& counters) const;
};

// A beam segment: the convex hull of four start points and four end points, corner by corner.
struct BeamSegment {
    glm::dvec3 start[4];
    glm::dvec3 end[4];
};

class BeamTracer {
  public:
    // Queries through the uniform grid (the paper's), or through the ray tracer's BVH.
    BeamTracer(const TraceScene& scene, const UniformGrid& grid);
    BeamTracer(const TraceScene& scene, const RayBvh& bvh);

    // `corners`: the traces of the window's corner pixels in the order (x0, y0), (x1-1, y0),
    // (x1-1, y1-1), (x0, y1-1).
    BeamClass classify(const RayTrace* const corners[4], BeamCounts& counts) const;

    // F_w: how many distinct faces meet the window's first beam segment, out to the far
    // side of the scene; counting stops once it exceeds `enough`.
    uint32_t faces_in_beam(const RayTrace* const corners[4], BeamCounts& counts,
                           uint32_t enough = UINT32_MAX) const;

    // True when no piece but `skip_a` and `skip_b` comes within the tolerance of the segment.
    bool segment_is_empty(const BeamSegment& segment, uint32_t skip_a, uint32_t skip_b,
                          BeamCounts& counts) const;

  private:
    ConvexHull make_hull(const BeamSegment& segment) const;
    // Not separated from the hull by more than the tolerance on any axis tried.
    bool touches(const ConvexHull& hull, uint32_t piece) const;
    // Calls visit(piece) for each piece but the two skipped that touches the hull; stops
    // when visit returns true.
    template <class Visit>
    void for_each_touching(const ConvexHull& hull, uint32_t skip_a, uint32_t skip_b, Visit&& visit,
                           BeamCounts& counts) const;
    bool inside_with_margin(uint32_t piece, const glm::dvec3& p) const;
    // The segment of four rays from their origins to beyond the grid's box.
    BeamSegment to_far_side(const Ray* rays[4]) const;

    const TraceScene& m_scene;
    const UniformGrid* m_grid = nullptr;  // one of the two
    const RayBvh* m_bvh = nullptr;
    glm::dvec3 m_lo{0}, m_hi{0};  // the grid's box (box_around_pieces): a beam's far side beyond it
    mutable Mailbox m_pieces;     // per piece: the last grid query that saw it
    mutable Mailbox m_ids;        // per face id: the last F_w query that counted it
};

}  // namespace fb89::host
