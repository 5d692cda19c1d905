#include "host/scene/lathe.h"

#include <cmath>
#include <numbers>

namespace fb89::host {

GeneratedPolygons generate_lathe(const std::vector<glm::dvec2>& profile, int segments,
                                 LatheCaps caps) {
    const auto n = static_cast<size_t>(segments);
    // one angle table, so that neighbouring faces share their vertices bit for bit
    std::vector<double> cos_t(n + 1), sin_t(n + 1);
    for (size_t j = 0; j < n; ++j) {
        double t = 2 * std::numbers::pi * static_cast<double>(j) / segments;
        cos_t[j] = std::cos(t);
        sin_t[j] = std::sin(t);
    }
    cos_t[n] = cos_t[0];
    sin_t[n] = sin_t[0];
    auto at = [&](const glm::dvec2& p, size_t j) {
        return glm::dvec3(p.x * cos_t[j], p.y, p.x * sin_t[j]);
    };

    GeneratedPolygons out;
    // first cap: ring 0 walked backwards, against the first band's edges
    const glm::dvec2& first = profile.front();
    if ((caps == LatheCaps::First || caps == LatheCaps::Both) && first.x > 0) {
        GeneratedPolygon cap;
        for (size_t j = n; j-- > 0;)
            cap.vertices.push_back(at(first, j));
        out.push_back(std::move(cap));
    }
    // bands: quads, or triangles where the profile touches the axis
    for (size_t i = 0; i + 1 < profile.size(); ++i) {
        const glm::dvec2 &p = profile[i], &q = profile[i + 1];
        if (p.x == 0 && q.x == 0) continue;
        for (size_t j = 0; j < n; ++j) {
            GeneratedPolygon face;
            if (p.x == 0)
                face.vertices = {at(p, j), at(q, j + 1), at(q, j)};
            else if (q.x == 0)
                face.vertices = {at(p, j), at(p, j + 1), at(q, j)};
            else
                face.vertices = {at(p, j), at(p, j + 1), at(q, j + 1), at(q, j)};
            out.push_back(std::move(face));
        }
    }
    // last cap: the last ring walked forwards
    const glm::dvec2& last = profile.back();
    if ((caps == LatheCaps::Last || caps == LatheCaps::Both) && last.x > 0) {
        GeneratedPolygon cap;
        for (size_t j = 0; j < n; ++j)
            cap.vertices.push_back(at(last, j));
        out.push_back(std::move(cap));
    }
    return out;
}

GeneratedPolygons generate_sphere(const glm::dvec3& center, double radius, int segments,
                                  int rings) {
    std::vector<glm::dvec2> profile;
    for (int k = 0; k <= rings; ++k) {
        double phi = std::numbers::pi * k / rings;
        double r = (k == 0 || k == rings) ? 0.0 : radius * std::sin(phi);
        profile.emplace_back(r, -radius * std::cos(phi));
    }
    GeneratedPolygons out = generate_lathe(profile, segments, LatheCaps::None);
    for (auto& face : out)
        for (auto& v : face.vertices)
            v += center;
    return out;
}

}  // namespace fb89::host
