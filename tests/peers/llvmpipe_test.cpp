// Peers: Mesa's llvmpipe, driven live through OSMesa (bench/peers), renders the same
// face-id buffers as our Z-buffer (and the hybrid, when built): no coverage mismatch and
// no id mismatch beyond depth ties (planes within 2^-20 at a pixel centre). First, the
// harness's own conventions (NDC, row order, colours) are checked against the stored
// llvmpipe fixtures of tests/golden/conformance/.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "bench/peers/exactness.h"
#include "bench/peers/llvmpipe_renderer.h"
#include "bench/peers/peer_scenes.h"
#include "bench/peers/side_by_side.h"
#include "controller_sim/png_io.h"

namespace fb89::peers {
namespace {

const std::string kConformance = std::string(FB89_TEST_DATA_DIR) + "/golden/conformance/";

std::vector<uint32_t> render_with_llvmpipe(const host::ScreenScene& scene) {
    static LlvmpipeRenderer llvmpipe;  // one context per process
    llvmpipe.upload(scene);
    llvmpipe.render();
    return llvmpipe.face_ids();
}

// Every method this build has, against llvmpipe.
void expect_exact_against_llvmpipe(const PeerScene& scene) {
    const std::vector<uint32_t> theirs = render_with_llvmpipe(scene.screen);
    for (const char* method : {"zbuffer", "hybrid"}) {
        std::vector<uint32_t> ours;
        try {
            ours = our_face_ids(scene.screen, method);
        } catch (const std::invalid_argument&) {
            continue;  // not in this build
        }
        Exactness e = compare_face_ids(scene.screen, ours, theirs);
        EXPECT_EQ(e.coverage_mismatches, 0u) << scene.name << ", " << method << ": " << e.first;
        EXPECT_EQ(e.real_mismatches, 0u) << scene.name << ", " << method << ": " << e.first;
    }
}

TEST(PeerLlvmpipe, LiveRenderingReproducesTheStoredConformanceFixtures) {
    for (const char* name : {"random_large_flat", "mesh_on_centres", "fans_on_centres",
                             "ideal_two_layers", "small_sloped_interpenetrating"}) {
        PeerScene scene = file_scene(kConformance + name + ".tri");
        const std::vector<uint32_t> live = render_with_llvmpipe(scene.screen);
        controller::PngImage want = controller::read_png(kConformance + name + ".ids.png");
        ASSERT_EQ(static_cast<int>(want.width), scene.screen.width);
        ASSERT_EQ(static_cast<int>(want.height), scene.screen.height);
        uint64_t differ = 0;
        for (size_t i = 0; i < live.size(); ++i) {
            const uint8_t* w = &want.pixels[i * want.channels];
            differ += live[i] != ((uint32_t{w[0]} << 16) | (uint32_t{w[1]} << 8) | w[2]);
        }
        EXPECT_EQ(differ, 0u) << name;
    }
}

TEST(PeerLlvmpipe, ConformanceRandomLargeFlatIsExact) {
    expect_exact_against_llvmpipe(file_scene(kConformance + "random_large_flat.tri"));
}

TEST(PeerLlvmpipe, ThousandRandomSlopedTrianglesAreExactUpToDepthTies) {
    expect_exact_against_llvmpipe(random_onscreen_triangles(1024, 780, 1000, 700, 1989));
}

TEST(PeerLlvmpipe, IdealSceneTwoLayersIsExact) {
    expect_exact_against_llvmpipe(ideal_scene(1024, 780, 2, 1024));
}

TEST(PeerLlvmpipe, SceneAIsExact) {
    expect_exact_against_llvmpipe(file_scene(std::string(FB89_SCENES_DIR) + "/A.json"));
}

}  // namespace
}  // namespace fb89::peers
