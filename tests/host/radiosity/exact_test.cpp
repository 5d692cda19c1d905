// The exact form factors against REFERENCES.md's oracles: Howell C-11 and C-14 in closed
// form, Lambert's point-to-polygon value, the closed cube, reciprocity and bounds, and
// additivity over triangles, which takes the quadrature path (edges neither parallel nor
// perpendicular, edges meeting at vertices) to the same closed-form values.
#include "host/radiosity/exact.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace fb89::host {
namespace {

using Polygon = std::vector<glm::dvec3>;

const double kPi = std::acos(-1.0);

// Howell C-11: parallel, directly opposed a x b rectangles at distance c.
double howell_c11(double a, double b, double c) {
    const double x = a / c, y = b / c;
    const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
    return 2 / (kPi * x * y) *
           (std::log(std::sqrt((1 + x * x) * (1 + y * y) / (1 + x * x + y * y))) +
            x * sy * std::atan(x / sy) + y * sx * std::atan(y / sx) - x * std::atan(x) -
            y * std::atan(y));
}

// Howell C-14: from a w x l rectangle to an h x l one, perpendicular, sharing the edge l.
double howell_c14(double l, double w, double h) {
    const double W = w / l, H = h / l, w2 = W * W, h2 = H * H, s = w2 + h2;
    const double log_term = std::log((1 + w2) * (1 + h2) / (1 + s)) +
                            w2 * std::log(w2 * (1 + s) / ((1 + w2) * s)) +
                            h2 * std::log(h2 * (1 + s) / ((1 + h2) * s));
    return 1 / (kPi * W) *
           (W * std::atan(1 / W) + H * std::atan(1 / H) -
            std::sqrt(s) * std::atan(1 / std::sqrt(s)) + 0.25 * log_term);
}

// a x b in z = 0 (normal +z), its opposite at height c (normal −z), and the c-high wall
// over its edge y = 0 (normal +y).
Polygon floor_rect(double a, double b) {
    return {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}};
}
Polygon ceiling_rect(double a, double b, double c) {
    return {{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}};
}
Polygon wall_rect(double a, double c) {
    return {{0, 0, 0}, {0, 0, c}, {a, 0, c}, {a, 0, 0}};
}

double area(const Polygon& p) {
    glm::dvec3 n(0);
    for (size_t k = 0; k < p.size(); ++k)
        n += glm::cross(p[k], p[(k + 1) % p.size()]);
    return 0.5 * glm::length(n);
}

// The fan of triangles from `apex` (inside or on the boundary of convex `poly`).
std::vector<Polygon> fan(const Polygon& poly, const glm::dvec3& apex) {
    std::vector<Polygon> out;
    for (size_t k = 0; k < poly.size(); ++k) {
        const Polygon t = {apex, poly[k], poly[(k + 1) % poly.size()]};
        if (area(t) > 1e-12) out.push_back(t);
    }
    return out;
}

TEST(ExactFormFactor, ParallelUnitSquaresMatchHowellC11) {
    EXPECT_NEAR(polygon_to_polygon(floor_rect(1, 1), ceiling_rect(1, 1, 1)), 0.199825, 1e-6);
    EXPECT_NEAR(polygon_to_polygon(floor_rect(1, 1), ceiling_rect(1, 1, 2)), 0.068590, 1e-6);
    EXPECT_NEAR(polygon_to_polygon(floor_rect(1, 1), ceiling_rect(1, 1, 0.5)), 0.415253, 1e-6);
}

TEST(ExactFormFactor, ParallelRectanglesMatchTheC11FormulaForOtherSizes) {
    for (const double a : {0.3, 1.0, 2.5})
        for (const double b : {0.7, 4.0})
            for (const double c : {0.2, 1.0, 3.0})
                EXPECT_NEAR(polygon_to_polygon(floor_rect(a, b), ceiling_rect(a, b, c)),
                            howell_c11(a, b, c), 1e-9)
                    << a << " x " << b << " at " << c;
}

