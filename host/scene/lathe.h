// Surfaces of revolution: a profile curve turned about the y axis (the `lathe` and `sphere`
// generators). Goblets, vases, bottles, bowls, tree crowns: the paper's test scenes (§2,
// Fig. 2.2) are made of such objects.
#pragma once

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "host/scene/generators.h"

namespace fb89::host {

// Which ends of an open profile are closed by a flat polygon.
enum class LatheCaps { None, First, Last, Both };

// Revolves `profile` ([r, y] points, r >= 0, consecutive points distinct) about the y axis
// in `segments` equal steps. Profile segment i and angular step j make face
// i * segments + j (after the first cap, if any): a quad, planar because its two edges
// across the axis are parallel chords, or a triangle where the profile touches the axis;
// a segment lying on the axis makes no face. A cap is one regular polygon of `segments`
// vertices at a profile end that is off the axis; an end on the axis needs none. Faces are
// wound consistently, so a closed profile gives an oriented closed surface.
GeneratedPolygons generate_lathe(const std::vector<glm::dvec2>& profile, int segments,
                                 LatheCaps caps);

// UV sphere: `rings` bands from pole to pole (triangles at the poles, quads between),
// `segments` around the axis, which is parallel to y. segments * rings faces, closed.
GeneratedPolygons generate_sphere(const glm::dvec3& center, double radius, int segments, int rings);

}  // namespace fb89::host
