#include "host/radiosity/solver.h"

#include <algorithm>
#include <cmath>

namespace fb89::host {

namespace {

// E and ρ of every patch, from its element.
struct PatchTerms {
    std::vector<glm::dvec3> emission, reflectance;
    std::vector<double> area;
    double max_emission = 0;
};

PatchTerms patch_terms(const Mesh& mesh) {
    PatchTerms t;
    const size_t n = mesh.patches.size();
    t.emission.resize(n);
    t.reflectance.resize(n);
    t.area.resize(n);
    for (size_t i = 0; i < n; ++i) {
        const Element& e = mesh.elements[mesh.patches[i].element];
        t.emission[i] = e.emission;
        t.reflectance[i] = e.reflectance;
        t.area[i] = mesh.patches[i].area;
        t.max_emission = std::max(t.max_emission, max_component(e.emission));
    }
    return t;
}

// A solution that has blown up (the estimate gives more than it receives) stops here.
constexpr double kDiverged = 1e12;

}  // namespace

RowSums row_sums(const std::vector<double>& F, size_t n) {
    RowSums out;
    for (size_t i = 0; i < n; ++i) {
        double sum = 0;
        for (size_t j = 0; j < n; ++j)
            sum += F[i * n + j];
        if (sum > out.largest) {
            out.largest = sum;
            out.largest_patch = i;
        }
        out.above_one += sum > 1 + 1e-9;
    }
    return out;
}

double max_row_sum(const std::vector<double>& F, size_t n) {
    return row_sums(F, n).largest;
}

double radiosity_residual(const Mesh& mesh, const std::vector<double>& F,
                          const std::vector<glm::dvec3>& B, bool transposed) {
    const PatchTerms t = patch_terms(mesh);
    const size_t n = B.size();
    if (t.max_emission == 0) return 0;
    // what each patch gathers: Σ_j F_ij B_j, or Σ_i A_i F_ij B_i / A_j for the shooting form
    std::vector<glm::dvec3> gathered(n, glm::dvec3(0));
    for (size_t i = 0; i < n; ++i) {
        const double* row = &F[i * n];
        if (transposed) {
            const glm::dvec3 shot = t.area[i] * B[i];
            for (size_t j = 0; j < n; ++j)
                gathered[j] += row[j] * shot;
        } else {
            glm::dvec3 sum(0);
            for (size_t j = 0; j < n; ++j)
                sum += row[j] * B[j];
            gathered[i] = sum;
        }
    }
    double worst = 0;
    for (size_t i = 0; i < n; ++i) {
        const glm::dvec3 in = transposed ? gathered[i] / t.area[i] : gathered[i];
        worst = std::max(worst, max_component(t.emission[i] + t.reflectance[i] * in - B[i]));
    }
    return worst / t.max_emission;
}

RadiositySolution solve_gauss_seidel(const Mesh& mesh, const std::vector<double>& F,
                                     double tolerance, int max_iterations) {
    const PatchTerms t = patch_terms(mesh);
    const size_t n = mesh.patches.size();
    RadiositySolution s;
    s.radiosity = t.emission;
    if (t.max_emission == 0) {
        s.converged = true;
        return s;
    }
    std::vector<glm::dvec3>& B = s.radiosity;
    while (s.iterations < max_iterations) {
        ++s.iterations;
        double change = 0;
        // one sweep, each B_i from the latest values
        for (size_t i = 0; i < n; ++i) {
            const double* row = &F[i * n];
            glm::dvec3 sum(0);
            for (size_t j = 0; j < n; ++j)
                if (j != i) sum += row[j] * B[j];
            const glm::dvec3 self = 1.0 - t.reflectance[i] * row[i];
            const glm::dvec3 next = (t.emission[i] + t.reflectance[i] * sum) / self;
            change = std::max(change, max_component(next - B[i]));
            B[i] = next;
        }
        if (change <= tolerance * t.max_emission) {
            s.converged = true;
            break;
        }
        if (!(change < kDiverged * t.max_emission)) break;
    }
    s.residual = radiosity_residual(mesh, F, B, false);
    return s;
}

RadiositySolution solve_progressive(const Mesh& mesh, const std::vector<double>& F,
                                    double tolerance, int max_shots) {
    const PatchTerms t = patch_terms(mesh);
    const size_t n = mesh.patches.size();
    RadiositySolution s;
    s.radiosity = t.emission;
    if (t.max_emission == 0) {
        s.converged = true;
        return s;
    }
    std::vector<glm::dvec3>& B = s.radiosity;
    std::vector<glm::dvec3> unshot = t.emission;
    for (;;) {
        // the shooter: most unshot power; the stop test: largest unshot radiosity
        size_t shooter = 0;
        double most_power = -1, most_unshot = 0;
        for (size_t i = 0; i < n; ++i) {
            const glm::dvec3& u = unshot[i];
            const double power = (std::abs(u.x) + std::abs(u.y) + std::abs(u.z)) * t.area[i];
            if (power > most_power) {
                most_power = power;
                shooter = i;
            }
            most_unshot = std::max(most_unshot, max_component(u));
        }
        if (most_unshot <= tolerance * t.max_emission) {
            s.converged = true;
            break;
        }
        if (s.iterations >= max_shots || !(most_unshot < kDiverged * t.max_emission)) break;
        ++s.iterations;

        // shoot: B_j += ρ_j F_ji ΔB_i with F_ji = A_i F_ij / A_j
        const double* row = &F[shooter * n];
        const glm::dvec3 shot = unshot[shooter] * t.area[shooter];
        unshot[shooter] = glm::dvec3(0);
        for (size_t j = 0; j < n; ++j) {
            if (row[j] == 0) continue;
            const glm::dvec3 gain = t.reflectance[j] * shot * (row[j] / t.area[j]);
            B[j] += gain;
            unshot[j] += gain;
        }
    }
    s.residual = radiosity_residual(mesh, F, B, true);
    return s;
}

}  // namespace fb89::host
