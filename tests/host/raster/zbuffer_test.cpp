// The Z-buffer against a brute-force reference of the shared coverage and depth rule,
// on whole screens and on windows, with each depth kernel; ties, counts and spans.
#include "host/raster/zbuffer.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <numeric>
#include <utility>

#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "host/raster/screen_setup.h"
#include "host/scene/generators.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"
#include "tests/host/raster/raster_test_util.h"

namespace fb89::host {
namespace {

ScreenScene face_id_screen(const Scene& scene) {
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
    ScreenScene s = face_id_screen(random_scene(160, 120, 300, 150, 7));
    ZBuffer zbuffer;
    zbuffer.keep_face_buffer(true);
    protocol::MemoryBuffer buffer;
    HostStats stats;
    zbuffer.render(s, buffer, stats);
    EXPECT_EQ(ids_of(s, zbuffer.face_buffer()), reference_ids(s, s.screen()));
}

TEST(ZBuffer, RendersAWindowAndLeavesTheRestAlone) {
    ScreenScene s = face_id_screen(random_scene(160, 120, 200, 200, 11));
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

// Awkward faces: slivers, faces smaller than a pixel, faces far larger than the screen,
// nearly edge-on (steep) planes, vertices off every border, and runs of every length.
Scene awkward_faces(int width, int height) {
    return parse_scene_json(fmt::format(R"({{"camera": {{"projection": "screen"}},
        "image": {{"width": {}, "height": {}}},
        "objects": [
          {{"polygon": [[-40, -30, 0.9], [130, -25, 0.2], [40, 140, 0.5]]}},
          {{"polygon": [[0.3, 5.1, 0.1], [99.7, 6.2, 0.1], [99.6, 6.3, 0.1]]}},
          {{"polygon": [[50.2, 1, 0.05], [50.9, 1.2, 0.05], [50.4, 77, 0.05]]}},
          {{"polygon": [[10.4, 10.4, 0.0], [10.6, 10.45, 0.0], [10.5, 10.7, 0.0]]}},
          {{"polygon": [[20, 20, 0.0], [21, 20, 0.0], [20, 21, 0.0]]}},
          {{"polygon": [[5, 40, -50], [90, 41, 60], [6, 60, -49]]}},
          {{"polygon": [[70, -500, 0.3], [600, 90, 0.3], [70, 600, 0.3]]}},
          {{"polygon": [[-3, 33.5, 0.15], [103, 33.5, 0.15], [103, 36.5, 0.15], [-3, 36.5, 0.15]]}},
          {{"polygon": [[1.5, 50.5, 0.12], [2.5, 50.5, 0.12], [2.5, 70.5, 0.12], [1.5, 70.5, 0.12]]}}
        ]}})",
                                        width, height),
                            "awkward.json", ".");
}

TEST(ZBuffer, EveryKernelMatchesTheReferenceOnAwkwardFaces) {
    for (bool avx2 : {true, false}) {
        for (const auto& [w, h] : {std::pair{100, 80}, std::pair{97, 53}, std::pair{7, 5}}) {
            ScreenScene s = face_id_screen(awkward_faces(w, h));
            if (w == 100) {
                ASSERT_EQ(s.faces.size(), 9u);  // none lost in set-up
            }
            ZBuffer zbuffer;
            zbuffer.allow_avx2(avx2);
            zbuffer.keep_face_buffer(true);
            protocol::MemoryBuffer buffer;
            HostStats stats;
            zbuffer.render(s, buffer, stats);
            EXPECT_EQ(ids_of(s, zbuffer.face_buffer()), reference_ids(s, s.screen()))
                << w << "x" << h << (avx2 ? " (AVX2 where there)" : " (baseline)");
            // and the commands say the same
            EXPECT_EQ(testing::ids_from_commands(buffer.commands(), w, h),
                      ids_of(s, zbuffer.face_buffer()));
        }
    }
}

TEST(ZBuffer, EveryKernelSendsTheSameCommandsAndCounts) {
    for (const auto& [count, area] : {std::pair{3000, 4.0}, std::pair{400, 300.0}}) {
        ScreenScene s = face_id_screen(random_scene(203, 150, count, area, 5));
        protocol::MemoryBuffer wide, baseline;
        HostStats wide_stats, baseline_stats;
        ZBuffer a, b;
        b.allow_avx2(false);
        a.render(s, wide, wide_stats);
        b.render(s, baseline, baseline_stats);
        EXPECT_EQ(wide.commands(), baseline.commands());
        for (const char* counter : {"depth_tests", "pixels_written", "spans", "faces_rasterised"})
            EXPECT_EQ(wide_stats.counters.get(counter), baseline_stats.counters.get(counter))
                << counter;
    }
}

// The entries of `ids` (a whole screen) inside `window`, row by row.
std::vector<uint32_t> inside(const std::vector<uint32_t>& ids, int width, const PixelRect& w) {
    std::vector<uint32_t> out;
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x)
            out.push_back(ids[static_cast<size_t>(y) * width + x]);
    return out;
}

TEST(ZBuffer, WindowsAfterWindowsAtTheRightBorderAndOfEveryWidth) {
    ScreenScene s = face_id_screen(random_scene(61, 47, 150, 120, 3));
    std::vector<uint32_t> all(s.faces.size());
    std::iota(all.begin(), all.end(), 0u);
    ZBuffer zbuffer;  // one for every window, as the hybrid uses it
    zbuffer.keep_face_buffer(true);
    for (int x0 = 40; x0 < 61; x0 += 3) {
        for (int x1 = x0 + 1; x1 <= 61; x1 += 4) {
            const PixelRect window{x0, 5 + x0 % 4, x1, 47 - x1 % 3};
            protocol::MemoryBuffer buffer;
            ZBufferCounts counts;
            zbuffer.render_window(s, all, window, buffer, counts);
            ASSERT_EQ(inside(ids_of(s, zbuffer.face_buffer()), s.width, window),
                      inside(reference_ids(s, window), s.width, window))
                << "window x " << x0 << ".." << x1;
        }
    }
}

TEST(ZBuffer, EqualDepthGoesToTheLowerId) {
    Scene scene = parse_scene_json(
        R"({"camera": {"projection": "screen"}, "image": {"width": 32, "height": 32},
        "objects": [{"polygon": [[4, 4, 0.5], [20, 4, 0.5], [20, 20, 0.5], [4, 20, 0.5]]},
                    {"polygon": [[10, 10, 0.5], [28, 10, 0.5], [28, 28, 0.5], [10, 28, 0.5]]},
                    {"polygon": [[0, 0, 0.5], [32, 0, 0.5], [32, 32, 0.5], [0, 32, 0.5]]}]})",
        "tie.json", ".");
    ScreenScene s = face_id_screen(scene);
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
    ScreenScene s = face_id_screen(scene);
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
