// Golden: the five conformance triangle sets render, through the real pipeline (Z-buffer
// -> command stream -> simulated controller), to the face-id buffers Mesa's llvmpipe
// renders for them, pixel for pixel (tests/golden/conformance/README.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "host/methods.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"

namespace fb89 {
namespace {

struct Mismatch {
    long long pixels = 0;    // id differs
    long long coverage = 0;  // one side is background, the other not
    std::string first;
};

Mismatch compare_with_fixture(const std::string& name, host::Method method) {
    const std::string base =
        (std::filesystem::path(FB89_TEST_DATA_DIR) / "golden" / "conformance" / name).string();
    host::Scene scene = host::load_scene(base + ".tri");
    host::HostStats stats;
    host::ScreenScene ids = host::project_scene(scene, host::ColorMode::FaceId, stats.counters);
    auto renderer = host::make_renderer(method);
    renderer->setup(ids);
    protocol::MemoryBuffer commands;
    host::render_frame(*renderer, ids, commands, stats);
    controller::Controller ctl(controller::load_profile("ideal"));
    commands.replay_into(ctl);

    controller::PngImage want = controller::read_png(base + ".ids.png");
    const controller::Framebuffer& fb = ctl.framebuffer();
    EXPECT_EQ(want.width, fb.width());
    EXPECT_EQ(want.height, fb.height());
    Mismatch m;
    for (uint32_t y = 0; y < want.height; ++y) {
        for (uint32_t x = 0; x < want.width; ++x) {
            const uint8_t* w =
                &want.pixels[(static_cast<size_t>(y) * want.width + x) * want.channels];
            protocol::Rgb got = fb.pixel(x, y);
            uint32_t want_id = (uint32_t{w[0]} << 16) | (uint32_t{w[1]} << 8) | w[2];
            uint32_t got_id = host::face_id_from_color(got);
            if (want_id == got_id) continue;
            if (m.pixels++ == 0)
                m.first = fmt::format("({}, {}): llvmpipe id+1 {}, ours {}", x, y, want_id, got_id);
            m.coverage += (want_id == 0) != (got_id == 0);
        }
    }
    return m;
}

class GoldenConformance : public ::testing::TestWithParam<const char*> {};

TEST_P(GoldenConformance, FaceIdBufferMatchesLlvmpipePixelForPixel) {
    Mismatch m = compare_with_fixture(GetParam(), host::Method::ZBuffer);
    EXPECT_EQ(m.coverage, 0) << "coverage mismatches; first: " << m.first;
    EXPECT_EQ(m.pixels, 0) << "id mismatches; first: " << m.first;
}

// The hierarchical Z-buffer culls conservatively and keeps the tie rule: the same ids.
TEST_P(GoldenConformance, HierarchicalZBufferMatchesLlvmpipePixelForPixel) {
    Mismatch m = compare_with_fixture(GetParam(), host::Method::Hzb);
    EXPECT_EQ(m.coverage, 0) << "coverage mismatches; first: " << m.first;
    EXPECT_EQ(m.pixels, 0) << "id mismatches; first: " << m.first;
}

INSTANTIATE_TEST_SUITE_P(Llvmpipe, GoldenConformance,
                         ::testing::Values("random_large_flat", "mesh_on_centres",
                                           "fans_on_centres", "ideal_two_layers",
                                           "small_sloped_interpenetrating"));

}  // namespace
}  // namespace fb89
