// The terrain generator: a seeded height field of a few octaves of turned sine bumps over a
// grid of cells, two triangles per cell, for scenes of any size (the growth ladder of
// bench/growth goes to a million faces).
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "host/scene/generators.h"

namespace fb89::host {

size_t terrain_face_count(const TerrainOptions& o) {
    return 2 * static_cast<size_t>(o.cells_x) * static_cast<size_t>(o.cells_z);
}

GeneratedPolygons generate_terrain(const TerrainOptions& o) {
    // the octaves: each a field of bumps, sin(f u + p) sin(f v + q) in axes (u, v) turned
    // by a random angle, twice the frequency and half the amplitude of the one before
    std::mt19937_64 rng(o.seed);
    auto uniform = [&rng](double lo, double hi) {
        return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
    };
    struct Octave {
        double cos_a, sin_a, p, q, frequency, amplitude;
    };
    std::vector<Octave> octaves;
    double total = 0;
    const double base = 6.283185307179586 / std::max(o.size_x, o.size_z);
    for (int k = 0; k < o.octaves; ++k) {
        const double angle = uniform(0, 6.283185307179586);
        const double p = uniform(0, 6.283185307179586), q = uniform(0, 6.283185307179586);
        const double frequency = base * std::ldexp(1.0, k) * uniform(0.8, 1.25);
        octaves.push_back({std::cos(angle), std::sin(angle), p, q, frequency, std::ldexp(1.0, -k)});
        total += std::ldexp(1.0, -k);
    }

    // heights at the (cells_x + 1) x (cells_z + 1) grid points, once each
    const size_t nx = static_cast<size_t>(o.cells_x), nz = static_cast<size_t>(o.cells_z);
    std::vector<glm::dvec3> points((nx + 1) * (nz + 1));
    for (size_t k = 0; k <= nz; ++k) {
        for (size_t i = 0; i <= nx; ++i) {
            const double x = o.size_x * (static_cast<double>(i) / o.cells_x - 0.5);
            const double z = o.size_z * (static_cast<double>(k) / o.cells_z - 0.5);
            double y = 0;
            for (const Octave& w : octaves) {
                const double u = w.cos_a * x + w.sin_a * z, v = w.cos_a * z - w.sin_a * x;
                y +=
                    w.amplitude * std::sin(w.frequency * u + w.p) * std::sin(w.frequency * v + w.q);
            }
            points[k * (nx + 1) + i] = {x, 0.5 * o.height * y / total, z};
        }
    }

    // two triangles per cell, normals up, coloured by their mean height
    auto color = [&](double y) {
        const double t = o.height > 0 ? std::clamp(y / o.height + 0.5, 0.0, 1.0) : 0.5;
        const glm::dvec3 grass{0.28, 0.52, 0.22}, rock{0.52, 0.44, 0.36}, snow{0.94, 0.95, 0.97};
        return t < 0.6 ? grass + (rock - grass) * (t / 0.6)
                       : rock + (snow - rock) * std::min(1.0, (t - 0.6) / 0.3);
    };
    GeneratedPolygons out;
    out.reserve(terrain_face_count(o));
    for (size_t k = 0; k < nz; ++k) {
        for (size_t i = 0; i < nx; ++i) {
            const glm::dvec3& a = points[k * (nx + 1) + i];
            const glm::dvec3& b = points[k * (nx + 1) + i + 1];
            const glm::dvec3& c = points[(k + 1) * (nx + 1) + i + 1];
            const glm::dvec3& d = points[(k + 1) * (nx + 1) + i];
            out.push_back({{a, d, c}, color((a.y + d.y + c.y) / 3)});
            out.push_back({{a, c, b}, color((a.y + c.y + b.y) / 3)});
        }
    }
    return out;
}

}  // namespace fb89::host
