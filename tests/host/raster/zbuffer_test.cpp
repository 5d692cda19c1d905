// The Z-buffer against a brute-force reference of the shared coverage and depth rule,
// on whole screens and on windows; ties, counts and spans.
#include "host/raster/zbuffer.h"

#include <gtest/gtest.h>

#include <numeric>

#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "host/raster/screen_setup.h"
#include "host/scene/generators.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"
#include "tests/host/raster/raster_test_util.h"

namespace fb89::host {
namespace {

ScreenScene screen_scene(const Scene& scene) {
    Counters counters;
    return project_scene(scene, ColorMode::FaceId, counters);
}

using testing::random_scene;

// The rule itself, pixel by pixel over every face: ids + 1, 0 for background.
std::vector<uint32_t> reference_ids(const ScreenScene& s, const PixelRect& window) {
    std::vector<uint32_t> ids(static_cast<size_t>(s.width) * s.height, 0);
    for (int y = window.y0; y < window.y1; ++y) {
        for (int x = window.x0; x < window.x1; ++x) {
            double best_z = 0;
            uint32_t best = 0;
            for (const auto& f : s.faces) {
                if (!covers(s.edges_of(f), f.point_count, x, y)) continue;
                double z = depth_at(f.depth, x, y);
                if (best == 0 || nearer(z, f.id, best_z, best - 1)) {
                    best_z = z;
                    best = f.id + 1;
                }
            }
            ids[static_cast<size_t>(y) * s.width + x] = best;
        }
    }
    return ids;
}

std::vector<uint32_t> ids_of(const ScreenScene& s, const std::vector<uint32_t>& faces) {
    std::vector<uint32_t> ids(faces.size());
    for (size_t i = 0; i < faces.size(); ++i)
        ids[i] = faces[i] ? s.faces[faces[i] - 1].id + 1 : 0;
    return ids;
}

TEST(ZBuffer, MatchesTheReferenceRuleOnInterpenetratingTriangles) {
    ScreenScene s = screen_scene(random_scene(160, 120, 300, 150, 7));
    ZBuffer zbuffer;
    zbuffer.keep_face_buffer(true);
    protocol::MemoryBuffer buffer;
    HostStats stats;
    zbuffer.render(s, buffer, stats);
    EXPECT_EQ(ids_of(s, zbuffer.face_buffer()), reference_ids(s, s.screen()));
}

TEST(ZBuffer, RendersAWindowAndLeavesTheRestAlone) {
    ScreenScene s = screen_scene(random_scene(160, 120, 200, 200, 11));
    PixelRect window{37, 21, 101, 90};
    std::vector<uint32_t> all(s.faces.size());
    std::iota(all.begin(), all.end(), 0u);
    ZBuffer zbuffer;
    zbuffer.keep_face_buffer(true);
    protocol::MemoryBuffer buffer;
    ZBufferCounts counts;
    zbuffer.render_window(s, all, window, buffer, counts);
    EXPECT_EQ(ids_of(s, zbuffer.face_buffer()), reference_ids(s, window));
    for (const auto& c : buffer.commands()) {
        const auto& span = std::get<protocol::DrawSpan>(c);
        EXPECT_GE(span.y, window.y0);
        EXPECT_LT(span.y, window.y1);
        EXPECT_GE(span.x0, window.x0);
        EXPECT_LT(span.x1, window.x1);
    }
}

TEST(ZBuffer, EqualDepthGoesToTheLowerId) {
    Scene scene = parse_scene_json(
        R"({"camera": {"projection": "screen"}, "image": {"width": 32, "height": 32},
        "objects": [{"polygon": [[4, 4, 0.5], [20, 4, 0.5], [20, 20, 0.5], [4, 20, 0.5]]},
                    {"polygon": [[10, 10, 0.5], [28, 10, 0.5], [28, 28, 0.5], [10, 28, 0.5]]},
                    {"polygon": [[0, 0, 0.5], [32, 0, 0.5], [32, 32, 0.5], [0, 32, 0.5]]}]})",
        "tie.json", ".");
    ScreenScene s = screen_scene(scene);
    ZBuffer zbuffer;
    zbuffer.keep_face_buffer(true);
    protocol::MemoryBuffer buffer;
    HostStats stats;
    zbuffer.render(s, buffer, stats);
    auto id_at = [&](int x, int y) {
        return ids_of(s, zbuffer.face_buffer())[static_cast<size_t>(y) * 32 + x];
    };
    EXPECT_EQ(id_at(15, 15), 1u);  // faces 0 and 1 and 2 overlap: 0 wins
    EXPECT_EQ(id_at(25, 25), 2u);  // 1 and 2: 1 wins
    EXPECT_EQ(id_at(1, 30), 3u);
}

TEST(ZBuffer, CountsDepthTestsPixelsAndSpansExactly) {
    // two overlapping axis-aligned rectangles with edges between pixel centres:
    // A covers x 2..9, y 2..5 (8 x 4 = 32 centres) at z 0.5; B covers x 6..13, y 4..7 (32) at 0.25
    Scene scene = parse_scene_json(
        R"({"camera": {"projection": "screen"}, "image": {"width": 16, "height": 10},
        "objects": [{"polygon": [[2, 2, 0.5], [10, 2, 0.5], [10, 6, 0.5], [2, 6, 0.5]]},
                    {"polygon": [[6, 4, 0.25], [14, 4, 0.25], [14, 8, 0.25], [6, 8, 0.25]]}]})",
        "count.json", ".");
    ScreenScene s = screen_scene(scene);
    ZBuffer zbuffer;
    protocol::MemoryBuffer buffer;
    HostStats stats;
    zbuffer.render(s, buffer, stats);
    EXPECT_EQ(stats.counters.get("depth_tests"), 64u);
    EXPECT_EQ(stats.counters.get("pixels_written"), 64u);  // B is nearer and drawn second
    // rows 2-3: A alone (1 span each); rows 4-5: A then B (2 each); rows 6-7: B alone
    EXPECT_EQ(stats.counters.get("spans"), 8u);
    EXPECT_EQ(buffer.size(), 8u);
}

}  // namespace
}  // namespace fb89::host
