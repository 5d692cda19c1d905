// The decahedral hybrid (the paper's §5, Figs. 5.2-5.6): δ for the facing patch pairs of
// two elements at once when the convex hull of the two (the "decahedron") holds no other
// face; else the larger one's patch grid is split into four, each quarter is tried against
// the other, and region pairs not worth a query go to flux tracing (flux_tracing.cpp).
//
// How ours differs from the paper:
//   - Regions are rectangles of an element's patch grid, [i0, i1) x [j0, j1), halved unevenly
//     where a count is odd; a side of one patch is not split, and when the larger region is a
//     single patch the other is split. Before a region pair is tried, each region shrinks to
//     the rectangle around its patches in front of the other element's plane (a floor region
//     behind a box's face is left out of that face's hull).
//   - The hull of the two outlines (region_corners) is built by gift wrapping: its facets are
//     either outline's plane or hold an edge of one and a corner of the other.
//   - The query counts only the hull's open interior: a piece is out when some axis (the
//     boxes', the hull's facets, the piece's plane, their edges' cross products) sees the two
//     overlap by no more than the scene's tolerance, so a wall meeting the floor-to-ceiling
//     hull along its side, or a neighbour sharing an edge, leaves it empty. An element pair's
//     hull tests every piece listed in the grid cells its box reaches that its planes do not
//     cull; a child's hull lies inside its parent's, so it tests only the pieces found in the
//     parent's hull, and of those only the ones whose boxes reach its box; when there are
//     none it is empty without being built (still counted as a query).
//   - Why treating touching as apart cannot change δ: a flux ray from c_p to c_q counts hits at
//     t in (ε, 1 − ε), ε = 4 tol / |c_q − c_p|. When the hull is found empty, no piece but the
//     two ends' holds a point deeper than tol inside it: around such a point every axis sees
//     an overlap above tol. The centres lie strictly inside their regions, so unless the two
//     regions are coplanar no plane supporting the hull holds both, and the open segment
//     between them lies in the hull's open interior; its depth grows from the ends like
//     t |c_q − c_p| cos φ_p, far above tol (a billionth of the scene) except within a few
//     tolerances of c_p and c_q, where a blocker would have to touch the patch's own face at
//     its centre. So an empty hull means every ray between its regions gets through, as flux
//     tracing finds; the tests check δ(hybrid) == δ(flux) room by room.
//   - Coplanar region pairs (within tol) give a flat hull: in_front keeps their patches from
//     facing, but any facing pair there goes to flux tracing.
//   - When to stop querying is a cost model, not the paper's "relatively crude heuristics":
//     query a region pair of n facing pairs when Q + (1 − P) · 4 · S(n/4) < n · R, where
//       R = the mean ray so far: kRayFixed + kRayPerCell x cells walked + kRayPerTest x
//           pieces tested (FluxTracer's counts, with a prior of 3 cells and 6 tests);
//       Q = kHull + kPerPiece x the pieces it would test: for an element pair those the grid
//           lists in the cells of the hull's box (at most all), for a child its parent's
//           pieces near its box;
//       P = the chance it comes back empty, learned as the run goes: the fraction of queries
//           found empty so far among those of its kind (an element pair, or a child with k =
//           1 .. 8+ of its parent's pieces near: the parent's result) and of its size (log2
//           n), shrunk towards its kind's rate over all sizes by a prior of two queries;
//       S(m) = min(m · R, Q' + (1 − P) · 4 · S(m/4)), the same choice one level down (Q' for
//           a child of the same kind; an element pair's children are taken as kind 1).
//     The constants are ns on the development machine (AMD EPYC, 2 cores shared with other
//     builds, one thread, GCC 12 -O3), fitted by least squares on relative error over the
//     garish room, the programmer's cell and a box room at 400 to 1600 patches: flux tracing
//     time against cells walked and pieces tested gave 52 ns a cell and ~1 ns a test (the
//     cell dominates: a crowded cell's grid is set up for each ray); the hybrid's time with
//     min_pairs_for_query 1, 4, 16 and 64, less that ray model, against hulls built and
//     pieces tested gave 1450 ns a hull (with the visits around it) and 70 ns a piece.
//     DecahedralOptions::min_pairs_for_query > 0 replaces the model: query exactly the
//     region pairs of more facing pairs than that.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "host/radiosity/visibility.h"
#include "host/trace/mailbox.h"

