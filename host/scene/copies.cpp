#include "host/scene/copies.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace fb89::host {

GeneratedPolygons place_copies(const GeneratedPolygons& parts,
                               const std::vector<Placement>& placements) {
    GeneratedPolygons out;
    out.reserve(parts.size() * placements.size());
    for (const Placement& p : placements) {
        double t = p.yaw_degrees * std::numbers::pi / 180;
        double c = std::cos(t), s = std::sin(t);
        for (const GeneratedPolygon& part : parts) {
            GeneratedPolygon face;
            face.vertices.reserve(part.vertices.size());
            // scale, turn about y (as glm::rotate about +y), move
            for (const glm::dvec3& v : part.vertices) {
                glm::dvec3 w = v * p.scale;
                face.vertices.emplace_back(c * w.x + s * w.z + p.offset.x, w.y + p.offset.y,
                                           -s * w.x + c * w.z + p.offset.z);
            }
            if (p.color)
                face.color = p.color;
            else if (part.color)
                face.color = glm::clamp(*part.color * p.shade, 0.0, 1.0);
            out.push_back(std::move(face));
        }
    }
    return out;
}

std::vector<Placement> array_placements(int nx, int ny, int nz, const glm::dvec3& step) {
    std::vector<Placement> out;
    out.reserve(static_cast<size_t>(nx) * ny * nz);
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                out.push_back({glm::dvec3(i, j, k) * step, 1, 0, 1, {}});
    return out;
}

std::vector<Placement> scatter_placements(const ScatterOptions& o) {
    std::mt19937_64 rng(o.seed);
    auto uniform = [&rng](double lo, double hi) {  // the same on every standard library
        return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
    };
    // copies placed so far, hashed by cells of min_distance: only 27 cells to look at
    const double cell = o.min_distance > 0 ? o.min_distance : 1;
    auto cell_of = [&](const glm::dvec3& p) { return glm::floor(p / cell); };
    auto key = [](const glm::dvec3& c) {
        return std::hash<double>{}(c.x) ^ (std::hash<double>{}(c.y) * 31) ^
               (std::hash<double>{}(c.z) * 1000003);
    };
    std::unordered_multimap<size_t, glm::dvec3> placed;
    auto keeps_distance = [&](const glm::dvec3& at) {
        if (o.min_distance <= 0) return true;
        glm::dvec3 c = cell_of(at);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    auto [b, e] = placed.equal_range(key(c + glm::dvec3(dx, dy, dz)));
                    for (auto it = b; it != e; ++it)
                        if (glm::distance(it->second, at) < o.min_distance) return false;
                }
        return true;
    };

    std::vector<Placement> out;
    out.reserve(static_cast<size_t>(o.count));
    while (static_cast<int>(out.size()) < o.count) {
        // position: up to kTries draws until one keeps its distance from every copy so far
        constexpr int kTries = 1000;
        glm::dvec3 at{0, 0, 0};
        bool fits = false;
        for (int t = 0; t < kTries && !fits; ++t) {
            at = {uniform(o.min.x, o.max.x), uniform(o.min.y, o.max.y), uniform(o.min.z, o.max.z)};
            fits = keeps_distance(at);
        }
        if (!fits) break;
        placed.emplace(key(cell_of(at)), at);
        Placement p;
        p.offset = at;
        p.scale = uniform(o.scale_min, o.scale_max);
        double yaw = uniform(0, 360);
        p.yaw_degrees = o.random_yaw ? yaw : 0;
        p.shade = uniform(1 - o.color_jitter, 1 + o.color_jitter);
        out.push_back(p);
    }
    return out;
}

}  // namespace fb89::host
