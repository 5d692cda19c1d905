// The ray tracer: watertight hits through shared edges and vertices, ties to the lower
// piece, mirrors and their limit, shading as the raster methods shade, exact counts.
#include "host/trace/ray_tracer.h"

#include <gtest/gtest.h>

#include "host/scene/projection.h"
#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using testing::add_face;
using testing::add_square;
using testing::render_trace;
using testing::trace_options;
using testing::world_scene;

TEST(RayTracer, NoRaySlipsThroughSharedEdgesOrVertices) {
    const Scene scene = testing::lattice_through_pixel_centres(61, 6);
    TraceScene trace(scene, true, 0);
    RayTracer tracer(trace);
    TraceCounts counts;
    RayTrace path;
    // every pixel centre within the mesh's outline, borders included
    for (int y = 0; y < 61; ++y)
        for (int x = 0; x < 61; ++x) {
            tracer.trace_pixel(x, y, path, counts);
            ASSERT_EQ(path.count, 1) << "pixel " << x << "," << y;
        }
    EXPECT_EQ(counts.rays, 61u * 61u);
}

TEST(RayTracer, AnExactTieGoesToTheLowerPieceAndIsCounted) {
    Scene s = world_scene(32, 32);
    add_square(s, 0, 0, 0, 1, {1, 0, 0});
    add_square(s, 0, 0, 0, 1, {0, 1, 0});  // the same square again: every hit ties
    TraceScene trace(s, true, 0);
    RayTracer tracer(trace);
    TraceCounts counts;
    RayTrace path;
    tracer.trace_pixel(16, 16, path, counts);
    ASSERT_EQ(path.count, 1);
    EXPECT_EQ(path.hits[0].piece, 0u);
    EXPECT_EQ(counts.ties, 1u);
}

TEST(RayTracer, ClosestHitEqualsEveryPieceTriedInTurn) {
    // seeded random triangles in a box, rays in random directions: the BVH walk must find
    // what testing every piece finds
    Scene s = world_scene(8, 8);
    uint64_t state = 1989;
    auto next = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    for (int i = 0; i < 400; ++i) {
        const glm::dvec3 c(next() * 4 - 2, next() * 4 - 2, next() * 4 - 2);
        auto jitter = [&] { return glm::dvec3(next() - 0.5, next() - 0.5, next() - 0.5) * 0.8; };
        add_face(s, {c + jitter(), c + jitter(), c + jitter()}, {1, 1, 1});
    }
    TraceScene trace(s, true, 0);
    RayTracer tracer(trace);
    TraceCounts counts;
    for (int r = 0; r < 2000; ++r) {
        const Ray ray{{next() * 6 - 3, next() * 6 - 3, next() * 6 - 3},
                      {next() - 0.5, next() - 0.5, next() - 0.5}};
        const Hit hit = tracer.closest_hit(ray, 0, kNoFace, counts);
        Hit brute{INFINITY, kNoFace};
        const RaySpace space(ray);
        for (uint32_t p = 0; p < trace.faces().size(); ++p) {
            double t;
            if (trace.intersect(ray, space, p, 0, t) && t < brute.t) brute = {t, p};
        }
        ASSERT_EQ(hit.piece, brute.piece) << "ray " << r;
    }
    EXPECT_LT(counts.face_tests, 2000u * 400u / 4) << "the BVH should test few pieces";
}

TEST(RayTracer, FacingMirrorsStopAtTheReflectionLimit) {
    Scene s = world_scene(16, 16);
    s.camera.eye = {0, 0, 0.5};
    s.camera.look_at = {0, 0, -1};
    add_square(s, 0, 0, -1, 10, {1, 1, 1}, 1.0);  // in front of the eye
    add_square(s, 0, 0, 1, 10, {1, 1, 1}, 1.0);   // behind it
    for (int limit : {0, 1, 5}) {
        TraceScene trace(s, true, limit);
        RayTracer tracer(trace);
        TraceCounts counts;
        RayTrace path;
        tracer.trace_pixel(8, 8, path, counts);
        EXPECT_EQ(path.count, limit + 1);
        EXPECT_FALSE(path.escaped);
        EXPECT_EQ(counts.rays, static_cast<uint64_t>(limit + 1));
        // the id of the face finally seen: the two mirrors alternate
        EXPECT_EQ(path.hits[path.count - 1].piece, static_cast<uint32_t>(limit % 2));
    }
}

TEST(RayTracer, AMirrorMixesItsColourWithWhatItReflects) {
    Scene s = world_scene(1, 1);
    s.light.ambient = 1;                         // unlit colours: easy sums
    add_square(s, 0, 0, 0, 3, {1, 0, 0}, 0.25);  // the mirror, facing the eye
    TraceScene trace(s, false, 4);
    RayTracer tracer(trace);
    TraceCounts counts;
    RayTrace path;
    tracer.trace_pixel(0, 0, path, counts);
    ASSERT_EQ(path.count, 1);
    EXPECT_TRUE(path.escaped);  // its reflection goes back past the eye, into nothing
    // 0.75 red + 0.25 background (0.1, 0.2, 0.3)
    EXPECT_EQ(path.color.r, std::lround((0.75 + 0.025) * 255));
    EXPECT_EQ(path.color.g, std::lround(0.05 * 255));
    EXPECT_EQ(path.color.b, std::lround(0.075 * 255));
}

TEST(RayTracer, ShadesFacesAsTheRasterMethodsDo) {
    // a face seen directly: the same colour under the Z-buffer and the ray tracer
    Scene s = world_scene(64, 48);
    add_face(s, {{-1, -1, 0}, {1, -1, -0.5}, {1, 1, 0}, {-1, 1, 0.5}}, {0.9, 0.6, 0.3});
    const auto rays = render_trace(s, trace_options("raytrace"));
    const auto zbuffer = render_trace(s, trace_options("zbuffer"));
    const size_t centre = (24 * 64 + 32) * 3;
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(rays.pixels[centre + c], zbuffer.pixels[centre + c]);
}

TEST(RayTracer, CountsOneRayPerPixelPlusOnePerReflection) {
    Scene s = world_scene(40, 30);
    add_square(s, -0.6, 0, 0, 0.5, {1, 1, 1}, 0.5);  // a mirror on the left
    add_square(s, 0.6, 0, 0, 0.5, {1, 0, 0});        // a plain face on the right
    const auto frame = render_trace(s, trace_options("raytrace"));
    uint64_t mirror_pixels = 0;
    for (uint32_t id : frame.ids)
        mirror_pixels += id == 1;  // the mirror reflects into nothing: its id stays on top
    ASSERT_GT(mirror_pixels, 0u);
    EXPECT_EQ(frame.stats.counters.get("rays"), 40u * 30u + mirror_pixels);
    EXPECT_EQ(frame.stats.counters.get("pixels_by_rays"), 40u * 30u);
}

}  // namespace
}  // namespace fb89::host
