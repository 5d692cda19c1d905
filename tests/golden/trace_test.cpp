// Golden checks of the ray and beam tracers on every bundled scene with mirrors (and two
// without): the beam-ray hybrid's face-id buffer and image equal the ray tracer's at named
// thresholds, its pixels are all accounted for, and where nothing reflects the ray tracer
// agrees with the Z-buffer but for pixels on the edges between faces (rays are not snapped
// to the 1/256-pixel grid).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "host/scene/scene_loader.h"
#include "host/trace/kernel_level.h"
#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using testing::render_trace;
using testing::trace_options;

constexpr int kWidth = 256, kHeight = 195;

Scene bundled(const std::string& name) {
    Scene s = load_scene(std::string(FB89_SCENES_DIR) + "/" + name);
    s.width = kWidth;
    s.height = kHeight;
    return s;
}

class GoldenTrace : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenTrace, BeamsShowWhatRaysShowAtEveryThreshold) {
    const Scene scene = bundled(GetParam());
    const auto rays = render_trace(scene, trace_options("raytrace"));
    for (double threshold : {0.0, 1.0, 100.0, double{INFINITY}}) {
        const auto beams = render_trace(scene, trace_options("beam", threshold));
        ASSERT_EQ(beams.ids, rays.ids) << GetParam() << " at threshold " << threshold;
        ASSERT_EQ(beams.pixels, rays.pixels) << GetParam() << " at threshold " << threshold;
        const auto& c = beams.stats.counters;
        EXPECT_EQ(c.get("pixels_by_beams") + c.get("pixels_by_rays"), uint64_t{kWidth} * kHeight);
        EXPECT_LE(c.get("rays"), rays.stats.counters.get("rays"))
            << "a beam-ray frame never traces more rays than the ray tracer alone";
    }
}

INSTANTIATE_TEST_SUITE_P(MirrorScenes, GoldenTrace,
                         ::testing::Values("G.json", "H.json", "I.json", "cornell_mirror.json",
                                           "cornell_box.json", "A.json"));

// Pixels whose id differs from a 4-neighbour's: where a face's edge passes.
bool on_an_edge(const std::vector<uint32_t>& ids, int x, int y) {
    const uint32_t id = ids[static_cast<size_t>(y) * kWidth + x];
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
        const int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= kWidth || ny >= kHeight) continue;
        if (ids[static_cast<size_t>(ny) * kWidth + nx] != id) return true;
    }
    return false;
}

class GoldenTraceRaster : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenTraceRaster, RaysAgreeWithTheZBufferButOnEdges) {
    const Scene scene = bundled(GetParam());
    const auto rays = render_trace(scene, trace_options("raytrace"));
    const auto zbuffer = render_trace(scene, trace_options("zbuffer"));
    uint64_t differ = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const size_t i = static_cast<size_t>(y) * kWidth + x;
            if (rays.ids[i] == zbuffer.ids[i]) continue;
            ++differ;
            EXPECT_TRUE(on_an_edge(zbuffer.ids, x, y))
                << GetParam() << ": pixel " << x << "," << y << " differs off an edge";
        }
    EXPECT_LT(differ, uint64_t{kWidth} * kHeight / 100) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(ScenesWithoutMirrors, GoldenTraceRaster,
                         ::testing::Values("cornell_box.json", "A.json", "C.json", "demo.json"));

// Every kernel level this machine runs (host/trace/kernel_level.h) makes the same frames and
// the same counts as the baseline: ids, pixels, rays, nodes visited, face tests, beams.
class GoldenTraceLevels : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenTraceLevels, EveryInstructionSetGivesTheBaselinesFramesAndCounts) {
    const Scene scene = bundled(GetParam());
    const KernelLevel was = kernel_level();
    struct Result {
        testing::Frame rays, beams;
    };
    auto run = [&](KernelLevel level) {
        set_kernel_level(level);
        return Result{render_trace(scene, trace_options("raytrace")),
                      render_trace(scene, trace_options("beam", 1.0))};
    };
    const Result base = run(KernelLevel::Baseline);
    for (KernelLevel level : supported_kernel_levels()) {
        SCOPED_TRACE(std::string(kernel_level_name(level)));
        const Result r = run(level);
        EXPECT_EQ(r.rays.ids, base.rays.ids);
        EXPECT_EQ(r.rays.pixels, base.rays.pixels);
        EXPECT_EQ(r.beams.ids, base.beams.ids);
        EXPECT_EQ(r.beams.pixels, base.beams.pixels);
        EXPECT_EQ(r.rays.stats.counters.items(), base.rays.stats.counters.items());
        EXPECT_EQ(r.beams.stats.counters.items(), base.beams.stats.counters.items());
    }
    set_kernel_level(was);
    EXPECT_GE(supported_kernel_levels().size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(MirrorScenes, GoldenTraceLevels,
                         ::testing::Values("G.json", "H.json", "I.json", "cornell_box.json"));

}  // namespace
}  // namespace fb89::host
