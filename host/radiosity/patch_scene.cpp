#include "host/radiosity/patch_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace fb89::host {

namespace {

double largest_channel(const glm::dvec3& v) {
    return std::max({v.x, v.y, v.z});
}

// The faces' corners in a uniform grid of cubes, for finding the corners near an edge.
class CornerGrid {
  public:
    CornerGrid(const std::vector<Face>& faces, double cell) : m_cell(cell) {
        for (const Face& f : faces)
            for (const glm::dvec3& v : f.vertices) {
                m_corners.push_back(v);
                m_cells[key(cell_of(v))].push_back(static_cast<uint32_t>(m_corners.size() - 1));
            }
    }

    // Calls `visit(corner)` for each corner in a cell that the box [lo, hi] meets (a corner
    // once per time it is some face's corner); every corner when the box spans more cells
    // than there are corners.
    template <class Visit>
    void near(const glm::dvec3& lo, const glm::dvec3& hi, Visit visit) const {
        const glm::dvec3 a = cell_of(lo), b = cell_of(hi);
        const glm::dvec3 span = b - a + 1.0;
        if (span.x * span.y * span.z > static_cast<double>(m_corners.size())) {
            for (const glm::dvec3& v : m_corners)
                visit(v);
            return;
        }
        for (double x = a.x; x <= b.x; ++x)
            for (double y = a.y; y <= b.y; ++y)
                for (double z = a.z; z <= b.z; ++z)
                    if (auto it = m_cells.find(key({x, y, z})); it != m_cells.end())
                        for (uint32_t k : it->second)
                            visit(m_corners[k]);
    }

  private:
    glm::dvec3 cell_of(const glm::dvec3& v) const { return glm::floor(v / m_cell); }
    static uint64_t key(const glm::dvec3& c) {
        const auto part = [](double x) { return static_cast<uint64_t>(static_cast<int64_t>(x)); };
        return part(c.x) * 0x9E3779B97F4A7C15ull ^ part(c.y) * 0xC2B2AE3D27D4EB4Full ^
               part(c.z) * 0x165667B19E3779F9ull;
    }

    double m_cell;
    std::vector<glm::dvec3> m_corners;
    std::unordered_map<uint64_t, std::vector<uint32_t>> m_cells;
};

// The corners of other faces that lie inside the edge a -> b, in order from a, once each.
std::vector<glm::dvec3> corners_on_edge(const CornerGrid& grid, const glm::dvec3& a,
                                        const glm::dvec3& b) {
    const glm::dvec3 d = b - a;
    const double length = glm::length(d);
    const double tolerance = 1e-9 * std::max(1.0, length);
    if (length <= tolerance) return {};
    std::vector<std::pair<double, glm::dvec3>> on;  // (distance from a, corner)
    grid.near(glm::min(a, b) - tolerance, glm::max(a, b) + tolerance, [&](const glm::dvec3& v) {
        const double along = glm::dot(v - a, d) / length;
        if (along <= tolerance || along >= length - tolerance) return;
        if (glm::length(v - (a + d * (along / length))) > tolerance) return;
        on.emplace_back(along, v);
    });
    std::sort(on.begin(), on.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<glm::dvec3> out;
    double last = -1;
    for (const auto& [along, v] : on)
        if (along - last > tolerance) {
            out.push_back(v);
            last = along;
        }
    return out;
}

}  // namespace

void close_t_junctions(std::vector<Face>& faces) {
    if (faces.size() < 2) return;
    double shortest_sum = 0;  // the cell: the faces' mean shortest edge
    for (const Face& f : faces) {
        double shortest = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < f.vertices.size(); ++k)
            shortest = std::min(
                shortest, glm::length(f.vertices[(k + 1) % f.vertices.size()] - f.vertices[k]));
        shortest_sum += std::isfinite(shortest) ? shortest : 0;
    }
    const double cell = shortest_sum / static_cast<double>(faces.size());
    if (!(cell > 0)) return;
    const CornerGrid grid(faces, cell);
    std::vector<std::vector<glm::dvec3>> closed(faces.size());
    for (size_t i = 0; i < faces.size(); ++i) {
        const std::vector<glm::dvec3>& v = faces[i].vertices;
        for (size_t k = 0; k < v.size(); ++k) {
            closed[i].push_back(v[k]);
            for (const glm::dvec3& p : corners_on_edge(grid, v[k], v[(k + 1) % v.size()]))
                closed[i].push_back(p);
        }
    }
    for (size_t i = 0; i < faces.size(); ++i)
        faces[i].vertices = std::move(closed[i]);
}

double automatic_exposure(const Mesh& mesh, const std::vector<glm::dvec3>& radiosity) {
    // (largest channel, area) of the non-emitting patches, or of all when every patch emits
    std::vector<std::pair<double, double>> lit, all;
    for (size_t p = 0; p < mesh.patches.size(); ++p) {
        const std::pair<double, double> v{largest_channel(radiosity[p]), mesh.patches[p].area};
        all.push_back(v);
        if (largest_channel(mesh.elements[mesh.patches[p].element].emission) == 0) lit.push_back(v);
    }
    std::vector<std::pair<double, double>>& v = lit.empty() ? all : lit;
    std::sort(v.begin(), v.end());
    double total = 0;
    for (const auto& [b, area] : v)
        total += area;
    // the level at which kExposedArea of the area lies at or below
    double below = 0, level = 0;
    for (const auto& [b, area] : v) {
        level = b;
        below += area;
        if (below >= kExposedArea * total) break;
    }
    return level > 0 ? 1.0 / level : 1.0;
}

Scene patch_scene(const Scene& world, const Mesh& mesh, const std::vector<glm::dvec3>& radiosity,
                  double exposure) {
    Scene s;
    s.source = world.source;
    s.projection = world.projection;
    s.camera = world.camera;
    s.width = world.width;
    s.height = world.height;
    s.background = world.background;
    s.light.direction = world.light.direction;
    s.light.ambient = 1;  // unshaded: the colour is the tone-mapped radiosity
    const double scale = exposure > 0 ? exposure : automatic_exposure(mesh, radiosity);

    s.faces.reserve(mesh.patches.size());
    for (size_t p = 0; p < mesh.patches.size(); ++p) {
        const Patch& patch = mesh.patches[p];
        Face f;
        f.vertices.assign(patch.corners.begin(), patch.corners.begin() + patch.corner_count);
        f.material.color = glm::clamp(radiosity[p] * scale, 0.0, 1.0);
        f.id = static_cast<uint32_t>(p);
        f.object = patch.element;
        s.faces.push_back(std::move(f));
    }
    s.face_count = static_cast<uint32_t>(mesh.patches.size());
    close_t_junctions(s.faces);
    return s;
}

}  // namespace fb89::host
