// Beam classification (the paper's Fig. 4.1) where it is known to be hard: lateral rays
// through shared edges, faces sharing an edge with the hit face, coplanar overlaps,
// reflected beams, and faces that only touch a segment.
#include "host/trace/beam_tracer.h"

#include <gtest/gtest.h>

#include <set>

#include "tests/host/raster/raster_test_util.h"
#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using testing::add_face;
using testing::add_square;
using testing::world_scene;

// A scene, its grid and tracers, and the classification of one pixel window. Each question
// is asked of both structures, the grid's beams and the BVH's, which must answer the same;
// the grid's answer is returned.
struct Beams {
    explicit Beams(const Scene& scene)
        : trace(scene, true, 8),
          grid(trace),
          rays(trace),
          beams(trace, grid),
          bvh_beams(trace, rays.bvh()) {}

    bool segment_is_empty(const BeamSegment& s, uint32_t skip_a, uint32_t skip_b) {
        const bool empty = beams.segment_is_empty(s, skip_a, skip_b, counts);
        EXPECT_EQ(bvh_beams.segment_is_empty(s, skip_a, skip_b, bvh_counts), empty) << "the BVH";
        return empty;
    }
    uint32_t faces_in_beam(const RayTrace* const corners[4]) {
        const uint32_t faces = beams.faces_in_beam(corners, counts);
        EXPECT_EQ(bvh_beams.faces_in_beam(corners, bvh_counts), faces) << "the BVH";
        return faces;
    }

    // The traces of the window's corner pixels, in the order classify takes them.
    void trace_corners(const PixelRect& w, RayTrace traces[4]) {
        const int xs[4] = {w.x0, w.x1 - 1, w.x1 - 1, w.x0};
        const int ys[4] = {w.y0, w.y0, w.y1 - 1, w.y1 - 1};
        for (int i = 0; i < 4; ++i)
            rays.trace_pixel(xs[i], ys[i], traces[i], ray_counts);
    }
    BeamClass classify(const PixelRect& w) {
        RayTrace traces[4];
        trace_corners(w, traces);
        const RayTrace* corners[4];
        for (int i = 0; i < 4; ++i)
            corners[i] = &traces[i];
        const BeamClass c = beams.classify(corners, counts);
        EXPECT_EQ(bvh_beams.classify(corners, bvh_counts), c) << "the BVH";
        return c;
    }

    TraceScene trace;
    UniformGrid grid;
    RayTracer rays;
    BeamTracer beams;      // through the grid
    BeamTracer bvh_beams;  // through the rays' BVH
    TraceCounts ray_counts;
    BeamCounts counts, bvh_counts;
};

TEST(BeamTracer, AWindowInsideOneFaceIsAHit) {
    Scene s = world_scene(64, 64);
    add_square(s, 0, 0, 0, 1, {1, 0, 0});
    Beams b(s);
    EXPECT_EQ(b.classify({24, 24, 40, 40}), BeamClass::Hit);
    EXPECT_EQ(b.counts.queries, 1u);
}

TEST(BeamTracer, AWindowAcrossTwoFacesIsAPartialHit) {
    Scene s = world_scene(64, 64);
    add_square(s, -1, 0, 0, 1, {1, 0, 0});
    add_square(s, 1, 0, 0, 1, {0, 1, 0});
    Beams b(s);
    EXPECT_EQ(b.classify({24, 24, 40, 40}), BeamClass::Partial);
    EXPECT_EQ(b.counts.queries, 0u) << "differing lateral rays need no query";
}

TEST(BeamTracer, ASmallFaceInsideTheBeamBlocksIt) {
    Scene s = world_scene(64, 64);
    add_square(s, 0, 0, 0, 2, {1, 0, 0});
    add_square(s, 0, 0, 1, 0.05, {0, 1, 0});  // between the corners' rays
    Beams b(s);
    EXPECT_EQ(b.classify({8, 8, 56, 56}), BeamClass::Blocked);
    EXPECT_EQ(b.classify({8, 8, 20, 20}), BeamClass::Hit) << "it lies outside this one";
}

