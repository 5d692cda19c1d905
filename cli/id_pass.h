// The face-id pass (DESIGN.md "Face ids"): the scene projected in id mode, rendered by a
// method through the same sink and controller as a shaded pass, so that the controller's
// framebuffer is the face-id buffer (id + 1 as 24-bit RGB, 0 = background). Shared by
// `render --ids` and the experiments that count pixels wrong.
#pragma once

#include "controller_sim/framebuffer.h"
#include "host/raster/renderer.h"
#include "host/scene/scene.h"

namespace fb89::cli {

controller::Framebuffer id_framebuffer(const host::Scene& scene, host::Renderer& renderer);

}  // namespace fb89::cli
