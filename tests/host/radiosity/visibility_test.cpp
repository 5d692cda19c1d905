// Which patch pairs face each other, and flux tracing (the paper's §5 baseline) where it is
// known to be hard: adjacent patches (r → 0), shared edges, grazing angles, back faces.
#include "host/radiosity/visibility.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace fb89::host {
namespace {

using glm::dvec3;

void add_visibility_quad(Scene& s, dvec3 a, dvec3 b, dvec3 c, dvec3 d) {
    Face f;
    f.vertices = {a, b, c, d};
    f.id = s.face_count++;
    s.faces.push_back(f);
}

// Six quads around [lo, hi], normals inward (a room) or outward (a box).
void add_visibility_box(Scene& s, dvec3 lo, dvec3 hi, bool inward) {
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // e_u x e_v = e_axis
        for (int side = 0; side < 2; ++side) {
            dvec3 p = lo, du(0), dv(0);
            p[axis] = side ? hi[axis] : lo[axis];
            du[u] = hi[u] - lo[u];
            dv[v] = hi[v] - lo[v];
            if ((side == 0) == inward)  // normal +e_axis
                add_visibility_quad(s, p, p + du, p + du + dv, p + dv);
            else
                add_visibility_quad(s, p, p + dv, p + du + dv, p + du);
        }
    }
}

struct VisibilityWorld {
    VisibilityWorld(const Scene& s, double patch_size)
        : mesh(mesh_scene(s, {patch_size, 64})), trace(s, true, 0), grid(trace) {}
    RadiosityWorld world() const { return {trace, grid}; }
    uint32_t patch_at(const dvec3& point) const {  // the patch whose centre is nearest
        uint32_t best = 0;
        for (uint32_t p = 1; p < mesh.patches.size(); ++p)
            if (glm::length(mesh.patches[p].centre - point) <
                glm::length(mesh.patches[best].centre - point))
                best = p;
        return best;
    }
    Mesh mesh;
    TraceScene trace;
    UniformGrid grid;
};

// δ by testing every piece, no grid: what flux tracing must find.
Delta brute_force(const VisibilityWorld& w, uint32_t p, uint32_t q) {
    if (p > q) std::swap(p, q);
    const Patch& a = w.mesh.patches[p];
    const Patch& b = w.mesh.patches[q];
    const Ray ray{a.centre, b.centre - a.centre};
    const double eps = 4 * w.trace.tolerance() / glm::length(ray.dir);
    const RaySpace space(ray);
    for (uint32_t piece = 0; piece < w.trace.faces().size(); ++piece) {
        if (piece == w.mesh.elements[a.element].piece || piece == w.mesh.elements[b.element].piece)
            continue;
        double t;
        if (w.trace.intersect(ray, space, piece, eps, t) && t < 1 - eps) return Delta::Hidden;
    }
    return Delta::Visible;
}

Scene room_with_box(dvec3 lo, dvec3 hi) {
    Scene s;
    add_visibility_box(s, {0, 0, 0}, {4, 4, 4}, true);
    add_visibility_box(s, lo, hi, false);
    return s;
}

TEST(Visibility, PairsFaceWhenEachCentreIsInFrontOfTheOther) {
    Scene s;
    add_visibility_box(s, {0, 0, 0}, {4, 4, 4}, true);
    VisibilityWorld w(s, 1);
    const uint32_t floor = w.patch_at({1.5, 0, 1.5}), ceiling = w.patch_at({1.5, 4, 2.5});
    const uint32_t floor_next = w.patch_at({2.5, 0, 1.5}), wall = w.patch_at({0, 0.5, 0.5});
    EXPECT_TRUE(facing(w.mesh, floor, ceiling));
    EXPECT_TRUE(facing(w.mesh, ceiling, floor));
    EXPECT_TRUE(facing(w.mesh, floor, wall)) << "across the corner, r small";
    EXPECT_FALSE(facing(w.mesh, floor, floor_next)) << "one element";
}

