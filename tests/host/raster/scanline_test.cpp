// The scan-line renderer against the Z-buffer: the same face-id buffer and the same
// DRAW_SPAN list on random interpenetrating triangles, the conformance sets, the bundled
// scenes and the cases DESIGN.md lists as hard for scan-line (edges through pixel
// centres, horizontal edges, interpenetration, coplanar overlaps, shared edges, slivers).
#include "host/raster/scanline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include <fmt/format.h>

#include "host/raster/screen_setup.h"
#include "host/raster/zbuffer.h"
#include "host/scene/generators.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"
#include "tests/host/raster/raster_test_util.h"

namespace fb89::host {
namespace {

ScreenScene screen_scene(const Scene& scene, ColorMode mode = ColorMode::FaceId) {
    Counters counters;
    return project_scene(scene, mode, counters);
}

using testing::random_scene;

// `count` random triangles all on the plane z = a x + b y + c: with a = b = 0 their planes
// are bit-identical; sloped, each is rebuilt from its own vertices and differs by rounding.
Scene one_plane_scene(int width, int height, int count, double a, double b, uint64_t seed) {
    Scene scene;
    scene.projection = Projection::Screen;
    scene.width = width;
    scene.height = height;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(0, width), uy(0, height);
    for (int i = 0; i < count; ++i) {
        Face f;
        for (int v = 0; v < 3; ++v) {
            const double x = ux(rng), y = uy(rng);
            f.vertices.push_back({x, y, 0.2 + a * x + b * y});
        }
        f.id = scene.face_count++;
        scene.faces.push_back(std::move(f));
    }
    return scene;
}

Scene screen_json(int width, int height, const std::string& objects) {
    return parse_scene_json(fmt::format(R"({{"camera": {{"projection": "screen"}},
        "image": {{"width": {}, "height": {}}}, "objects": [{}]}})",
                                        width, height, objects),
                            "test.json", ".");
}

struct ScanRendered {
    protocol::MemoryBuffer commands;
    HostStats stats;
};

ScanRendered render_with(Renderer& renderer, const ScreenScene& s) {
    ScanRendered r;
    renderer.setup(s);
    renderer.render(s, r.commands, r.stats);
    return r;
}

// The id buffer the spans paint (face-id colours: id + 1; 0 where nothing is drawn).
std::vector<uint32_t> painted_ids(const ScreenScene& s, const protocol::MemoryBuffer& b) {
    std::vector<uint32_t> ids(static_cast<size_t>(s.width) * s.height, 0);
    for (const auto& c : b.commands()) {
        const auto& span = std::get<protocol::DrawSpan>(c);
        for (int x = span.x0; x <= span.x1; ++x)
            ids[static_cast<size_t>(span.y) * s.width + x] = face_id_from_color(span.color);
    }
    return ids;
}

std::string first_difference(const ScreenScene& s, const std::vector<uint32_t>& got,
                             const std::vector<uint32_t>& want) {
    long long count = 0;
    std::string first;
    for (size_t i = 0; i < got.size(); ++i) {
        if (got[i] == want[i]) continue;
        if (count++ == 0)
            first = fmt::format("({}, {}): scan-line id+1 {}, Z-buffer {}", i % s.width,
                                i / s.width, got[i], want[i]);
    }
    return count ? fmt::format("{} pixels differ; first {}", count, first) : "";
}

// Renders with both methods; expects equal face-id buffers and equal span lists.
HostStats expect_same_as_zbuffer(const ScreenScene& s, ScanLine& scanline) {
    ZBuffer zbuffer;
    ScanRendered want = render_with(zbuffer, s);
    ScanRendered got = render_with(scanline, s);
    EXPECT_EQ(first_difference(s, painted_ids(s, got.commands), painted_ids(s, want.commands)), "");
    EXPECT_TRUE(got.commands.commands() == want.commands.commands()) << "span lists differ";
    EXPECT_EQ(got.stats.counters.get("spans"), want.stats.counters.get("spans"));
    return got.stats;
}

HostStats expect_same_as_zbuffer(const ScreenScene& s) {
    ScanLine scanline;
    return expect_same_as_zbuffer(s, scanline);
}

TEST(ScanLine, MatchesTheZBufferOnSeededRandomInterpenetratingTriangles) {
    ScanLine scanline;  // one renderer for every scene: nothing leaks between frames
    for (uint64_t seed = 1; seed <= 6; ++seed) {
        SCOPED_TRACE(fmt::format("seed {}", seed));
        HostStats stats = expect_same_as_zbuffer(
            screen_scene(random_scene(160, 120, 300, seed % 2 ? 150 : 1500, seed)), scanline);
        EXPECT_GT(stats.counters.get("scanline_segments_split"), 0u);
    }
}