TEST(BeamTracer, AFaceBehindTheHitFaceDoesNotBlock) {
    Scene s = world_scene(64, 64);
    add_square(s, 0, 0, 0, 2, {1, 0, 0});
    add_square(s, 0, 0, -1, 0.5, {0, 1, 0});
    Beams b(s);
    EXPECT_EQ(b.classify({8, 8, 56, 56}), BeamClass::Hit);
}

TEST(BeamTracer, LateralRaysOnASharedEdgeAreNeverAHit) {
    // two faces meeting along x = 0; the window's right column lies exactly on the edge
    Scene s = world_scene(65, 65);  // pixel column 32's rays lie in the plane x = 0
    add_face(s, {{-6, -6, 0}, {0, -6, 0}, {0, 6, 0}, {-6, 6, 0}}, {1, 0, 0});
    add_face(s, {{0, -6, 0}, {6, -6, 0}, {6, 6, 0}, {0, 6, 0}}, {0, 1, 0});
    Beams b(s);
    // a window whose corner rays hit the left face close to the edge: the neighbour
    // sharing the edge touches the segment only if the corners reach the edge
    EXPECT_EQ(b.classify({10, 10, 30, 30}), BeamClass::Hit);
    EXPECT_NE(b.classify({10, 10, 33, 30}), BeamClass::Hit);
}

TEST(BeamTracer, CoplanarOverlappingFacesBlock) {
    Scene s = world_scene(64, 64);
    add_square(s, 0, 0, 0, 2, {1, 0, 0});
    add_square(s, 0.5, 0, 0, 0.3, {0, 1, 0});  // the same plane, inside the first
    Beams b(s);
    EXPECT_EQ(b.classify({8, 8, 56, 56}), BeamClass::Blocked);
}

TEST(BeamTracer, AReflectedBeamIsAHitOnlyWhenItsSegmentIsEmpty) {
    Scene s = world_scene(64, 64);
    s.camera.eye = {0, 0, 3};
    s.camera.look_at = {0, 0, 0};
    // a mirror facing the eye, tilted so that its reflection looks at a wall to the side
    add_face(s, {{-1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, 1}}, {1, 1, 1}, 1.0);
    add_face(s, {{6, -6, -2}, {6, 6, -2}, {6, 6, 6}, {6, -6, 6}}, {0, 0, 1});
    {
        Beams b(s);
        EXPECT_EQ(b.classify({16, 16, 48, 48}), BeamClass::Hit);
        EXPECT_EQ(b.counts.queries, 2u) << "one query per segment";
    }
    // a small face between the mirror and the wall, out of the eye's sight, that no
    // lateral ray meets
    add_face(s, {{3, -0.1, -0.1}, {3, 0.1, -0.1}, {3, 0.1, 0.1}, {3, -0.1, 0.1}}, {1, 1, 0});
    {
        Beams b(s);
        EXPECT_EQ(b.classify({16, 16, 48, 48}), BeamClass::Blocked);
    }
}

TEST(BeamTracer, AFaceTouchingASegmentWithinTheToleranceCountsAsOccupied) {
    Scene s = world_scene(64, 64);
    add_square(s, 0, 0, 0, 2, {1, 0, 0});
    Beams b(s);
    BeamSegment seg;
    for (int i = 0; i < 4; ++i)
        seg.start[i] = {0, 0, 5};
    seg.end[0] = {-1, -1, 0};
    seg.end[1] = {1, -1, 0};
    seg.end[2] = {1, 1, 0};
    seg.end[3] = {-1, 1, 0};
    EXPECT_FALSE(b.segment_is_empty(seg, kNoFace, kNoFace)) << "the end face";
    EXPECT_TRUE(b.segment_is_empty(seg, kNoFace, 0)) << "skipped";
    // pulled back from the face by less than the tolerance: still touching
    for (auto& e : seg.end)
        e.z = b.trace.tolerance() * 0.5;
    EXPECT_FALSE(b.segment_is_empty(seg, kNoFace, kNoFace));
    for (auto& e : seg.end)
        e.z = b.trace.tolerance() * 10;
    EXPECT_TRUE(b.segment_is_empty(seg, kNoFace, kNoFace));
}

