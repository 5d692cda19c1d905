// Warnock's looker and thinker: the same face-id buffer as the Z-buffer in both window
// tests, exact sample counts where they can be worked out by hand, and termination with
// bounded recursion where the method is weakest (DESIGN.md "Where each method is known
// to fail").
#include "host/raster/warnock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "host/raster/screen_setup.h"
#include "host/raster/zbuffer.h"
#include "host/scene/generators.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"
#include "tests/host/raster/raster_test_util.h"

namespace fb89::host {
namespace {

Scene scene_of(int width, int height, GeneratedPolygons polys) {
    Scene scene;
    scene.projection = Projection::Screen;
    scene.width = width;
    scene.height = height;
    for (auto& p : polys) {
        Face f;
        f.vertices = std::move(p.vertices);
        f.id = scene.face_count++;
        scene.faces.push_back(std::move(f));
    }
    return scene;
}

ScreenScene ids_scene(const Scene& scene) {
    Counters counters;
    return project_scene(scene, ColorMode::FaceId, counters);
}

// The face-id buffer a method leaves in a framebuffer, replayed from its commands.
std::vector<uint32_t> id_buffer(Renderer& renderer, const ScreenScene& s,
                                Counters* counters = nullptr) {
    protocol::MemoryBuffer buffer;
    HostStats stats;
    renderer.render(s, buffer, stats);
    std::vector<uint32_t> ids = testing::ids_from_commands(buffer.commands(), s.width, s.height);
    if (counters) *counters = stats.counters;
    return ids;
}

// Runs both window tests and checks them against the Z-buffer; returns the area counts.
Counters expect_warnock_same_as_zbuffer(const Scene& scene) {
    ScreenScene s = ids_scene(scene);
    ZBuffer zbuffer;
    std::vector<uint32_t> want = id_buffer(zbuffer, s);
    Counters area, centres;
    Warnock warnock_area({WindowTest::Area, {}}), warnock_centres({WindowTest::Centres, {}});
    EXPECT_EQ(id_buffer(warnock_area, s, &area), want) << "area window test";
    EXPECT_EQ(id_buffer(warnock_centres, s, &centres), want) << "centres window test";
    // recursion is bounded by the halvings of the longer side, plus the 1-pixel level
    const uint64_t bound = static_cast<uint64_t>(std::ceil(std::log2(std::max(s.width, s.height))));
    EXPECT_LE(area.get("max_depth"), bound);
    EXPECT_LE(centres.get("max_depth"), bound);
    EXPECT_LE(centres.get("window_samples"), area.get("window_samples"));
    return area;
}

TEST(Warnock, AScreenFillingFaceTakesOneSampleAndOneFill) {
    Counters c = expect_warnock_same_as_zbuffer(
        scene_of(64, 48, {{{{-1, -1, 0.5}, {70, -1, 0.5}, {70, 50, 0.5}, {-1, 50, 0.5}}, {}}}));
    EXPECT_EQ(c.get("window_samples"), 1u);
    EXPECT_EQ(c.get("fills"), 1u);
    EXPECT_EQ(c.get("face_computations"), 0u);
}

TEST(Warnock, AnEmptyScreenTakesOneSampleAndSendsNothing) {
    Counters c = expect_warnock_same_as_zbuffer(scene_of(64, 48, {}));
    EXPECT_EQ(c.get("window_samples"), 1u);
    EXPECT_EQ(c.get("empty_windows"), 1u);
    EXPECT_EQ(c.get("fills"), 0u);
}

TEST(Warnock, OneSquareInOneQuadrantSamplesFiveWindows) {
    // a face exactly covering the top-left quadrant: screen (fails), then 4 quadrants:
    // one surrounded, three empty
    Counters c = expect_warnock_same_as_zbuffer(
        scene_of(64, 64, {{{{0, 0, 0.5}, {32, 0, 0.5}, {32, 32, 0.5}, {0, 32, 0.5}}, {}}}));
    EXPECT_EQ(c.get("window_samples"), 5u);
    EXPECT_EQ(c.get("empty_windows"), 3u);
    EXPECT_EQ(c.get("fills"), 1u);
    EXPECT_EQ(c.get("face_sorts"), 1u);
}

TEST(Warnock, MatchesTheZBufferOnInterpenetratingRandomTriangles) {
    expect_warnock_same_as_zbuffer(
        scene_of(160, 120, generate_random_triangles(160, 120, 400, 120, 5)));
}

TEST(Warnock, EndsOnInterpenetratingFaces) {
    // two large quads that cut through each other along a sloped line: no surrounder is in
    // front anywhere near the cut, so windows there go down to single pixels
    Counters c = expect_warnock_same_as_zbuffer(
        scene_of(128, 96,
                 {{{{4, 4, 0.1}, {124, 4, 0.9}, {124, 92, 0.9}, {4, 92, 0.1}}, {}},
                  {{{4, 4, 0.9}, {124, 4, 0.1}, {124, 92, 0.1}, {4, 92, 0.9}}, {}}}));
    EXPECT_GT(c.get("pixel_windows"), 0u);
}

TEST(Warnock, EndsOnCyclicOverlap) {
    // three bars, each over the next and under the one before: no face is in front of the
    // others where all three meet
    Counters c = expect_warnock_same_as_zbuffer(
        scene_of(96, 96,
                 {{{{10, 20, 0.2}, {86, 20, 0.4}, {86, 32, 0.4}, {10, 32, 0.2}}, {}},
                  {{{70, 10, 0.2}, {82, 10, 0.2}, {82, 86, 0.4}, {70, 86, 0.4}}, {}},
                  {{{86, 70, 0.2}, {10, 70, 0.4}, {10, 82, 0.4}, {86, 82, 0.2}}, {}},
                  {{{14, 86, 0.2}, {14, 10, 0.4}, {26, 10, 0.4}, {26, 86, 0.2}}, {}}}));
    EXPECT_GT(c.get("window_samples"), 5u);
}

TEST(Warnock, EndsOnSubPixelFaces) {
    GeneratedPolygons tiny;
    for (int i = 0; i < 200; ++i) {
        double x = 3.3 + (i % 20) * 2.7, y = 2.1 + (i / 20) * 3.9;
        tiny.push_back({{{x, y, 0.5}, {x + 0.4, y + 0.1, 0.4}, {x + 0.2, y + 0.45, 0.6}}, {}});
    }
    Counters c = expect_warnock_same_as_zbuffer(scene_of(64, 48, std::move(tiny)));
    EXPECT_GT(c.get("pixel_windows"), 0u);
}

TEST(Warnock, EndsOnNearlyEdgeOnFaces) {
    // slivers a fraction of a pixel wide, standing almost edge-on, over a background face
    GeneratedPolygons polys{{{{0, 0, 0.9}, {64, 0, 0.9}, {64, 48, 0.9}, {0, 48, 0.9}}, {}}};
    for (int i = 0; i < 30; ++i) {
        double x = 1.7 + 2.1 * i;
        polys.push_back(
            {{{x, 1, 0.1}, {x + 0.05, 1, 0.8}, {x + 0.3, 47, 0.8}, {x + 0.25, 47, 0.1}}, {}});
    }
    expect_warnock_same_as_zbuffer(scene_of(64, 48, std::move(polys)));
}

TEST(Warnock, EndsWithHundredsOfFacesInOneWindow) {
    // 600 overlapping triangles piled into a 6 x 6 pixel corner
    GeneratedPolygons pile;
    for (auto& t : generate_random_triangles(6, 6, 600, 4, 3))
        pile.push_back(std::move(t));
    Counters c = expect_warnock_same_as_zbuffer(scene_of(64, 48, std::move(pile)));
    EXPECT_GT(c.get("face_computations"), 600u);
}

TEST(Warnock, CoplanarFacesTieToTheLowerId) {
    expect_warnock_same_as_zbuffer(
        scene_of(48, 48,
                 {{{{4, 4, 0.5}, {30, 4, 0.5}, {30, 30, 0.5}, {4, 30, 0.5}}, {}},
                  {{{10, 10, 0.5}, {44, 10, 0.5}, {44, 44, 0.5}, {10, 44, 0.5}}, {}},
                  {{{0, 0, 0.5}, {48, 0, 0.5}, {48, 48, 0.5}, {0, 48, 0.5}}, {}}}));
}

TEST(Warnock, OddSizedScreensSplitWithoutEmptyWindows) {
    Counters c = expect_warnock_same_as_zbuffer(
        scene_of(37, 11, generate_random_triangles(37, 11, 40, 20, 9)));
    EXPECT_GT(c.get("window_samples"), 0u);
}

TEST(Warnock, PerspectiveScenesMatchTheZBuffer) {
    for (const char* name : {"demo.json", "cornell_box.json"}) {
        Scene scene = load_scene(std::string(FB89_SCENES_DIR) + "/" + name);
        scene.width = 256;
        scene.height = 195;
        expect_warnock_same_as_zbuffer(scene);
    }
}

}  // namespace
}  // namespace fb89::host
