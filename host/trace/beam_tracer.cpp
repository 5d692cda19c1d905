#include "host/trace/beam_tracer.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace fb89::host {

void BeamCounts::publish(Counters& counters) const {
    counters.add("beams", beams);
    counters.add("beam_hits", hits);
    counters.add("partial_hits", partial);
    counters.add("blocked_hits", blocked);
    counters.add("beam_queries", queries);
    counters.add("window_face_counts", face_counts);
    if (query_cells > 0)
        counters.add("query_cells", query_cells);
    else
        counters.add("query_nodes", query_nodes);
    counters.add("query_face_tests", query_face_tests);
}

namespace {

glm::dvec3 newell(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::dvec3& d) {
    const glm::dvec3 p[4] = {a, b, c, d};
    glm::dvec3 n(0);
    for (int i = 0; i < 4; ++i) {
        const glm::dvec3& u = p[i];
        const glm::dvec3& v = p[(i + 1) % 4];
        n += glm::dvec3((u.y - v.y) * (u.z + v.z), (u.z - v.z) * (u.x + v.x),
                        (u.x - v.x) * (u.y + v.y));
    }
    return n;
}

// Unit `v`, or false when it is too short to be a direction (degenerate corners).
bool unit(glm::dvec3& v, double scale) {
    const double len = glm::length(v);
    if (!(len > scale * 1e-12)) return false;
    v /= len;
    return true;
}

// A mailbox with a slot for every face id of the scene.
Mailbox id_mailbox(const TraceScene& scene) {
    Mailbox ids(scene.face_count() + 1);
    for (const auto& f : scene.faces())
        ids.grow(f.id + size_t{1});
    return ids;
}

}  // namespace

BeamTracer::BeamTracer(const TraceScene& scene, const UniformGrid& grid)
    : m_scene(scene),
      m_grid(&grid),
      m_lo(grid.lo()),
      m_hi(grid.hi()),
      m_pieces(scene.faces().size()),
      m_ids(id_mailbox(scene)) {}

BeamTracer::BeamTracer(const TraceScene& scene, const RayBvh& bvh)
    : m_scene(scene), m_bvh(&bvh), m_ids(id_mailbox(scene)) {
    // the grid's box, though there is no grid: the same segments to the far side either way
    const PieceBox box = box_around_pieces(scene);
    m_lo = box.lo;
    m_hi = box.hi;
}

ConvexHull BeamTracer::make_hull(const BeamSegment& s) const {
    ConvexHull h;
    const double tol = m_scene.tolerance();
    for (int i = 0; i < 4; ++i) {
        h.points[i] = s.start[i];
        h.points[4 + i] = s.end[i];
    }
    h.point_count = 8;
    h.fit_box();
    const double scale = glm::length(h.hi - h.lo) + tol;
    // bounding planes: four sides, the end, the start (unless it is the eye's point)
    auto add_plane = [&](glm::dvec3 n) {
        if (!unit(n, scale * scale)) return;
        h.planes[h.plane_count] = n;
        project(h.points, 8, n, h.plane_lo[h.plane_count], h.plane_hi[h.plane_count]);
        ++h.plane_count;
    };
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        add_plane(newell(s.start[i], s.start[j], s.end[j], s.end[i]));
    }
    add_plane(newell(s.end[0], s.end[1], s.end[2], s.end[3]));
    add_plane(newell(s.start[0], s.start[1], s.start[2], s.start[3]));
    // edges: lateral, around the end, around the start
    auto add_edge = [&](glm::dvec3 e) {
        if (unit(e, scale)) h.edges[h.edge_count++] = e;
    };
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) % 4;
        add_edge(s.end[i] - s.start[i]);
        add_edge(s.end[j] - s.end[i]);
        add_edge(s.start[j] - s.start[i]);
    }
    return h;
}

bool BeamTracer::touches(const ConvexHull& h, uint32_t piece) const {
    const double tol = m_scene.tolerance();
    // bounding boxes first, the piece's kept by the scene
    const PieceBox& box = m_scene.box(piece);
    if (TouchingBlocks::boxes_apart(box.lo, box.hi, h.lo, h.hi, tol)) return false;
    const TraceFace& f = m_scene.faces()[piece];
    const glm::dvec3* v = m_scene.vertices_of(f);
    const int n = static_cast<int>(f.vertex_count);
    // the hull's planes, the piece's plane, then edge against edge
    return !planes_separate<TouchingBlocks>(h, v, n, f.normal, tol) &&
           !edges_separate<TouchingBlocks>(h, v, n, tol);
}

