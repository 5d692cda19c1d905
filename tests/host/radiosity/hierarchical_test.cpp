// Hierarchical radiosity (hierarchical.h) checked, not assumed: the closed forms of
// exact_test.cpp (parallel and perpendicular unit squares, the closed cube), convergence to the
// dense exact solution on its own leaf mesh as ε → 0, energy balance, and where it fails
// (refinement that cannot stop early, touching faces, no emitter).
#include "host/radiosity/hierarchical.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "host/radiosity/exact.h"
#include "host/radiosity/pipeline.h"
#include "host/radiosity/shaft.h"
#include "host/trace/grid.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {
namespace {

using glm::dvec3;

// Closed forms for unit squares (Howell C-11 and C-14), and a point under a unit square's
// centre at height 1 (exact_test.cpp).
constexpr double kOpposite = 0.199825, kAdjacent = 0.200044, kPointUnderCentre = 0.239456;

void add_quad(Scene& s, dvec3 a, dvec3 b, dvec3 c, dvec3 d, double rho, double emission) {
    Face f;
    f.vertices = {a, b, c, d};
    f.id = s.face_count++;
    f.material.color = dvec3(rho);
    f.material.emission = dvec3(emission);
    s.faces.push_back(f);
}

// The unit cube, faces wound inward: floor (y = 0), ceiling (y = 1), then the walls.
Scene cube(double rho, double floor_emission, double ceiling_emission, double wall_emission) {
    Scene s;
    add_quad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, rho, floor_emission);
    add_quad(s, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, rho, ceiling_emission);
    add_quad(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, rho, wall_emission);
    add_quad(s, {1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}, rho, wall_emission);
    add_quad(s, {1, 0, 1}, {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, rho, wall_emission);
    add_quad(s, {0, 0, 1}, {0, 0, 0}, {0, 1, 0}, {0, 1, 1}, rho, wall_emission);
    return s;
}

// A world of input elements (one patch each) and the flux tracer's grid.
struct HierarchicalWorld {
    explicit HierarchicalWorld(const Scene& s)
        : mesh(mesh_scene(s, {std::numeric_limits<double>::infinity(), 64})),
          trace(s, true, 0),
          grid(trace) {}
    RadiosityWorld world() const { return {trace, grid}; }
    HierarchicalResult solve(const HierarchicalOptions& o) const {
        return hierarchical_radiosity(mesh, world(), o);
    }
    Mesh mesh;
    TraceScene trace;
    UniformGrid grid;
};

// The area-weighted mean radiosity (first channel) of the leaves on input face `face`.
double mean_on(const HierarchicalResult& r, uint32_t face) {
    double sum = 0, area = 0;
    for (const Patch& p : r.leaves.patches)
        if (r.leaves.elements[p.element].face_id == face) {
            sum += p.area * r.solution.radiosity[&p - r.leaves.patches.data()].x;
            area += p.area;
        }
    return sum / area;
}

HierarchicalOptions fine(double epsilon, double min_area) {
    HierarchicalOptions o;
    o.epsilon = epsilon;
    o.min_area = min_area;
    o.link_rays = 1;
    o.tolerance = 1e-10;
    return o;
}

// Two unit squares a unit apart: the lower emits 1 and reflects nothing, the upper reflects
// half. The upper's mean radiosity is ρ E F exactly, whatever the refinement: links split the
// pair of squares into pieces whose exact factors add up to the whole.
TEST(Hierarchical, ParallelSquaresGiveHowellC11AtEveryEpsilon) {
    Scene s;
    add_quad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0, 1);    // y = 0, facing +y
    add_quad(s, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, 0.5, 0);  // y = 1, facing -y
    const HierarchicalWorld w(s);
    ASSERT_EQ(w.mesh.elements.size(), 2u);
    // the windings face each other
    ASSERT_GT(glm::dot(w.mesh.elements[0].normal, dvec3(0, 1, 0)), 0);
    for (double eps : {1.0, 1e-2, 1e-3, 1e-4}) {
        const HierarchicalResult r = w.solve(fine(eps, 1.0 / 256));
        EXPECT_NEAR(mean_on(r, 1), 0.5 * kOpposite, 1e-6) << "epsilon " << eps;
        EXPECT_NEAR(mean_on(r, 0), 1.0, 1e-12);
        EXPECT_TRUE(r.solution.converged);
    }
    // refinement follows epsilon: more leaves and links as it falls
    const auto coarse = w.solve(fine(1e-2, 1.0 / 256)).counts;
    const auto finer = w.solve(fine(1e-4, 1.0 / 256)).counts;
    EXPECT_EQ(w.solve(fine(1.0, 1.0 / 256)).counts.links, 2u);  // ρ E F ≤ 0.5: one each way
    EXPECT_GT(finer.leaves, coarse.leaves);
    EXPECT_GT(finer.links, coarse.links);
    EXPECT_GT(coarse.refinements, 0u);
}

