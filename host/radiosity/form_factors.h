// Form factors between patches (the paper's §5, Eq. 5.1), from intervisibility δ.
//
// Eq. 5.2 as printed is dimensionally wrong (REFERENCES.md); ours is
//     F_ij ≈ A_j cos φi cos φj δ_ij / (π r²),
// so that A_i F_ij = A_j F_ji exactly, with Wallace et al.'s disk form
//     F_ij ≈ A_j cos φi cos φj δ_ij / (π r² + A_j)
// as an option: it stays bounded as r → 0 (adjacent patches), where the centre form
// blows up. Baselines and oracles: the hemicube (hemicube.h) and exact polygon-to-polygon
// form factors by the contour integral (exact.h).
#pragma once

#include <cstdint>
#include <vector>

#include "host/radiosity/mesh.h"
#include "host/radiosity/visibility.h"

namespace fb89::host {

enum class CentreForm { PointToPoint, Disk };

// F as a dense row-major N x N matrix: F[i * N + j] is the fraction of what leaves patch i
// that reaches patch j. Pairs that do not face each other or are hidden get 0.
std::vector<double> centre_form_factors(const Mesh& mesh, const Visibility& delta, CentreForm form,
                                        const WorkObserver& work = {});

// The centre estimate for one pair, unoccluded.
double centre_form_factor(const Patch& from, const glm::dvec3& from_normal, const Patch& to,
                          const glm::dvec3& to_normal, CentreForm form);

}  // namespace fb89::host
