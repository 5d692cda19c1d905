#include "experiments/depth_agreement.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "controller_sim/controller.h"
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
    struct Pair {
        uint64_t pixels = 0;
        double dz = 0;
    };
    std::map<std::pair<uint32_t, uint32_t>, Pair> pairs;  // ids + 1, the nearer first
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
                const bool want_nearer =
                    host::depth_at(*plane[want], px, py) <= host::depth_at(*plane[got], px, py);
                auto& pair = pairs[{want_nearer ? want : got, want_nearer ? got : want}];
                if (pair.pixels++ == 0) pair.dz = dz;
            } else {
                ++a.wrong;
            }
        }
    for (const auto& [ids, pair] : pairs)
        if (pair.pixels > a.tie_pair_pixels) {
            a.tie_near = ids.first - 1;
            a.tie_far = ids.second - 1;
            a.tie_pair_pixels = pair.pixels;
            a.tie_pair_dz = pair.dz;
        }
    return a;
}

std::string z_fighting_note(const DepthAgreement& a) {
    const auto pixels = static_cast<double>(a.pixels), ties = static_cast<double>(a.ties);
    if (a.pixels == 0 || ties <= kZFightingShare * pixels) return "";
    return fmt::format(
        "z-fighting: {} pixels ({:.2f}% of the frame) tie in the {}-bit depth word, whose step "
        "is {:.2g} in window depth: the controller may keep either face there; the pair tying "
        "most is faces {} and {} ({} pixels, {:.2g} apart in depth where they first tie). A "
        "32-bit word (\"depth_bits\": 32 in a profile) or a farther near plane tells them apart",
        controller::grouped(a.ties), 100.0 * ties / pixels, a.depth_bits,
        protocol::depth_step(a.depth_bits), a.tie_near, a.tie_far,
        controller::grouped(a.tie_pair_pixels), a.tie_pair_dz);
}

}  // namespace fb89::experiments
