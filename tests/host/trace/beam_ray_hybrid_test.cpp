// The beam-ray hybrid shows what the ray tracer alone shows, pixel for pixel, at every
// threshold, on the configurations beams are known to get wrong.
#include "host/trace/beam_ray_hybrid.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using testing::add_face;
using testing::add_square;
using testing::render_trace;
using testing::trace_options;
using testing::world_scene;

// Cubes of quads sharing edges and vertices, a coplanar overlap, faces meeting at edges,
// and two mirrors that see each other.
Scene mirror_room(int width, int height) {
    Scene s = world_scene(width, height);
    s.camera.eye = {0.3, 0.4, 4.5};
    s.camera.look_at = {0, 0, 0};
    s.camera.fovy_degrees = 60;
    // the room's walls, meeting along shared edges
    const double r = 3;
    add_face(s, {{-r, -r, -r}, {r, -r, -r}, {r, -r, r}, {-r, -r, r}}, {0.8, 0.8, 0.8});
    add_face(s, {{-r, -r, -r}, {-r, r, -r}, {r, r, -r}, {r, -r, -r}}, {0.9, 0.9, 0.9}, 0.7);
    add_face(s, {{r, -r, -r}, {r, r, -r}, {r, r, r}, {r, -r, r}}, {0.2, 0.7, 0.2}, 0.9);
    add_face(s, {{-r, -r, -r}, {-r, -r, r}, {-r, r, r}, {-r, r, -r}}, {0.7, 0.2, 0.2});
    // a cube of six quads sharing every edge
    const double lo = -0.8, hi = 0.2;
    add_face(s, {{lo, lo, hi}, {hi, lo, hi}, {hi, hi, hi}, {lo, hi, hi}}, {0.9, 0.5, 0.1});
    add_face(s, {{lo, lo, lo}, {lo, hi, lo}, {hi, hi, lo}, {hi, lo, lo}}, {0.9, 0.5, 0.1});
    add_face(s, {{lo, lo, lo}, {hi, lo, lo}, {hi, lo, hi}, {lo, lo, hi}}, {0.5, 0.9, 0.1});
    add_face(s, {{lo, hi, lo}, {lo, hi, hi}, {hi, hi, hi}, {hi, hi, lo}}, {0.5, 0.9, 0.1});
    add_face(s, {{lo, lo, lo}, {lo, lo, hi}, {lo, hi, hi}, {lo, hi, lo}}, {0.1, 0.5, 0.9});
    add_face(s, {{hi, lo, lo}, {hi, hi, lo}, {hi, hi, hi}, {hi, lo, hi}}, {0.1, 0.5, 0.9});
    // a face coplanar with the cube's front, overlapping it
    add_face(s, {{0, 0, hi}, {0.6, 0, hi}, {0.6, 0.6, hi}, {0, 0.6, hi}}, {1, 1, 0});
    // a triangle sharing an edge with the floor
    add_face(s, {{1, -r, 0}, {2, -r, 0}, {1.5, -1.5, 0}}, {0.6, 0.1, 0.6});
    return s;
}

// ... and the same beams whether they query the BVH (the default) or the paper's grid: the
// queries' answers are the same, only the pieces tested on the way differ.
void expect_same_as_rays(const Scene& scene, const char* what) {
    const auto rays = render_trace(scene, trace_options("raytrace"));
    for (double threshold : {0.0, 0.5, 5.0, double{INFINITY}}) {
        const auto beams = render_trace(scene, trace_options("beam", threshold));
        EXPECT_EQ(beams.ids, rays.ids) << what << " at threshold " << threshold;
        EXPECT_EQ(beams.pixels, rays.pixels) << what << " at threshold " << threshold;
        const auto& c = beams.stats.counters;
        EXPECT_EQ(c.get("pixels_by_beams") + c.get("pixels_by_rays"),
                  static_cast<uint64_t>(scene.width) * scene.height);
        EXPECT_EQ(c.get("beams"),
                  c.get("beam_hits") + c.get("partial_hits") + c.get("blocked_hits"));
        const bool queried = c.get("beam_queries") + c.get("window_face_counts") > 0;
        EXPECT_EQ(c.get("query_nodes") > 0, queried) << what;
        EXPECT_EQ(c.get("query_cells"), 0u) << what;

        MethodOptions on_grid = trace_options("beam", threshold);
        on_grid.trace.accel = Accel::Grid;
        const auto grid = render_trace(scene, on_grid);
        EXPECT_EQ(grid.ids, rays.ids) << what << " on the grid at threshold " << threshold;
        EXPECT_EQ(grid.pixels, rays.pixels) << what << " on the grid at threshold " << threshold;
        const auto& g = grid.stats.counters;
        for (const char* count : {"beams", "beam_hits", "partial_hits", "blocked_hits",
                                  "beam_queries", "window_face_counts", "rays", "pixels_by_beams"})
            EXPECT_EQ(g.get(count), c.get(count))
                << what << " at threshold " << threshold << ": " << count;
        EXPECT_EQ(g.get("query_cells") > 0, queried) << what;
        EXPECT_EQ(g.get("query_nodes"), 0u) << what;
    }
}

TEST(BeamRayHybrid, ShowsWhatTheRayTracerShowsInAMirrorRoom) {
    expect_same_as_rays(mirror_room(160, 120), "mirror room");
}

TEST(BeamRayHybrid, ShowsWhatTheRayTracerShowsWhereCornersLieOnSharedEdges) {
    expect_same_as_rays(testing::lattice_through_pixel_centres(97, 6), "lattice");
}

TEST(BeamRayHybrid, ShowsWhatTheRayTracerShowsOnRandomTriangles) {
    expect_same_as_rays(testing::random_scene(128, 96, 300, 150, 7), "random triangles");
}

TEST(BeamRayHybrid, FillsExactlyThePixelsItsBeamsDecide) {
    const Scene scene = mirror_room(160, 120);
    const auto beams = render_trace(scene, trace_options("beam", INFINITY));
    uint64_t marked = 0;
    for (uint8_t m : beams.beam_mask)
        marked += m;
    EXPECT_EQ(marked, beams.stats.counters.get("pixels_by_beams"));
    EXPECT_GT(marked, 160u * 120u / 2) << "most of this room is coherent";
    // at infinity only windows of at most 4x4 pixels whose beams failed go to the ray tracer
    const uint64_t windows = beams.stats.counters.get("windows_to_rays");
    const uint64_t pixels = beams.stats.counters.get("pixels_by_rays");
    EXPECT_GT(windows, 0u);
    EXPECT_LE(windows, pixels);
    EXPECT_LE(pixels, 16 * windows);
    EXPECT_EQ(beams.stats.counters.get("window_face_counts"), 0u) << "no F_w query at infinity";
}

TEST(BeamRayHybrid, ThresholdZeroHandsTheFirstWindowThatIsNotAHitToRays) {
    const auto beams = render_trace(mirror_room(160, 120), trace_options("beam", 0.0));
    EXPECT_EQ(beams.stats.counters.get("beams"), 1u);
    EXPECT_EQ(beams.stats.counters.get("windows_to_rays"), 1u);
    EXPECT_EQ(beams.stats.counters.get("pixels_by_rays"), 160u * 120u);
    EXPECT_EQ(
        beams.stats.counters.get("rays"),
        render_trace(mirror_room(160, 120), trace_options("raytrace")).stats.counters.get("rays"))
        << "every ray once: the corners are not traced again";
}

}  // namespace
}  // namespace fb89::host