template <class Visit>
void BeamTracer::for_each_touching(const ConvexHull& h, uint32_t skip_a, uint32_t skip_b,
                                   Visit&& visit, BeamCounts& counts) const {
    uint64_t tests = 0;
    auto test = [&](uint32_t piece) {
        if (piece == skip_a || piece == skip_b) return false;
        ++tests;
        return touches(h, piece) && visit(piece);
    };
    const double tol = m_scene.tolerance();
    if (m_bvh)
        counts.query_nodes += scan_hull_bvh<TouchingBlocks>(*m_bvh, h, tol, test);
    else
        counts.query_cells += scan_hull_cells<TouchingBlocks>(*m_grid, h, tol, m_pieces, test);
    counts.query_face_tests += tests;
}

bool BeamTracer::segment_is_empty(const BeamSegment& segment, uint32_t skip_a, uint32_t skip_b,
                                  BeamCounts& counts) const {
    ++counts.queries;
    bool empty = true;
    for_each_touching(
        make_hull(segment), skip_a, skip_b,
        [&](uint32_t) {
            empty = false;
            return true;
        },
        counts);
    return empty;
}

BeamSegment BeamTracer::to_far_side(const Ray* rays[4]) const {
    BeamSegment s;
    for (int i = 0; i < 4; ++i) {
        const Ray& r = *rays[i];
        // beyond the farthest corner of the grid's box, whichever structure the queries use
        const glm::dvec3 far = glm::max(glm::abs(m_lo - r.origin), glm::abs(m_hi - r.origin));
        const double t = (glm::length(far) + m_scene.tolerance()) / glm::length(r.dir) * 1.001;
        s.start[i] = r.origin;
        s.end[i] = r.origin + t * r.dir;
    }
    return s;
}

uint32_t BeamTracer::faces_in_beam(const RayTrace* const corners[4], BeamCounts& counts,
                                   uint32_t enough) const {
    ++counts.face_counts;
    const Ray* rays[4];
    for (int i = 0; i < 4; ++i)
        rays[i] = &corners[i]->primary;
    Mailbox::Round ids = m_ids.begin();
    uint32_t faces = 0;
    for_each_touching(
        make_hull(to_far_side(rays)), kNoFace, kNoFace,
        [&](uint32_t piece) {
            if (ids.first_visit(m_scene.faces()[piece].id)) ++faces;
            return faces > enough;
        },
        counts);
    return faces;
}

bool BeamTracer::inside_with_margin(uint32_t piece, const glm::dvec3& p) const {
    const TraceFace& f = m_scene.faces()[piece];
    const glm::dvec3* v = m_scene.vertices_of(f);
    const double margin = 4 * m_scene.tolerance();
    for (uint32_t i = 0; i < f.vertex_count; ++i) {
        const glm::dvec3& a = v[i];
        const glm::dvec3& b = v[(i + 1) % f.vertex_count];
        const glm::dvec3 inward = glm::cross(f.normal, b - a);  // Newell's normal: CCW
        if (glm::dot(inward, p - a) < margin * glm::length(inward)) return false;
    }
    return true;
}

BeamClass BeamTracer::classify(const RayTrace* const corners[4], BeamCounts& counts) const {
    ++counts.beams;
    const RayTrace& a = *corners[0];
    auto result = [&](BeamClass c) {
        (c == BeamClass::Hit       ? counts.hits
         : c == BeamClass::Partial ? counts.partial
                                   : counts.blocked)++;
        return c;
    };
    // the lateral rays must share one path, well inside each face on it
    for (int i = 1; i < 4; ++i) {
        const RayTrace& b = *corners[i];
        if (b.count != a.count || b.escaped != a.escaped) return result(BeamClass::Partial);
        for (int k = 0; k < a.count; ++k)
            if (!(b.hits[k] == a.hits[k])) return result(BeamClass::Partial);
    }
    for (int k = 0; k < a.count; ++k)
        for (int i = 0; i < 4; ++i)
            if (!inside_with_margin(a.hits[k].piece, corners[i]->points[k]))
                return result(BeamClass::Partial);

    // every segment along the path must be empty
    for (int k = 0; k < a.count; ++k) {
        BeamSegment s;
        for (int i = 0; i < 4; ++i) {
            s.start[i] = k == 0 ? corners[i]->primary.origin : corners[i]->points[k - 1];
            s.end[i] = corners[i]->points[k];
        }
        const uint32_t from = k == 0 ? kNoFace : a.hits[k - 1].piece;
        if (!segment_is_empty(s, from, a.hits[k].piece, counts)) return result(BeamClass::Blocked);
    }
    // and so must the beam the lateral rays leave by, when they hit nothing
    if (a.escaped) {
        const Ray* rays[4];
        for (int i = 0; i < 4; ++i)
            rays[i] = &corners[i]->last;
        const uint32_t from = a.count > 0 ? a.hits[a.count - 1].piece : kNoFace;
        if (!segment_is_empty(to_far_side(rays), from, kNoFace, counts))
            return result(BeamClass::Partial);
    }
    return result(BeamClass::Hit);
}

}  // namespace fb89::host
