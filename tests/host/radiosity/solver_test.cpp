// The radiosity solvers: the furnace test (REFERENCES.md), convergence, energy balance and
// agreement on small random systems.
#include "host/radiosity/solver.h"

#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>

#include "host/radiosity/mesh.h"

namespace fb89::host {
namespace {

Face square(std::vector<glm::dvec3> v, const glm::dvec3& rho, const glm::dvec3& emission) {
    Face f;
    f.vertices = std::move(v);
    f.material.color = rho;
    f.material.emission = emission;
    return f;
}

// The closed unit cube, faces wound inward, one patch each: floor, ceiling, then the walls
// z = 0, x = 1, z = 1, x = 0 (so face k + 2's opposite is (k + 2) % 4 + 2).
Mesh furnace_cube(double rho, double emission) {
    Scene s;
    const glm::dvec3 r(rho), e(emission);
    s.faces.push_back(square({{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, r, e));  // y = 0, +y
    s.faces.push_back(square({{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}, r, e));  // y = 1, -y
    s.faces.push_back(square({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, r, e));  // z = 0, +z
    s.faces.push_back(square({{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}, r, e));  // x = 1, -x
    s.faces.push_back(square({{1, 0, 1}, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}}, r, e));  // z = 1, -z
    s.faces.push_back(square({{0, 0, 1}, {0, 0, 0}, {0, 1, 0}, {0, 1, 1}}, r, e));  // x = 0, +x
    MeshOptions o;
    o.patch_size = 10;
    return mesh_scene(s, o);
}

// Closed forms for unit squares (Howell C-11 and C-14).
constexpr double kOppositeFactor = 0.199825, kAdjacentFactor = 0.200044;

std::vector<double> furnace_form_factors() {
    const int opposite[6] = {1, 0, 4, 5, 2, 3};
    std::vector<double> F(36, 0.0);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            if (j != i) F[i * 6 + j] = j == opposite[i] ? kOppositeFactor : kAdjacentFactor;
    return F;
}

TEST(Solver, FurnaceCubeMeshesToSixInwardPatches) {
    Mesh m = furnace_cube(0.5, 1);
    ASSERT_EQ(m.patches.size(), 6u);
    for (const Element& e : m.elements)
        EXPECT_NEAR(glm::dot(e.normal, glm::dvec3(0.5) - e.corners[0]), 0.5, 1e-12);
}

TEST(Solver, FurnaceTestGivesTwoByGaussSeidel) {
    Mesh m = furnace_cube(0.5, 1);
    RadiositySolution s = solve_gauss_seidel(m, furnace_form_factors(), 1e-9, 1000);
    EXPECT_TRUE(s.converged);
    for (const glm::dvec3& b : s.radiosity)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(b[c], 2.0, 1e-5);
    EXPECT_LT(s.residual, 1e-8);
}

TEST(Solver, FurnaceTestGivesTwoByShooting) {
    Mesh m = furnace_cube(0.5, 1);
    RadiositySolution s = solve_progressive(m, furnace_form_factors(), 1e-9, 100000);
    EXPECT_TRUE(s.converged);
    for (const glm::dvec3& b : s.radiosity)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(b[c], 2.0, 1e-5);
    EXPECT_LT(s.residual, 1e-8);
}

// N single-patch squares of random sizes, random ρ and a few emitters, with a random
// reciprocal F (A_i F_ij = A_j F_ji) whose rows sum to at most `row_sum`.
struct RandomSystem {
    Mesh mesh;
    std::vector<double> F;
};

RandomSystem random_system(int n, unsigned seed, double row_sum) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    Scene s;
    for (int k = 0; k < n; ++k) {
        const double side = 0.5 + u(rng);
        const double x = 3.0 * k;
        const glm::dvec3 rho(0.1 + 0.8 * u(rng), 0.1 + 0.8 * u(rng), 0.1 + 0.8 * u(rng));
        const glm::dvec3 e = k % 4 == 0 ? glm::dvec3(u(rng), u(rng), u(rng)) : glm::dvec3(0);
        s.faces.push_back(
            square({{x, 0, 0}, {x + side, 0, 0}, {x + side, side, 0}, {x, side, 0}}, rho, e));
    }
    MeshOptions o;
    o.patch_size = 10;
    RandomSystem r;
    r.mesh = mesh_scene(s, o);
    const size_t N = r.mesh.patches.size();
    std::vector<double> G(N * N, 0.0);  // A_i F_ij, symmetric
    for (size_t i = 0; i < N; ++i)
        for (size_t j = i + 1; j < N; ++j)
            G[i * N + j] = G[j * N + i] = u(rng) < 0.3 ? 0.0 : u(rng);
    double scale = 1e300;
    for (size_t i = 0; i < N; ++i) {
        double sum = 0;
        for (size_t j = 0; j < N; ++j)
            sum += G[i * N + j];
        if (sum > 0) scale = std::min(scale, row_sum * r.mesh.patches[i].area / sum);
    }
    r.F.resize(N * N);
    for (size_t i = 0; i < N; ++i)
        for (size_t j = 0; j < N; ++j)
            r.F[i * N + j] = scale * G[i * N + j] / r.mesh.patches[i].area;
    return r;
}

TEST(Solver, RandomSystemsConvergeAndSolversAgree) {
    for (unsigned seed = 1; seed <= 8; ++seed) {
        RandomSystem sys = random_system(20 + static_cast<int>(seed) * 3, seed, 0.95);
        RadiositySolution gs = solve_gauss_seidel(sys.mesh, sys.F, 1e-10, 10000);
        RadiositySolution pr = solve_progressive(sys.mesh, sys.F, 1e-10, 1000000);
        ASSERT_TRUE(gs.converged) << "seed " << seed;
        ASSERT_TRUE(pr.converged) << "seed " << seed;
        EXPECT_LT(gs.residual, 1e-8);
        EXPECT_LT(pr.residual, 1e-8);
        // for a reciprocal F both solve the same system
        EXPECT_LT(radiosity_residual(sys.mesh, sys.F, pr.radiosity, false), 1e-8);
        for (size_t i = 0; i < gs.radiosity.size(); ++i)
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(gs.radiosity[i][c], pr.radiosity[i][c], 1e-7) << "seed " << seed;
    }
}

// Emitted power = absorbed power + power that leaves the open system:
// Σ A_i E_i = Σ A_i (1 − ρ_i) H_i + Σ A_i B_i (1 − Σ_j F_ij), with H_i = Σ_j F_ij B_j.
TEST(Solver, EnergyBalancesOnRandomSystems) {
    for (unsigned seed = 11; seed <= 15; ++seed) {
        RandomSystem sys = random_system(30, seed, 0.9);
        RadiositySolution s = solve_gauss_seidel(sys.mesh, sys.F, 1e-12, 10000);
        const size_t N = s.radiosity.size();
        glm::dvec3 emitted(0), absorbed(0), escaped(0);
        for (size_t i = 0; i < N; ++i) {
            const Element& e = sys.mesh.elements[sys.mesh.patches[i].element];
            const double A = sys.mesh.patches[i].area;
            glm::dvec3 H(0);
            double row = 0;
            for (size_t j = 0; j < N; ++j) {
                H += sys.F[i * N + j] * s.radiosity[j];
                row += sys.F[i * N + j];
            }
            emitted += A * e.emission;
            absorbed += A * (1.0 - e.reflectance) * H;
            escaped += A * (1.0 - row) * s.radiosity[i];
        }
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(emitted[c], absorbed[c] + escaped[c], 1e-9 * emitted[c]) << "seed " << seed;
    }
}

TEST(Solver, ShootingStopsAtItsShotLimit) {
    RandomSystem sys = random_system(25, 3, 0.95);
    RadiositySolution s = solve_progressive(sys.mesh, sys.F, 1e-12, 5);
    EXPECT_FALSE(s.converged);
    EXPECT_EQ(s.iterations, 5);
    EXPECT_GT(s.residual, 1e-12);
}

TEST(Solver, NoEmitterGivesBlackWithoutIterating) {
    Mesh m = furnace_cube(0.5, 0);
    for (auto solve : {solve_gauss_seidel, solve_progressive}) {
        RadiositySolution s = solve(m, furnace_form_factors(), 1e-6, 100);
        EXPECT_TRUE(s.converged);
        EXPECT_EQ(s.iterations, 0);
        for (const glm::dvec3& b : s.radiosity)
            EXPECT_EQ(b, glm::dvec3(0));
    }
}

TEST(Solver, DivergenceStopsEarly) {
    // rows summing to 3 with ρ = 0.9: the iteration grows without bound
    Mesh m = furnace_cube(0.9, 1);
    std::vector<double> F = furnace_form_factors();
    for (double& f : F)
        f *= 3;
    RadiositySolution s = solve_gauss_seidel(m, F, 1e-6, 100000);
    EXPECT_FALSE(s.converged);
    EXPECT_LT(s.iterations, 100000);
    EXPECT_GT(max_row_sum(F, 6), 2.9);
}

}  // namespace
}  // namespace fb89::host