// The leaf under the emitter's centre approaches the point-to-polygon factor.
TEST(Hierarchical, LeafAtTheCentreApproachesThePointFormFactor) {
    Scene s;
    add_quad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0, 1);
    add_quad(s, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, 1, 0);
    const HierarchicalWorld w(s);
    const HierarchicalResult r = w.solve(fine(1e-3, 1.0 / 1024));
    double best = 1e9, at = 0;
    for (size_t k = 0; k < r.leaves.patches.size(); ++k) {
        const Patch& p = r.leaves.patches[k];
        const double d = glm::length(p.centre - dvec3(0.5, 1, 0.5));
        if (r.leaves.elements[p.element].face_id == 1 && d < best) {
            best = d;
            at = r.solution.radiosity[k].x;
        }
    }
    EXPECT_LT(best, 0.05);
    EXPECT_NEAR(at, kPointUnderCentre, 0.01 * kPointUnderCentre);
}

TEST(Hierarchical, PerpendicularSquaresSharingAnEdgeGiveHowellC14) {
    Scene s;
    add_quad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0, 1);    // floor y = 0, up
    add_quad(s, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0.5, 0);  // wall z = 0, +z
    const HierarchicalWorld w(s);
    for (double eps : {1.0, 1e-3}) {
        const HierarchicalResult r = w.solve(fine(eps, 1.0 / 1024));
        EXPECT_NEAR(mean_on(r, 1), 0.5 * kAdjacent, 1e-6) << "epsilon " << eps;
        for (const glm::dvec3& b : r.solution.radiosity)
            EXPECT_TRUE(std::isfinite(b.x));
        EXPECT_LE(r.rows.largest, 1 + 1e-6);  // touching, yet no factor runs away
    }
}

// The furnace: every face emits 1 and reflects half, so B = 1 / (1 − ρ) = 2 in a closed cube.
// With every link at the roots it is exact; refined, each face's mean stays 2 while a leaf
// gathering through its ancestors' links (a parent's mean factor, not its own) is off by the
// spread of the factor across the parent — bounded, and the price of a coarse link.
TEST(Hierarchical, FurnaceCubeGivesTwo) {
    const HierarchicalWorld w(cube(0.5, 1, 1, 1));
    const HierarchicalResult roots = w.solve(fine(1e6, 1.0 / 64));
    for (const glm::dvec3& b : roots.solution.radiosity)
        EXPECT_NEAR(b.x, 2.0, 1e-6);
    const HierarchicalResult r = w.solve(fine(0.05, 1.0 / 64));
    EXPECT_GT(r.counts.leaves, 6u);
    for (uint32_t face = 0; face < 6; ++face)
        EXPECT_NEAR(mean_on(r, face), 2.0, 0.02) << "face " << face;
    for (const glm::dvec3& b : r.solution.radiosity)
        EXPECT_NEAR(b.x, 2.0, 0.12);
}

// The ceiling-lit cube at ε large is the six-patch system with Howell's factors exactly.
TEST(Hierarchical, CeilingLitCubeAtTheRootsIsTheSixPatchSolution) {
    const HierarchicalWorld w(cube(0.5, 0, 1, 0));
    const HierarchicalResult r = w.solve(fine(1e6, 1.0));
    ASSERT_EQ(r.counts.links, 30u);  // every root from every other
    const int opposite[6] = {1, 0, 4, 5, 2, 3};
    std::vector<double> F(36, 0.0);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            if (j != i) F[i * 6 + j] = j == opposite[i] ? kOpposite : kAdjacent;
    const RadiositySolution dense = solve_gauss_seidel(w.mesh, F, 1e-12, 1000);
    for (size_t k = 0; k < 6; ++k)
        EXPECT_NEAR(mean_on(r, w.mesh.elements[k].face_id), dense.radiosity[k].x, 1e-5);
}