TEST(ExactFormFactor, PerpendicularSquaresSharingAnEdgeMatchHowellC14) {
    EXPECT_NEAR(polygon_to_polygon(floor_rect(1, 1), wall_rect(1, 1)), 0.200044, 1e-6);
    EXPECT_NEAR(polygon_to_polygon(floor_rect(1, 1), wall_rect(1, 2)), 0.232853, 1e-6);
    for (const double l : {0.5, 2.0})
        for (const double w : {0.3, 1.0})
            for (const double h : {0.25, 3.0})
                EXPECT_NEAR(polygon_to_polygon(floor_rect(l, w), wall_rect(l, h)),
                            howell_c14(l, w, h), 1e-9)
                    << l << " " << w << " " << h;
}

TEST(ExactFormFactor, OneFaceOfAClosedCubeSeesTheOtherFiveWithSumOne) {
    const Polygon floor = floor_rect(1, 1);
    const std::vector<Polygon> others = {ceiling_rect(1, 1, 1),
                                         wall_rect(1, 1),                                // y = 0
                                         {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}},   // y = 1
                                         {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}},   // x = 0
                                         {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}};  // x = 1
    double sum = 0;
    for (const Polygon& p : others)
        sum += polygon_to_polygon(floor, p);
    EXPECT_NEAR(sum, 1.0, 1e-6);
}

TEST(ExactFormFactor, PointUnderAUnitSquaresCentreAtHeightOneSees0239456) {
    const Polygon square = ceiling_rect(1, 1, 1);
    EXPECT_NEAR(point_to_polygon({0.5, 0.5, 0}, {0, 0, 1}, square), 0.239456, 1e-6);
    // the winding does not matter; the part behind the point does not count
    EXPECT_NEAR(point_to_polygon({0.5, 0.5, 0}, {0, 0, 1}, floor_rect(1, 1) /* in plane */), 0.0,
                1e-12);
    const Polygon straddling = {{0, 0, -1}, {0, 1, -1}, {1, 1, 1}, {1, 0, 1}};
    const Polygon front_half = {{0.5, 0, 0}, {0.5, 1, 0}, {1, 1, 1}, {1, 0, 1}};
    EXPECT_NEAR(point_to_polygon({0.5, 0.5, 0}, {0, 0, 1}, straddling),
                point_to_polygon({0.5, 0.5, 0}, {0, 0, 1}, front_half), 1e-12);
}

// Triangles put edges at 45° and other angles to the square's, meeting at vertices on the
// shared edge and inside it: the quadrature path must add up to the closed forms.
TEST(ExactFormFactor, TrianglesAddUpToTheirSquareThroughTheQuadraturePath) {
    const Polygon floor = floor_rect(1, 1), ceiling = ceiling_rect(1, 1, 1), wall = wall_rect(1, 1);
    for (const glm::dvec3 apex : {glm::dvec3(0.5, 0.5, 0), glm::dvec3(0.8, 0.3, 0),
                                  glm::dvec3(0.3, 0, 0), glm::dvec3(1, 1, 0)}) {
        double to_ceiling = 0, to_wall = 0;
        for (const Polygon& t : fan(floor, apex)) {
            to_ceiling += area(t) * polygon_to_polygon(t, ceiling);
            to_wall += area(t) * polygon_to_polygon(t, wall);
        }
        EXPECT_NEAR(to_ceiling, howell_c11(1, 1, 1), 1e-9);
        EXPECT_NEAR(to_wall, howell_c14(1, 1, 1), 1e-9);
    }
    for (const glm::dvec3 apex : {glm::dvec3(0.6, 0, 0.4), glm::dvec3(0, 0, 0)}) {
        double to_wall = 0;
        for (const Polygon& t : fan(wall, apex))
            to_wall += polygon_to_polygon(floor, t);
        EXPECT_NEAR(to_wall, howell_c14(1, 1, 1), 1e-9);
    }
}

// A general pair against Lambert's formula integrated over the source by Gauss–Legendre
// on a fan of triangles (Duffy's map), where the source is wholly in front of the target.
double lambert_integrated(const Polygon& from, const Polygon& to, int n) {
    std::vector<double> x(n), w(n);
    for (int k = 0; k < n; ++k) {  // Gauss–Legendre on [0, 1]
        double z = std::cos(kPi * (k + 0.75) / (n + 0.5)), dp = 1;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1, p1 = z;
            for (int m = 2; m <= n; ++m) {
                const double p2 = ((2 * m - 1) * z * p1 - (m - 1) * p0) / m;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (z * p1 - p0) / (z * z - 1);
            z -= p1 / dp;
        }
        x[k] = 0.5 * (1 - z);
        w[k] = 1 / ((1 - z * z) * dp * dp);
    }
    const glm::dvec3 normal = glm::normalize(glm::cross(from[1] - from[0], from[2] - from[0]));
    double sum = 0;
    for (const Polygon& t : fan(from, from[0]))
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const glm::dvec3 p = t[0] + x[i] * (t[1] - t[0]) + x[i] * x[j] * (t[2] - t[1]);
                sum += w[i] * w[j] * 2 * area(t) * x[i] * point_to_polygon(p, normal, to);
            }
    return sum / area(from);
}

