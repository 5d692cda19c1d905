// Golden: every raster method produces the same face-id buffer and the same image on every
// bundled scene, through the real pipeline (method -> command stream -> controller). The
// methods share one coverage and depth rule, so any difference is a bug, not a tolerance.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "experiments/id_pass.h"
#include "host/methods.h"
#include "host/scene/projection.h"
#include "host/scene/scene_loader.h"

namespace fb89 {
namespace {

std::vector<std::string> bundled_scenes() {
    std::vector<std::string> out;
    for (const auto& entry : std::filesystem::directory_iterator(FB89_SCENES_DIR))
        if (entry.path().extension() == ".json") out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}

struct Frame {
    std::vector<uint8_t> pixels;
    uint64_t checksum = 0;
};

Frame render(const host::Scene& scene, host::ColorMode mode, const host::MethodOptions& options) {
    auto renderer = host::make_renderer(options);
    const controller::Framebuffer fb = experiments::framebuffer_of(scene, mode, *renderer);
    const auto px = fb.pixels();
    return {{px.begin(), px.end()}, fb.checksum()};
}

host::MethodOptions method(host::Method m, host::WindowTest test = host::WindowTest::Area) {
    host::MethodOptions o(m);
    o.warnock.window_test = test;
    return o;
}

// Pixels that differ, and the first of them, for a readable failure.
std::string difference(const Frame& want, const Frame& got, int width) {
    size_t count = 0, first = 0;
    for (size_t i = 0; i < want.pixels.size(); i += 3)
        if (want.pixels[i] != got.pixels[i] || want.pixels[i + 1] != got.pixels[i + 1] ||
            want.pixels[i + 2] != got.pixels[i + 2])
            if (count++ == 0) first = i / 3;
    if (count == 0) return "";
    return std::to_string(count) + " pixels differ, first at (" + std::to_string(first % width) +
           ", " + std::to_string(first / width) + ")";
}

class GoldenMethods : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenMethods, EveryMethodAndHybridThresholdGivesTheZBuffersIdsAndImage) {
    host::Scene scene = host::load_scene(std::string(FB89_SCENES_DIR) + "/" + GetParam());
    const host::MethodOptions reference(host::Method::ZBuffer);
    const Frame ids = render(scene, host::ColorMode::FaceId, reference);
    const Frame image = render(scene, host::ColorMode::Shaded, reference);
    std::vector<host::MethodOptions> methods{
        method(host::Method::ScanLine), method(host::Method::Warnock),
        method(host::Method::Warnock, host::WindowTest::Centres), method(host::Method::Hzb)};
    for (double threshold : {0.0, 0.003, 0.04, 0.5}) {
        host::MethodOptions hybrid = method(host::Method::Hybrid);
        hybrid.hybrid.threshold = threshold;
        methods.push_back(hybrid);
    }
    host::MethodOptions hybrid_centres = method(host::Method::Hybrid, host::WindowTest::Centres);
    hybrid_centres.hybrid.threshold = 0.01;
    hybrid_centres.hybrid.depth = host::DepthEstimate::Scene;
    methods.push_back(hybrid_centres);
    for (const host::MethodOptions& o : methods) {
        const std::string label =
            std::string(host::method_info(o.method).name) + " " +
            host::to_string(o.warnock.window_test) +
            (o.method == host::Method::Hybrid ? " " + std::to_string(o.hybrid.threshold) : "");
        Frame got_ids = render(scene, host::ColorMode::FaceId, o);
        EXPECT_EQ(got_ids.checksum, ids.checksum)
            << label << " ids: " << difference(ids, got_ids, scene.width);
        Frame got_image = render(scene, host::ColorMode::Shaded, o);
        EXPECT_EQ(got_image.checksum, image.checksum)
            << label << " image: " << difference(image, got_image, scene.width);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenMethods, ::testing::ValuesIn(bundled_scenes()),
                         [](const auto& param_info) {
                             std::string name =
                                 param_info.param.substr(0, param_info.param.find('.'));
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

}  // namespace
}  // namespace fb89
