// How a controller that tests depth itself (the depth commands, stream format version 3)
// agrees with the host Z-buffer's exact rule: face-id buffers compared pixel by pixel. Depth
// travels and is stored in fixed point (protocol/depth_fixed.h), so where two faces' exact
// depths lie within the depth word's step (plus the rounding of their planes' fixed-point
// slopes over the screen) the controller may keep the other face: those pixels are ties.
// Any other difference is a bug: a pixel covered on one side and not the other (coverage,
// which must be zero: both sides use one coverage rule), or two faces far apart in depth
// drawn the wrong way round (wrong, which must be zero too).
//
// The bound, in units of Z (kDepthOne a window depth of 1). Each command's Z is the exact
// depth at an anchor pixel, rounded (off by at most 1/2), and each slope is rounded (off by
// at most 1/2 a pixel); the controller steps Z from the anchor exactly, in integers, so at a
// pixel dx, dy from its anchor Z is off by at most (1 + |dx| + |dy|) / 2. The host anchors
// every command on screen at a pixel whose depth lies in [0, 1], where nothing is held
// (host/raster/controller_depth.cpp): a DEPTH_SPAN at its first pixel (|dx| <= w - 1, dy =
// 0), a FACE at a pixel it covers (|dx| <= w - 1, |dy| <= h - 1). Past [0, 1] the controller
// holds Z to the range, which keeps the order of any two depths. The controller keeps face B
// over face A (A exactly nearer) only if B's word is not larger than A's: within the word's
// step, so B's exact depth lies within step + both errors, under
//     step + (1 + w + h) / kDepthOne,
// the tolerance (two units spare): a difference beyond it is wrong, and none can be.
#pragma once

#include <cstdint>
#include <string>

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
    // the pair of faces (ids, the nearer first) that tie on the most pixels, and how far
    // apart in depth they lie at the first of those pixels
    uint32_t tie_near = 0, tie_far = 0;
    uint64_t tie_pair_pixels = 0;
    double tie_pair_dz = 0;
    bool exact() const { return coverage == 0 && wrong == 0; }
};

// The tolerance of a depth word of `bits` on a width x height frame: its step, and half a
// unit of each plane's two slopes over the frame's width and height, for both faces.
double depth_tolerance(uint32_t bits, int width, int height);

// The share of the frame whose ties mean z-fighting worth a word: 0.1%.
inline constexpr double kZFightingShare = 0.001;

// When the ties exceed kZFightingShare of the frame, a sentence saying so: how many, the
// word's size and step, and the pair of faces that tie most. Empty otherwise.
std::string z_fighting_note(const DepthAgreement& a);

// Compares `controller_ids` (a depth-command method's id pass) with `reference_ids` (the host
// Z-buffer's) on `scene`, the scene projected in id mode (its faces' depth planes).
DepthAgreement depth_agreement(const host::ScreenScene& scene,
                               const controller::Framebuffer& reference_ids,
                               const controller::Framebuffer& controller_ids, uint32_t depth_bits);

}  // namespace fb89::experiments
