#include "host/scene/shell.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <glm/vec3.hpp>

namespace fb89::host {

size_t shell_face_count(const ShellOptions& o) {
    return 2 * static_cast<size_t>(o.turns) * static_cast<size_t>(o.segments_per_turn) *
               static_cast<size_t>(o.sides) +
           1;
}

GeneratedPolygons generate_shell(const ShellOptions& o) {
    const auto steps = static_cast<size_t>(o.turns) * static_cast<size_t>(o.segments_per_turn);
    const auto sides = static_cast<size_t>(o.sides);
    // the tube's centre at the aperture, from the aperture's outer radius
    const double centre = o.size / (1 + o.tube);

    // one table of generating-curve offsets, so that neighbouring faces share their vertices
    std::vector<double> across(sides), along(sides);
    for (size_t j = 0; j < sides; ++j) {
        double phi = 2 * std::numbers::pi * static_cast<double>(j) / o.sides;
        across[j] = o.tube * std::cos(phi);
        along[j] = o.tube * o.aspect * std::sin(phi);
    }

    // rings: the generating curve at each step, from the apex (i = 0) to the aperture
    std::vector<glm::dvec3> ring((steps + 1) * sides);
    for (size_t i = 0; i <= steps; ++i) {
        double turn = static_cast<double>(i) / o.segments_per_turn;
        double theta = 2 * std::numbers::pi * turn;
        double r = centre * std::pow(o.growth, turn - o.turns);  // tube centre's distance
        glm::dvec3 radial(std::cos(theta), 0, std::sin(theta));
        glm::dvec3 c = r * radial + glm::dvec3(0, -o.translation * r, 0);
        for (size_t j = 0; j < sides; ++j)
            ring[i * sides + j] = c + r * across[j] * radial + glm::dvec3(0, r * along[j], 0);
    }
    auto at = [&](size_t i, size_t j) { return ring[i * sides + j % sides]; };

    GeneratedPolygons out;
    out.reserve(shell_face_count(o));
    // apex cap: the first ring walked backwards, against the first cells' edges
    GeneratedPolygon cap;
    for (size_t j = sides; j-- > 0;)
        cap.vertices.push_back(at(0, j));
    out.push_back(std::move(cap));
    // cells: two triangles each, split along the same diagonal
    for (size_t i = 0; i < steps; ++i) {
        for (size_t j = 0; j < sides; ++j) {
            glm::dvec3 a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
            out.push_back({{a, b, c}, {}});
            out.push_back({{a, c, d}, {}});
        }
    }
    return out;
}

}  // namespace fb89::host
