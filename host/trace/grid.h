// Uniform-grid spatial enumeration (Fujimoto, Tanaka and Iwata's ARTS, 1986): the scene's
// bounding box cut into equal cells, each listing the face pieces that may touch it, walked
// along a ray by Amanatides and Woo's 3D-DDA (1987). The beam tracer's queries take the
// cells of a box and radiosity's rays walk it; the ray tracer's rays use the BVH (bvh.h).
//
// How ours is built: about `density` cells per piece (0.5 by default: coarse, since
// crowded cells are refined, below), cubic cells as far as the
// box's shape allows, at most 256 per axis. A piece is listed in a cell when its bounding box
// overlaps the cell and its plane passes through it, both with a margin of the scene's
// tolerance, so a hit near a cell boundary is never lost to rounding. The walk hands each
// cell and the distance at which the ray leaves it to a visitor; the visitor stops the walk
// only when its hit lies no farther than that exit (REFERENCES.md: a hit found in a cell may
// lie beyond it). Direction components of zero are guarded.
//
// Two levels (a "hierarchical uniform grid", as in Jevans and Wyvill 1989): a cell listing
// more than kCrowded pieces carries a grid of its own, so a small detailed object in a large
// room (the goblets of H, the shell of I) does not force fine cells on the whole room.
// Rays walk both levels (walk_levels); volume queries scan the top level only
// (convex_hull.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "host/trace/trace_scene.h"

namespace fb89::host {

// Top-level cells per face piece by default: coarse, since crowded cells get a grid of their
// own (RESULTS.md §4).
inline constexpr double kDefaultGridDensity = 0.5;

// The box around every piece, each grown by the scene's tolerance, and never flat (an axis
// thinner than a thousandth of the widest is widened to it): the grid's box.
PieceBox box_around_pieces(const TraceScene& scene);

class UniformGrid {
  public:
    explicit UniformGrid(const TraceScene& scene, double density = kDefaultGridDensity);

    const glm::dvec3& lo() const { return m_lo; }
    const glm::dvec3& hi() const { return m_hi; }
    const glm::ivec3& resolution() const { return m_n; }
    uint64_t cell_count() const { return m_start.size() - 1; }
    uint64_t entries() const { return m_items.size(); }

    std::span<const uint32_t> cell(uint32_t index) const {
        return {m_items.data() + m_start[index], m_items.data() + m_start[index + 1]};
    }
    uint32_t index(int x, int y, int z) const {
        return static_cast<uint32_t>((z * m_n.y + y) * m_n.x + x);
    }
    // The cells a box [lo, hi] overlaps, as inclusive index ranges; false if none.
    bool cell_range(const glm::dvec3& lo, const glm::dvec3& hi, glm::ivec3& first,
                    glm::ivec3& last) const;
    glm::dvec3 cell_lo(int x, int y, int z) const { return m_lo + glm::dvec3(x, y, z) * m_cell; }
    const glm::dvec3& cell_size() const { return m_cell; }

    // The finer grid of a crowded cell (more than kCrowded pieces), or null. It covers the
    // cell's box and lists the cell's pieces again; rays walk it inside the cell, queries
    // need not (the cell's own list is complete).
    const UniformGrid* sub(uint32_t cell) const {
        return m_sub_of.empty() || m_sub_of[cell] < 0 ? nullptr : m_subs[m_sub_of[cell]].get();
    }
    static constexpr size_t kCrowded = 8;
    static constexpr double kSubDensity = 8;  // cells per piece of a crowded cell's grid

    // Walks the cells the ray crosses for tmin < t < tmax, in order; `visit(cell index,
    // t_exit)` returns true to stop. Returns the number of cells visited.
    template <class Visit>
    uint64_t walk(const Ray& ray, double tmin, double tmax, Visit&& visit) const;

    struct LevelCounts {
        uint64_t cells = 0;      // cells of this grid visited
        uint64_t sub_cells = 0;  // cells of crowded cells' grids visited
    };
    // Walks both levels: the cells the ray crosses and, inside a crowded cell, the cells of
    // its own grid (the whole cell, should rounding let the ray miss that grid's box).
    // `test(pieces)` tests one cell's list; `done(t)` says after each cell whether the walk
    // may stop, t being where the ray leaves that cell.
    template <class Test, class Done>
    LevelCounts walk_levels(const Ray& ray, double tmin, double tmax, Test&& test,
                            Done&& done) const;

