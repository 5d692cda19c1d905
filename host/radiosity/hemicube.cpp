// The hemicube (Cohen and Greenberg 1985), the baseline the paper's §5 sets flux tracing
// against. Over each patch centre, oriented by its element's normal n, five faces: the top
// at distance 1 (resolution² cells over [-1, 1]²) and four sides (resolution x
// resolution/2 cells over [-1, 1] x [0, 1], up along n). Each cell carries its delta form
// factor at the cell centre, not renormalised (they sum to 1 only as the cells shrink):
//     top:  ΔA / (π (x² + y² + 1)²),   side:  z ΔA / (π (y² + z² + 1)²).
// Every other patch is clipped to the face's near plane (depth > ε), projected, and scan
// converted as a convex polygon, sampling cell centres (half-open: left and bottom edges
// in, right and top out, so patches sharing an edge share no cell), depth-tested on 1/z,
// which is affine over the face. A cell seeing the back of a patch is blocked but credits
// nobody, as in flux tracing, where back faces block.
#include "host/radiosity/hemicube.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace fb89::host {

namespace {

struct Point2 {
    double a, b;
};

// One face of the hemicube: `forward` is the view axis, cells are centred at
// a = -1 + (k + ½) s, b = bottom + (m + ½) s with s = 2 / resolution.
struct HemicubeFace {
    glm::dvec3 right, up, forward;
    int rows;
    double bottom;
    const std::vector<double>* delta;  // rows x resolution, row-major
};

struct HemicubeZBuffer {
    int cols = 0, rows = 0;
    std::vector<double> inv_depth;  // 0: nothing seen
    std::vector<int32_t> id;
    void clear(int r) {
        rows = r;
        std::fill_n(inv_depth.begin(), static_cast<size_t>(rows) * cols, 0.0);
        std::fill_n(id.begin(), static_cast<size_t>(rows) * cols, -1);
    }
};

// The delta form factors of the top face (side = false) or of a side face.
std::vector<double> delta_form_factors(int resolution, bool side) {
    const double s = 2.0 / resolution;
    const int rows = side ? resolution / 2 : resolution;
    std::vector<double> d(static_cast<size_t>(rows) * resolution);
    for (int m = 0; m < rows; ++m)
        for (int k = 0; k < resolution; ++k) {
            const double x = -1 + (k + 0.5) * s;
            const double y = (side ? 0.0 : -1.0) + (m + 0.5) * s;
            const double q = x * x + y * y + 1;
            d[static_cast<size_t>(m) * resolution + k] =
                (side ? y : 1.0) * s * s / (std::numbers::pi * q * q);
        }
    return d;
}

// First index whose cell centre origin + (k + ½) s is at or beyond `v`, clamped to [0, n].
int first_cell_at_or_after(double v, double origin, double s, int n) {
    const double k = std::ceil((v - origin) / s - 0.5);
    return static_cast<int>(std::clamp(k, 0.0, static_cast<double>(n)));
}

// Scan converts a convex polygon of the face's plane with inverse depth
// `plane.x a + plane.y b + plane.z`, keeping the nearest per cell.
uint64_t scan_convex(const std::array<Point2, 8>& poly, int count, const glm::dvec3& plane,
                     int32_t patch, const HemicubeFace& face, HemicubeZBuffer& z) {
    const int cols = z.cols;
    const double s = 2.0 / cols;
    double bmin = poly[0].b, bmax = poly[0].b;
    for (int k = 1; k < count; ++k)
        bmin = std::min(bmin, poly[k].b), bmax = std::max(bmax, poly[k].b);
    const int m0 = first_cell_at_or_after(bmin, face.bottom, s, face.rows);
    const int m1 = first_cell_at_or_after(bmax, face.bottom, s, face.rows);
    uint64_t tested = 0;
    for (int m = m0; m < m1; ++m) {
        // span of the row: the crossings of edges with p.b <= b < q.b
        const double b = face.bottom + (m + 0.5) * s;
        double xl = HUGE_VAL, xr = -HUGE_VAL;
        for (int k = 0; k < count; ++k) {
            Point2 p = poly[k], q = poly[(k + 1) % count];
            if (p.b > q.b) std::swap(p, q);
            if (!(p.b <= b && b < q.b)) continue;
            const double x = p.a + (b - p.b) * (q.a - p.a) / (q.b - p.b);
            xl = std::min(xl, x), xr = std::max(xr, x);
        }
        if (!(xl < xr)) continue;
        const int k0 = first_cell_at_or_after(xl, -1.0, s, cols);
        const int k1 = first_cell_at_or_after(xr, -1.0, s, cols);
        // depth test
        const size_t row = static_cast<size_t>(m) * cols;
        for (int k = k0; k < k1; ++k) {
            const double inv = plane.x * (-1 + (k + 0.5) * s) + plane.y * b + plane.z;
            if (inv > z.inv_depth[row + k]) z.inv_depth[row + k] = inv, z.id[row + k] = patch;
        }
        tested += static_cast<uint64_t>(k1 - k0);
    }
    return tested;
}

// Clips patch `j` to the face's near plane, projects it and scan converts it.
uint64_t rasterise_patch(const Mesh& mesh, uint32_t j, const glm::dvec3& eye,
                         const HemicubeFace& face, double near, HemicubeZBuffer& z) {
    const Patch& p = mesh.patches[j];
    const glm::dvec3& normal = mesh.elements[p.element].normal;
    // the patch's plane as inverse depth over the face: n·(z (a, b, 1)) = n·(p0 − eye)
    const double dist = glm::dot(normal, p.corners[0] - eye);
    if (!(std::abs(dist) > near)) return 0;  // seen edge-on
    const glm::dvec3 plane = glm::dvec3(glm::dot(normal, face.right), glm::dot(normal, face.up),
                                        glm::dot(normal, face.forward)) /
                             dist;
    // to face coordinates, clipped to depth > near (Sutherland–Hodgman on one plane)
    std::array<glm::dvec3, 4> local;
    for (int k = 0; k < p.corner_count; ++k) {
        const glm::dvec3 d = p.corners[k] - eye;
        local[k] = {glm::dot(d, face.right), glm::dot(d, face.up), glm::dot(d, face.forward)};
    }
    std::array<Point2, 8> poly;
    int count = 0;
    const int n = p.corner_count;
    for (int k = 0; k < n; ++k) {
        const glm::dvec3& a = local[k];
        const glm::dvec3& b = local[(k + 1) % n];
        if (a.z > near) poly[count++] = {a.x / a.z, a.y / a.z};
        if ((a.z > near) != (b.z > near)) {
            const glm::dvec3 c = a + (b - a) * ((near - a.z) / (b.z - a.z));
            poly[count++] = {c.x / near, c.y / near};
        }
    }
    if (count < 3) return 0;
    return scan_convex(poly, count, plane, static_cast<int32_t>(j), face, z);
}

// A unit vector perpendicular to n.
glm::dvec3 perpendicular(const glm::dvec3& n) {
    const glm::dvec3 axis = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(n, axis));
}

