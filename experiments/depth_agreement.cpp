#include "experiments/depth_agreement.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include "host/raster/depth.h"
#include "host/scene/projection.h"
#include "protocol/depth_fixed.h"

namespace fb89::experiments {

double depth_tolerance(uint32_t bits, int width, int height) {
    // each face: its Z rounded (half a unit) and each slope rounded (half a unit a pixel)
    // over at most the frame's width and height from its reference pixel
    const double rounding = 0.5 * (1 + width + height) / protocol::kDepthOne;
    return protocol::depth_step(bits) + 2 * rounding;
}

DepthAgreement depth_agreement(const host::ScreenScene& scene,
                               const controller::Framebuffer& reference_ids,
                               const controller::Framebuffer& controller_ids, uint32_t depth_bits) {
    if (reference_ids.width() != controller_ids.width() ||
        reference_ids.height() != controller_ids.height())
        throw std::invalid_argument("depth_agreement: the two id buffers differ in size");
    // each id's plane (a face's pieces share it)
    std::vector<const host::DepthPlane*> plane(scene.face_count + 1, nullptr);
    for (const host::ScreenFace& f : scene.faces)
        if (f.id < scene.face_count && !plane[f.id + 1]) plane[f.id + 1] = &f.depth;
    DepthAgreement a;
    a.depth_bits = depth_bits;
    a.tolerance = depth_tolerance(depth_bits, scene.width, scene.height);
    const uint32_t w = reference_ids.width(), h = reference_ids.height();
    a.pixels = uint64_t{w} * h;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const uint32_t want = host::face_id_from_color(reference_ids.pixel(x, y));
            const uint32_t got = host::face_id_from_color(controller_ids.pixel(x, y));
            if (want == got) continue;
            ++a.differ;
            if (want == 0 || got == 0 || want >= plane.size() || got >= plane.size() ||
                !plane[want] || !plane[got]) {
                ++a.coverage;
                continue;
            }
            const int px = static_cast<int>(x), py = static_cast<int>(y);
            const double dz = std::abs(host::depth_at(*plane[want], px, py) -
                                       host::depth_at(*plane[got], px, py));
            if (dz <= a.tolerance) {
                ++a.ties;
                a.max_tie_dz = std::max(a.max_tie_dz, dz);
            } else {
                ++a.wrong;
            }
        }
    return a;
}

}  // namespace fb89::experiments
