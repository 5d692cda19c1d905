// Sutherland–Hodgman clipping of a convex polygon in homogeneous coordinates against
// half-spaces dot(plane, p) >= 0.
//
// Watertight across shared edges: the point where an edge crosses a plane is computed from
// the edge's endpoints in a canonical order, so two faces that share an edge (traversed in
// opposite directions) get bit-identical new vertices, and after snapping no crack opens.
#pragma once

#include <span>
#include <vector>

#include <glm/vec4.hpp>

namespace fb89::host {

// Clips `poly` in place against every plane; returns false when nothing is left.
// `scratch` is reused storage.
bool clip_polygon(std::vector<glm::dvec4>& poly, std::span<const glm::dvec4> planes,
                  std::vector<glm::dvec4>& scratch);

}  // namespace fb89::host