namespace fb89::host {

namespace {

// the cost model, ns on the development machine (see above)
constexpr double kRayFixed = 5;
constexpr double kRayPerCell = 52;
constexpr double kRayPerTest = 1;
constexpr double kHull = 1450;
constexpr double kPerPiece = 70;
constexpr double kPriorRays = 16, kPriorCells = 3, kPriorTests = 6;  // per ray
constexpr int kKinds = 9;     // an element pair; a child with 1 .. 8 (or more) pieces near
constexpr int kBuckets = 48;  // log2 of a region pair's facing pairs

constexpr int kMaxPoints = 8, kMaxPlanes = 24, kMaxEdges = 40;

struct Region {
    int i0, i1, j0, j1;
    int patches() const { return (i1 - i0) * (j1 - j0); }
};

// The hull of two regions, made ready for separating-axis tests.
struct Hull {
    glm::dvec3 points[kMaxPoints];  // the first region's corners, then the second's
    int point_count = 0, na = 0;
    glm::dvec3 lo{0}, hi{0};
    glm::dvec3 planes[kMaxPlanes];  // outward, unit
    double plane_lo[kMaxPlanes], plane_hi[kMaxPlanes];
    uint32_t on[kMaxPlanes];  // the points on each facet, as bits
    int plane_count = 0;
    bool edges_found = false;     // find_edges has run
    glm::dvec3 edges[kMaxEdges];  // unit
    int edge_count = 0;
};

void project(const glm::dvec3* p, int count, const glm::dvec3& axis, double& lo, double& hi) {
    lo = hi = glm::dot(p[0], axis);
    for (int i = 1; i < count; ++i) {
        const double d = glm::dot(p[i], axis);
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
}

// Two extents along one axis that overlap by no more than `tol`: touching is apart.
bool apart(double lo_a, double hi_a, double lo_b, double hi_b, double tol) {
    return hi_a - lo_b <= tol || hi_b - lo_a <= tol;
}

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
void add_plane(Hull& h, const glm::dvec3& normal, const glm::dvec3& through, double tol) {
    for (int k = 0; k < h.plane_count; ++k)
        if (glm::dot(h.planes[k], normal) > 1 - 1e-9) return;
    if (h.plane_count == kMaxPlanes) return;  // fewer axes: only more conservative
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
void wrap_edges(Hull& h, const glm::dvec3* p, int n, const glm::dvec3& up, const glm::dvec3* q,
                int m, double tol) {
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

// The hull of both outlines; false when it is flat (every point within tol of one plane).
// A facet of the hull of two convex polygons is one's plane, or holds an edge of one and a
// corner of the other, found by wrapping each edge.
bool make_hull(const std::array<glm::dvec3, 4>& ra, const std::array<glm::dvec3, 4>& rb, double tol,
               Hull& h) {
    const int na = distinct_corners(ra, tol, h.points);
    const int nb = distinct_corners(rb, tol, h.points + na);
    const int n = h.point_count = na + nb;
    h.na = na;
    h.lo = h.hi = h.points[0];
    for (int k = 1; k < n; ++k) {
        h.lo = glm::min(h.lo, h.points[k]);
        h.hi = glm::max(h.hi, h.points[k]);
    }
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
    wrap_edges(h, a, na, up_a, b, nb, tol);
    wrap_edges(h, b, nb, up_b, a, na, tol);
    return h.plane_count >= 4;
}

// The hull's edge directions, once a piece needs them: the outlines' and those between the
// two on two facets at once.
void find_edges(Hull& h) {
    h.edges_found = true;
    const int na = h.na, nb = h.point_count - h.na;
    const glm::dvec3* a = h.points;
    const glm::dvec3* b = h.points + na;
    auto add_edge = [&](const glm::dvec3& from, const glm::dvec3& to) {
        const glm::dvec3 e = glm::normalize(to - from);
        for (int k = 0; k < h.edge_count; ++k)
            if (std::abs(glm::dot(h.edges[k], e)) > 1 - 1e-9) return;
        if (h.edge_count < kMaxEdges) h.edges[h.edge_count++] = e;
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

// A grid cell entirely outside the hull, or only touching it.
bool outside(const Hull& h, const glm::dvec3& lo, const glm::dvec3& size, double tol) {
    const glm::dvec3 half = size * 0.5, centre = lo + half;
    for (int k = 0; k < h.plane_count; ++k) {
        const double c = glm::dot(h.planes[k], centre);
        const double r = glm::dot(glm::abs(h.planes[k]), half);
        if (apart(c - r, c + r, h.plane_lo[k], h.plane_hi[k], tol)) return true;
    }
    return false;
}

// Calls `test(piece)` for the pieces listed in the cells of the grid that the hull's box
// covers and its planes do not cull. A crowded cell's own grid is not used: culling its many
// small cells costs more than testing the cell's pieces.
template <class Test>
void scan(const UniformGrid& grid, const Hull& h, double tol, Test&& test) {
    glm::ivec3 first, last;
    if (!grid.cell_range(h.lo - tol, h.hi + tol, first, last)) return;
    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x)
                if (!outside(h, grid.cell_lo(x, y, z), grid.cell_size(), tol))
                    for (uint32_t piece : grid.cell(grid.index(x, y, z)))
                        test(piece);
}

// Decides δ for the region pairs of one element pair after another.
class Decahedra {
  public:
    Decahedra(const Mesh& mesh, const RadiosityWorld& world, const DecahedralOptions& options,
              VisibilityCounts& counts, Visibility& delta);
    void element_pair(uint32_t ea, uint32_t eb);

  private:
    struct Side {  // one element of the pair and its patches in front of the other's plane
        const Element* e = nullptr;
        std::vector<uint8_t> front;  // per patch, j * nu + i
        bool sort(const Mesh& mesh, const Element& self, const Element& other);
        uint64_t tighten(Region& r) const;
        std::array<glm::dvec3, 4> outline(const Region& r) const {
            return region_corners(*e, r.i0, r.i1, r.j0, r.j1);
        }
    };
    enum class Answer { Empty, Occupied, Flat };
    void visit(Region ra, Region rb, int depth);
    Answer query(const std::array<glm::dvec3, 4>& ca, const std::array<glm::dvec3, 4>& cb,
                 int depth);
    bool occupies(Hull& h, uint32_t piece) const;
    bool box_apart(uint32_t piece, const glm::dvec3& lo, const glm::dvec3& hi) const;
    double listed_in_cells(const glm::dvec3& lo, const glm::dvec3& hi) const;
    template <class Decide>
    void each_pair(const Region& ra, const Region& rb, Decide&& decide);
    // the cost model
    bool worth_querying(uint64_t pairs, int kind, double candidates) const;
    double settle_cost(double pairs, int kind, double query, double ray) const;
    double p_empty(double pairs, int kind) const;
    void learn(uint64_t pairs, int kind, bool empty);

    const Mesh& m_mesh;
    const TraceScene& m_scene;
    const UniformGrid& m_grid;
    const DecahedralOptions& m_options;
    VisibilityCounts& m_counts;
    Visibility& m_delta;
    FluxTracer m_tracer;
    double m_tol;
    std::vector<glm::dvec3> m_box_lo, m_box_hi;   // per piece
    Mailbox m_mailbox;                            // per piece: the last query that tested it
    std::vector<std::vector<uint32_t>> m_inside;  // per depth: the pieces in that hull
    std::vector<uint32_t> m_near;                 // the parent's pieces near a child's box
    uint64_t m_rays = 0;                          // cast by this run
    Side m_a, m_b;
    // queries and empty ones by kind (an element pair, or a child with 1 .. kKinds - 1
    // of its parent's pieces near) and by log2 of the facing pairs
    uint64_t m_queries[kKinds][kBuckets] = {}, m_empty[kKinds][kBuckets] = {};
    uint64_t m_kind_queries[kKinds] = {}, m_kind_empty[kKinds] = {};  // over all sizes
};

Decahedra::Decahedra(const Mesh& mesh, const RadiosityWorld& world,
                     const DecahedralOptions& options, VisibilityCounts& counts, Visibility& delta)
    : m_mesh(mesh),
      m_scene(world.scene),
      m_grid(world.grid),
      m_options(options),
      m_counts(counts),
      m_delta(delta),
      m_tracer(mesh, world),
      m_tol(world.scene.tolerance()),
      m_mailbox(world.scene.faces().size()) {
    for (const TraceFace& f : m_scene.faces()) {
        const glm::dvec3* v = m_scene.vertices_of(f);
        glm::dvec3 lo = v[0], hi = v[0];
        for (uint32_t i = 1; i < f.vertex_count; ++i) {
            lo = glm::min(lo, v[i]);
            hi = glm::max(hi, v[i]);
        }
        m_box_lo.push_back(lo);
        m_box_hi.push_back(hi);
    }
}

bool Decahedra::Side::sort(const Mesh& mesh, const Element& self, const Element& other) {
    e = &self;
    const auto count = static_cast<uint32_t>(self.nu * self.nv);
    front.resize(count);
    bool any = false;
    for (uint32_t k = 0; k < count; ++k)
        any |= (front[k] = in_front(other, mesh.patches[self.first_patch + k].centre)) != 0;
    return any;
}

// Shrinks a region to the rectangle around its patches in front; their count (0: none).
uint64_t Decahedra::Side::tighten(Region& r) const {
    Region t{r.i1, r.i0, r.j1, r.j0};
    uint64_t count = 0;
    for (int j = r.j0; j < r.j1; ++j)
        for (int i = r.i0; i < r.i1; ++i)
            if (front[j * e->nu + i]) {
                ++count;
                t = {std::min(t.i0, i), std::max(t.i1, i + 1), std::min(t.j0, j),
                     std::max(t.j1, j + 1)};
            }
    if (count > 0) r = t;
    return count;
}

template <class Decide>
void Decahedra::each_pair(const Region& ra, const Region& rb, Decide&& decide) {
    const Element& a = *m_a.e;
    const Element& b = *m_b.e;
    for (int ja = ra.j0; ja < ra.j1; ++ja)
        for (int ia = ra.i0; ia < ra.i1; ++ia) {
            if (!m_a.front[ja * a.nu + ia]) continue;
            const uint32_t p = a.patch(ia, ja);
            for (int jb = rb.j0; jb < rb.j1; ++jb)
                for (int ib = rb.i0; ib < rb.i1; ++ib)
                    if (m_b.front[jb * b.nu + ib]) {
                        const uint32_t q = b.patch(ib, jb);
                        m_delta.set(p, q, decide(p, q));
                    }
        }
}

bool Decahedra::box_apart(uint32_t piece, const glm::dvec3& lo, const glm::dvec3& hi) const {
    for (int a = 0; a < 3; ++a)
        if (apart(m_box_lo[piece][a], m_box_hi[piece][a], lo[a], hi[a], m_tol)) return true;
    return false;
}

bool Decahedra::occupies(Hull& h, uint32_t piece) const {
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
    double lo_p, hi_p, lo_h, hi_h;
    for (int k = 0; k < h.plane_count; ++k) {
        project(v, n, h.planes[k], lo_p, hi_p);
        if (apart(lo_p, hi_p, h.plane_lo[k], h.plane_hi[k], m_tol)) return false;
    }
    project(v, n, f.normal, lo_p, hi_p);
    project(h.points, h.point_count, f.normal, lo_h, hi_h);
    if (apart(lo_p, hi_p, lo_h, hi_h, m_tol)) return false;
    if (!h.edges_found) find_edges(h);
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 edge = v[(i + 1) % n] - v[i];
        const double edge_len = glm::length(edge);
        for (int k = 0; k < h.edge_count; ++k) {
            glm::dvec3 axis = glm::cross(edge, h.edges[k]);
            const double len = glm::length(axis);
            if (!(len > 1e-9 * edge_len)) continue;  // parallel edges
            axis /= len;
            project(v, n, axis, lo_p, hi_p);
            project(h.points, h.point_count, axis, lo_h, hi_h);
            if (apart(lo_p, hi_p, lo_h, hi_h, m_tol)) return false;
        }
    }
    return true;
}

// Fills m_inside[depth] with the pieces in the hull of two outlines: at depth 0 from every
// piece the grid lists near it, deeper from the parent's pieces near it (m_near) alone,
// since a child's hull lies in its parent's.
Decahedra::Answer Decahedra::query(const std::array<glm::dvec3, 4>& ca,
                                   const std::array<glm::dvec3, 4>& cb, int depth) {
    if (m_inside.size() <= static_cast<size_t>(depth)) m_inside.resize(depth + 1);
    std::vector<uint32_t>& inside = m_inside[depth];
    inside.clear();
    uint64_t tests = 0;
    if (depth == 0 || !m_near.empty()) {
        Hull h;
        if (!make_hull(ca, cb, m_tol, h)) return Answer::Flat;
        auto test = [&](uint32_t piece) {
            ++tests;
            if (occupies(h, piece)) inside.push_back(piece);
        };
        if (depth > 0) {
            for (uint32_t piece : m_near)
                test(piece);
        } else {
            const Mailbox::Round round = m_mailbox.begin();
            const uint32_t skip_a = m_a.e->piece, skip_b = m_b.e->piece;
            scan(m_grid, h, m_tol, [&](uint32_t piece) {
                if (!round.first_visit(piece)) return;
                if (piece != skip_a && piece != skip_b) test(piece);
            });
        }
    }
    ++m_counts.queries;
    m_counts.query_face_tests += tests;
    if (!inside.empty()) return Answer::Occupied;
    ++m_counts.empty_queries;
    return Answer::Empty;
}

double Decahedra::listed_in_cells(const glm::dvec3& lo, const glm::dvec3& hi) const {
    uint64_t listed = 0;
    glm::ivec3 first, last;
    if (m_grid.cell_range(lo, hi, first, last))
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x)
                    listed += m_grid.cell(m_grid.index(x, y, z)).size();
    return static_cast<double>(std::min<uint64_t>(listed, m_scene.faces().size()));
}

// The chance that a query of this kind and size comes back empty: the fraction found empty
// so far, with a prior of two queries at the kind's rate over all sizes (itself from a
// prior of one empty and one occupied).
double Decahedra::p_empty(double pairs, int kind) const {
    const int b = std::clamp(static_cast<int>(std::log2(std::max(pairs, 1.0))), 0, kBuckets - 1);
    const double prior = (static_cast<double>(m_kind_empty[kind]) + 1) /
                         (static_cast<double>(m_kind_queries[kind]) + 2);
    return (static_cast<double>(m_empty[kind][b]) + 2 * prior) /
           (static_cast<double>(m_queries[kind][b]) + 2);
}

void Decahedra::learn(uint64_t pairs, int kind, bool empty) {
    const int b =
        std::clamp(static_cast<int>(std::log2(static_cast<double>(pairs))), 0, kBuckets - 1);
    ++m_queries[kind][b];
    m_empty[kind][b] += empty;
    ++m_kind_queries[kind];
    m_kind_empty[kind] += empty;
}

// The expected cost of settling a region pair of `pairs` facing pairs: by rays, or by a
// query and, when it is occupied, four children of a quarter of the pairs each.
double Decahedra::settle_cost(double pairs, int kind, double query, double ray) const {
    const double rays = pairs * ray;
    if (pairs < 2) return rays;
    const double occupied = 1 - p_empty(pairs, kind);
    return std::min(rays, query + occupied * 4 * settle_cost(pairs / 4, kind, query, ray));
}

bool Decahedra::worth_querying(uint64_t pairs, int kind, double candidates) const {
    if (m_options.min_pairs_for_query > 0) return pairs > m_options.min_pairs_for_query;
    if (pairs < 2) return false;
    const double rays = static_cast<double>(m_rays) + kPriorRays;
    const double cells = static_cast<double>(m_tracer.cells()) + kPriorRays * kPriorCells;
    const double tests = static_cast<double>(m_tracer.face_tests()) + kPriorRays * kPriorTests;
    const double ray = kRayFixed + (kRayPerCell * cells + kRayPerTest * tests) / rays;
    const double query = kHull + kPerPiece * candidates;
    const double n = static_cast<double>(pairs);
    // the children: a child kind like this one's, an element pair's like one piece near
    const int child = kind == 0 ? 1 : kind;
    const double child_query = kHull + kPerPiece * (kind == 0 ? 1 : candidates);
    const double occupied = 1 - p_empty(n, kind);
    return query + occupied * 4 * settle_cost(n / 4, child, child_query, ray) < n * ray;
}

void Decahedra::visit(Region ra, Region rb, int depth) {
    const uint64_t pairs = m_a.tighten(ra) * m_b.tighten(rb);
    if (pairs == 0) return;
    if (depth == 0) m_counts.facing_pairs += pairs;
    auto trace = [&] {
        each_pair(ra, rb, [&](uint32_t p, uint32_t q) { return m_tracer.trace(p, q); });
        m_counts.rays += pairs;
        m_rays += pairs;
    };
    if (ra.patches() == 1 && rb.patches() == 1) return trace();

    // the outlines, their box, and what may be in their hull: the pieces the grid lists
    // there, or the parent's pieces whose boxes reach it
    const auto ca = m_a.outline(ra), cb = m_b.outline(rb);
    glm::dvec3 lo = ca[0], hi = ca[0];
    for (const auto* outline : {&ca, &cb})
        for (const glm::dvec3& p : *outline) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    int kind = 0;
    double candidates = 0;
    if (depth > 0) {
        m_near.clear();
        for (uint32_t piece : m_inside[depth - 1])
            if (!box_apart(piece, lo, hi)) m_near.push_back(piece);
        candidates = static_cast<double>(m_near.size());
        kind = static_cast<int>(std::min<size_t>(m_near.size(), kKinds - 1));
    } else if (m_options.min_pairs_for_query == 0 && pairs > 1) {
        candidates = listed_in_cells(lo, hi);
    }
    const bool free = depth > 0 && m_near.empty();  // nothing near: empty without a hull
    if (!(free && m_options.min_pairs_for_query == 0) && !worth_querying(pairs, kind, candidates))
        return trace();

    // the query
    const Answer answer = query(ca, cb, depth);
    if (answer == Answer::Flat) return trace();  // coplanar regions
    if (!free) learn(pairs, kind, answer == Answer::Empty);
    if (answer == Answer::Empty) {
        each_pair(ra, rb, [](uint32_t, uint32_t) { return Delta::Visible; });
        m_counts.pairs_by_queries += pairs;
        return;
    }

    // occupied: the region of more patches (a single patch is not split) into four
    const bool split_a = rb.patches() == 1 || (ra.patches() > 1 && ra.patches() >= rb.patches());
    Region& r = split_a ? ra : rb;
    const Region whole = r;
    const int is[3] = {whole.i0, whole.i0 + (whole.i1 - whole.i0) / 2, whole.i1};
    const int js[3] = {whole.j0, whole.j0 + (whole.j1 - whole.j0) / 2, whole.j1};
    for (int v = 0; v < 2; ++v)
        for (int u = 0; u < 2; ++u) {
            r = {is[u], is[u + 1], js[v], js[v + 1]};
            if (r.i0 < r.i1 && r.j0 < r.j1) visit(ra, rb, depth + 1);
        }
}

void Decahedra::element_pair(uint32_t ea, uint32_t eb) {
    const Element& a = m_mesh.elements[ea];
    const Element& b = m_mesh.elements[eb];
    if (!m_b.sort(m_mesh, b, a) || !m_a.sort(m_mesh, a, b)) return;
    visit({0, a.nu, 0, a.nv}, {0, b.nu, 0, b.nv}, 0);
}

}  // namespace

Visibility decahedral_hybrid(const Mesh& mesh, const RadiosityWorld& world,
                             const DecahedralOptions& options, VisibilityCounts& counts) {
    Visibility delta(static_cast<uint32_t>(mesh.patches.size()));
    Decahedra decahedra(mesh, world, options, counts, delta);
    const auto elements = static_cast<uint32_t>(mesh.elements.size());
    for (uint32_t ea = 0; ea < elements; ++ea)
        for (uint32_t eb = ea + 1; eb < elements; ++eb)
            decahedra.element_pair(ea, eb);
    return delta;
}

}  // namespace fb89::host
