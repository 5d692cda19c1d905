// The Warnock/Z-buffer hybrid: Expr. 3.1 as implemented, the two extremes of the
// threshold, the Z-buffer's face-id buffer at every threshold, and the approximate mode's
// bounded error.
#include "host/raster/hybrid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "host/model/analytic_model.h"
#include "host/raster/screen_setup.h"
#include "host/scene/generators.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"
#include "tests/host/raster/raster_test_util.h"

namespace fb89::host {
namespace {

ScreenScene scene_screen(const char* name, ColorMode mode) {
    Scene scene = load_scene(std::filesystem::path(FB89_SCENES_DIR) / name);
    Counters counters;
    return project_scene(scene, mode, counters);
}

std::vector<protocol::Command> commands_of(Renderer& r, const ScreenScene& s,
                                           Counters* c = nullptr) {
    protocol::MemoryBuffer buffer;
    HostStats stats;
    r.setup(s);
    r.render(s, buffer, stats);
    if (c) *c = stats.counters;
    return buffer.commands();
}

std::vector<uint32_t> ids_from_commands(const std::vector<protocol::Command>& commands,
                                        const ScreenScene& s) {
    return testing::ids_from_commands(commands, s.width, s.height);
}

TEST(Hybrid, Expr31FollowsThePaperAndStatedConventions) {
    // square windows with F_w > D: the paper's Expr. 3.1 exactly
    EXPECT_DOUBLE_EQ(expr_3_1_cost(64, 4, 32 * 32), model::expr_3_1(64, 4, 32));
    // F_w <= D: the sorting term is 0, leaving F_w / E_w^2
    EXPECT_DOUBLE_EQ(expr_3_1_cost(3, 4, 100), 0.03);
    // non-square windows: E_w^2 is the area
    EXPECT_DOUBLE_EQ(expr_3_1_cost(16, 1, 8 * 32), (16 * 2 + 16) / 256.0);
    EXPECT_EQ(expr_3_1_cost(0, 1, 100), 0.0);
}

TEST(Hybrid, ThresholdZeroIsThePureZBuffer) {
    ScreenScene s = scene_screen("C.json", ColorMode::FaceId);
    ZBuffer zbuffer;
    HybridOptions o;
    o.threshold = 0;
    Hybrid hybrid(o);
    Counters c;
    EXPECT_EQ(commands_of(hybrid, s, &c), commands_of(zbuffer, s));
    EXPECT_EQ(c.get("hybrid_pixels_warnock"), 0u);
    EXPECT_EQ(c.get("window_samples"), 0u);
}

TEST(Hybrid, InfiniteThresholdIsPureWarnock) {
    ScreenScene s = scene_screen("B.json", ColorMode::FaceId);
    Warnock warnock;
    HybridOptions o;
    o.threshold = std::numeric_limits<double>::infinity();
    Hybrid hybrid(o);
    Counters c;
    EXPECT_EQ(commands_of(hybrid, s, &c), commands_of(warnock, s));
    EXPECT_EQ(c.get("hybrid_pixels_zbuffer"), 0u);
}

TEST(Hybrid, EveryThresholdGivesTheZBuffersIds) {
    ScreenScene s = scene_screen("D.json", ColorMode::FaceId);
    ZBuffer zbuffer;
    const auto want = ids_from_commands(commands_of(zbuffer, s), s);
    for (double t : {1e-4, 1e-3, 0.01, 0.04, 0.2, 1.0}) {
        for (DepthEstimate d : {DepthEstimate::Window, DepthEstimate::Scene}) {
            HybridOptions o;
            o.threshold = t;
            o.depth = d;
            Hybrid hybrid(o);
            Counters c;
            EXPECT_EQ(ids_from_commands(commands_of(hybrid, s, &c), s), want) << "threshold " << t;
            EXPECT_EQ(c.get("hybrid_pixels_zbuffer") + c.get("hybrid_pixels_warnock"),
                      static_cast<uint64_t>(s.width) * s.height);
        }
    }
}

TEST(Hybrid, HandsOverMoreOfTheScreenAsTheThresholdFalls) {
    ScreenScene s = scene_screen("A.json", ColorMode::Shaded);
    uint64_t previous = 0;
    for (double t : {1.0, 0.1, 0.01, 0.001, 0.0}) {
        HybridOptions o;
        o.threshold = t;
        Hybrid hybrid(o);
        Counters c;
        commands_of(hybrid, s, &c);
        EXPECT_GE(c.get("hybrid_pixels_zbuffer"), previous) << "threshold " << t;
        previous = c.get("hybrid_pixels_zbuffer");
    }
    EXPECT_EQ(previous, static_cast<uint64_t>(s.width) * s.height);
}

TEST(Hybrid, ApproximateFillsMissAtMostEpsilonOfTheirWindows) {
    ScreenScene s = scene_screen("C.json", ColorMode::FaceId);
    ZBuffer zbuffer;
    const auto want = ids_from_commands(commands_of(zbuffer, s), s);
    Warnock exact_k({WindowTest::Area, {16, 0.0}});
    EXPECT_EQ(ids_from_commands(commands_of(exact_k, s), s), want) << "epsilon 0 must stay exact";
    Warnock approx({WindowTest::Area, {16, 0.05}});
    Counters c;
    const auto got = ids_from_commands(commands_of(approx, s, &c), s);
    uint64_t wrong = 0;
    for (size_t i = 0; i < got.size(); ++i)
        wrong += got[i] != want[i];
    EXPECT_GT(c.get("approximate_fills"), 0u);
    EXPECT_GT(wrong, 0u);
    // wrong pixels lie only in filled windows, at most 5% of each
    EXPECT_LE(wrong, static_cast<uint64_t>(0.05 * static_cast<double>(c.get("filled_pixels"))));
}

}  // namespace
}  // namespace fb89::host
