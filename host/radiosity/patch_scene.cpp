#include "host/radiosity/patch_scene.h"

#include <algorithm>

#include <glm/common.hpp>

namespace fb89::host {

namespace {

double largest(const glm::dvec3& v) {
    return std::max({v.x, v.y, v.z});
}

}  // namespace

double automatic_exposure(const Mesh& mesh, const std::vector<glm::dvec3>& radiosity) {
    // (largest channel, area) of the non-emitting patches, or of all when every patch emits
    std::vector<std::pair<double, double>> lit, all;
    for (size_t p = 0; p < mesh.patches.size(); ++p) {
        const std::pair<double, double> v{largest(radiosity[p]), mesh.patches[p].area};
        all.push_back(v);
        if (largest(mesh.elements[mesh.patches[p].element].emission) == 0) lit.push_back(v);
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
    return s;
}

}  // namespace fb89::host
