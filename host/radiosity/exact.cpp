// Exact unoccluded form factors, the oracles the centre estimate and the hemicube are
// measured against (REFERENCES.md "Form-factor oracles").
//
// Point to polygon is Lambert's formula (Baum, Rushmeier and Winget 1989), on the part of
// the polygon in front of the point. Polygon to polygon is the contour integral
//     A_i F_ij = (1 / 2π) ∮_i ∮_j ln r  dx_i · dx_j
// (Stokes, as in Schröder and Hanrahan 1993), summed over pairs of edges. Ours differs from
// their closed form in how each pair is integrated:
//   - parallel edges (collinear, shared or not) in closed form, with
//     Ψ(z) = ¼ (z² − d²) ln(z² + d²) − ¾ z² + d z atan(z / d), Ψ'' = ln √(z² + d²),
//     whose d = 0 case gives the shared edge's L² (ln L − 3/2);
//   - other pairs with the inner integral in closed form and the outer by quadrature:
//     16-point Gauss–Legendre where the edges are far apart for their length, otherwise
//     tanh-sinh on the edge split at its point nearest the other edge, which takes the
//     logarithmic singularity of edges meeting at a vertex at an end of each piece.
// Each polygon is first clipped to the front of the other's plane, so pairs that face each
// other only in part get the exact value of the part (the cosines are then both ≥ 0).
#include "host/radiosity/exact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "host/scene/polygon.h"