// Power balance in a closed room: what the emitters send is what the surfaces absorb,
// Σ A E = Σ A (B − E)(1 − ρ)/ρ, to within the solver's tolerance and the coarse links' use of
// a source's mean radiosity.
TEST(Hierarchical, EnergyIsConservedInAClosedCube) {
    const HierarchicalWorld w(cube(0.6, 0, 1, 0));
    // coarse links use a source's mean radiosity, so the balance is looser at a large ε
    for (const auto& [eps, bound] : {std::pair{0.1, 0.06}, {0.01, 0.01}, {0.002, 0.01}}) {
        const HierarchicalResult r = w.solve(fine(eps, 1.0 / 1024));
        double emitted = 0, absorbed = 0;
        for (size_t k = 0; k < r.leaves.patches.size(); ++k) {
            const Element& e = r.leaves.elements[r.leaves.patches[k].element];
            const double a = r.leaves.patches[k].area;
            emitted += a * e.emission.x;
            absorbed += a * (r.solution.radiosity[k].x - e.emission.x) * (1 - 0.6) / 0.6;
        }
        EXPECT_NEAR(absorbed / emitted, 1.0, bound) << "epsilon " << eps;
    }
}

// A cube with a floating blocker: as ε → 0 (every link at the leaves, one centre ray each),
// the hierarchy's answer is the dense exact solution on its own leaf mesh, to the tolerance.
TEST(Hierarchical, ConvergesToTheExactSolutionOnItsLeafMesh) {
    Scene s = cube(0.7, 0, 0, 0);
    s.faces[1].material.color = dvec3(0.2);
    // a light patch under the ceiling, a blocker in the middle facing down and up
    add_quad(s, {0.375, 0.99, 0.375}, {0.625, 0.99, 0.375}, {0.625, 0.99, 0.625},
             {0.375, 0.99, 0.625}, 0, 10);
    add_quad(s, {0.25, 0.5, 0.25}, {0.25, 0.5, 0.75}, {0.75, 0.5, 0.75}, {0.75, 0.5, 0.25}, 0.5, 0);
    add_quad(s, {0.25, 0.5, 0.25}, {0.75, 0.5, 0.25}, {0.75, 0.5, 0.75}, {0.25, 0.5, 0.75}, 0.5, 0);
    const HierarchicalWorld w(s);
    const HierarchicalResult r = w.solve(fine(0, 1.0 / 64));
    ASSERT_TRUE(r.solution.converged);
    const Mesh& leaves = r.leaves;
    const TraceScene trace(s, true, 0);
    const UniformGrid grid(trace);
    VisibilityCounts counts;
    const Visibility delta = flux_tracing(leaves, {trace, grid}, counts);
    const std::vector<double> F = exact_form_factors(leaves, delta);
    const RadiositySolution dense = solve_gauss_seidel(leaves, F, 1e-12, 5000);
    double worst = 0;
    for (size_t k = 0; k < leaves.patches.size(); ++k)
        worst = std::max(worst, std::abs(r.solution.radiosity[k].x - dense.radiosity[k].x));
    EXPECT_LT(worst, 1e-5);
    // and at a coarser ε it is near, with far fewer links than the n² pairs
    const HierarchicalResult coarse = w.solve(fine(0.01, 1.0 / 64));
    EXPECT_LT(coarse.counts.links, r.counts.links / 4);
}

// Links see what the flux tracer sees: a blocker between the squares halves a link's rays.
TEST(Hierarchical, LinkVisibilityIsTheShareOfClearRays) {
    Scene s;
    add_quad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0, 1);
    add_quad(s, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, 1, 0);
    add_quad(s, {-1, 0.5, -1}, {-1, 0.5, 2}, {0.5, 0.5, 2}, {0.5, 0.5, -1}, 0, 0);  // half
    const HierarchicalWorld w(s);
    HierarchicalOptions o = fine(1e6, 1);
    o.link_rays = 256;
    const HierarchicalResult r = w.solve(o);
    EXPECT_EQ(r.counts.rays, r.counts.form_factors * 256);
    const double unblocked = kOpposite;
    const double mean = mean_on(r, 1);
    EXPECT_GT(mean, 0.25 * unblocked);
    EXPECT_LT(mean, 0.75 * unblocked);
    o.link_rays = 1;  // the centre ray passes the blocker's edge: all or nothing
    const double centre = mean_on(w.solve(o), 1);
    EXPECT_TRUE(centre == 0 || std::abs(centre - unblocked) < 1e-6) << centre;
}

