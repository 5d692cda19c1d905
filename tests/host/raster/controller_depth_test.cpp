// The depth commands' fixed-point arithmetic pushed where it is weakest: the longest spans,
// the steepest slopes, faces against the far and the near plane, faces that run far past the
// screen (a FACE's anchor), with both depth words. Whatever the controller decides must be
// the host Z-buffer's ids or a tie within the proven bound (experiments/depth_agreement.h):
// never a pixel covered differently, never a wrong one.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include <fmt/format.h>

#include "experiments/depth_agreement.h"
#include "host/scene/scene_loader.h"
#include "tests/depth_commands_check.h"

namespace fb89 {
namespace {

// Every depth-command method with both words against the Z-buffer; returns the ties.
uint64_t expect_no_wrong_pixel(const host::Scene& scene, const std::string& what) {
    uint64_t ties = 0;
    for (const testing::DepthCheck& c : testing::depth_commands_against_zbuffer(scene)) {
        EXPECT_EQ(c.agreement.coverage, 0u) << what << ": " << c.label();
        EXPECT_EQ(c.agreement.wrong, 0u) << what << ": " << c.label();
        ties += c.agreement.ties;
    }
    return ties;
}

// A `.tri` line: a triangle of id `id`, its points (x, y, window depth).
std::string tri(uint32_t id, const double (&p)[9]) {
    return fmt::format("{} {} {} {} {} {} {} {} {} {}\n", id, p[0], p[1], p[2], p[3], p[4], p[5],
                       p[6], p[7], p[8]);
}

// Pairs of full-width bands, each a quad (two triangles of one id) whose depth runs across
// the frame from z0 to z1, its partner (drawn after it) `gap` in front of it: the longest
// spans there are, at a depth near `base`, the gaps from well inside a 16-bit step to a few
// steps.
std::string long_band_pairs(double base, double run, std::mt19937_64& rng) {
    std::string text;
    uint32_t id = 0, triangles = 0;
    std::uniform_real_distribution<double> unit(0, 1);
    const double step16 = experiments::depth_tolerance(16, 1024, 780);
    for (int band = 0; band < 24; ++band) {
        const double y0 = band * 32.25, y1 = y0 + 31.5;
        const double z0 = base + run * unit(rng), z1 = base + run * unit(rng);
        for (int layer = 0; layer < 2; ++layer) {
            const double gap = layer == 0 ? 0 : step16 * (0.05 + 3 * unit(rng));
            const double a = z0 - gap, b = z1 - gap;
            text += tri(id, {-40.0, y0, a, 1064.0, y0, b, 1064.0, y1, b});
            text += tri(id, {-40.0, y0, a, 1064.0, y1, b, -40.0, y1, a});
            triangles += 2;
            ++id;
        }
    }
    return fmt::format("1024 780 {}\n", triangles) + text;
}

TEST(ControllerDepthArithmetic, TheLongestSpansNearTheFarPlaneAreExactOrTied) {
    std::mt19937_64 rng(1);
    const host::Scene scene = host::parse_tri(long_band_pairs(0.9995, 0.0004, rng), "far");
    EXPECT_GT(expect_no_wrong_pixel(scene, "far bands"), 0u);
}

TEST(ControllerDepthArithmetic, TheLongestSpansAtMidDepthAreExactOrTied) {
    std::mt19937_64 rng(2);
    const host::Scene scene = host::parse_tri(long_band_pairs(0.3, 0.2, rng), "mid");
    expect_no_wrong_pixel(scene, "mid bands");
}

// Faces that run past the near and the far plane (clipped there: Z at their edge is 0 or
// kDepthOne) and far past the screen's sides (a FACE's anchor must stay on screen).
TEST(ControllerDepthArithmetic, FacesClippedAtBothPlanesAndFarOffScreenHaveNoWrongPixel) {
    std::string text;
    uint32_t n = 0;
    for (int i = 0; i < 12; ++i) {
        const double y0 = i * 64.0 + 2, y1 = y0 + 60;
        const double lean = 1e-6 * i;
        // from in front of the near plane to behind the far one, across 8,000 pixels
        text += tri(2 * i, {-4000.0, y0, -0.2, 4000.0, y0, 1.3, 4000.0, y1, 1.3 + lean});
        text += tri(2 * i, {-4000.0, y0, -0.2, 4000.0, y1, 1.3 + lean, -4000.0, y1, -0.2});
        // its partner a hair behind it
        const double gap = 2e-5 * (i % 4);
        text += tri(2 * i + 1,
                    {-4000.0, y0, -0.2 + gap, 4000.0, y0, 1.3 + gap, 4000.0, y1, 1.3 + lean + gap});
        text += tri(2 * i + 1, {-4000.0, y0, -0.2 + gap, 4000.0, y1, 1.3 + lean + gap, -4000.0, y1,
                                -0.2 + gap});
        n += 4;
    }
    const host::Scene scene = host::parse_tri(fmt::format("1024 780 {}\n", n) + text, "planes");
    expect_no_wrong_pixel(scene, "clipped at both planes");
}

// Slivers whose depth climbs from 0 to 1 over a few pixels (slopes up to and past the 8 a
// pixel a 32-bit slope carries) crossing wide, nearly flat faces.
TEST(ControllerDepthArithmetic, TheSteepestSlopesCrossingFlatFacesHaveNoWrongPixel) {
    std::string text;
    uint32_t n = 0, id = 0;
    for (int i = 0; i < 16; ++i) {
        const double x = 40 + i * 60.0, width = 0.1 + 0.5 * i;  // depth 0 -> 1 over `width`
        text += tri(id, {x, 10.0, 0.0, x + width, 10.0, 1.0, x + width, 770.0, 1.0});
        text += tri(id++, {x, 10.0, 0.0, x + width, 770.0, 1.0, x, 770.0, 0.0});
        n += 2;
    }
    for (int i = 0; i < 8; ++i) {
        const double y0 = 20 + i * 95.0, z = 0.05 + 0.11 * i;
        text += tri(id, {0.0, y0, z, 1024.0, y0, z + 1e-4, 1024.0, y0 + 90, z + 2e-4});
        text += tri(id++, {0.0, y0, z, 1024.0, y0 + 90, z + 2e-4, 0.0, y0 + 90, z + 1e-4});
        n += 2;
    }
    const host::Scene scene = host::parse_tri(fmt::format("1024 780 {}\n", n) + text, "steep");
    expect_no_wrong_pixel(scene, "steep slivers");
}

// A ship's deck in perspective: long planks from behind the camera to the horizon, three
// layers a few millimetres apart (the near plane clips every plank).
TEST(ControllerDepthArithmetic, PlanksFromBehindTheCameraToTheHorizonHaveNoWrongPixel) {
    std::string objects;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int layer = 0; layer < 3; ++layer)
        for (int i = 0; i < 40; ++i) {
            const double x0 = -8 + i * 0.4, y = layer * 0.003;
            objects += fmt::format(
                "{}{{\"polygon\": [[{},{},-300],[{},{},-300],[{},{},20],[{},{},20]],"
                "\"material\": {{\"color\": [{},{},{}]}}}}",
                objects.empty() ? "" : ",", x0, y, x0 + 0.4, y, x0 + 0.4, y, x0, y, unit(rng),
                unit(rng), unit(rng));
        }
    const std::string json = fmt::format(
        R"({{"camera": {{"eye": [0, 1.5, 5], "look_at": [0, 0.5, -20], "up": [0, 1, 0],
             "fovy": 60, "near": 0.05, "far": 300}},
            "image": {{"width": 1024, "height": 780}}, "background": [0, 0, 0],
            "light": {{"direction": [0, -1, 0], "ambient": 0.3}}, "objects": [{}]}})",
        objects);
    const host::Scene scene = host::parse_scene_json(json, "deck", ".");
    EXPECT_GT(expect_no_wrong_pixel(scene, "deck"), 0u);
}

}  // namespace
}  // namespace fb89
