// The decahedral hybrid (the paper's §5, Figs. 5.2-5.6): δ for the facing patch pairs of
// two elements at once when the convex hull of the two (the "decahedron") holds no other
// face; else the larger one's patch grid is split into four, each quarter is tried against
// the other, and region pairs not worth a query go to flux tracing (flux_tracing.cpp).
//
// How ours differs from the paper (docs/DECAHEDRA.md gives the details and the argument):
//   - Regions are rectangles of an element's patch grid, halved unevenly where a count is
//     odd, each shrunk to the rectangle around its patches in front of the other element's
//     plane before it is tried.
//   - The hull is built by gift wrapping (decahedral_hull.h), and only its open interior
//     counts: a piece touching its boundary leaves it empty. δ is still exactly flux
//     tracing's, pair for pair.
//   - An element pair's hull tests the pieces of the grid cells its planes do not cull
//     (convex_hull.h); a child's hull lies inside its parent's, so it tests only the
//     parent's pieces near its box, and with none it is empty without being built.
//   - When to stop querying is a cost model (decahedral_cost.h), not the paper's "relatively
//     crude heuristics"; DecahedralOptions::min_pairs_for_query > 0 replaces it.
#include <algorithm>
#include <array>
#include <vector>

#include <glm/common.hpp>

#include "host/radiosity/decahedral_cost.h"
#include "host/radiosity/decahedral_hull.h"
#include "host/radiosity/visibility.h"
#include "host/trace/convex_hull.h"
#include "host/trace/mailbox.h"

namespace fb89::host {

namespace {

struct Region {
    int i0, i1, j0, j1;
    int patches() const { return (i1 - i0) * (j1 - j0); }
};

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
    struct Candidates {  // what may be in a hull, for the cost model
        int kind = 0;    // DecahedralCost's kinds
        double pieces = 0;
        bool none = false;  // a child with none of its parent's pieces near: empty, no hull
    };
    void visit(Region ra, Region rb, int depth);
    void split(Region ra, Region rb, int depth);
    Candidates candidates(const std::array<glm::dvec3, 4>& ca, const std::array<glm::dvec3, 4>& cb,
                          uint64_t pairs, int depth);
    Answer query(const std::array<glm::dvec3, 4>& ca, const std::array<glm::dvec3, 4>& cb,
                 int depth);
    double listed_in_cells(const glm::dvec3& lo, const glm::dvec3& hi) const;
    template <class Decide>
    void each_pair(const Region& ra, const Region& rb, Decide&& decide);
    bool worth_querying(uint64_t pairs, int kind, double candidates) const;

    const Mesh& m_mesh;
    const TraceScene& m_scene;
    const UniformGrid& m_grid;
    const DecahedralOptions& m_options;
    VisibilityCounts& m_counts;
    Visibility& m_delta;
    FluxTracer m_tracer;
    double m_tol;
    HullPieces m_pieces;
    Mailbox m_mailbox;                            // per piece: the last query that tested it
    std::vector<std::vector<uint32_t>> m_inside;  // per depth: the pieces in that hull
    std::vector<uint32_t> m_near;                 // the parent's pieces near a child's box
    uint64_t m_rays = 0;                          // cast by this run
    Side m_a, m_b;
    DecahedralCost m_cost;
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
      m_pieces(world.scene),
      m_mailbox(world.scene.faces().size()) {}

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
        DecahedralHull h;
        if (!make_decahedral_hull(ca, cb, m_tol, h)) return Answer::Flat;
        auto test = [&](uint32_t piece) {
            ++tests;
            if (m_pieces.occupies(h, piece)) inside.push_back(piece);
        };
        if (depth > 0) {
            for (uint32_t piece : m_near)
                test(piece);
        } else {
            const uint32_t skip_a = m_a.e->piece, skip_b = m_b.e->piece;
            scan_hull_cells<TouchingIsApart>(m_grid, h, m_tol, m_mailbox, [&](uint32_t piece) {
                if (piece != skip_a && piece != skip_b) test(piece);
                return false;
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

bool Decahedra::worth_querying(uint64_t pairs, int kind, double candidates) const {
    if (m_options.min_pairs_for_query > 0) return pairs > m_options.min_pairs_for_query;
    return m_cost.worth_querying(pairs, kind, candidates,
                                 {m_rays, m_tracer.cells(), m_tracer.face_tests()});
}

// What may be in the hull of two outlines: the pieces the grid lists in the cells of their
// box (an element pair), or the parent's pieces whose boxes reach it (m_near, a child).
Decahedra::Candidates Decahedra::candidates(const std::array<glm::dvec3, 4>& ca,
                                            const std::array<glm::dvec3, 4>& cb, uint64_t pairs,
                                            int depth) {
    glm::dvec3 lo = ca[0], hi = ca[0];
    for (const auto* outline : {&ca, &cb})
        for (const glm::dvec3& p : *outline) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    Candidates c;
    if (depth > 0) {
        m_near.clear();
        for (uint32_t piece : m_inside[depth - 1])
            if (!m_pieces.box_apart(piece, lo, hi)) m_near.push_back(piece);
        c.pieces = static_cast<double>(m_near.size());
        c.kind = static_cast<int>(std::min<size_t>(m_near.size(), DecahedralCost::kKinds - 1));
        c.none = m_near.empty();
    } else if (m_options.min_pairs_for_query == 0 && pairs > 1) {
        c.pieces = listed_in_cells(lo, hi);
    }
    return c;
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

    // the outlines, and whether a query is worth it
    const auto ca = m_a.outline(ra), cb = m_b.outline(rb);
    const Candidates near = candidates(ca, cb, pairs, depth);
    if (!(near.none && m_options.min_pairs_for_query == 0) &&
        !worth_querying(pairs, near.kind, near.pieces))
        return trace();

    // the query
    const Answer answer = query(ca, cb, depth);
    if (answer == Answer::Flat) return trace();  // coplanar regions
    if (!near.none) m_cost.learn(pairs, near.kind, answer == Answer::Empty);
    if (answer == Answer::Empty) {
        each_pair(ra, rb, [](uint32_t, uint32_t) { return Delta::Visible; });
        m_counts.pairs_by_queries += pairs;
        return;
    }
    split(ra, rb, depth);
}

// An occupied region pair: the region of more patches (a single patch is not split) into
// four, each tried against the other region.
void Decahedra::split(Region ra, Region rb, int depth) {
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
                             const DecahedralOptions& options, VisibilityCounts& counts,
                             const WorkObserver& work) {
    Visibility delta(static_cast<uint32_t>(mesh.patches.size()));
    Decahedra decahedra(mesh, world, options, counts, delta);
    const auto elements = static_cast<uint32_t>(mesh.elements.size());
    const uint64_t n = mesh.patches.size();
    for (uint32_t ea = 0; ea < elements; ++ea) {
        for (uint32_t eb = ea + 1; eb < elements; ++eb)
            decahedra.element_pair(ea, eb);
        const Element& a = mesh.elements[ea];
        if (work)
            work(pairs_before(n, a.first_patch + static_cast<uint64_t>(a.nu * a.nv)),
                 pairs_before(n, n));
    }
    return delta;
}

}  // namespace fb89::host