TEST(ExactFormFactor, SkewQuadrilateralsAgreeWithLambertIntegratedReciprocalAndBounded) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    const Polygon from = {{0, 0, 0}, {1, 0, 0}, {1.2, 0.9, 0}, {-0.1, 1.1, 0}};
    int tested = 0;
    while (tested < 6) {
        const glm::dvec3 o(u(rng), u(rng), 1.5 + 0.5 * u(rng));
        const glm::dvec3 e1 = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
        const glm::dvec3 e2 = glm::normalize(glm::cross(e1, glm::dvec3(u(rng), u(rng), u(rng))));
        const Polygon to = {o, o + e1, o + e1 + 0.7 * e2, o + 0.5 * e2};
        const glm::dvec3 nt = glm::cross(to[1] - to[0], to[2] - to[0]);
        bool wholly_in_front = true;
        for (const glm::dvec3& p : from)
            wholly_in_front &= glm::dot(p - to[0], nt) > 0;
        if (!wholly_in_front) continue;
        const double fij = polygon_to_polygon(from, to), fji = polygon_to_polygon(to, from);
        EXPECT_NEAR(fij, lambert_integrated(from, to, 24), 1e-9);
        EXPECT_NEAR(area(from) * fij, area(to) * fji, 1e-12);
        EXPECT_GE(fij, 0.0);
        EXPECT_LE(fij, 1.0);
        ++tested;
    }
}

TEST(ExactFormFactor, PolygonsFacingAwayOrCoplanarExchangeNothing) {
    EXPECT_EQ(polygon_to_polygon(floor_rect(1, 1), floor_rect(1, 1)), 0.0);
    Polygon back = ceiling_rect(1, 1, 1);
    std::reverse(back.begin(), back.end());  // now facing up, away from the floor
    EXPECT_EQ(polygon_to_polygon(floor_rect(1, 1), back), 0.0);
    const Polygon beside = {{2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}};
    EXPECT_EQ(polygon_to_polygon(floor_rect(1, 1), beside), 0.0);
}

// The unit cube with inward faces, meshed 2 x 2: every row of the exact matrix sums to 1.
TEST(ExactFormFactors, MeshedClosedCubeRowsSumToOneAndRespectDelta) {
    Scene s;
    const std::vector<Polygon> faces = {floor_rect(1, 1),
                                        ceiling_rect(1, 1, 1),
                                        wall_rect(1, 1),
                                        {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}},
                                        {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}},
                                        {{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}};
    for (const Polygon& p : faces) {
        Face f;
        f.vertices = p;
        f.id = static_cast<uint32_t>(s.faces.size());
        s.faces.push_back(f);
    }
    const Mesh mesh = mesh_scene(s, {.patch_size = 0.5});
    const auto n = static_cast<uint32_t>(mesh.patches.size());
    ASSERT_EQ(n, 24u);
    Visibility delta(n);
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            if (facing(mesh, i, j)) delta.set(i, j, Delta::Visible);
    std::vector<double> f = exact_form_factors(mesh, delta);
    for (uint32_t i = 0; i < n; ++i) {
        double row = 0;
        for (uint32_t j = 0; j < n; ++j) {
            row += f[i * n + j];
            EXPECT_NEAR(mesh.patches[i].area * f[i * n + j], mesh.patches[j].area * f[j * n + i],
                        1e-15);
        }
        EXPECT_NEAR(row, 1.0, 1e-6) << "patch " << i;
    }
    delta.set(0, 23, Delta::Hidden);
    f = exact_form_factors(mesh, delta);
    EXPECT_EQ(f[0 * n + 23], 0.0);
    EXPECT_EQ(f[23 * n + 0], 0.0);
}

}  // namespace
}  // namespace fb89::host
