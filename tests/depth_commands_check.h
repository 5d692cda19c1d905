// What the depth-command tests share: a scene through every method that sends depth commands
// (zspans, faces) with both depth words, each face-id buffer held to the host Z-buffer's
// (experiments/depth_agreement.h), labelled for the test's messages.
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

#include "experiments/depth_agreement.h"
#include "experiments/id_pass.h"
#include "host/methods.h"
#include "host/raster/screen_setup.h"

namespace fb89::testing {

struct DepthCheck {
    std::string method;  // its name
    uint32_t bits = 0;   // the depth word
    experiments::DepthAgreement agreement;
    std::string label() const { return fmt::format("{} {}-bit", method, bits); }
};

inline std::vector<DepthCheck> depth_commands_against_zbuffer(const host::Scene& scene) {
    host::Counters counters;
    const host::ScreenScene screen = host::project_scene(scene, host::ColorMode::FaceId, counters);
    auto zbuffer = host::make_renderer(host::Method::ZBuffer);
    const controller::Framebuffer want = experiments::id_framebuffer(scene, *zbuffer);
    std::vector<DepthCheck> out;
    for (host::Method m : {host::Method::DepthSpans, host::Method::Faces})
        for (uint32_t bits : {16u, 32u}) {
            auto renderer = host::make_renderer(m);
            const controller::Framebuffer got = experiments::id_framebuffer(scene, *renderer, bits);
            out.push_back({std::string(host::method_info(m).name), bits,
                           experiments::depth_agreement(screen, want, got, bits)});
        }
    return out;
}

}  // namespace fb89::testing