namespace fb89::host {

namespace {

constexpr double kPi = std::numbers::pi;

using Polygon = std::vector<glm::dvec3>;

// The part of `poly` (convex) on the front side of the plane through `origin` with
// normal `normal`; vertices within `tolerance` of the plane count as on it, and a polygon
// with no vertex in front (one lying in the plane) leaves nothing.
Polygon clip_to_front(const Polygon& poly, const glm::dvec3& origin, const glm::dvec3& normal,
                      double tolerance) {
    Polygon out;
    const size_t n = poly.size();
    auto side = [&](const glm::dvec3& p) {
        const double d = glm::dot(p - origin, normal);
        return std::abs(d) <= tolerance ? 0.0 : d;
    };
    bool any_in_front = false;
    for (const glm::dvec3& p : poly)
        any_in_front = any_in_front || side(p) > 0;
    if (!any_in_front) return out;
    for (size_t k = 0; k < n; ++k) {
        const glm::dvec3& a = poly[k];
        const glm::dvec3& b = poly[(k + 1) % n];
        const double da = side(a), db = side(b);
        if (da >= 0) out.push_back(a);
        if ((da > 0 && db < 0) || (da < 0 && db > 0)) out.push_back(a + (b - a) * (da / (da - db)));
    }
    return out;
}

// ---- quadrature rules on [0, 1] ----

struct Node {
    double x;  // abscissa in [0, 1]
    double w;
};

// Gauss–Legendre, 16 points, by Newton's iteration on P_16.
const std::array<Node, 16>& gauss_legendre_16() {
    static const std::array<Node, 16> rule = [] {
        constexpr int n = 16;
        std::array<Node, n> r{};
        for (int k = 0; k < n; ++k) {
            double x = std::cos(kPi * (k + 0.75) / (n + 0.5));
            double dp = 0;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = x;
                for (int m = 2; m <= n; ++m) {
                    const double p2 = ((2 * m - 1) * x * p1 - (m - 1) * p0) / m;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n * (x * p1 - p0) / (x * x - 1);
                const double dx = p1 / dp;
                x -= dx;
                if (std::abs(dx) < 1e-16) break;
            }
            r[k] = {0.5 * (1 - x), 1 / ((1 - x * x) * dp * dp)};  // half the weight on [-1, 1]
        }
        return r;
    }();
    return rule;
}

// Tanh-sinh (double exponential) nodes in pairs symmetric about ½, kept as the distance
// `x` from the nearer end so that points close to a singular end are exact.
struct TanhSinh {
    double centre_weight = 0;
    std::vector<Node> pairs;
};

const TanhSinh& tanh_sinh() {
    static const TanhSinh rule = [] {
        constexpr double step = 1.0 / 8;  // ~50 nodes: exact to ~1e-15 on the tests
        TanhSinh r;
        r.centre_weight = step * 0.5 * (kPi / 2);
        for (int k = 1;; ++k) {
            const double t = k * step;
            const double y = (kPi / 2) * std::sinh(t);
            const double w = step * 0.5 * (kPi / 2) * std::cosh(t) / (std::cosh(y) * std::cosh(y));
            const double x = 1 / (1 + std::exp(2 * y));
            if (w < 1e-20 || x < 1e-300) break;
            r.pairs.push_back({x, w});
        }
        return r;
    }();
    return rule;
}

// ---- the logarithmic kernel along edges ----

struct Edge {
    glm::dvec3 start;
    glm::dvec3 dir;  // unit
    double length;
};

// ∫ ln √(x² + h²) dx, the antiderivative.
double line_log_antiderivative(double x, double h) {
    const double q = x * x + h * h;
    const double log_term = q > 0 ? 0.5 * x * std::log(q) : 0.0;
    const double atan_term = h > 0 ? h * std::atan(x / h) : 0.0;
    return log_term - x + atan_term;
}

// ∫₀ᴸ ln |p − (b.start + t b.dir)| dt.
double log_integral_to_edge(const glm::dvec3& p, const Edge& b) {
    const glm::dvec3 w = p - b.start;
    const double u = glm::dot(w, b.dir);
    const double h = glm::length(glm::cross(w, b.dir));
    return line_log_antiderivative(b.length - u, h) - line_log_antiderivative(-u, h);
}

// Ψ(z) with Ψ''(z) = ln √(z² + d²).
double parallel_log_kernel(double z, double d) {
    const double q = z * z + d * d;
    const double log_term = q > 0 ? 0.25 * (z * z - d * d) * std::log(q) : 0.0;
    const double atan_term = d > 0 ? d * z * std::atan(z / d) : 0.0;
    return log_term - 0.75 * z * z + atan_term;
}

// ∫∫ ln r ds dt over two parallel edges, in closed form.
double parallel_edges_log_integral(const Edge& a, const Edge& b) {
    const glm::dvec3 w = b.start - a.start;
    const double along = glm::dot(w, a.dir);
    const double d = glm::length(w - along * a.dir);
    const double sense = glm::dot(a.dir, b.dir) > 0 ? 1.0 : -1.0;
    const double y0 = std::min(along, along + sense * b.length);
    const double y1 = std::max(along, along + sense * b.length);
    const double x0 = 0, x1 = a.length;
    return -(parallel_log_kernel(x1 - y1, d) - parallel_log_kernel(x1 - y0, d) -
             parallel_log_kernel(x0 - y1, d) + parallel_log_kernel(x0 - y0, d));
}

// The parameter along `a` (0..a.length) of its point nearest segment `b`, and the distance.
std::pair<double, double> nearest_on_edge(const Edge& a, const Edge& b) {
    const glm::dvec3 r = a.start - b.start;
    const double c = glm::dot(a.dir, b.dir);
    const double e = glm::dot(a.dir, r), f = glm::dot(b.dir, r);
    const double denom = 1 - c * c;  // > 0: the edges are not parallel here
    double s = std::clamp((c * f - e) / denom, 0.0, a.length);
    double t = std::clamp(s * c + f, 0.0, b.length);
    s = std::clamp(t * c - e, 0.0, a.length);
    t = std::clamp(s * c + f, 0.0, b.length);
    const double distance = glm::length(a.start + s * a.dir - b.start - t * b.dir);
    return {s, distance};
}

// ∫ over [lo, hi] of a of the inner integral over b: Gauss–Legendre when the edges are
// at least half of a's length apart (the integrand's nearest complex singularity is then
// far enough for 16 points to reach ~1e-12), else tanh-sinh, whose nodes crowd at both
// ends, where the caller puts the near approach.
double outer_integral(const Edge& a, const Edge& b, double lo, double hi, bool smooth) {
    const double len = hi - lo;
    auto g = [&](double s) { return log_integral_to_edge(a.start + s * a.dir, b); };
    double sum = 0;
    if (smooth) {
        for (const Node& q : gauss_legendre_16())
            sum += q.w * g(lo + len * q.x);
        return len * sum;
    }
    const TanhSinh& ts = tanh_sinh();
    sum = ts.centre_weight * g(lo + 0.5 * len);
    for (const Node& q : ts.pairs)
        sum += q.w * (g(lo + len * q.x) + g(hi - len * q.x));
    return len * sum;
}

// ∫₀^La ∫₀^Lb ln |a(s) − b(t)| dt ds.
double edge_pair_log_integral(const Edge& a, const Edge& b) {
    if (glm::length(glm::cross(a.dir, b.dir)) < 1e-9) return parallel_edges_log_integral(a, b);
    const auto [s, gap] = nearest_on_edge(a, b);
    if (gap >= 0.5 * a.length) return outer_integral(a, b, 0, a.length, true);
    // split where the edges come nearest (a shared vertex, a crossing)
    double sum = 0;
    if (s > 0) sum += outer_integral(a, b, 0, s, false);
    if (s < a.length) sum += outer_integral(a, b, s, a.length, false);
    return sum;
}

std::vector<Edge> edges_of(const Polygon& poly, double min_length) {
    std::vector<Edge> edges;
    for (size_t k = 0; k < poly.size(); ++k) {
        const glm::dvec3 d = poly[(k + 1) % poly.size()] - poly[k];
        const double len = glm::length(d);
        if (len > min_length) edges.push_back({poly[k], d / len, len});
    }
    return edges;
}

Polygon patch_polygon(const Patch& p) {
    return Polygon(p.corners.begin(), p.corners.begin() + p.corner_count);
}

}  // namespace

double point_to_polygon(const glm::dvec3& p, const glm::dvec3& n, const Polygon& poly) {
    double scale = 0;
    for (const glm::dvec3& v : poly)
        scale = std::max(scale, glm::length(v - p));
    const Polygon front = clip_to_front(poly, p, n, 1e-12 * scale);
    if (front.size() < 3) return 0;
    // sum of β_i (n · Γ_i) over the edges as seen from p
    double sum = 0;
    for (size_t k = 0; k < front.size(); ++k) {
        const glm::dvec3 r0 = front[k] - p, r1 = front[(k + 1) % front.size()] - p;
        const glm::dvec3 c = glm::cross(r0, r1);
        const double len = glm::length(c);
        if (!(len > 0)) continue;
        const double beta = std::atan2(len, glm::dot(r0, r1));
        sum += beta * glm::dot(n, c) / len;
    }
    return std::abs(sum) / (2 * kPi);
}

double polygon_to_polygon(const Polygon& from, const Polygon& to) {
    if (from.size() < 3 || to.size() < 3) return 0;
    // work in coordinates of order 1: the contour sum is invariant under scaling
    const glm::dvec3 origin = from[0];
    double scale = 0;
    for (const glm::dvec3& v : from)
        scale = std::max(scale, glm::length(v - origin));
    for (const glm::dvec3& v : to)
        scale = std::max(scale, glm::length(v - origin));
    if (!(scale > 0)) return 0;
    Polygon f, t;
    for (const glm::dvec3& v : from)
        f.push_back((v - origin) / scale);
    for (const glm::dvec3& v : to)
        t.push_back((v - origin) / scale);
    const glm::dvec3 nf = newell_normal(f), nt = newell_normal(t);
    const double area_from = 0.5 * glm::length(nf);
    if (!(area_from > 0) || !(glm::length(nt) > 0)) return 0;
    // clip each to the front of the other
    constexpr double kOnPlane = 1e-12;
    const Polygon fc = clip_to_front(f, t[0], glm::normalize(nt), kOnPlane);
    const Polygon tc = clip_to_front(t, f[0], glm::normalize(nf), kOnPlane);
    if (fc.size() < 3 || tc.size() < 3) return 0;
    // sum over pairs of edges
    const std::vector<Edge> ef = edges_of(fc, 1e-14), et = edges_of(tc, 1e-14);
    double sum = 0;
    for (const Edge& a : ef)
        for (const Edge& b : et) {
            const double c = glm::dot(a.dir, b.dir);
            if (std::abs(c) < 1e-15) continue;
            sum += c * edge_pair_log_integral(a, b);
        }
    return std::clamp(sum / (2 * kPi * area_from), 0.0, 1.0);
}

std::vector<double> exact_form_factors(const Mesh& mesh, const Visibility& delta,
                                       const WorkObserver& work) {
    const size_t n = mesh.patches.size();
    if (delta.size() != n)
        throw std::invalid_argument("exact_form_factors: visibility is for another mesh");
    std::vector<double> f(n * n, 0.0);
    for (uint32_t i = 0; i < n; ++i) {
        const Patch& pi = mesh.patches[i];
        const Polygon poly_i = patch_polygon(pi);
        for (uint32_t j = i + 1; j < n; ++j) {
            if (delta.get(i, j) != Delta::Visible) continue;
            const Patch& pj = mesh.patches[j];
            const double fij = polygon_to_polygon(poly_i, patch_polygon(pj));
            f[i * n + j] = fij;
            f[j * n + i] = pj.area > 0 ? fij * pi.area / pj.area : 0.0;  // reciprocity
        }
        if (work) work(pairs_before(n, i + 1), pairs_before(n, n));
    }
    return f;
}

}  // namespace fb89::host
