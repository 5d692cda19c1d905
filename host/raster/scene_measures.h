// Measures of a projected scene that the paper's model is stated in: depth complexity,
// visible faces, mean visible face size. Computed with the Z-buffer off the clock, for
// scene documentation and the model's inputs; not part of any method's timed work.
#pragma once

#include <cstdint>

#include "host/raster/screen_scene.h"

namespace fb89::host {

struct SceneMeasures {
    uint64_t faces = 0;                  // distinct face ids that reach the screen
    uint64_t face_pixels = 0;            // pixel centres covered, summed over faces
    uint64_t covered_pixels = 0;         // pixels covered by at least one face
    uint64_t visible_faces = 0;          // distinct ids that win at least one pixel
    double depth_complexity = 0;         // face_pixels / covered_pixels
    double mean_visible_face = 0;        // covered_pixels / visible_faces
    double screen_depth_complexity = 0;  // face_pixels / (width * height)
};

SceneMeasures measure_scene(const ScreenScene& scene);

}  // namespace fb89::host
