// Convex hulls against pieces: the two touching rules on constructed contacts (a face, an
// edge, a small gap, a small overlap), and the culled grid scan.
#include "host/trace/convex_hull.h"

#include <map>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/host/raster/raster_test_util.h"
#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using glm::dvec3;

constexpr double kTol = 1e-6;

// The box [lo, hi] as a hull: its eight corners, three planes, three edge directions.
ConvexHull box_hull(dvec3 lo, dvec3 hi) {
    ConvexHull h;
    for (int k = 0; k < 8; ++k)
        h.points[k] = {k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    h.point_count = 8;
    h.fit_box();
    for (int a = 0; a < 3; ++a) {
        dvec3 n(0);
        n[a] = 1;
        h.planes[a] = h.edges[a] = n;
        project(h.points, 8, n, h.plane_lo[a], h.plane_hi[a]);
    }
    h.plane_count = h.edge_count = 3;
    return h;
}

struct Piece {
    std::vector<dvec3> v;
    dvec3 normal;
};

// A square of side 2 in the plane x = at, normal +x.
Piece square_at_x(double at) {
    return {{{at, -1, -1}, {at, 1, -1}, {at, 1, 1}, {at, -1, 1}}, {1, 0, 0}};
}

template <class Rule>
bool separated(const ConvexHull& h, const Piece& p) {
    const int n = static_cast<int>(p.v.size());
    return planes_separate<Rule>(h, p.v.data(), n, p.normal, kTol) ||
           edges_separate<Rule>(h, p.v.data(), n, kTol);
}

TEST(ConvexHull, TheRulesDifferOnlyWithinTheTolerance) {
    // [0, 1] against b at gaps and overlaps around the tolerance
    const double small = kTol / 2, wide = 2 * kTol;
    EXPECT_TRUE(TouchingBlocks::apart(0, 1, 1 + wide, 2, kTol));
    EXPECT_FALSE(TouchingBlocks::apart(0, 1, 1 + small, 2, kTol)) << "a narrow gap blocks";
    EXPECT_FALSE(TouchingBlocks::apart(0, 1, 1 - small, 2, kTol));
    EXPECT_TRUE(TouchingIsApart::apart(0, 1, 1 + wide, 2, kTol));
    EXPECT_TRUE(TouchingIsApart::apart(0, 1, 1 + small, 2, kTol));
    EXPECT_TRUE(TouchingIsApart::apart(0, 1, 1 - small, 2, kTol)) << "a thin overlap is apart";
    EXPECT_FALSE(TouchingIsApart::apart(0, 1, 1 - wide, 2, kTol));
}

TEST(ConvexHull, AFaceTouchingTheHullBlocksForBeamsAndIsApartForDecahedra) {
    const ConvexHull cube = box_hull({0, 0, 0}, {1, 1, 1});
    const Piece on_face = square_at_x(1);  // lies in the cube's face x = 1
    EXPECT_FALSE(separated<TouchingBlocks>(cube, on_face));
    EXPECT_TRUE(separated<TouchingIsApart>(cube, on_face));
}

TEST(ConvexHull, AFaceTouchingTheHullAlongAnEdgeBlocksForBeamsAndIsApartForDecahedra) {
    const ConvexHull cube = box_hull({0, 0, 0}, {1, 1, 1});
    // in the plane x + y = 2, through the cube's edge x = y = 1
    const double r = 1 / std::sqrt(2.0);
    const Piece on_edge{{{1.5, 0.5, -1}, {0.5, 1.5, -1}, {0.5, 1.5, 2}, {1.5, 0.5, 2}}, {r, r, 0}};
    EXPECT_FALSE(separated<TouchingBlocks>(cube, on_edge));
    EXPECT_TRUE(separated<TouchingIsApart>(cube, on_edge));
}

TEST(ConvexHull, BothRulesAgreeBeyondTheTolerance) {
    const ConvexHull cube = box_hull({0, 0, 0}, {1, 1, 1});
    EXPECT_TRUE(separated<TouchingBlocks>(cube, square_at_x(1 + 2 * kTol)));
    EXPECT_TRUE(separated<TouchingIsApart>(cube, square_at_x(1 + 2 * kTol)));
    EXPECT_FALSE(separated<TouchingBlocks>(cube, square_at_x(0.5)));
    EXPECT_FALSE(separated<TouchingIsApart>(cube, square_at_x(0.5)));
}

TEST(ConvexHull, BoxesTouchingBlockForBeamsAndAreApartForDecahedra) {
    const dvec3 lo(0), hi(1), other_lo(1, 0, 0), other_hi(2, 1, 1);  // sharing the face x = 1
    EXPECT_FALSE(TouchingBlocks::boxes_apart(other_lo, other_hi, lo, hi, kTol));
    EXPECT_TRUE(TouchingIsApart::boxes_apart(other_lo, other_hi, lo, hi, kTol));
}

// A floor of one large square and two small ones, under a grid of small cells, and a
// triangular prism over the floor's quadrant x, y > 0 below x + y = 1.
struct Floor {
    Floor() : trace(scene(), true, 0), grid(trace, 500) {}
    static Scene scene() {
        Scene s = testing::world_scene(8, 8);
        testing::add_square(s, 0, 0, 0, 2, {1, 1, 1});         // piece 0: the whole floor
        testing::add_square(s, 0.2, 0.2, 0, 0.01, {1, 1, 1});  // piece 1: inside the prism
        testing::add_square(s, 0.9, 0.9, 0, 0.01, {1, 1, 1});  // piece 2: in its box, not in it
        return s;
    }
    static ConvexHull prism() {
        ConvexHull h;
        const dvec3 corners[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        for (int k = 0; k < 6; ++k)
            h.points[k] = corners[k % 3] + dvec3(0, 0, k < 3 ? -0.1 : 0.1);
        h.point_count = 6;
        h.fit_box();
        const double r = 1 / std::sqrt(2.0);
        for (const dvec3& n : {dvec3(1, 0, 0), dvec3(0, 1, 0), dvec3(r, r, 0), dvec3(0, 0, 1)}) {
            h.planes[h.plane_count] = n;
            project(h.points, 6, n, h.plane_lo[h.plane_count], h.plane_hi[h.plane_count]);
            ++h.plane_count;
        }
        return h;
    }
    TraceScene trace;
    UniformGrid grid;
};

TEST(ConvexHull, TheCulledScanHandsEachPieceOverOnceAndSkipsCulledCells) {
    Floor floor;
    const ConvexHull prism = Floor::prism();
    Mailbox mailbox(floor.trace.faces().size());
    for (int pass = 0; pass < 2; ++pass) {  // a second query sees them all again
        std::map<uint32_t, int> seen;
        const uint64_t cells =
            scan_hull_cells<TouchingBlocks>(floor.grid, prism, kTol, mailbox, [&](uint32_t piece) {
                ++seen[piece];
                return false;
            });
        EXPECT_GT(cells, 1u);
        EXPECT_EQ(seen[0], 1) << "listed in every cell, handed over once";
        EXPECT_EQ(seen[1], 1);
        EXPECT_EQ(seen.count(2), 0u) << "its cells lie beyond the plane x + y = 1";
    }
}

TEST(ConvexHull, TheCulledScanStopsWhenTheVisitorSaysSo) {
    Floor floor;
    Mailbox mailbox(floor.trace.faces().size());
    int visits = 0;
    const uint64_t cells =
        scan_hull_cells<TouchingIsApart>(floor.grid, Floor::prism(), kTol, mailbox, [&](uint32_t) {
            ++visits;
            return true;
        });
    EXPECT_EQ(visits, 1);
    EXPECT_EQ(cells, 1u);
}

TEST(ConvexHull, TheCulledScanOfAHullBesideTheGridVisitsNothing) {
    Floor floor;
    Mailbox mailbox(floor.trace.faces().size());
    const ConvexHull far = box_hull({10, 10, 10}, {11, 11, 11});
    int visits = 0;
    EXPECT_EQ(scan_hull_cells<TouchingBlocks>(floor.grid, far, kTol, mailbox,
                                              [&](uint32_t) { return ++visits > 0; }),
              0u);
    EXPECT_EQ(visits, 0);
}

// The BVH walk: the same floor and prism, through the ray tracer's BVH.
TEST(ConvexHull, TheBvhWalkHandsEachPieceOverOnceAndSkipsCulledBoxes) {
    Floor floor;
    const RayBvh bvh(floor.trace);
    std::map<uint32_t, int> seen;
    const uint64_t boxes =
        scan_hull_bvh<TouchingBlocks>(bvh, Floor::prism(), kTol, [&](uint32_t piece) {
            ++seen[piece];
            return false;
        });
    EXPECT_GT(boxes, 1u);
    EXPECT_EQ(seen[0], 1);
    EXPECT_EQ(seen[1], 1);
    EXPECT_EQ(seen.count(2), 0u) << "its box lies beyond the plane x + y = 1";
}

TEST(ConvexHull, TheBvhWalkStopsWhenTheVisitorSaysSo) {
    Floor floor;
    const RayBvh bvh(floor.trace);
    int visits = 0;
    scan_hull_bvh<TouchingIsApart>(bvh, Floor::prism(), kTol, [&](uint32_t) {
        ++visits;
        return true;
    });
    EXPECT_EQ(visits, 1);
}

TEST(ConvexHull, TheBvhWalkOfAHullBesideTheSceneTestsTheRootAlone) {
    Floor floor;
    const RayBvh bvh(floor.trace);
    int visits = 0;
    EXPECT_EQ(scan_hull_bvh<TouchingBlocks>(bvh, box_hull({10, 10, 10}, {11, 11, 11}), kTol,
                                            [&](uint32_t) { return ++visits > 0; }),
              1u);
    EXPECT_EQ(visits, 0);
}

// Nothing that touches is ever culled: over random triangles and random boxes, every piece
// the separating-axis test finds touching (asked of each piece in turn) is handed over, by
// the BVH walk and by the grid scan alike.
TEST(ConvexHull, BothScansHandOverEveryPieceThatTouches) {
    const Scene s = testing::random_scene(128, 96, 300, 150, 3);
    const TraceScene trace(s, true, 0);
    const UniformGrid grid(trace);
    const RayBvh bvh(trace);
    Mailbox mailbox(trace.faces().size());
    const double tol = trace.tolerance();
    std::mt19937_64 random(11);
    const dvec3 lo = grid.lo(), size = grid.hi() - grid.lo();
    std::uniform_real_distribution<double> unit(0, 1);
    int touching = 0;
    for (int q = 0; q < 300; ++q) {
        const dvec3 a = lo + size * dvec3(unit(random), unit(random), unit(random));
        const dvec3 extent = size * 0.2 * dvec3(unit(random), unit(random), unit(random));
        const ConvexHull h = box_hull(a, a + extent);
        std::vector<char> by_bvh(trace.faces().size()), by_grid(trace.faces().size());
        scan_hull_bvh<TouchingBlocks>(bvh, h, tol, [&](uint32_t p) {
            by_bvh[p] = 1;
            return false;
        });
        scan_hull_cells<TouchingBlocks>(grid, h, tol, mailbox, [&](uint32_t p) {
            by_grid[p] = 1;
            return false;
        });
        for (uint32_t p = 0; p < trace.faces().size(); ++p) {
            const TraceFace& f = trace.faces()[p];
            const dvec3* v = trace.vertices_of(f);
            const int n = static_cast<int>(f.vertex_count);
            if (planes_separate<TouchingBlocks>(h, v, n, f.normal, tol) ||
                edges_separate<TouchingBlocks>(h, v, n, tol))
                continue;
            ++touching;
            EXPECT_TRUE(by_bvh[p]) << "query " << q << ", piece " << p;
            EXPECT_TRUE(by_grid[p]) << "query " << q << ", piece " << p;
        }
    }
    EXPECT_GT(touching, 300);
}

}  // namespace
}  // namespace fb89::host
