// From scene to screen: shading, the camera (gluLookAt + gluPerspective conventions),
// near/far and guard-band clipping, the perspective divide, depth planes and snapping to
// the 1/256-pixel grid. The set-up stage of every raster method.
#pragma once

#include "host/scene/scene.h"
#include "host/scene/screen_scene.h"
#include "host/stats.h"

namespace fb89::host {

// Pixels beyond each screen border kept by the guard band. Keeps every snapped coordinate
// within +-2^15 pixels (2^23 grid units), so edge functions stay far from 64-bit overflow.
inline constexpr double kGuardBandPixels = 8192;

enum class ColorMode {
    Shaded,  // flat Lambertian with the scene's light (screen-space scenes: unlit colour)
    FaceId,  // colour = id + 1 as a 24-bit number, unshaded: the face-id pass
};

protocol::Rgb face_id_color(uint32_t id);
uint32_t face_id_from_color(protocol::Rgb c);  // id + 1; 0 is background

// Counts what it clipped and dropped into `counters`.
ScreenScene project_scene(const Scene& scene, ColorMode mode, Counters& counters);

}  // namespace fb89::host
