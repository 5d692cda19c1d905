// Centre-to-centre form factors (the paper's §5, Eq. 5.2 corrected, see form_factors.h):
// each patch stands for a differential area at its centroid, with its element's normal.
// Of the two estimates, the point form is exactly reciprocal (A_i F_ij = A_j F_ji) and
// converges as O(h²) between separated faces but only as O(h) across a shared edge
// (REFERENCES.md); the disk form trades exact reciprocity for staying bounded there.
#include "host/radiosity/form_factors.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace fb89::host {

double centre_form_factor(const Patch& from, const glm::dvec3& from_normal, const Patch& to,
                          const glm::dvec3& to_normal, CentreForm form) {
    const glm::dvec3 d = to.centre - from.centre;
    const double r2 = glm::dot(d, d);
    if (!(r2 > 0)) return 0;
    const double r = std::sqrt(r2);
    const double cos_from = glm::dot(from_normal, d) / r;
    const double cos_to = -glm::dot(to_normal, d) / r;
    if (cos_from <= 0 || cos_to <= 0) return 0;
    const double denominator =
        form == CentreForm::Disk ? std::numbers::pi * r2 + to.area : std::numbers::pi * r2;
    return to.area * cos_from * cos_to / denominator;
}

std::vector<double> centre_form_factors(const Mesh& mesh, const Visibility& delta, CentreForm form,
                                        const WorkObserver& work) {
    const size_t n = mesh.patches.size();
    if (delta.size() != n)
        throw std::invalid_argument("centre_form_factors: visibility is for another mesh");
    std::vector<double> f(n * n, 0.0);
    for (uint32_t i = 0; i < n; ++i) {
        const Patch& pi = mesh.patches[i];
        const glm::dvec3& ni = mesh.elements[pi.element].normal;
        for (uint32_t j = i + 1; j < n; ++j) {
            if (delta.get(i, j) != Delta::Visible) continue;
            const Patch& pj = mesh.patches[j];
            const glm::dvec3& nj = mesh.elements[pj.element].normal;
            f[i * n + j] = centre_form_factor(pi, ni, pj, nj, form);
            f[j * n + i] = centre_form_factor(pj, nj, pi, ni, form);
        }
        if (work) work(pairs_before(n, i + 1), pairs_before(n, n));
    }
    return f;
}

}  // namespace fb89::host
