// How a controller that tests depth itself (the depth commands, stream format version 3)
// agrees with the host Z-buffer's exact rule: face-id buffers compared pixel by pixel. Depth
// travels and is stored in fixed point (protocol/depth_fixed.h), so where two faces' exact
// depths lie within the depth word's step (plus the rounding of their planes' fixed-point
// slopes over the screen) the controller may keep the other face: those pixels are ties.
// Any other difference is a bug: a pixel covered on one side and not the other (coverage,
// which must be zero: both sides use one coverage rule), or two faces far apart in depth
// drawn the wrong way round (wrong, which must be zero too).
#pragma once

#include <cstdint>

#include "controller_sim/framebuffer.h"
#include "host/raster/screen_scene.h"

namespace fb89::experiments {

struct DepthAgreement {
    uint64_t pixels = 0;    // of the frame
    uint64_t differ = 0;    // pixels whose ids differ
    uint64_t ties = 0;      // of those, faces within `tolerance` of each other in depth
    uint64_t coverage = 0;  // of those, covered on one side only
    uint64_t wrong = 0;     // the rest: farther apart than the tolerance
    double tolerance = 0;   // in window depth
    double max_tie_dz = 0;  // the largest depth difference among the ties
    uint32_t depth_bits = 0;
    bool exact() const { return coverage == 0 && wrong == 0; }
};

// The tolerance of a depth word of `bits` on a width x height frame: its step, and half a
// unit of each plane's two slopes over the frame's width and height, for both faces.
double depth_tolerance(uint32_t bits, int width, int height);

// Compares `controller_ids` (a depth-command method's id pass) with `reference_ids` (the host
// Z-buffer's) on `scene`, the scene projected in id mode (its faces' depth planes).
DepthAgreement depth_agreement(const host::ScreenScene& scene,
                               const controller::Framebuffer& reference_ids,
                               const controller::Framebuffer& controller_ids, uint32_t depth_bits);

}  // namespace fb89::experiments
