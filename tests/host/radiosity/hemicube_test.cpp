// The hemicube baseline: rows of a closed cube sum to about 1, a unit square seen from
// under its centre converges on Lambert's 0.239456 (REFERENCES.md: "≈ 0.24"), occluders
// and back faces block, and the work grows as resolution².
#include "host/radiosity/hemicube.h"

#include <cmath>

#include <gtest/gtest.h>

#include "host/radiosity/exact.h"

namespace fb89::host {
namespace {

using Polygon = std::vector<glm::dvec3>;

void add_hemicube_face(Scene& s, Polygon v) {
    Face f;
    f.vertices = std::move(v);
    f.id = static_cast<uint32_t>(s.faces.size());
    s.faces.push_back(f);
    s.face_count = static_cast<uint32_t>(s.faces.size());
}

// The unit cube [0, 1]³ with faces turned inwards.
Scene closed_cube() {
    Scene s;
    add_hemicube_face(s, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});  // z = 0
    add_hemicube_face(s, {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});  // z = 1
    add_hemicube_face(s, {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});  // y = 0
    add_hemicube_face(s, {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}});  // y = 1
    add_hemicube_face(s, {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}});  // x = 0
    add_hemicube_face(s, {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}});  // x = 1
    return s;
}

// Floor and ceiling unit squares one apart, one patch each, facing each other.
Scene hemicube_square_pair() {
    Scene s;
    add_hemicube_face(s, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    add_hemicube_face(s, {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});
    return s;
}

TEST(Hemicube, RowsOfAClosedCubeSumToOne) {
    const Mesh mesh = mesh_scene(closed_cube(), {.patch_size = 0.5});
    const size_t n = mesh.patches.size();
    const std::vector<double> f = hemicube_form_factors(mesh, 64);
    for (size_t i = 0; i < n; ++i) {
        double row = 0;
        for (size_t j = 0; j < n; ++j)
            row += f[i * n + j];
        EXPECT_NEAR(row, 1.0, 1e-3) << "patch " << i;
        EXPECT_EQ(f[i * n + i], 0.0);
    }
}

TEST(Hemicube, EachEntryOfAClosedCubeIsNearLambertsValueFromTheCentre) {
    const Mesh mesh = mesh_scene(closed_cube(), {.patch_size = 0.5});
    const size_t n = mesh.patches.size();
    const std::vector<double> f = hemicube_form_factors(mesh, 128);
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j) {
            const Patch& p = mesh.patches[i];
            const Patch& q = mesh.patches[j];
            const Polygon target(q.corners.begin(), q.corners.begin() + q.corner_count);
            const double lambert =
                i == j ? 0.0 : point_to_polygon(p.centre, mesh.elements[p.element].normal, target);
            EXPECT_NEAR(f[i * n + j], lambert, 3e-3) << i << " -> " << j;
        }
}

TEST(Hemicube, UnitSquareOneAboveConvergesOnLamberts0239456) {
    const Mesh mesh = mesh_scene(hemicube_square_pair(), {.patch_size = 1});
    ASSERT_EQ(mesh.patches.size(), 2u);
    const double lambert = 0.239456;
    double previous = 1;
    for (const int resolution : {8, 32, 128, 512}) {
        const double f = hemicube_form_factors(mesh, resolution)[0 * 2 + 1];
        const double error = std::abs(f - lambert);
        EXPECT_NEAR(f, 0.24, 0.01) << "resolution " << resolution;
        EXPECT_LT(error, previous) << "resolution " << resolution;
        previous = error;
    }
    EXPECT_LT(previous, 1e-4);
}

TEST(Hemicube, AnOccluderAndABackFaceBlockButOnlyTheFrontIsCredited) {
    Scene s = hemicube_square_pair();
    // a small square halfway up, facing the floor, and one facing away, 0.1 above it
    add_hemicube_face(s, {{0.4, 0.4, 0.5}, {0.4, 0.6, 0.5}, {0.6, 0.6, 0.5}, {0.6, 0.4, 0.5}});
    add_hemicube_face(s, {{0.4, 0.4, 0.6}, {0.6, 0.4, 0.6}, {0.6, 0.6, 0.6}, {0.4, 0.6, 0.6}});
    const Mesh mesh = mesh_scene(s, {.patch_size = 1});
    ASSERT_EQ(mesh.patches.size(), 4u);
    const std::vector<double> f = hemicube_form_factors(mesh, 256);
    const Polygon blocker = {{0.4, 0.4, 0.5}, {0.4, 0.6, 0.5}, {0.6, 0.6, 0.5}, {0.6, 0.4, 0.5}};
    const double blocked = point_to_polygon({0.5, 0.5, 0}, {0, 0, 1}, blocker);
    // the blocker spans ~51 cells each way at 256: a cell of aliasing on each side
    EXPECT_NEAR(f[0 * 4 + 2], blocked, 2e-3);
    EXPECT_NEAR(f[0 * 4 + 1], 0.239456 - blocked, 2e-3);
    EXPECT_NEAR(f[0 * 4 + 1] + f[0 * 4 + 2], 0.239456, 2e-4);
    EXPECT_EQ(f[0 * 4 + 3], 0.0);  // hidden behind the blocker
    // from the ceiling, the upper square shows its front and hides the lower one's back
    EXPECT_GT(f[1 * 4 + 3], 0.0);
    EXPECT_EQ(f[1 * 4 + 2], 0.0);
}

TEST(Hemicube, CellsTestedGrowAsResolutionSquared) {
    const Mesh mesh = mesh_scene(closed_cube(), {.patch_size = 0.5});
    HemicubeCounts low, high;
    hemicube_form_factors(mesh, 32, low);
    hemicube_form_factors(mesh, 64, high);
    // the cube is closed: every cell of every hemicube sees something, about once
    const double per_cube_low = 32.0 * 32 * 3, per_cube_high = 64.0 * 64 * 3;
    EXPECT_NEAR(static_cast<double>(low.cells_tested) / (24 * per_cube_low), 1.0, 0.25);
    EXPECT_NEAR(static_cast<double>(high.cells_tested) / static_cast<double>(low.cells_tested),
                per_cube_high / per_cube_low, 0.2);
    EXPECT_EQ(low.patches_rasterised, high.patches_rasterised);
}

TEST(Hemicube, ResolutionMustBeEven) {
    const Mesh mesh = mesh_scene(hemicube_square_pair(), {.patch_size = 1});
    EXPECT_THROW(hemicube_form_factors(mesh, 7), std::invalid_argument);
    EXPECT_THROW(hemicube_form_factors(mesh, 0), std::invalid_argument);
}

}  // namespace
}  // namespace fb89::host
