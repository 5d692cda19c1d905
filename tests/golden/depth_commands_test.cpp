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

#include "host/scene/scene_loader.h"
#include "tests/depth_commands_check.h"

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
    for (const testing::DepthCheck& c : testing::depth_commands_against_zbuffer(scene)) {
        const experiments::DepthAgreement& a = c.agreement;
        EXPECT_EQ(a.coverage, 0u) << c.label();
        EXPECT_EQ(a.wrong, 0u) << c.label();
        EXPECT_EQ(a.differ, a.ties + a.coverage + a.wrong) << c.label();
        RecordProperty(fmt::format("{}_{}_ties", c.method, c.bits), std::to_string(a.ties));
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
