// The face-id pass (docs/ARCHITECTURE.md "Faces and ids"): the scene projected in id mode,
// rendered by a method through the same sink and controller as a shaded pass, so that the
// controller's framebuffer is the face-id buffer (id + 1 as 24-bit RGB, 0 = background).
// Shared by `render --ids`, the experiments that count pixels wrong, and the golden tests.
#pragma once

#include "controller_sim/framebuffer.h"
#include "host/raster/renderer.h"
#include "host/scene/projection.h"
#include "host/scene/scene.h"

namespace fb89::experiments {

// The frame `renderer` makes of `scene` projected in `mode`, as the controller holds it
// (pixels do not depend on the cost profile, but for the depth commands' on its depth word:
// the ideal profile is used, with a depth word of `depth_bits`).
controller::Framebuffer framebuffer_of(const host::Scene& scene, host::ColorMode mode,
                                       host::Renderer& renderer, uint32_t depth_bits = 32);

// framebuffer_of() in id mode: the face-id buffer.
controller::Framebuffer id_framebuffer(const host::Scene& scene, host::Renderer& renderer,
                                       uint32_t depth_bits = 32);

}  // namespace fb89::experiments
