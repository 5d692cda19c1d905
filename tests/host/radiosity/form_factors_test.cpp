// Centre-to-centre form factors: reciprocity of the point form, zero for pairs that do not
// face or are hidden, and the convergence REFERENCES.md states against the exact values:
// O(h²) between parallel squares, only O(h) across a shared edge, where the disk form
// stays bounded.
#include "host/radiosity/form_factors.h"

#include <cmath>

#include <gtest/gtest.h>

#include "host/radiosity/exact.h"

namespace fb89::host {
namespace {

constexpr double kParallelUnitSquares = 0.199825;       // Howell C-11, c = 1
constexpr double kPerpendicularUnitSquares = 0.200044;  // Howell C-14, w = h = 1

void add_face(Scene& s, std::vector<glm::dvec3> v) {
    Face f;
    f.vertices = std::move(v);
    f.id = static_cast<uint32_t>(s.faces.size());
    s.faces.push_back(f);
    s.face_count = static_cast<uint32_t>(s.faces.size());
}

// The unit floor (normal +z) and either the ceiling at height 1 (normal −z) or the wall
// over the floor's edge y = 0 (normal +y).
Scene square_pair(bool perpendicular) {
    Scene s;
    add_face(s, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    if (perpendicular)
        add_face(s, {{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}});
    else
        add_face(s, {{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}});
    return s;
}

Mesh mesh_of(const Scene& s, int per_side) {
    return mesh_scene(s, {.patch_size = 1.0 / per_side, .max_per_side = 64});
}

Visibility all_facing_visible(const Mesh& mesh) {
    const auto n = static_cast<uint32_t>(mesh.patches.size());
    Visibility v(n);
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            if (facing(mesh, i, j)) v.set(i, j, Delta::Visible);
    return v;
}

// F from the first face to the second by centre estimates over the meshed faces:
// Σ_i Σ_j A_i F_ij / A_face.
double face_to_face(const Mesh& mesh, CentreForm form) {
    double sum = 0, area = 0;
    for (const Patch& p : mesh.patches) {
        if (p.element != 0) continue;
        area += p.area;
        for (const Patch& q : mesh.patches)
            if (q.element == 1)
                sum += p.area * centre_form_factor(p, mesh.elements[0].normal, q,
                                                   mesh.elements[1].normal, form);
    }
    return sum / area;
}

double relative_error(double estimate, double exact) {
    return (estimate - exact) / exact;
}

TEST(CentreFormFactor, PointFormIsReciprocalTo1e12) {
    const Mesh mesh = mesh_of(square_pair(true), 4);
    const Visibility delta = all_facing_visible(mesh);
    const std::vector<double> f = centre_form_factors(mesh, delta, CentreForm::PointToPoint);
    const size_t n = mesh.patches.size();
    int checked = 0;
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < n; ++j) {
            const double aij = mesh.patches[i].area * f[i * n + j];
            const double aji = mesh.patches[j].area * f[j * n + i];
            EXPECT_NEAR(aij, aji, 1e-12 * std::max(aij, aji)) << i << " " << j;
            checked += aij > 0;
        }
    EXPECT_EQ(checked, 2 * 16 * 16);
}

TEST(CentreFormFactor, IsTheFormulaAndZeroWhenEitherCosineIsNotPositive) {
    Patch a, b;
    a.centre = {0, 0, 0};
    b.centre = {0, 0, 2};
    a.area = 0.5;
    b.area = 0.25;
    const glm::dvec3 up{0, 0, 1}, down{0, 0, -1};
    const double pi = std::acos(-1.0);
    EXPECT_DOUBLE_EQ(centre_form_factor(a, up, b, down, CentreForm::PointToPoint), 0.25 / (pi * 4));
    EXPECT_DOUBLE_EQ(centre_form_factor(a, up, b, down, CentreForm::Disk), 0.25 / (pi * 4 + 0.25));
    EXPECT_EQ(centre_form_factor(a, up, b, up, CentreForm::PointToPoint), 0.0);      // b's back
    EXPECT_EQ(centre_form_factor(a, down, b, down, CentreForm::PointToPoint), 0.0);  // a's back
    EXPECT_EQ(centre_form_factor(a, {1, 0, 0}, b, down, CentreForm::Disk), 0.0);     // grazing
}

TEST(CentreFormFactor, HiddenAndNotFacingPairsGetZero) {
    const Mesh mesh = mesh_of(square_pair(false), 2);
    Visibility delta = all_facing_visible(mesh);
    delta.set(0, 4, Delta::Hidden);
    delta.set(1, 5, Delta::NotFacing);
    const std::vector<double> f = centre_form_factors(mesh, delta, CentreForm::Disk);
    const size_t n = mesh.patches.size();
    EXPECT_EQ(f[0 * n + 4], 0.0);
    EXPECT_EQ(f[4 * n + 0], 0.0);
    EXPECT_EQ(f[1 * n + 5], 0.0);
    EXPECT_GT(f[0 * n + 5], 0.0);
    EXPECT_EQ(f[0 * n + 1], 0.0);  // coplanar patches of one face
    EXPECT_EQ(f[0], 0.0);
}

// REFERENCES.md: +1.9% at n = 4, +0.1% at n = 16, O(h²).
TEST(CentreFormFactor, ParallelSquaresConvergeAsHSquared) {
    const double e4 =
        relative_error(face_to_face(mesh_of(square_pair(false), 4), CentreForm::PointToPoint),
                       kParallelUnitSquares);
    const double e16 =
        relative_error(face_to_face(mesh_of(square_pair(false), 16), CentreForm::PointToPoint),
                       kParallelUnitSquares);
    EXPECT_NEAR(e4, 0.019, 0.002);
    EXPECT_NEAR(e16, 0.001, 0.0005);
    // a quarter of h: about a sixteenth of the error
    EXPECT_GT(e4 / e16, 12.0);
    EXPECT_LT(e4 / e16, 20.0);
}

// REFERENCES.md: +4.2% at n = 16, +1.1% at n = 64, only O(h).
TEST(CentreFormFactor, PerpendicularSquaresWithASharedEdgeConvergeOnlyAsH) {
    const double e16 =
        relative_error(face_to_face(mesh_of(square_pair(true), 16), CentreForm::PointToPoint),
                       kPerpendicularUnitSquares);
    const double e64 =
        relative_error(face_to_face(mesh_of(square_pair(true), 64), CentreForm::PointToPoint),
                       kPerpendicularUnitSquares);
    EXPECT_NEAR(e16, 0.042, 0.003);
    EXPECT_NEAR(e64, 0.011, 0.002);
    // a quarter of h: about a quarter of the error
    EXPECT_GT(e16 / e64, 3.5);
    EXPECT_LT(e16 / e64, 4.5);
}

// Strips 1 long and h wide on either side of a shared edge: the point form grows as
// 1/(π h), the disk form stays under ½.
TEST(CentreFormFactor, DiskFormStaysBoundedForAdjacentPatches) {
    for (const double h : {0.1, 0.01, 0.001}) {
        Patch floor, wall;
        floor.centre = {0.5, h / 2, 0};
        wall.centre = {0.5, 0, h / 2};
        floor.area = wall.area = h;
        const glm::dvec3 up{0, 0, 1}, ahead{0, 1, 0};
        const double point = centre_form_factor(floor, up, wall, ahead, CentreForm::PointToPoint);
        const double disk = centre_form_factor(floor, up, wall, ahead, CentreForm::Disk);
        EXPECT_NEAR(point, 1 / (std::acos(-1.0) * h), 1e-9 / h);
        EXPECT_LT(disk, 0.5);
        EXPECT_GT(disk, 0.3);
    }
    // and on the meshed shared edge, the disk form's error stays small, row sums below 1
    const Mesh mesh = mesh_of(square_pair(true), 16);
    const double e =
        relative_error(face_to_face(mesh, CentreForm::Disk), kPerpendicularUnitSquares);
    EXPECT_LT(std::abs(e), 0.05);
    const std::vector<double> f =
        centre_form_factors(mesh, all_facing_visible(mesh), CentreForm::Disk);
    const size_t n = mesh.patches.size();
    for (size_t i = 0; i < n; ++i) {
        double row = 0;
        for (size_t j = 0; j < n; ++j)
            row += f[i * n + j];
        EXPECT_LT(row, 1.0) << "patch " << i;
    }
}

}  // namespace
}  // namespace fb89::host