// The shaft holds every segment between its two boxes, and cuts off the union box's corners
// that the segments do not reach.
TEST(Shaft, HoldsEverySegmentBetweenItsBoxesAndNotTheUnionBoxsCorners) {
    const PieceBox a{{0, 0, 0}, {1, 1, 0}};  // a unit square at z = 0
    const PieceBox b{{3, 0, 2}, {4, 1, 2}};  // another at z = 2, three along x
    const Shaft shaft(a, b);
    EXPECT_GT(shaft.planes(), 0);
    uint32_t seed = 12345;
    auto uniform = [&seed] {
        seed = seed * 1664525u + 1013904223u;
        return (seed >> 8) * 0x1.0p-24;
    };
    for (int i = 0; i < 2000; ++i) {
        const dvec3 p(uniform(), uniform(), 0), q(3 + uniform(), uniform(), 2);
        const dvec3 x = p + uniform() * (q - p);
        EXPECT_TRUE(shaft.may_meet({x, x}, 0)) << x.x << " " << x.y << " " << x.z;
    }
    // in the union box, beside B but near A's height: outside the hull, so outside the shaft
    EXPECT_FALSE(shaft.may_meet({{3.2, 0.2, 0.2}, {3.8, 0.8, 0.4}}, 1e-9));
    EXPECT_FALSE(shaft.may_meet({{0.1, 0.2, 1.6}, {0.6, 0.8, 1.9}}, 1e-9));  // its other corner
    EXPECT_TRUE(shaft.may_meet({{0.6, 0.2, 0.2}, {1.2, 0.8, 0.4}}, 1e-9));   // on the way
    EXPECT_TRUE(shaft.may_meet({{-5, -5, 0.9}, {9, 9, 1.1}}, 0));            // a wall across it
    EXPECT_FALSE(shaft.may_meet({{0, 2, 0}, {4, 3, 2}}, 1e-9));              // above the union
    // slack: a box just beyond a side meets it with enough slack
    EXPECT_FALSE(shaft.may_meet({{0, 1.01, 0}, {1, 1.02, 0}}, 0.001));
    EXPECT_TRUE(shaft.may_meet({{0, 1.01, 0}, {1, 1.02, 0}}, 0.1));
}

// Shaft culling changes only the rays: the same links, factors and radiosities, with no ray
// where nothing stands between two squares and every ray where something might.
TEST(Hierarchical, ShaftCullingSparesRaysAndChangesNothingElse) {
    Scene open;
    add_quad(open, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0, 1);
    add_quad(open, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, 0.5, 0);
    Scene blocked = open;  // and a plate half across the gap
    add_quad(blocked, {-1, 0.5, -1}, {-1, 0.5, 2}, {0.5, 0.5, 2}, {0.5, 0.5, -1}, 0.3, 0);
    for (const Scene* s : {&open, &blocked}) {
        const HierarchicalWorld w(*s);
        HierarchicalOptions o = fine(1e-3, 1.0 / 64);
        o.link_rays = 4;
        const HierarchicalResult plain = w.solve(o);
        o.shaft_culling = true;
        const HierarchicalResult culled = w.solve(o);
        EXPECT_EQ(plain.counts.shafts, 0u);
        EXPECT_EQ(culled.counts.links, plain.counts.links);
        EXPECT_EQ(culled.counts.leaves, plain.counts.leaves);
        EXPECT_EQ(culled.counts.form_factors, plain.counts.form_factors);
        ASSERT_EQ(culled.solution.radiosity.size(), plain.solution.radiosity.size());
        for (size_t i = 0; i < plain.solution.radiosity.size(); ++i)
            EXPECT_EQ(culled.solution.radiosity[i], plain.solution.radiosity[i]) << i;
        EXPECT_EQ(culled.counts.shafts, culled.counts.form_factors);
        // the rays cast are those of the links whose shaft something met
        EXPECT_EQ(culled.counts.rays, (culled.counts.shafts - culled.counts.shafts_clear) * 4);
        if (s == &open) {
            EXPECT_EQ(culled.counts.rays, 0u);
            EXPECT_EQ(culled.counts.shafts_clear, culled.counts.shafts);
            EXPECT_EQ(culled.counts.shaft_tests, 0u);  // no piece but the two ends
        } else {
            EXPECT_GT(culled.counts.shaft_tests, 0u);
            EXPECT_GT(culled.counts.rays, 0u);
            EXPECT_LT(culled.counts.rays, plain.counts.rays);
        }
    }
}

