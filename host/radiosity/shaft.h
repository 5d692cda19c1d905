// A shaft between two boxes (Haines and Wallace, "Shaft Culling for Efficient Ray-Traced
// Radiosity", Eurographics Workshop on Rendering 1991): their union box cut by a plane through
// an edge of each wherever one box alone reaches a side of the union and the other alone an
// adjacent side. The shaft holds the convex hull of the two boxes, so every segment from a point
// of one to a point of the other: a piece whose box it does not meet blocks none of them.
// Hierarchical radiosity uses it to spare the rays of links nothing can block.
#pragma once

#include <array>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "host/trace/trace_scene.h"

namespace fb89::host {

class Shaft {
  public:
    Shaft(const PieceBox& a, const PieceBox& b)
        : m_lo(glm::min(a.lo, b.lo)), m_hi(glm::max(a.hi, b.hi)) {
        auto extreme = [](const PieceBox& box, int axis, int side) {
            return side == 0 ? box.lo[axis] : box.hi[axis];
        };
        // which box alone reaches the union's side (axis, 0 low / 1 high); -1: both
        auto alone = [&](int axis, int side) {
            const double u = side == 0 ? m_lo[axis] : m_hi[axis];
            const bool ra = extreme(a, axis, side) == u, rb = extreme(b, axis, side) == u;
            return ra && !rb ? 0 : rb && !ra ? 1 : -1;
        };
        for (int i = 0; i < 3; ++i)
            for (int j = i + 1; j < 3; ++j)
                for (int si = 0; si < 2; ++si)
                    for (int sj = 0; sj < 2; ++sj) {
                        const int oi = alone(i, si), oj = alone(j, sj);
                        if (oi < 0 || oj < 0 || oi == oj) continue;
                        // the line, in axes (i, j), through the two boxes' corners on these
                        // sides, its normal towards the union's corner it cuts off
                        const double ai = extreme(a, i, si), aj = extreme(a, j, sj);
                        const double bi = extreme(b, i, si), bj = extreme(b, j, sj);
                        double ni = bj - aj, nj = ai - bi;
                        const double ci = (si == 0 ? m_lo[i] : m_hi[i]) - ai;
                        const double cj = (sj == 0 ? m_lo[j] : m_hi[j]) - aj;
                        if (ni * ci + nj * cj < 0) ni = -ni, nj = -nj;
                        glm::dvec3 n(0);
                        n[i] = ni;
                        n[j] = nj;
                        m_planes[m_count++] = {n, ni * ai + nj * aj};
                    }
    }

    // Whether a box may meet the shaft: false only when it lies beyond the union box or one
    // of the planes by more than `slack` (a length).
    bool may_meet(const PieceBox& box, double slack) const {
        for (int k = 0; k < 3; ++k)
            if (box.lo[k] > m_hi[k] + slack || box.hi[k] < m_lo[k] - slack) return false;
        for (int p = 0; p < m_count; ++p) {
            const glm::dvec3& n = m_planes[p].normal;
            // the box's corner deepest on the inside
            const glm::dvec3 c(n.x > 0 ? box.lo.x : box.hi.x, n.y > 0 ? box.lo.y : box.hi.y,
                               n.z > 0 ? box.lo.z : box.hi.z);
            if (glm::dot(n, c) - m_planes[p].offset > slack * glm::length(n)) return false;
        }
        return true;
    }

    int planes() const { return m_count; }  // the cutting planes, 0 to 12

  private:
    struct Plane {
        glm::dvec3 normal;  // outward, not unit
        double offset = 0;  // inside: dot(normal, x) <= offset
    };
    glm::dvec3 m_lo, m_hi;
    std::array<Plane, 12> m_planes{};
    int m_count = 0;
};

}  // namespace fb89::host
