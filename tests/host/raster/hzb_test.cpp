// The hierarchical Z-buffer (host/raster/hzb.h): the Z-buffer's commands exactly, with exact
// ties arriving out of id order, and on the ideal scene at depth complexity 16 the culling
// that is its point; never more depth tests than the Z-buffer on any bundled scene.
#include "host/raster/hzb.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "host/raster/screen_setup.h"
#include "host/raster/zbuffer.h"
#include "host/scene/generators.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"
#include "tests/host/raster/raster_test_util.h"

namespace fb89::host {
namespace {

struct Rendered {
    std::vector<protocol::Command> commands;
    Counters counters;
};

Rendered run(Renderer& r, const ScreenScene& s) {
    protocol::MemoryBuffer buffer;
    HostStats stats;
    r.setup(s);
    r.render(s, buffer, stats);
    return {buffer.commands(), stats.counters};
}

// The Z-buffer's run and the hierarchical Z-buffer's of one scene.
struct Both {
    Rendered z, h;
};
Both both(const ScreenScene& s) {
    ZBuffer zbuffer;
    HierarchicalZBuffer hzb;
    return {run(zbuffer, s), run(hzb, s)};
}

TEST(Hzb, TheIdealSceneAtDepthComplexity16IsCulledToItsFrontLayer) {
    const int layers = 16, cells = 8;  // 64 faces a layer, 1,024 in all
    Counters setup;
    const ScreenScene s =
        project_scene(ideal_scene(256, 256, layers, 32, 32, 0.5), ColorMode::FaceId, setup);
    const auto [z, h] = both(s);
    EXPECT_EQ(h.commands, z.commands);
    // the front layer is drawn and covers the screen's every centre it can; of the 15 layers
    // behind it, faces and whole nodes are culled
    const uint64_t faces = s.faces.size();
    EXPECT_EQ(z.counters.get("faces_rasterised"), faces);
    EXPECT_GE(h.counters.get("faces_rasterised"), static_cast<uint64_t>(cells * cells));
    EXPECT_LE(h.counters.get("faces_rasterised"), faces / 4);
    EXPECT_GT(h.counters.get("hzb_nodes_culled") + h.counters.get("hzb_faces_culled"), 0u);
    EXPECT_LE(h.counters.get("depth_tests") * 4, z.counters.get("depth_tests"));
    EXPECT_EQ(h.counters.get("spans"), z.counters.get("spans"));
}

// Where it would lose (depth complexity 1: nothing to cull), it does not use the hierarchy:
// every band's faces' rectangles cover it less than kHierarchyFromCover times, so each band
// is drawn as the Z-buffer draws it, with no pyramid test, every depth test the Z-buffer makes
// and no more, and the same commands.
TEST(Hzb, AtDepthComplexityOneEveryBandIsDrawnWithoutThePyramidAndExactly) {
    Counters setup;
    const ScreenScene s =
        project_scene(ideal_scene(256, 256, 1, 16, 16, 0.5), ColorMode::FaceId, setup);
    const auto [z, h] = both(s);
    EXPECT_EQ(h.commands, z.commands);
    EXPECT_EQ(h.counters.get("depth_tests"), z.counters.get("depth_tests"));
    EXPECT_EQ(h.counters.get("faces_rasterised"), s.faces.size());
    const uint64_t bands =
        (256 + HierarchicalZBuffer::kBandRows - 1) / HierarchicalZBuffer::kBandRows;
    EXPECT_EQ(h.counters.get("hzb_bands_direct"), bands);
    EXPECT_EQ(h.counters.get("hzb_bands_hierarchical"), 0u);
    EXPECT_EQ(h.counters.get("hzb_pyramid_tests"), 0u);
    EXPECT_EQ(h.counters.get("hzb_face_tests"), 0u);
}

// Where the hierarchy pays, every band uses it: at depth complexity 16 each band's faces
// cover it 16 times over.
TEST(Hzb, AtDepthComplexity16EveryBandUsesThePyramid) {
    Counters setup;
    const ScreenScene s =
        project_scene(ideal_scene(256, 256, 16, 16, 16, 0.5), ColorMode::FaceId, setup);
    const auto [z, h] = both(s);
    EXPECT_EQ(h.commands, z.commands);
    const uint64_t bands =
        (256 + HierarchicalZBuffer::kBandRows - 1) / HierarchicalZBuffer::kBandRows;
    EXPECT_EQ(h.counters.get("hzb_bands_hierarchical"), bands);
    EXPECT_EQ(h.counters.get("hzb_bands_direct"), 0u);
    EXPECT_GT(h.counters.get("hzb_faces_culled") + h.counters.get("hzb_nodes_culled"), 0u);
}

TEST(Hzb, ExactTiesGoToTheLowerIdWhateverOrderTheOctreeTakesThem) {
    // 400 random triangles, all in one plane: every overlap is an exact tie
    Scene scene = testing::random_scene(192, 144, 400, 600, 7);
    for (Face& f : scene.faces)
        for (glm::dvec3& v : f.vertices)
            v.z = 0.5;
    Counters setup;
    const ScreenScene s = project_scene(scene, ColorMode::FaceId, setup);
    const auto [z, h] = both(s);
    EXPECT_EQ(h.commands, z.commands);
    EXPECT_GT(h.counters.get("depth_tests"), h.counters.get("pixels_written"));  // ties met
}

TEST(Hzb, SlopedInterpenetratingTrianglesGiveTheZBuffersCommands) {
    for (uint64_t seed : {1u, 2u, 3u}) {
        Counters setup;
        const ScreenScene s = project_scene(testing::random_scene(320, 240, 2000, 300, seed),
                                            ColorMode::FaceId, setup);
        const auto [z, h] = both(s);
        EXPECT_EQ(h.commands, z.commands) << "seed " << seed;
    }
}

TEST(Hzb, NeverTestsMoreThanTheZBufferOnABundledScene) {
    for (const char* name : {"A.json", "C.json", "E.json", "F.json", "demo.json"}) {
        SCOPED_TRACE(name);
        Scene scene = load_scene(std::filesystem::path(FB89_SCENES_DIR) / name);
        Counters setup;
        const ScreenScene s = project_scene(scene, ColorMode::FaceId, setup);
        const auto [z, h] = both(s);
        EXPECT_EQ(h.commands, z.commands);
        EXPECT_LE(h.counters.get("depth_tests"), z.counters.get("depth_tests"));
        EXPECT_LE(h.counters.get("pixels_written"), z.counters.get("pixels_written"));
        EXPECT_LE(h.counters.get("faces_rasterised"), z.counters.get("faces_rasterised"));
        EXPECT_LE(h.counters.get("hzb_faces_culled"), h.counters.get("hzb_face_tests"));
    }
}

TEST(Hzb, AnEmptySceneSendsNothing) {
    Scene scene;
    scene.projection = Projection::Screen;
    scene.width = 64;
    scene.height = 48;
    Counters setup;
    const ScreenScene s = project_scene(scene, ColorMode::FaceId, setup);
    HierarchicalZBuffer hzb;
    const Rendered h = run(hzb, s);
    EXPECT_TRUE(h.commands.empty());
    EXPECT_EQ(h.counters.get("hzb_nodes_visited"), 0u);
}

}  // namespace
}  // namespace fb89::host
