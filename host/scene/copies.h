// Copies of a group of parts: a regular `array` (rows of bottles on a shelf, table legs) or
// a seeded random `scatter` on a ground (a forest). Scenes with thousands of faces stay a
// few lines long, and a seed makes a random scene the same on every machine.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "host/scene/generators.h"

namespace fb89::host {

// Where one copy goes: scaled uniformly about the parts' origin, turned about the y axis,
// then moved by `offset`. `shade` multiplies the parts' colours; `color`, when set,
// replaces them.
struct Placement {
    glm::dvec3 offset{0, 0, 0};
    double scale = 1;
    double yaw_degrees = 0;
    double shade = 1;
    std::optional<glm::dvec3> color;
};

// Every part's faces, copy by copy, in the parts' order within each copy.
GeneratedPolygons place_copies(const GeneratedPolygons& parts,
                               const std::vector<Placement>& placements);

// count.x * count.y * count.z copies at i * step.x, j * step.y, k * step.z, x fastest.
std::vector<Placement> array_placements(int nx, int ny, int nz, const glm::dvec3& step);

struct ScatterOptions {
    int count = 1;
    glm::dvec3 min{0, 0, 0}, max{0, 0, 0};  // offsets uniform in this box
    double min_distance = 0;                // between any two offsets
    double scale_min = 1, scale_max = 1;
    bool random_yaw = false;
    double color_jitter = 0;  // shade uniform in [1 - jitter, 1 + jitter]
    uint64_t seed = 1;
};

// Dart throwing, up to 1000 tries a copy: the same options give the same placements
// on every machine (a 64-bit Mersenne Twister read through our own uniform mapping). Fewer
// than `count` come back when they do not fit at `min_distance`.
std::vector<Placement> scatter_placements(const ScatterOptions& options);

}  // namespace fb89::host
