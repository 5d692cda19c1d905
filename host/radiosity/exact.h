// Exact form factors for unoccluded polygons, the oracles of REFERENCES.md:
//   - point to polygon (Lambert; Baum, Rushmeier and Winget 1989):
//       F = (1 / 2π) Σ β_i (n · Γ_i);
//   - polygon to polygon by the contour integral (Schröder and Hanrahan 1993), with the
//     analytic term for shared edges, ∫₀ᴸ∫₀ᴸ ln|s − t| ds dt = L² (ln L − 3/2).
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "host/radiosity/mesh.h"
#include "host/radiosity/visibility.h"

namespace fb89::host {

// From a differential area at `p` with unit normal `n` to the polygon `poly` (convex, either
// winding); the part of `poly` behind the point's plane counts for nothing.
double point_to_polygon(const glm::dvec3& p, const glm::dvec3& n,
                        const std::vector<glm::dvec3>& poly);

// From polygon `from` (area A_from) to polygon `to`, unoccluded: F_from,to. Both convex,
// their fronts given by their windings (Newell's normals); the part of each behind the
// other's plane exchanges nothing.
double polygon_to_polygon(const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& to);

// Every facing pair's exact unoccluded form factor times δ (0 where hidden): the dense
// N x N matrix of form_factors.h.
std::vector<double> exact_form_factors(const Mesh& mesh, const Visibility& delta,
                                       const WorkObserver& work = {});

}  // namespace fb89::host