  private:
    UniformGrid(const TraceScene& scene, const std::vector<uint32_t>& pieces, const glm::dvec3& lo,
                const glm::dvec3& hi, double density);
    void build(const TraceScene& scene, const std::vector<uint32_t>& pieces, double density);

    glm::dvec3 m_lo{0}, m_hi{0}, m_cell{1};
    glm::ivec3 m_n{1};
    std::vector<uint32_t> m_start;  // per cell, into m_items; one more than cells
    std::vector<uint32_t> m_items;  // piece indices
    std::vector<int32_t> m_sub_of;  // per cell: index into m_subs, or -1
    std::vector<std::unique_ptr<UniformGrid>> m_subs;
};

template <class Visit>
uint64_t UniformGrid::walk(const Ray& ray, double tmin, double tmax, Visit&& visit) const {
    // clip the ray to the grid's box
    double t0 = tmin, t1 = tmax;
    double inv[3];
    for (int a = 0; a < 3; ++a) {
        if (ray.dir[a] == 0) {
            if (ray.origin[a] < m_lo[a] || ray.origin[a] > m_hi[a]) return 0;
            inv[a] = 0;
            continue;
        }
        inv[a] = 1.0 / ray.dir[a];
        double ta = (m_lo[a] - ray.origin[a]) * inv[a], tb = (m_hi[a] - ray.origin[a]) * inv[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    if (!(t0 <= t1)) return 0;

    // the first cell and the 3D-DDA's steps
    int cell[3], step[3], end[3];
    double next[3], delta[3];
    for (int a = 0; a < 3; ++a) {
        const double p = ray.origin[a] + t0 * ray.dir[a];
        cell[a] =
            std::clamp(static_cast<int>(std::floor((p - m_lo[a]) / m_cell[a])), 0, m_n[a] - 1);
        if (ray.dir[a] > 0) {
            step[a] = 1;
            end[a] = m_n[a];
            next[a] = (m_lo[a] + (cell[a] + 1) * m_cell[a] - ray.origin[a]) * inv[a];
            delta[a] = m_cell[a] * inv[a];
        } else if (ray.dir[a] < 0) {
            step[a] = -1;
            end[a] = -1;
            next[a] = (m_lo[a] + cell[a] * m_cell[a] - ray.origin[a]) * inv[a];
            delta[a] = -m_cell[a] * inv[a];
        } else {
            step[a] = 0;
            end[a] = -2;
            next[a] = INFINITY;
            delta[a] = INFINITY;
        }
    }
    const int stride[3] = {1, m_n.x, m_n.x * m_n.y};
    int at = static_cast<int>(index(cell[0], cell[1], cell[2]));
    uint64_t visited = 0;
    for (;;) {
        const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
        ++visited;
        if (visit(static_cast<uint32_t>(at), std::min(next[a], t1))) return visited;
        if (next[a] > t1) return visited;
        cell[a] += step[a];
        if (cell[a] == end[a]) return visited;
        at += step[a] * stride[a];
        next[a] += delta[a];
    }
}

template <class Test, class Done>
UniformGrid::LevelCounts UniformGrid::walk_levels(const Ray& ray, double tmin, double tmax,
                                                  Test&& test, Done&& done) const {
    uint64_t sub_cells = 0;
    const uint64_t cells = walk(ray, tmin, tmax, [&](uint32_t at, double t_exit) {
        if (const UniformGrid* fine = sub(at)) {
            // a crowded cell: its own grid
            const uint64_t inner = fine->walk(ray, tmin, t_exit, [&](uint32_t c, double t) {
                test(fine->cell(c));
                return done(t);
            });
            if (inner == 0) test(cell(at));
            sub_cells += inner;
        } else {
            test(cell(at));
        }
        return done(t_exit);
    });
    return {cells, sub_cells};
}

}  // namespace fb89::host