// Where it fails: close facing faces at a tiny ε refine without end; the budget stops it with
// a note, in bounded time, and the answer stays finite and conserves the light sent.
TEST(Hierarchical, BudgetStopsRefinementThatCannotStopEarly) {
    Scene s;
    add_quad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0.5, 1);
    add_quad(s, {0, 0.01, 0}, {1, 0.01, 0}, {1, 0.01, 1}, {0, 0.01, 1}, 0.9, 0);
    const HierarchicalWorld w(s);
    HierarchicalOptions o = fine(1e-9, 1e-12);
    o.max_nodes = 1000;
    const HierarchicalResult r = w.solve(o);
    EXPECT_TRUE(r.counts.budget_hit);
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_NE(r.notes[0].find("budget"), std::string::npos);
    EXPECT_LE(r.counts.nodes, 1000u);
    for (const glm::dvec3& b : r.solution.radiosity)
        EXPECT_TRUE(std::isfinite(b.x) && b.x >= 0);
    o.max_nodes = 2'000'000;
    o.max_links = 2000;
    EXPECT_TRUE(w.solve(o).counts.budget_hit);
}

// Coincident faces back to back exchange nothing; faces touching at a corner stay finite.
TEST(Hierarchical, CoplanarAndTouchingFacesStayFinite) {
    Scene s;
    add_quad(s, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, 0.5, 0);  // y = 0, facing -y
    add_quad(s, {0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}, 0.5,
             1);  // the same square, +y, emitting
    add_quad(s, {1, 0, 1}, {1, 1, 1}, {2, 1, 1}, {2, 0, 1}, 0.5, 0);  // -z, touching a corner
    const HierarchicalWorld w(s);
    const HierarchicalResult r = w.solve(fine(1e-3, 1e-3));
    EXPECT_NEAR(mean_on(r, 0), 0.0, 1e-12);  // back to back with the emitter
    EXPECT_GT(mean_on(r, 2), 0.0);
    for (const glm::dvec3& b : r.solution.radiosity)
        EXPECT_TRUE(std::isfinite(b.x));
    EXPECT_LE(r.rows.largest, 1 + 1e-6);
}

TEST(Hierarchical, OptionsOutOfRangeAreRefused) {
    const HierarchicalWorld w(cube(0.5, 0, 1, 0));
    HierarchicalOptions o;
    o.link_rays = 0;
    EXPECT_THROW(w.solve(o), std::invalid_argument);
    o = {};
    o.epsilon = -1;
    EXPECT_THROW(w.solve(o), std::invalid_argument);
    o = {};
    o.min_area = std::nan("");
    EXPECT_THROW(w.solve(o), std::invalid_argument);
}

// Through the pipeline: one face per leaf, counts reported, no emitter an error.
TEST(Hierarchical, PipelineDrawsOneFacePerLeafAndRefusesADarkScene) {
    Scene s = cube(0.5, 0, 1, 0);
    s.projection = Projection::Perspective;
    RadiosityOptions o;
    o.form_factors = FormFactorMethod::Hierarchical;
    o.patches = 96;
    const RadiosityResult r = solve_radiosity(s, o);
    ASSERT_TRUE(r.hierarchy.has_value());
    EXPECT_EQ(r.hierarchy->roots, 6u);
    EXPECT_EQ(r.hierarchy->leaves, r.mesh.patches.size());
    EXPECT_EQ(r.patches.faces.size(), r.mesh.patches.size());
    EXPECT_EQ(r.counts.rays, r.hierarchy->rays);
    EXPECT_TRUE(r.solution.converged);
    const Scene dark = cube(0.5, 0, 0, 0);
    EXPECT_THROW(solve_radiosity(dark, o), std::invalid_argument);
}

}  // namespace
}  // namespace fb89::host