TEST(Visibility, CoplanarAndBackToBackPatchesNeverFace) {
    Scene s;
    add_visibility_quad(s, {0, 0, 0}, {0, 0, 2}, {2, 0, 2},
                        {2, 0, 0});  // two floor tiles, normal +y
    add_visibility_quad(s, {2, 0, 0}, {2, 0, 2}, {4, 0, 2}, {4, 0, 0});
    add_visibility_quad(s, {0, 1, 0}, {2, 1, 0}, {2, 1, 2}, {0, 1, 2});  // above, normal −y...
    add_visibility_quad(s, {0, 2, 0}, {0, 2, 2}, {2, 2, 2},
                        {2, 2, 0});  // ...and its back, normal +y
    VisibilityWorld w(s, 1);
    for (uint32_t p = 0; p < 4; ++p)
        for (uint32_t q = 4; q < 8; ++q)
            EXPECT_FALSE(facing(w.mesh, p, q)) << "coplanar tiles " << p << " " << q;
    EXPECT_TRUE(facing(w.mesh, 0, w.patch_at({0.5, 1, 0.5})));
    EXPECT_FALSE(facing(w.mesh, w.patch_at({0.5, 1, 0.5}), w.patch_at({0.5, 2, 0.5})))
        << "back to back";
}

TEST(FluxTracing, CastsOneRayPerFacingPair) {
    VisibilityWorld w(room_with_box({1.5, 1.5, 1.5}, {2.5, 2.5, 2.5}), 0.5);
    VisibilityCounts counts;
    const Visibility delta = flux_tracing(w.mesh, w.world(), counts);
    uint64_t pairs = 0;
    for (uint32_t p = 0; p < w.mesh.patches.size(); ++p)
        for (uint32_t q = p + 1; q < w.mesh.patches.size(); ++q) {
            const bool f = facing(w.mesh, p, q);
            pairs += f;
            EXPECT_EQ(delta.get(p, q) != Delta::NotFacing, f);
        }
    EXPECT_EQ(counts.facing_pairs, pairs);
    EXPECT_EQ(counts.rays, pairs);
    EXPECT_EQ(counts.queries, 0u);
}

TEST(FluxTracing, ABlockerBetweenTheCentresHidesThePairAndNothingElseDoes) {
    VisibilityWorld w(room_with_box({1.2, 1.5, 1.2}, {2.8, 2.5, 2.8}), 1);
    VisibilityCounts counts;
    const Visibility delta = flux_tracing(w.mesh, w.world(), counts);
    const uint32_t floor = w.patch_at({1.5, 0, 1.5}), ceiling = w.patch_at({1.5, 4, 1.5});
    const uint32_t corner = w.patch_at({0.5, 0, 0.5}), far = w.patch_at({0.5, 4, 0.5});
    EXPECT_EQ(delta.get(floor, ceiling), Delta::Hidden);
    EXPECT_EQ(delta.get(corner, far), Delta::Visible);
    // the box's bottom faces the floor below it
    EXPECT_EQ(delta.get(floor, w.patch_at({1.6, 1.5, 1.6})), Delta::Visible);
}

TEST(FluxTracing, BackFacesBlock) {
    Scene s;
    add_visibility_box(s, {0, 0, 0}, {4, 4, 4}, true);
    add_visibility_quad(s, {1, 2, 1}, {3, 2, 1}, {3, 2, 3},
                        {1, 2, 3});  // normal −y: seen from below...
    VisibilityWorld w(s, 1);
    VisibilityCounts counts;
    const Visibility delta = flux_tracing(w.mesh, w.world(), counts);
    const uint32_t floor = w.patch_at({1.5, 0, 1.5}), ceiling = w.patch_at({1.5, 4, 1.5});
    EXPECT_EQ(delta.get(floor, ceiling), Delta::Hidden);  // ...its back, from above
    EXPECT_EQ(delta.get(ceiling, floor), Delta::Hidden);
}