TEST(ScanLine, MatchesTheZBufferOnSliversThinnerThanAPixel) {
    for (uint64_t seed = 1; seed <= 3; ++seed)
        expect_same_as_zbuffer(screen_scene(random_scene(120, 90, 2000, 0.6, seed)));
    // long needles crossing each other, under a pixel wide
    expect_same_as_zbuffer(screen_scene(screen_json(64, 48, R"(
        {"polygon": [[1, 1, 0.2], [63, 20.3, 0.8], [62.9, 20.6, 0.8]]},
        {"polygon": [[2, 40, 0.9], [60, 2.5, 0.1], [60.2, 2.9, 0.1]]},
        {"polygon": [[30.5, 0.5, 0.5], [30.8, 0.5, 0.5], [30.6, 47.5, 0.1]]})")));
}

TEST(ScanLine, MatchesTheZBufferWithEdgesThroughPixelCentresAndHorizontalEdges) {
    // squares split into triangles, every vertex on a pixel centre: shared edges, shared
    // vertices, horizontal edges exactly on centre rows, diagonals through centres
    std::string objects;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 5; ++i) {
            const double x0 = 2.5 + 6 * i, y0 = 1.5 + 5 * j, x1 = x0 + 6, y1 = y0 + 5;
            const double z = 0.1 * (1 + (i + j) % 3);
            objects += fmt::format(R"({}{{"polygon": [[{},{},{}],[{},{},{}],[{},{},{}]]}},)", "",
                                   x0, y0, z, x1, y0, z, x1, y1, z);
            objects += fmt::format(R"({{"polygon": [[{},{},{}],[{},{},{}],[{},{},{}]]}},)", x0, y0,
                                   z, x1, y1, z, x0, y1, z);
        }
    }
    // a sloped rectangle over them with horizontal edges on centre rows
    objects += R"({"polygon": [[4.5, 3.5, 0.0], [20.5, 3.5, 0.4], [20.5, 12.5, 0.4],
                               [4.5, 12.5, 0.0]]})";
    ScreenScene s = screen_scene(screen_json(36, 24, objects));
    expect_same_as_zbuffer(s);

    // the top-left rule on the rectangle alone: centres on its top and left edges are in
    ScreenScene one = screen_scene(screen_json(36, 24, R"({"polygon": [[4.5, 3.5, 0.0],
        [20.5, 3.5, 0.4], [20.5, 12.5, 0.4], [4.5, 12.5, 0.0]]})"));
    ScanLine scanline;
    ScanRendered r = render_with(scanline, one);
    ASSERT_EQ(r.commands.size(), 9u);  // rows 3..11
    const auto& top = std::get<protocol::DrawSpan>(r.commands.commands().front());
    EXPECT_EQ(top.y, 3);
    EXPECT_EQ(top.x0, 4);
    EXPECT_EQ(top.x1, 19);
}