TEST(BeamTracer, CountsTheFacesInAWindowsBeam) {
    Scene s = world_scene(64, 64);
    add_square(s, 0, 0, 0, 2, {1, 0, 0});
    add_square(s, 0, 0, 1, 0.05, {0, 1, 0});
    add_square(s, 0, 0, -1, 0.05, {0, 1, 0});  // behind, inside the beam
    add_square(s, 5, 5, 1, 0.05, {0, 1, 0});   // outside every beam here
    Beams b(s);
    const int xs[4] = {8, 55, 55, 8}, ys[4] = {8, 8, 55, 55};
    RayTrace traces[4];
    const RayTrace* corners[4];
    for (int i = 0; i < 4; ++i) {
        b.rays.trace_pixel(xs[i], ys[i], traces[i], b.ray_counts);
        corners[i] = &traces[i];
    }
    EXPECT_EQ(b.faces_in_beam(corners), 3u);
}

// The beam-ray hybrid skips the F_w query when the distinct faces its corner rays hit first
// already exceed what the query would count (BeamRayHybrid::window): sound only if the
// query always counts those faces. Every window of 2 to 32 pixels a side on a grid of
// positions, over random triangles and over edges through pixel centres.
TEST(BeamTracer, TheFacesInAWindowsBeamIncludeTheFacesItsCornerRaysHit) {
    for (const Scene& s : {testing::random_scene(128, 96, 300, 150, 7),
                           testing::lattice_through_pixel_centres(97, 6)}) {
        Beams b(s);
        int windows = 0;
        for (int size = 2; size <= 32; size *= 2)
            for (int y = 0; y + size <= s.height; y += 7)
                for (int x = 0; x + size <= s.width; x += 5) {
                    RayTrace traces[4];
                    b.trace_corners({x, y, x + size, y + size}, traces);
                    const RayTrace* corners[4];
                    std::set<uint32_t> first;
                    for (int i = 0; i < 4; ++i) {
                        corners[i] = &traces[i];
                        if (traces[i].count > 0)
                            first.insert(b.trace.faces()[traces[i].hits[0].piece].id);
                    }
                    ASSERT_GE(b.faces_in_beam(corners), first.size())
                        << "window " << x << "," << y << " size " << size;
                    ++windows;
                }
        EXPECT_GT(windows, 500);
    }
}

// The BVH's queries answer as the grid's on segments cut from random triangles' beams at
// several depths, some empty and some not, and test fewer pieces on the way.
TEST(BeamTracer, TheBvhAndTheGridAnswerEverySegmentAlike) {
    const Scene s = testing::random_scene(128, 96, 300, 150, 7);
    Beams b(s);
    int empty = 0, occupied = 0;
    for (int size = 2; size <= 64; size *= 2)
        for (int y = 0; y + size <= s.height; y += 9)
            for (int x = 0; x + size <= s.width; x += 7) {
                RayTrace traces[4];
                b.trace_corners({x, y, x + size, y + size}, traces);
                for (double depth : {0.5, 0.999, 1.5}) {
                    BeamSegment seg;
                    for (int i = 0; i < 4; ++i) {
                        const Ray& r = traces[i].primary;
                        // the first hit, or past the grid's far side
                        const double far = glm::length(b.grid.hi() - b.grid.lo()) +
                                           glm::length(b.grid.lo() - r.origin);
                        const glm::dvec3 end = traces[i].count > 0
                                                   ? traces[i].points[0]
                                                   : r.origin + far * glm::normalize(r.dir);
                        seg.start[i] = r.origin;
                        seg.end[i] = r.origin + depth * (end - r.origin);
                    }
                    (b.segment_is_empty(seg, kNoFace, kNoFace) ? empty : occupied)++;
                }
            }
    EXPECT_GT(empty, 100);
    EXPECT_GT(occupied, 100);
    EXPECT_EQ(b.bvh_counts.queries, b.counts.queries);
    EXPECT_LT(b.bvh_counts.query_face_tests, b.counts.query_face_tests);
    EXPECT_GT(b.bvh_counts.query_nodes, 0u);
    EXPECT_EQ(b.bvh_counts.query_cells, 0u);
}

}  // namespace
}  // namespace fb89::host