TEST(FluxTracing, FindsWhatTestingEveryPieceFinds) {
    std::vector<Scene> scenes;
    scenes.push_back(room_with_box({1.5, 1.5, 1.5}, {2.5, 2.5, 2.5}));
    scenes.push_back(room_with_box({1, 0, 1}, {2, 1, 2}));  // standing on the floor
    Scene wall;
    add_visibility_box(wall, {0, 0, 0}, {4, 4, 4}, true);
    add_visibility_quad(wall, {2, 0, 0}, {2, 2, 0}, {2, 2, 4},
                        {2, 0, 4});  // half height, edge to edge
    scenes.push_back(wall);
    for (const Scene& s : scenes)
        for (double size : {1.0, 0.45}) {
            VisibilityWorld w(s, size);
            VisibilityCounts counts;
            const Visibility delta = flux_tracing(w.mesh, w.world(), counts);
            uint64_t hidden = 0;
            for (uint32_t p = 0; p < w.mesh.patches.size(); ++p)
                for (uint32_t q = p + 1; q < w.mesh.patches.size(); ++q)
                    if (facing(w.mesh, p, q)) {
                        ASSERT_EQ(delta.get(p, q), brute_force(w, p, q)) << p << " " << q;
                        hidden += delta.get(p, q) == Delta::Hidden;
                    }
            EXPECT_GT(hidden, 0u);
        }
}

TEST(FluxTracing, AdjacentPatchesAcrossACornerSeeEachOther) {
    // r → 0: floor and wall patches at their corner, and a box standing on the floor whose
    // faces meet it along their lower edges
    Scene s;
    add_visibility_quad(s, {0, 0, 0}, {0, 0, 4}, {4, 0, 4}, {4, 0, 0});  // floor, normal +y
    add_visibility_quad(s, {0, 0, 0}, {0, 4, 0}, {0, 4, 4}, {0, 0, 4});  // wall, normal +x
    add_visibility_box(s, {1, 0, 1}, {2, 1, 2}, false);
    VisibilityWorld w(s, 0.25);
    VisibilityCounts counts;
    const Visibility delta = flux_tracing(w.mesh, w.world(), counts);
    const uint32_t beside_box = w.patch_at({2.125, 0, 1.625});
    EXPECT_EQ(delta.get(w.patch_at({0.125, 0, 1.625}), w.patch_at({0, 0.125, 1.625})),
              Delta::Visible);
    EXPECT_EQ(delta.get(beside_box, w.patch_at({2, 0.125, 1.625})), Delta::Visible)
        << "the floor beside the box and the box's side";
    EXPECT_EQ(delta.get(beside_box, w.patch_at({0, 0.125, 1.625})), Delta::Hidden)
        << "the box between, the ray 0.007 above the floor where it meets it";
}

TEST(FluxTracing, GrazingRaysAgreeWithTestingEveryPiece) {
    // a panel whose patches see the floor at cos ≈ 1e-3 over a low wall: some rays pass
    // just over its top edge, some hit it just below
    Scene s;
    add_visibility_quad(s, {0, 0, 0}, {0, 0, 4}, {4, 0, 4}, {4, 0, 0});  // floor, normal +y
    add_visibility_quad(s, {0, 0.01, 8}, {4, 0.01, 8}, {4, 0.014, 12}, {0, 0.014, 12});  // about −y
    add_visibility_quad(s, {0, 0, 6}, {4, 0, 6}, {4, 0.006, 6}, {0, 0.006, 6});  // low wall, +z
    VisibilityWorld w(s, 1);
    VisibilityCounts counts;
    const Visibility delta = flux_tracing(w.mesh, w.world(), counts);
    uint64_t hidden = 0, visible = 0;
    for (uint32_t p = 0; p < w.mesh.patches.size(); ++p)
        for (uint32_t q = p + 1; q < w.mesh.patches.size(); ++q)
            if (facing(w.mesh, p, q)) {
                EXPECT_EQ(delta.get(p, q), brute_force(w, p, q));
                (delta.get(p, q) == Delta::Hidden ? hidden : visible)++;
            }
    EXPECT_GT(hidden, 0u);
    EXPECT_GT(visible, 0u);
}

TEST(Visibility, CountsArePublishedUnderTheirNames) {
    VisibilityCounts c{10, 4, 3, 2, 7, 6};
    Counters counters;
    c.publish(counters);
    EXPECT_EQ(counters.get("radiosity_facing_pairs"), 10u);
    EXPECT_EQ(counters.get("flux_rays"), 4u);
    EXPECT_EQ(counters.get("volume_queries"), 3u);
    EXPECT_EQ(counters.get("empty_volume_queries"), 2u);
    EXPECT_EQ(counters.get("volume_query_face_tests"), 7u);
    EXPECT_EQ(counters.get("pairs_by_volume_queries"), 6u);
}

}  // namespace
}  // namespace fb89::host
