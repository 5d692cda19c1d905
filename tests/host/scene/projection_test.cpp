// Projection to screen space: camera conventions, near-plane and guard-band clipping that
// leaves no cracks, depth planes; through the raster set-up, every pixel covered once.
#include "host/raster/screen_setup.h"

#include <gtest/gtest.h>

#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

// A 10 x 3 x 10 room with tessellated walls that share their vertices (no T-junctions);
// the camera stands inside, so the floor and walls cross the near plane and run far off
// screen on every side.
std::string room_scene(const std::string& camera) {
    return R"({"camera": )" + camera + R"(,
      "objects": [
        {"generator": "quad", "origin": [-5, 0, -5], "u": [10, 0, 0], "v": [0, 0, 10], "divisions": [6, 4], "triangles": true},
        {"generator": "quad", "origin": [-5, 3, -5], "u": [10, 0, 0], "v": [0, 0, 10], "divisions": [6, 4]},
        {"generator": "quad", "origin": [-5, 0, -5], "u": [10, 0, 0], "v": [0, 3, 0], "divisions": [6, 3]},
        {"generator": "quad", "origin": [-5, 0, 5], "u": [10, 0, 0], "v": [0, 3, 0], "divisions": [6, 3], "triangles": true},
        {"generator": "quad", "origin": [-5, 0, -5], "u": [0, 0, 10], "v": [0, 3, 0], "divisions": [4, 3]},
        {"generator": "quad", "origin": [5, 0, -5], "u": [0, 0, 10], "v": [0, 3, 0], "divisions": [4, 3], "triangles": true}
      ]})";
}

std::vector<int> pixel_coverage_counts(const ScreenScene& s) {
    std::vector<int> count(static_cast<size_t>(s.width) * s.height, 0);
    for (const auto& f : s.faces) {
        for (int y = f.bounds.y0; y < f.bounds.y1; ++y) {
            int xb = 0, xe = 0;
            if (!row_span(s.edges_of(f), f.point_count, y, 0, s.width, xb, xe)) continue;
            for (int x = xb; x < xe; ++x)
                ++count[static_cast<size_t>(y) * s.width + x];
        }
    }
    return count;
}

void expect_every_pixel_once(const std::string& camera) {
    Counters counters;
    ScreenScene s = project_scene(parse_scene_json(room_scene(camera), "room.json", "."),
                                  ColorMode::FaceId, counters);
    EXPECT_GT(counters.get("faces_clipped"), 0u) << "the view should cut through faces";
    std::vector<int> count = pixel_coverage_counts(s);
    size_t wrong = 0;
    for (int v : count)
        wrong += v != 1;
    EXPECT_EQ(wrong, 0u) << "pixels not covered exactly once";
}

TEST(Projection, CameraInsideRoomCoversEveryPixelExactlyOnce) {
    expect_every_pixel_once(
        R"({"eye": [0.3, 1.5, 0.7], "look_at": [2, 1.2, -3], "fovy": 70, "near": 0.05, "far": 100})");
}

TEST(Projection, CameraInsideRoomLookingDownACornerCoversEveryPixelExactlyOnce) {
    expect_every_pixel_once(
        R"({"eye": [-3.1, 2.2, 3.3], "look_at": [4.9, 0.1, -4.95], "up": [0.1, 1, 0], "fovy": 100, "near": 0.01, "far": 50})");
}

TEST(Projection, FollowsGluPerspectiveConventions) {
    // A point on the view axis lands on the screen centre; +y in the world is up on screen.
    Counters counters;
    Scene scene = parse_scene_json(
        R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fovy": 90, "near": 1, "far": 10},
        "image": {"width": 200, "height": 100},
        "objects": [{"polygon": [[-0.5, 0.5, 0], [0.5, 0.5, 0], [0, 1.5, 0]]}]})",
        "t.json", ".");
    ScreenScene s = project_scene(scene, ColorMode::FaceId, counters);
    ASSERT_EQ(s.faces.size(), 1u);
    // world y from 0.5 to 1.5 at distance 5 with tan(45°) = 1: rows 50 - 50*0.3 .. 50 - 50*0.1
    EXPECT_EQ(s.faces[0].bounds.y0, 35);
    EXPECT_EQ(s.faces[0].bounds.y1, 45);
    // window depth at the face follows gluPerspective: z_ndc = (f+n)/(f-n) - 2fn/((f-n) d)
    double z_ndc = 11.0 / 9.0 - 20.0 / (9.0 * 5.0);
    EXPECT_NEAR(depth_at(s.faces[0].depth, 100, 40), (z_ndc + 1) / 2, 1e-12);
}

TEST(Projection, FacesBehindTheCameraAreDropped) {
    Counters counters;
    Scene scene = parse_scene_json(
        R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fovy": 60, "near": 0.1, "far": 10},
        "objects": [{"polygon": [[-1, -1, 6], [1, -1, 6], [0, 1, 6]]}]})",
        "t.json", ".");
    ScreenScene s = project_scene(scene, ColorMode::FaceId, counters);
    EXPECT_TRUE(s.faces.empty());
    EXPECT_EQ(counters.get("faces_outside_frustum"), 1u);
}

TEST(Projection, StopsAtUnsnappedPolygonsWithTheirDepthPlanes) {
    Counters counters;
    Scene scene = parse_scene_json(
        R"({"camera": {"projection": "screen"}, "image": {"width": 16, "height": 16},
        "objects": [{"polygon": [[1.001, 1.0, 0.25], [9.3, 1.0, 0.5], [1.0, 9.7, 0.75]]}]})",
        "t.json", ".");
    ProjectedScene p = project_faces(scene, ColorMode::FaceId, counters);
    ASSERT_EQ(p.faces.size(), 1u);
    ASSERT_EQ(p.faces[0].vertex_count, 3u);
    EXPECT_EQ(p.vertices_of(p.faces[0])[0].x, 1.001);
    EXPECT_EQ(p.vertices_of(p.faces[0])[1].x, 9.3);
    const DepthPlane& d = p.faces[0].depth;
    for (uint32_t i = 0; i < 3; ++i) {
        const ProjectedVertex& v = p.vertices_of(p.faces[0])[i];
        EXPECT_NEAR(d.a * v.x + d.b * v.y + d.c, v.z, 1e-12);
    }
}

TEST(Projection, FaceIdPassHasABlackBackgroundWhateverTheScenes) {
    Counters counters;
    Scene scene =
        parse_scene_json(R"({"camera": {"projection": "screen"}, "background": [0.5, 0.7, 0.9],
        "objects": [{"polygon": [[1, 1, 0.5], [9, 1, 0.5], [1, 9, 0.5]]}]})",
                         "t.json", ".");
    EXPECT_EQ(project_scene(scene, ColorMode::FaceId, counters).background,
              (protocol::Rgb{0, 0, 0}));
    EXPECT_EQ(project_scene(scene, ColorMode::Shaded, counters).background,
              (protocol::Rgb{128, 179, 230}));
}

TEST(Projection, FaceIdColourRoundTrips) {
    for (uint32_t id : {0u, 1u, 255u, 256u, 65535u, 16777214u})
        EXPECT_EQ(face_id_from_color(face_id_color(id)), id + 1);
}

}  // namespace
}  // namespace fb89::host
