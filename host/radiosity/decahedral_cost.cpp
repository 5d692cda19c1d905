#include "host/radiosity/decahedral_cost.h"

#include <algorithm>
#include <cmath>

namespace fb89::host {

// The chance that a query of this kind and size comes back empty: the fraction found empty
// so far, with a prior of two queries at the kind's rate over all sizes (itself from a
// prior of one empty and one occupied).
double DecahedralCost::p_empty(double pairs, int kind) const {
    const int b = std::clamp(static_cast<int>(std::log2(std::max(pairs, 1.0))), 0, kBuckets - 1);
    const double prior = (static_cast<double>(m_kind_empty[kind]) + 1) /
                         (static_cast<double>(m_kind_queries[kind]) + 2);
    return (static_cast<double>(m_empty[kind][b]) + 2 * prior) /
           (static_cast<double>(m_queries[kind][b]) + 2);
}

void DecahedralCost::learn(uint64_t pairs, int kind, bool empty) {
    const int b =
        std::clamp(static_cast<int>(std::log2(static_cast<double>(pairs))), 0, kBuckets - 1);
    ++m_queries[kind][b];
    m_empty[kind][b] += empty;
    ++m_kind_queries[kind];
    m_kind_empty[kind] += empty;
}

// The expected cost of settling a region pair of `pairs` facing pairs: by rays, or by a
// query and, when it is occupied, four children of a quarter of the pairs each.
double DecahedralCost::settle_cost(double pairs, int kind, double query, double ray) const {
    const double rays = pairs * ray;
    if (pairs < 2) return rays;
    const double occupied = 1 - p_empty(pairs, kind);
    return std::min(rays, query + occupied * 4 * settle_cost(pairs / 4, kind, query, ray));
}

bool DecahedralCost::worth_querying(uint64_t pairs, int kind, double candidates,
                                    const RaysSoFar& so_far) const {
    if (pairs < 2) return false;
    // the mean ray so far
    const double rays = static_cast<double>(so_far.rays) + kPriorRays;
    const double cells = static_cast<double>(so_far.cells) + kPriorRays * kPriorCells;
    const double tests = static_cast<double>(so_far.tests) + kPriorRays * kPriorTests;
    const double ray = kRayFixed + (kRayPerCell * cells + kRayPerTest * tests) / rays;
    const double query = kHull + kPerPiece * candidates;
    const double n = static_cast<double>(pairs);
    // the children: a child kind like this one's, an element pair's like one piece near
    const int child = kind == 0 ? 1 : kind;
    const double child_query = kHull + kPerPiece * (kind == 0 ? 1 : candidates);
    const double occupied = 1 - p_empty(n, kind);
    return query + occupied * 4 * settle_cost(n / 4, child, child_query, ray) < n * ray;
}

}  // namespace fb89::host
