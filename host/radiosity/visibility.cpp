// What both intervisibility methods share: which patch pairs face each other (the paper's
// §5, Eq. 5.1: pairs with cos φ ≤ 0 at either end exchange nothing) and the counters.
//
// cos φ_p > 0 is measured between the centres, dot(n_p, c_q − c_p) > 0. A patch's centre
// lies on its element's plane, so that is "c_q in front of p's element's plane", which we
// measure against the plane through the element's first corner: the same for every patch of
// the element, so the hybrid can count a region pair's facing pairs as a product. "In front"
// means by more than a billionth of the element's coordinates, so that rounding never makes
// two coplanar elements (two floor tiles) face each other.
#include "host/radiosity/visibility.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace fb89::host {

bool in_front(const Element& e, const glm::dvec3& point) {
    double scale = 0;
    for (const glm::dvec3& c : e.corners)
        scale = std::max({scale, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
    return glm::dot(e.normal, point - e.corners[0]) > 1e-9 * scale;
}

bool facing(const Mesh& mesh, uint32_t p, uint32_t q) {
    const Patch& a = mesh.patches[p];
    const Patch& b = mesh.patches[q];
    if (a.element == b.element) return false;  // one plane: never
    return in_front(mesh.elements[a.element], b.centre) &&
           in_front(mesh.elements[b.element], a.centre);
}

void VisibilityCounts::publish(Counters& counters) const {
    counters.add("radiosity_facing_pairs", facing_pairs);
    counters.add("flux_rays", rays);
    counters.add("volume_queries", queries);
    counters.add("empty_volume_queries", empty_queries);
    counters.add("volume_query_face_tests", query_face_tests);
    counters.add("pairs_by_volume_queries", pairs_by_queries);
}

}  // namespace fb89::host
