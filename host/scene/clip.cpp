#include "host/scene/clip.h"

#include <glm/geometric.hpp>

namespace fb89::host {

namespace {

bool precedes(const glm::dvec4& a, const glm::dvec4& b) {
    for (int i = 0; i < 4; ++i)
        if (a[i] != b[i]) return a[i] < b[i];
    return false;
}

// Where the edge a-b crosses the plane, the same whichever way round the edge is given.
glm::dvec4 crossing(const glm::dvec4& a, double da, const glm::dvec4& b, double db) {
    if (precedes(b, a)) {
        std::swap(da, db);
        return crossing(b, da, a, db);
    }
    double t = da / (da - db);
    return a + t * (b - a);
}

}  // namespace

bool clip_polygon(std::vector<glm::dvec4>& poly, std::span<const glm::dvec4> planes,
                  std::vector<glm::dvec4>& scratch) {
    for (const glm::dvec4& plane : planes) {
        // quick accept: every vertex inside this plane
        bool all_inside = true;
        for (const auto& p : poly)
            all_inside = all_inside && glm::dot(plane, p) >= 0;
        if (all_inside) continue;

        scratch.clear();
        for (size_t i = 0; i < poly.size(); ++i) {
            const glm::dvec4& a = poly[i];
            const glm::dvec4& b = poly[(i + 1) % poly.size()];
            double da = glm::dot(plane, a), db = glm::dot(plane, b);
            if (da >= 0) scratch.push_back(a);
            if ((da >= 0) != (db >= 0)) scratch.push_back(crossing(a, da, b, db));
        }
        poly.swap(scratch);
        if (poly.size() < 3) return false;
    }
    return true;
}

}  // namespace fb89::host
