// The shared coverage rule: pixel centres, 64-bit edge functions, top-left ties.
#include "host/raster/coverage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

ScreenScene screen_of(const std::string& json) {
    Counters counters;
    return project_scene(parse_scene_json(json, "test.json", "."), ColorMode::FaceId, counters);
}

// How many faces cover each pixel centre.
std::vector<int> coverage_counts(const ScreenScene& s) {
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

TEST(Coverage, RowSpanAgreesWithPerPixelTest) {
    ScreenScene s = screen_of(R"({"camera": {"projection": "screen"},
        "image": {"width": 64, "height": 48},
        "objects": [{"polygon": [[3.25, 2.5, 0.5], [60.5, 10.75, 0.5], [20.125, 45.5, 0.5]]},
                    {"polygon": [[10, 10, 0.2], [40.5, 10, 0.2], [40.5, 30.5, 0.2], [10, 30.5, 0.2]]}]})");
    ASSERT_EQ(s.faces.size(), 2u);
    for (const auto& f : s.faces) {
        for (int y = 0; y < s.height; ++y) {
            int xb = 0, xe = 0;
            bool any = row_span(s.edges_of(f), f.point_count, y, 0, s.width, xb, xe);
            for (int x = 0; x < s.width; ++x) {
                bool in_span = any && x >= xb && x < xe;
                EXPECT_EQ(in_span, covers(s.edges_of(f), f.point_count, x, y)) << x << "," << y;
            }
        }
    }
}

TEST(Coverage, TopLeftRuleGivesLeftAndTopEdgesTheTies) {
    // A square whose edges run exactly through pixel centres: x in [2.5, 5.5], y in [1.5, 3.5].
    ScreenScene s = screen_of(R"({"camera": {"projection": "screen"},
        "image": {"width": 8, "height": 6},
        "objects": [{"polygon": [[2.5, 1.5, 0.5], [5.5, 1.5, 0.5], [5.5, 3.5, 0.5], [2.5, 3.5, 0.5]]}]})");
    const auto& f = s.faces.at(0);
    // centres on the left (x=2) and top (y=1) edges are in; on the right (x=5), bottom (y=3) out
    EXPECT_TRUE(covers(s.edges_of(f), f.point_count, 2, 1));
    EXPECT_TRUE(covers(s.edges_of(f), f.point_count, 4, 2));
    EXPECT_FALSE(covers(s.edges_of(f), f.point_count, 5, 2));
    EXPECT_FALSE(covers(s.edges_of(f), f.point_count, 3, 3));
    EXPECT_FALSE(covers(s.edges_of(f), f.point_count, 1, 2));
}

TEST(Coverage, TessellatedPlaneCoversEveryPixelExactlyOnce) {
    // A screen-filling rectangle cut into 37 x 29 cells of two triangles each, with cell
    // corners off the pixel grid and on it.
    ScreenScene s = screen_of(R"({"camera": {"projection": "screen"},
        "image": {"width": 257, "height": 201},
        "objects": [{"generator": "quad", "origin": [0, 0, 0.5], "u": [257, 0, 0], "v": [0, 201, 0],
                     "divisions": [37, 29], "triangles": true}]})");
    EXPECT_EQ(s.faces.size(), 37u * 29u * 2u);
    std::vector<int> count = coverage_counts(s);
    for (size_t i = 0; i < count.size(); ++i)
        ASSERT_EQ(count[i], 1) << "pixel " << i % 257 << "," << i / 257;
}

TEST(Coverage, FanAroundAPixelCentreCoversItOnce) {
    // 7 triangles meeting at a pixel centre: the shared vertex is covered by exactly one.
    std::string objects;
    const double cx = 20.5, cy = 20.5, r = 12;
    for (int k = 0; k < 7; ++k) {
        double a0 = 6.283185307179586 * k / 7, a1 = 6.283185307179586 * (k + 1) / 7;
        objects += (k ? "," : "") + std::string("{\"polygon\": [[") + std::to_string(cx) + "," +
                   std::to_string(cy) + ",0.5],[" + std::to_string(cx + r * std::cos(a0)) + "," +
                   std::to_string(cy + r * std::sin(a0)) + ",0.5],[" +
                   std::to_string(cx + r * std::cos(a1)) + "," +
                   std::to_string(cy + r * std::sin(a1)) + ",0.5]]}";
    }
    ScreenScene s = screen_of(R"({"camera": {"projection": "screen"},
        "image": {"width": 48, "height": 48}, "objects": [)" +
                              objects + "]}");
    std::vector<int> count = coverage_counts(s);
    EXPECT_EQ(count[20 * 48 + 20], 1);
    for (int v : count)
        EXPECT_LE(v, 1);
}

}  // namespace
}  // namespace fb89::host
