// Screen set-up: snapping to the 1/256-pixel grid, orientation, convex pieces, pixel bounds
// by the pixel-centre rule, and the counts of the set-up stage.
#include "host/raster/screen_setup.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "host/raster/coverage.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

TEST(ScreenSetup, VerticesSnapToTheSubpixelGrid) {
    Counters counters;
    Scene scene = parse_scene_json(
        R"({"camera": {"projection": "screen"}, "image": {"width": 16, "height": 16},
        "objects": [{"polygon": [[1.001, 1.0, 0.5], [9.3, 1.0, 0.5], [1.0, 9.7, 0.5]]}]})",
        "t.json", ".");
    ScreenScene s = project_scene(scene, ColorMode::FaceId, counters);
    ASSERT_EQ(s.faces.size(), 1u);
    const SnappedPoint* p = s.points_of(s.faces[0]);
    // 1.001 * 256 = 256.256 -> 256; 9.3 * 256 = 2380.8 -> 2381
    std::vector<int64_t> xs;
    for (uint32_t i = 0; i < s.faces[0].point_count; ++i)
        xs.push_back(p[i].x);
    EXPECT_NE(std::find(xs.begin(), xs.end(), 256), xs.end());
    EXPECT_NE(std::find(xs.begin(), xs.end(), 2381), xs.end());
    EXPECT_EQ(counters.get("screen_faces"), 1u);
}

TEST(ScreenSetup, SnapWindsPositivelyAndDropsRepeatsAndZeroArea) {
    const ProjectedVertex clockwise[] = {{0, 0, 0}, {0, 4, 0}, {0, 4.001, 0}, {4, 0, 0}};
    std::vector<SnappedPoint> s = snap(clockwise, 4);
    ASSERT_EQ(s.size(), 3u) << "4.001 snaps onto 4";
    int64_t area2 = 0;
    for (size_t i = 0; i < s.size(); ++i)
        area2 += s[i].x * s[(i + 1) % 3].y - s[(i + 1) % 3].x * s[i].y;
    EXPECT_GT(area2, 0);
    const ProjectedVertex line[] = {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}};
    EXPECT_TRUE(snap(line, 3).empty());
}

TEST(ScreenSetup, ABentPolygonIsCutIntoTrianglesThatCoverItsCentresOnce) {
    // a quadrilateral whose third vertex snapped inwards: not convex
    const std::vector<SnappedPoint> bent{
        {0, 0}, {8 * kSubpixel, 0}, {2 * kSubpixel, 2 * kSubpixel}, {0, 8 * kSubpixel}};
    const auto pieces = convex_pieces(bent);
    ASSERT_EQ(pieces.size(), 2u);
    std::vector<int> count(64, 0);
    for (const auto& piece : pieces) {
        EdgeFunction edges[3];
        setup_edges(piece.data(), 3, edges);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                count[static_cast<size_t>(y * 8 + x)] += covers(edges, 3, x, y);
    }
    EXPECT_EQ(*std::max_element(count.begin(), count.end()), 1) << "no centre twice";
    EXPECT_EQ(count[0], 1);
}

TEST(ScreenSetup, PixelBoundsHoldTheCentresWithinTheSnappedBox) {
    // x from 0.5 (a centre: pixel 0) to 3.25 (centre 3.5 outside: last pixel 2)
    const std::vector<SnappedPoint> tri{
        {kSubpixel / 2, kSubpixel}, {13 * kSubpixel / 4, kSubpixel}, {kSubpixel, 5 * kSubpixel}};
    const PixelRect r = pixel_bounds(tri, 100, 100);
    EXPECT_EQ(r.x0, 0);
    EXPECT_EQ(r.x1, 3);
    EXPECT_EQ(r.y0, 1);  // centre 1.5 is the first at or below y = 1
    EXPECT_EQ(r.y1, 5);  // centre 4.5 the last at or above y = 5
    EXPECT_EQ(pixel_bounds(tri, 2, 2).x1, 2) << "clamped to the screen";
}

}  // namespace
}  // namespace fb89::host
