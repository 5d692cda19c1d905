// Golden: the methods that move the split (zspans, faces) against the host Z-buffer, through
// the real pipeline (method -> depth commands -> the controller's own coverage and depth test),
// on every bundled scene and the five conformance sets, with both depth words. Coverage must
// agree exactly (one coverage rule, protocol/coverage.h); ids may differ only where two faces
// lie within the fixed-point depth's tolerance (experiments/depth_agreement.h), and those
// ties are counted.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "experiments/depth_agreement.h"
#include "experiments/id_pass.h"
#include "host/methods.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"

namespace fb89 {
namespace {

std::vector<std::string> inputs() {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(FB89_SCENES_DIR))
        if (entry.path().extension() == ".json") out.push_back(entry.path().string());
    for (const char* set : {"random_large_flat", "mesh_on_centres", "fans_on_centres",
                            "ideal_two_layers", "small_sloped_interpenetrating"})
        out.push_back((std::filesystem::path(FB89_TEST_DATA_DIR) / "golden" / "conformance" /
                       (std::string(set) + ".tri"))
                          .string());
    std::sort(out.begin(), out.end());
    return out;
}

class GoldenDepthCommands : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenDepthCommands, ControllerDepthGivesTheZBuffersIdsButForCountedTies) {
    const host::Scene scene = host::load_scene(GetParam());
    host::Counters counters;
    const host::ScreenScene screen = host::project_scene(scene, host::ColorMode::FaceId, counters);
    auto zbuffer = host::make_renderer(host::Method::ZBuffer);
    const controller::Framebuffer want = experiments::id_framebuffer(scene, *zbuffer);
    for (host::Method m : {host::Method::DepthSpans, host::Method::Faces})
        for (uint32_t bits : {16u, 32u}) {
            auto renderer = host::make_renderer(m);
            const controller::Framebuffer got = experiments::id_framebuffer(scene, *renderer, bits);
            const experiments::DepthAgreement a =
                experiments::depth_agreement(screen, want, got, bits);
            const std::string label = fmt::format("{} {}-bit", host::method_info(m).name, bits);
            EXPECT_EQ(a.coverage, 0u) << label;
            EXPECT_EQ(a.wrong, 0u) << label;
            EXPECT_EQ(a.differ, a.ties + a.coverage + a.wrong) << label;
            RecordProperty(fmt::format("{}_{}_ties", host::method_info(m).name, bits),
                           std::to_string(a.ties));
        }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenDepthCommands, ::testing::ValuesIn(inputs()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                             std::string name = std::filesystem::path(param.param).stem().string();
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace
}  // namespace fb89
