// When a decahedral query is worth making. The paper's §5 stops subdividing by "relatively
// crude heuristics"; ours is a cost model: query a region pair of n facing pairs when
//   Q + (1 − P) · 4 · S(n/4) < n · R,
// R the mean ray so far, Q the query, P the chance that it comes back empty (learned as the
// run goes), S the same choice one level down. The constants below were measured on the
// development machine; docs/DECAHEDRA.md ("The cost model") says how.
#pragma once

#include <cstdint>

namespace fb89::host {

// The flux tracer's work so far: the mean ray's cost comes from it.
struct RaysSoFar {
    uint64_t rays = 0;
    uint64_t cells = 0;  // top-level grid cells walked
    uint64_t tests = 0;  // pieces tested
};

class DecahedralCost {
  public:
    // the constants, ns on the development machine (docs/DECAHEDRA.md)
    static constexpr double kRayFixed = 5;     // a ray, besides its cells and tests
    static constexpr double kRayPerCell = 52;  // a grid cell a ray walks
    static constexpr double kRayPerTest = 1;   // a piece a ray tests
    static constexpr double kHull = 1450;      // a hull built, with the visits around it
    static constexpr double kPerPiece = 70;    // a piece tested against a hull
    // the prior of the mean ray: so many rays of so many cells and tests
    static constexpr double kPriorRays = 16, kPriorCells = 3, kPriorTests = 6;

    // Queries are learned by kind (0: an element pair; k = 1 .. kKinds - 1: a child with k
    // of its parent's pieces near, the last also for more) and by log2 of the facing pairs.
    static constexpr int kKinds = 9;
    static constexpr int kBuckets = 48;

    // Whether querying a region pair of `pairs` facing pairs of this kind, with `candidates`
    // pieces to test, costs less than its rays, all told.
    bool worth_querying(uint64_t pairs, int kind, double candidates, const RaysSoFar& so_far) const;
    // One more query of this kind and size, found empty or not.
    void learn(uint64_t pairs, int kind, bool empty);

  private:
    double settle_cost(double pairs, int kind, double query, double ray) const;
    double p_empty(double pairs, int kind) const;

    uint64_t m_queries[kKinds][kBuckets] = {}, m_empty[kKinds][kBuckets] = {};
    uint64_t m_kind_queries[kKinds] = {}, m_kind_empty[kKinds] = {};  // over all sizes
};

}  // namespace fb89::host