double mesh_extent(const Mesh& mesh) {
    double extent = 0;
    for (const Patch& p : mesh.patches)
        for (const glm::dvec3& c : p.corners)
            extent = std::max({extent, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
    return extent;
}

}  // namespace

std::vector<double> hemicube_form_factors(const Mesh& mesh, int resolution) {
    HemicubeCounts counts;
    return hemicube_form_factors(mesh, resolution, counts);
}

std::vector<double> hemicube_form_factors(const Mesh& mesh, int resolution, HemicubeCounts& counts,
                                          const WorkObserver& work) {
    if (resolution < 2 || resolution % 2 != 0)
        throw std::invalid_argument("hemicube_form_factors: resolution must be even and >= 2");
    const size_t n = mesh.patches.size();
    const std::vector<double> top = delta_form_factors(resolution, false);
    const std::vector<double> side = delta_form_factors(resolution, true);
    const double near = 1e-9 * std::max(mesh_extent(mesh), 1e-300);
    HemicubeZBuffer z;
    z.cols = resolution;
    z.inv_depth.resize(top.size());
    z.id.resize(top.size());
    std::vector<double> f(n * n, 0.0);
    std::vector<uint32_t> candidates;
    std::vector<uint8_t> front(n);
    uint64_t rasterised = 0, tested = 0;
    for (uint32_t i = 0; i < n; ++i) {
        const glm::dvec3 eye = mesh.patches[i].centre;
        const glm::dvec3 nrm = mesh.elements[mesh.patches[i].element].normal;
        const glm::dvec3 u = perpendicular(nrm), v = glm::cross(nrm, u);
        const std::array<HemicubeFace, 5> faces = {
            HemicubeFace{u, v, nrm, resolution, -1.0, &top},
            HemicubeFace{v, nrm, u, resolution / 2, 0.0, &side},
            HemicubeFace{-v, nrm, -u, resolution / 2, 0.0, &side},
            HemicubeFace{-u, nrm, v, resolution / 2, 0.0, &side},
            HemicubeFace{u, nrm, -v, resolution / 2, 0.0, &side}};
        // the patches not wholly behind or in the plane of patch i, and which show their front
        candidates.clear();
        for (uint32_t j = 0; j < n; ++j) {
            const Patch& p = mesh.patches[j];
            front[j] = glm::dot(mesh.elements[p.element].normal, eye - p.centre) > 0;
            bool above = false;
            for (int k = 0; k < p.corner_count; ++k)
                above = above || glm::dot(p.corners[k] - eye, nrm) > near;
            if (above && j != i) candidates.push_back(j);
        }
        for (const HemicubeFace& face : faces) {
            // Z-buffer the candidates
            z.clear(face.rows);
            for (const uint32_t j : candidates) {
                const uint64_t cells = rasterise_patch(mesh, j, eye, face, near, z);
                tested += cells;
                rasterised += cells > 0;
            }
            // credit each cell's delta form factor to the front face it sees
            for (size_t c = 0; c < static_cast<size_t>(face.rows) * resolution; ++c) {
                const int32_t j = z.id[c];
                if (j >= 0 && front[static_cast<uint32_t>(j)])
                    f[i * n + static_cast<uint32_t>(j)] += (*face.delta)[c];
            }
        }
        if (work) work(i + 1, n);
    }
    counts.patches_rasterised += rasterised;
    counts.cells_tested += tested;
    return f;
}

}  // namespace fb89::host
