// The ray tracer's BVH: every piece in one leaf, boxes that hold their pieces, a walk that
// loses no hit to float boxes (rays through vertices and along box faces), and the
// pruning that makes it cheaper than testing every piece.
#include "host/trace/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using testing::add_face;
using testing::world_scene;

// Seeded triangles in a box of side 4 around `centre`.
Scene random_triangles(int count, glm::dvec3 centre, uint64_t seed) {
    Scene s = world_scene(8, 8);
    uint64_t state = seed;
    auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 c = centre + glm::dvec3(next() * 4 - 2, next() * 4 - 2, next() * 4 - 2);
        auto jitter = [&] { return glm::dvec3(next() - 0.5, next() - 0.5, next() - 0.5) * 0.5; };
        add_face(s, {c + jitter(), c + jitter(), c + jitter()}, {1, 1, 1});
    }
    return s;
}

TEST(RayBvh, EveryPieceSitsInOneLeafWhoseBoxHoldsIt) {
    const Scene s = random_triangles(500, {0, 0, 0}, 7);
    const TraceScene trace(s, true, 0);
    const RayBvh bvh(trace);
    std::vector<int> seen(trace.faces().size(), 0);
    for (const RayBvh::Node& n : bvh.nodes()) {
        if (n.count == 0) continue;
        for (uint32_t i = n.index; i < n.index + n.count; ++i) {
            const uint32_t piece = bvh.pieces()[i];
            ++seen[piece];
            const TraceFace& f = trace.faces()[piece];
            for (uint32_t k = 0; k < f.vertex_count; ++k)
                for (int a = 0; a < 3; ++a) {
                    EXPECT_LT(RayBvh::lo(n, a), trace.vertices_of(f)[k][a]);
                    EXPECT_GT(RayBvh::hi(n, a), trace.vertices_of(f)[k][a]);
                }
        }
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; }));
    EXPECT_LE(bvh.depth(), RayBvh::kMaxDepth);
    EXPECT_GT(bvh.depth(), 5);  // 500 pieces do not fit in a shallow tree of small leaves
}

// Far from the origin, float boxes round coarsely: rays aimed exactly at vertices and along
// the boxes' faces must still find what testing every piece finds.
TEST(RayBvh, FloatBoxesLoseNoHitFarFromTheOrigin) {
    const glm::dvec3 far_away(1e4, -3e3, 7e3);
    const Scene s = random_triangles(300, far_away, 11);
    const TraceScene trace(s, true, 0);
    const RayBvh bvh(trace);
    uint64_t mismatches = 0, hits = 0;
    for (uint32_t p = 0; p < trace.faces().size(); ++p) {
        const glm::dvec3* v = trace.vertices_of(trace.faces()[p]);
        for (uint32_t k = 0; k < 3; ++k) {
            // from a point off to the side: at a vertex, an edge's midpoint, the centroid
            const glm::dvec3 target = k == 0   ? v[0]
                                      : k == 1 ? (v[0] + v[1]) / 2.0
                                               : (v[0] + v[1] + v[2]) / 3.0;
            const glm::dvec3 eye = far_away + glm::dvec3(10, 9, -8);
            const Ray ray{eye, target - eye};
            const RaySpace space(ray);
            Hit brute{INFINITY, kNoFace};
            for (uint32_t q = 0; q < trace.faces().size(); ++q) {
                double t;
                if (trace.intersect(ray, space, q, 0, t) &&
                    (t < brute.t || (t == brute.t && q < brute.piece)))
                    brute = {t, q};
            }
            Hit best{INFINITY, kNoFace};
            bvh.walk(
                ray, 0, INFINITY,
                [&](uint32_t q) {
                    double t;
                    if (trace.intersect(ray, space, q, 0, t) &&
                        (t < best.t || (t == best.t && q < best.piece)))
                        best = {t, q};
                },
                [&] { return best.t; });
            hits += brute.piece != kNoFace;
            mismatches += best.piece != brute.piece;
        }
    }
    EXPECT_EQ(mismatches, 0u);
    EXPECT_GT(hits, 600u);
}

TEST(RayBvh, ARayThatMissesTheSceneBoxTestsOneNode) {
    const Scene s = random_triangles(50, {0, 0, 0}, 3);
    const TraceScene trace(s, true, 0);
    const RayBvh bvh(trace);
    uint64_t tested = 0;
    const uint64_t nodes = bvh.walk(
        Ray{{100, 100, 100}, {1, 0, 0}}, 0, INFINITY, [&](uint32_t) { ++tested; },
        [] { return INFINITY; });
    EXPECT_EQ(nodes, 1u);
    EXPECT_EQ(tested, 0u);
}

TEST(RayBvh, AnEmptySceneHasNoNodes) {
    const Scene s = world_scene(4, 4);
    const TraceScene trace(s, true, 0);
    const RayBvh bvh(trace);
    EXPECT_TRUE(bvh.nodes().empty());
    EXPECT_EQ(bvh.walk(
                  Ray{{0, 0, 0}, {0, 0, 1}}, 0, INFINITY, [](uint32_t) {}, [] { return INFINITY; }),
              0u);
}

}  // namespace
}  // namespace fb89::host
