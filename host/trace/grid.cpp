#include "host/trace/grid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace fb89::host {

namespace {

constexpr int kMaxCellsPerAxis = 256;

// A piece's box grown by `margin`.
PieceBox piece_box(const TraceScene& scene, uint32_t piece, double margin) {
    PieceBox b = scene.box(piece);
    b.lo -= margin;
    b.hi += margin;
    return b;
}

}  // namespace

PieceBox box_around_pieces(const TraceScene& scene) {
    const auto& faces = scene.faces();
    if (faces.empty()) return {glm::dvec3(-1), glm::dvec3(1)};
    PieceBox box{glm::dvec3(INFINITY), glm::dvec3(-INFINITY)};
    for (uint32_t p = 0; p < faces.size(); ++p) {
        const PieceBox b = piece_box(scene, p, scene.tolerance());
        box.lo = glm::min(box.lo, b.lo);
        box.hi = glm::max(box.hi, b.hi);
    }
    // never flat
    const glm::dvec3 extent = box.hi - box.lo;
    const double largest = std::max({extent.x, extent.y, extent.z});
    for (int a = 0; a < 3; ++a) {
        if (extent[a] < largest * 1e-3) {
            const double grow = (largest * 1e-3 - extent[a]) / 2;
            box.lo[a] -= grow;
            box.hi[a] += grow;
        }
    }
    return box;
}

UniformGrid::UniformGrid(const TraceScene& scene, double density) {
    const double margin = scene.tolerance();
    std::vector<uint32_t> all(scene.faces().size());
    for (uint32_t p = 0; p < all.size(); ++p)
        all[p] = p;
    const PieceBox box = box_around_pieces(scene);
    m_lo = box.lo;
    m_hi = box.hi;
    build(scene, all, density);

    // crowded cells get a finer grid of their own for rays to walk
    m_sub_of.assign(static_cast<size_t>(cell_count()), -1);
    for (uint32_t c = 0; c < cell_count(); ++c) {
        const auto list = cell(c);
        if (list.size() <= kCrowded) continue;
        const int x = static_cast<int>(c % m_n.x), y = static_cast<int>((c / m_n.x) % m_n.y),
                  z = static_cast<int>(c / (static_cast<uint32_t>(m_n.x) * m_n.y));
        const glm::dvec3 lo = cell_lo(x, y, z) - margin, hi = cell_lo(x, y, z) + m_cell + margin;
        m_sub_of[c] = static_cast<int32_t>(m_subs.size());
        m_subs.push_back(std::unique_ptr<UniformGrid>(new UniformGrid(
            scene, std::vector<uint32_t>(list.begin(), list.end()), lo, hi, kSubDensity)));
    }
}

UniformGrid::UniformGrid(const TraceScene& scene, const std::vector<uint32_t>& pieces,
                         const glm::dvec3& lo, const glm::dvec3& hi, double density)
    : m_lo(lo), m_hi(hi) {
    build(scene, pieces, density);
}

void UniformGrid::build(const TraceScene& scene, const std::vector<uint32_t>& pieces,
                        double density) {
    const auto& faces = scene.faces();
    const double margin = scene.tolerance();
    const glm::dvec3 extent = m_hi - m_lo;
    const double largest = std::max({extent.x, extent.y, extent.z});

    // cell sizing: about `density` cells per piece, cubic where the box allows
    const double target = std::max(1.0, density * static_cast<double>(pieces.size()));
    // an axis thinner than a cell gets one cell, and the others share the count
    bool thin[3] = {false, false, false};
    double side = 0;
    for (int pass = 0; pass < 3; ++pass) {
        double measure = 1;
        int dims = 0;
        for (int a = 0; a < 3; ++a)
            if (!thin[a]) {
                measure *= extent[a];
                ++dims;
            }
        side = dims == 0 ? largest : std::pow(measure / target, 1.0 / dims);
        bool changed = false;
        for (int a = 0; a < 3; ++a)
            if (!thin[a] && extent[a] < side) thin[a] = changed = true;
        if (!changed) break;
    }
    for (int a = 0; a < 3; ++a) {
        m_n[a] = std::clamp(static_cast<int>(std::ceil(extent[a] / side)), 1, kMaxCellsPerAxis);
        m_cell[a] = extent[a] / m_n[a];
    }

    // list each piece in the cells its box overlaps and its plane passes through
    const size_t cells = static_cast<size_t>(m_n.x) * m_n.y * m_n.z;
    std::vector<std::vector<uint32_t>> lists(cells);
    const glm::dvec3 half = m_cell * 0.5;
    for (uint32_t p : pieces) {
        const TraceFace& f = faces[p];
        const PieceBox b = piece_box(scene, p, margin);
        glm::ivec3 first, last;
        if (!cell_range(b.lo, b.hi, first, last)) continue;
        const double reach = glm::dot(glm::abs(f.normal), half) + margin;
        for (int z = first.z; z <= last.z; ++z)
            for (int y = first.y; y <= last.y; ++y)
                for (int x = first.x; x <= last.x; ++x) {
                    const glm::dvec3 centre = cell_lo(x, y, z) + half;
                    if (std::abs(glm::dot(f.normal, centre) - f.plane) > reach) continue;
                    lists[index(x, y, z)].push_back(p);
                }
    }
    m_start.assign(cells + 1, 0);
    for (size_t c = 0; c < cells; ++c)
        m_start[c + 1] = m_start[c] + static_cast<uint32_t>(lists[c].size());
    m_items.reserve(m_start[cells]);
    for (const auto& list : lists)
        m_items.insert(m_items.end(), list.begin(), list.end());
}

bool UniformGrid::cell_range(const glm::dvec3& lo, const glm::dvec3& hi, glm::ivec3& first,
                             glm::ivec3& last) const {
    for (int a = 0; a < 3; ++a) {
        if (hi[a] < m_lo[a] || lo[a] > m_hi[a]) return false;
        first[a] =
            std::clamp(static_cast<int>(std::floor((lo[a] - m_lo[a]) / m_cell[a])), 0, m_n[a] - 1);
        last[a] =
            std::clamp(static_cast<int>(std::floor((hi[a] - m_lo[a]) / m_cell[a])), 0, m_n[a] - 1);
    }
    return true;
}

}  // namespace fb89::host
