// Intervisibility of patches (the paper's §5): δ for every unordered pair of patches that
// face each other (cos > 0 at both ends, measured between patch centres). Pairs that do
// not face each other exchange nothing and need no ray; they are recorded as such.
//
// Two ways to decide δ (flux_tracing.cpp, decahedron.cpp), which must agree on every pair:
//   - flux tracing: one ray from centre to centre, blocked by any face piece but the two
//     the patches lie on (t in (ε, 1 − ε)); back faces block;
//   - the decahedral hybrid: the convex hull of two elements' patch regions, queried for
//     emptiness; an empty hull makes every facing pair of the two regions visible at once,
//     an occupied one is split, and small enough regions go to flux tracing.
#pragma once

#include <cstdint>
#include <vector>

#include "host/progress.h"
#include "host/radiosity/mesh.h"
#include "host/stats.h"
#include "host/trace/grid.h"
#include "host/trace/mailbox.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {

enum class Delta : uint8_t { NotFacing = 0, Hidden = 1, Visible = 2 };

// δ for unordered pairs of N patches, kept as the upper triangle.
class Visibility {
  public:
    explicit Visibility(uint32_t patches = 0)
        : m_n(patches),
          m_delta(static_cast<size_t>(patches) * (patches ? patches - 1 : 0) / 2,
                  Delta::NotFacing) {}
    uint32_t size() const { return m_n; }
    Delta get(uint32_t i, uint32_t j) const { return m_delta[index(i, j)]; }
    void set(uint32_t i, uint32_t j, Delta d) { m_delta[index(i, j)] = d; }
    bool operator==(const Visibility&) const = default;

  private:
    size_t index(uint32_t i, uint32_t j) const {
        if (i > j) std::swap(i, j);  // i < j; i == j is not a pair
        return static_cast<size_t>(i) * (2 * static_cast<size_t>(m_n) - i - 1) / 2 + (j - i - 1);
    }
    uint32_t m_n;
    std::vector<Delta> m_delta;
};

// True when patches p and q face each other: each centre in front of the other's plane.
bool facing(const Mesh& mesh, uint32_t p, uint32_t q);

// True when `point` lies in front of element e's plane by more than rounding (a billionth of
// the element's coordinates). facing(p, q) is exactly in_front(element of p, centre of q) &&
// in_front(element of q, centre of p) for patches of different elements, so the facing
// pairs of two patch regions are a product of two counts.
bool in_front(const Element& e, const glm::dvec3& point);

struct VisibilityCounts {
    uint64_t facing_pairs = 0;      // unordered patch pairs that face each other
    uint64_t rays = 0;              // flux-tracing rays cast
    uint64_t queries = 0;           // decahedral volume queries
    uint64_t empty_queries = 0;     // of those, found empty
    uint64_t query_face_tests = 0;  // pieces tested against a hull
    uint64_t pairs_by_queries = 0;  // facing pairs decided by an empty hull
    void publish(Counters& counters) const;
};

// The world the queries and rays run in: the scene's pieces and a grid over them.
struct RadiosityWorld {
    const TraceScene& scene;
    const UniformGrid& grid;
};

Visibility flux_tracing(const Mesh& mesh, const RadiosityWorld& world, VisibilityCounts& counts,
                        const WorkObserver& work = {});

// One flux-tracing ray at a time (flux_tracing.cpp), so that both methods cast the very same
// rays: from the centre of the lower-numbered patch to the other's, any hit ends it.
class FluxTracer {
  public:
    FluxTracer(const Mesh& mesh, const RadiosityWorld& world);
    Delta trace(uint32_t p, uint32_t q);  // p and q must face each other
    // Whether a piece other than skip_a and skip_b meets the segment from `from` to `to`,
    // its ends trimmed by the tolerance ε: the one segment query of flux tracing.
    bool blocked(const glm::dvec3& from, const glm::dvec3& to, uint32_t skip_a, uint32_t skip_b);
    uint64_t cells() const { return m_cells; }            // top-level grid cells walked, all rays
    uint64_t face_tests() const { return m_face_tests; }  // ray-piece tests, all rays

  private:
    const Mesh& m_mesh;
    const TraceScene& m_scene;
    const UniformGrid& m_grid;
    Mailbox m_mailbox;
    uint64_t m_cells = 0, m_face_tests = 0;
};

struct DecahedralOptions {
    // Regions of at most this many facing patch pairs go to flux tracing without a query;
    // 0 lets the cost heuristic decide (decahedron.cpp).
    uint64_t min_pairs_for_query = 0;
};
Visibility decahedral_hybrid(const Mesh& mesh, const RadiosityWorld& world,
                             const DecahedralOptions& options, VisibilityCounts& counts,
                             const WorkObserver& work = {});

}  // namespace fb89::host