TEST(ScanLine, CoplanarOverlappingFacesGoToTheLowerId) {
    // flat: three squares at one depth
    ScreenScene flat = screen_scene(screen_json(32, 32, R"(
        {"polygon": [[4, 4, 0.5], [20, 4, 0.5], [20, 20, 0.5], [4, 20, 0.5]]},
        {"polygon": [[10, 10, 0.5], [28, 10, 0.5], [28, 28, 0.5], [10, 28, 0.5]]},
        {"polygon": [[0, 0, 0.5], [32, 0, 0.5], [32, 32, 0.5], [0, 32, 0.5]]})"));
    HostStats flat_stats = expect_same_as_zbuffer(flat);
    EXPECT_EQ(flat_stats.counters.get("scanline_pixels_resolved"), 0u);  // one plane: id decides
    ScanLine scanline;
    std::vector<uint32_t> ids = painted_ids(flat, render_with(scanline, flat).commands);
    EXPECT_EQ(ids[15 * 32 + 15], 1u);  // faces 0, 1 and 2 overlap: 0 wins
    EXPECT_EQ(ids[25 * 32 + 25], 2u);  // 1 and 2: 1 wins
    EXPECT_EQ(ids[30 * 32 + 1], 3u);

    // sloped: z = 0.01 x + 0.01 y + 0.06 given by different vertices, so the two planes
    // agree only to rounding and the overlap is decided centre by centre
    ScreenScene sloped = screen_scene(screen_json(48, 32, R"(
        {"polygon": [[2, 2, 0.1], [30, 2, 0.38], [30, 30, 0.66], [2, 30, 0.38]]},
        {"polygon": [[13, 7, 0.26], [45, 5, 0.56], [40, 29, 0.75]]})"));
    HostStats stats = expect_same_as_zbuffer(sloped);
    EXPECT_GT(stats.counters.get("scanline_pixels_resolved"), 0u);
}

TEST(ScanLine, MatchesTheZBufferOnManyOverlappingFacesOfOnePlane) {
    for (uint64_t seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(fmt::format("seed {}", seed));
        HostStats flat =
            expect_same_as_zbuffer(screen_scene(one_plane_scene(96, 64, 60, 0, 0, seed)));
        EXPECT_EQ(flat.counters.get("scanline_pixels_resolved"), 0u);
        HostStats sloped =
            expect_same_as_zbuffer(screen_scene(one_plane_scene(96, 64, 60, 0.003, -0.002, seed)));
        EXPECT_GT(sloped.counters.get("scanline_pixels_resolved"), 0u);
    }
}

TEST(ScanLine, SplitsASegmentWherePlanesCrossWithoutPerPixelWork) {
    // two rectangles over the same pixels, tilted opposite ways in x: they cross at x = 20
    ScreenScene s = screen_scene(screen_json(40, 20, R"(
        {"polygon": [[0, 0, 0.0], [40, 0, 1.0], [40, 20, 1.0], [0, 20, 0.0]]},
        {"polygon": [[0, 0, 1.0], [40, 0, 0.0], [40, 20, 0.0], [0, 20, 1.0]]})"));
    HostStats stats = expect_same_as_zbuffer(s);
    EXPECT_EQ(stats.counters.get("scanline_segments"), 20u);  // one per row
    EXPECT_EQ(stats.counters.get("scanline_segments_split"), 20u);
    // per row: both at the last centre, both at the first, one check of the predicted
    // crossing, both where the second face takes over; no centre decided alone
    EXPECT_EQ(stats.counters.get("scanline_pixels_resolved"), 0u);
    EXPECT_EQ(stats.counters.get("scanline_depth_evaluations"), 20u * 8);
    EXPECT_EQ(stats.counters.get("spans"), 40u);
}

TEST(ScanLine, CountsActiveFacesSegmentsAndSpansExactly) {
    // A covers x 2..9, y 2..5 at z 0.5; B covers x 6..13, y 4..7 at 0.25
    ScreenScene s = screen_scene(screen_json(16, 10, R"(
        {"polygon": [[2, 2, 0.5], [10, 2, 0.5], [10, 6, 0.5], [2, 6, 0.5]]},
        {"polygon": [[6, 4, 0.25], [14, 4, 0.25], [14, 8, 0.25], [6, 8, 0.25]]})"));
    HostStats stats = expect_same_as_zbuffer(s);
    EXPECT_EQ(stats.counters.get("scanline_active_face_rows"), 8u);
    EXPECT_EQ(stats.counters.get("scanline_face_runs"), 8u);
    // rows 2-3 and 6-7: one segment of one face; rows 4-5: A alone, A and B, B alone
    EXPECT_EQ(stats.counters.get("scanline_segments"), 10u);
    EXPECT_EQ(stats.counters.get("scanline_segments_one_face"), 8u);
    EXPECT_EQ(stats.counters.get("scanline_segments_split"), 0u);
    EXPECT_EQ(stats.counters.get("scanline_pixels_resolved"), 0u);
    EXPECT_EQ(stats.counters.get("scanline_depth_evaluations"), 8u);  // 2 x 2 per shared segment
    EXPECT_EQ(stats.counters.get("spans"), 8u);
}

TEST(ScanLine, MergesAdjacentFacesOfOneColourIntoOneSpanLikeTheZBuffer) {
    // two abutting squares of one colour, a third of another colour beside them
    ScreenScene s = screen_scene(screen_json(32, 8, R"(
        {"polygon": [[0, 0, 0.5], [8, 0, 0.5], [8, 8, 0.5], [0, 8, 0.5]], "material": {"color": [1, 0, 0]}},
        {"polygon": [[8, 0, 0.3], [16, 0, 0.3], [16, 8, 0.3], [8, 8, 0.3]], "material": {"color": [1, 0, 0]}},
        {"polygon": [[16, 0, 0.3], [24, 0, 0.3], [24, 8, 0.3], [16, 8, 0.3]], "material": {"color": [0, 1, 0]}})"),
                                 ColorMode::Shaded);
    HostStats stats = expect_same_as_zbuffer(s);
    EXPECT_EQ(stats.counters.get("spans"), 16u);  // per row: red 0..15, green 16..23
}

TEST(ScanLine, SendsTheZBuffersSpansOnTheShadedDemo) {
    Scene scene = load_scene(FB89_SCENES_DIR "/demo.json");
    expect_same_as_zbuffer(screen_scene(scene, ColorMode::Shaded));
}

TEST(ScanLine, MatchesTheZBufferOnTheBundledPerspectiveScenes) {
    for (const char* name : {"demo.json", "cornell_box.json"}) {
        SCOPED_TRACE(name);
        Scene scene = load_scene(std::string(FB89_SCENES_DIR) + "/" + name);
        expect_same_as_zbuffer(screen_scene(scene));
        expect_same_as_zbuffer(screen_scene(scene, ColorMode::Shaded));
    }
}

TEST(ScanLineGolden, FaceIdBufferEqualsTheZBuffersOnTheFiveConformanceSets) {
    for (const char* name : {"random_large_flat", "mesh_on_centres", "fans_on_centres",
                             "ideal_two_layers", "small_sloped_interpenetrating"}) {
        SCOPED_TRACE(name);
        // (fmt, not a chain of string +: GCC 12 warns falsely of the chain's memcpy bounds)
        Scene scene =
            load_scene(fmt::format("{}/golden/conformance/{}.tri", FB89_TEST_DATA_DIR, name));
        expect_same_as_zbuffer(screen_scene(scene));
    }
}

}  // namespace
}  // namespace fb89::host
