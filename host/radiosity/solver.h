// The radiosity equation (the paper's §5 solves it once its form factors are known):
//     B_i = E_i + ρ_i Σ_j F_ij B_j,
// per patch and per colour channel, E and ρ from the patch's element, F the dense row-major
// N x N matrix of form_factors.h.
//
// Two solvers:
//   - Gauss-Seidel gathering (Cohen and Greenberg 1985): sweeps i = 0..N−1 updating B_i in
//     place from the latest B; a nonzero F_ii (a non-planar patch) is moved to the left side;
//   - progressive refinement by shooting (Cohen, Chen, Wallace and Greenberg 1988): the
//     patch with the most unshot power ΔB_i A_i shoots it to every j through
//     F_ji = A_i F_ij / A_j (reciprocity), so only row i of F is read. For an F that is not
//     reciprocal (the hemicube's) that is the system with F_ji := A_i F_ij / A_j, the one
//     Cohen et al. solve with a hemicube at the shooter; its residual is measured against
//     that system.
// Both stop when the largest change still to come is below `tolerance` times the largest
// emission (Gauss-Seidel: the largest change in a sweep; progressive: the largest unshot
// radiosity, which bounds the residual since ρ ≤ 1 and rows of F sum to at most 1). A scene
// with no emission has B = 0 and needs no iteration.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec3.hpp>

#include "host/radiosity/mesh.h"

namespace fb89::host {

// The largest absolute component: how the solvers measure a colour's change or size.
inline double max_component(const glm::dvec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

struct RadiositySolution {
    std::vector<glm::dvec3> radiosity;  // per patch
    int iterations = 0;                 // sweeps (Gauss-Seidel) or shots (progressive)
    // max over patches and channels of |E + ρ F B − B|, divided by the largest emission
    double residual = 0;
    bool converged = false;  // residual test met before the iteration limit
};

RadiositySolution solve_gauss_seidel(const Mesh& mesh, const std::vector<double>& F,
                                     double tolerance, int max_iterations);

RadiositySolution solve_progressive(const Mesh& mesh, const std::vector<double>& F,
                                    double tolerance, int max_shots);

// The relative residual of B for the gathering system (F as given) or, with `transposed`,
// for the shooting system F_ji := A_i F_ij / A_j.
double radiosity_residual(const Mesh& mesh, const std::vector<double>& F,
                          const std::vector<glm::dvec3>& B, bool transposed = false);

// The largest row sum of F: above 1, the estimate gives a patch more than it sends out
// (the centre form does, for close patches) and the iteration may diverge.
double max_row_sum(const std::vector<double>& F, size_t n);

// The rows of F: patch i's row sums the shares of what it sends that reach each other patch,
// at most 1 in a closed room (less where the room is open). An estimate can exceed it.
struct RowSums {
    double largest = 0;
    size_t largest_patch = 0;
    size_t above_one = 0;  // rows summing to more than 1 + 1e-9
};
RowSums row_sums(const std::vector<double>& F, size_t n);

}  // namespace fb89::host
