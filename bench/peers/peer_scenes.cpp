// Building the harnesses' scenes: ideal scenes on a cell grid, random triangles kept on
// screen, scene files, and world scenes for the ray peer (see peer_scenes.h).
#include "bench/peers/peer_scenes.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <fmt/format.h>

#include "host/raster/screen_setup.h"
#include "host/scene/generators.h"
#include "host/scene/scene_loader.h"

namespace fb89::peers {

namespace {

// Face-id mode colours faces id + 1 but keeps the scene's background colour, which would
// read as an id; the background is made black (id + 1 = 0) as in llvmpipe's cleared buffer.
host::ScreenScene project_ids(const host::Scene& scene) {
    host::Counters counters;
    host::ScreenScene screen = host::project_scene(scene, host::ColorMode::FaceId, counters);
    screen.background = {0, 0, 0};
    return screen;
}

// A PeerScene does not keep its world scene: a method that traces rays must say so rather
// than read a scene that is gone.
PeerScene peer_scene(std::string name, const host::Scene& scene) {
    PeerScene out{std::move(name), project_ids(scene)};
    out.screen.world = nullptr;
    return out;
}

host::Scene screen_scene_of(int width, int height, host::GeneratedPolygons polygons) {
    host::Scene scene;
    scene.projection = host::Projection::Screen;
    scene.width = width;
    scene.height = height;
    for (auto& p : polygons) {
        host::Face f;
        f.vertices = std::move(p.vertices);
        f.id = scene.face_count++;
        scene.faces.push_back(std::move(f));
    }
    return scene;
}

}  // namespace

PeerScene ideal_scene(int width, int height, int layers, int f_v) {
    const int n = static_cast<int>(std::lround(std::sqrt(f_v)));
    if (n * n != f_v) throw std::invalid_argument("ideal scene: F_v must be a perfect square");
    const double cell_w = static_cast<double>(width) / n, cell_h = static_cast<double>(height) / n;
    host::Scene scene = screen_scene_of(
        width, height, host::generate_ideal(width, height, layers, cell_w, cell_h, 0.5));
    return peer_scene(fmt::format("ideal D={} Fv={}", layers, f_v), scene);
}

PeerScene random_onscreen_triangles(int width, int height, int count, double area, uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto uniform = [&rng](double lo, double hi) {
        return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
    };
    host::GeneratedPolygons triangles;
    triangles.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        // three directions, scaled to the wanted area, then a centre that keeps them on screen
        double a0 = uniform(0, 2.0944), a1 = a0 + uniform(1.5, 2.6), a2 = a1 + uniform(1.5, 2.6);
        const double dx[3] = {std::cos(a0), std::cos(a1), std::cos(a2)};
        const double dy[3] = {std::sin(a0), std::sin(a1), std::sin(a2)};
        double unit =
            0.5 * std::abs((dx[1] - dx[0]) * (dy[2] - dy[0]) - (dx[2] - dx[0]) * (dy[1] - dy[0]));
        double r = std::sqrt(area / std::max(unit, 1e-3));
        if (2 * r >= std::min(width, height))
            throw std::invalid_argument("random triangles: too large to keep on screen");
        double cx = uniform(r, width - r), cy = uniform(r, height - r);
        host::GeneratedPolygon t;
        for (int k = 0; k < 3; ++k) {
            // on the 1/256 grid; rounding must not push a vertex past the border
            double x = std::clamp(std::round((cx + r * dx[k]) * 256) / 256, 0.0,
                                  static_cast<double>(width));
            double y = std::clamp(std::round((cy + r * dy[k]) * 256) / 256, 0.0,
                                  static_cast<double>(height));
            t.vertices.emplace_back(x, y, uniform(0, 1));
        }
        triangles.push_back(std::move(t));
    }
    return peer_scene(fmt::format("random {}x{}px", count, area),
                      screen_scene_of(width, height, std::move(triangles)));
}

PeerScene file_scene(const std::filesystem::path& file) {
    return peer_scene(file.stem().string(), host::load_scene(file));  // "A", as fb89 names it
}

RayScene ray_file_scene(const std::filesystem::path& file, int width, int height) {
    RayScene out;
    out.world = std::make_unique<host::Scene>(host::load_scene(file));
    out.world->width = width;
    out.world->height = height;
    out.name = fmt::format("{} {}x{}", file.stem().string(), width, height);
    out.screen = project_ids(*out.world);
    return out;
}

RayScene random_world_triangles(int width, int height, int count, uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto uniform = [&rng](double lo, double hi) {
        return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
    };
    auto unit_vector = [&] {
        const double z = uniform(-1, 1), a = uniform(0, 6.283185307179586);
        const double r = std::sqrt(1 - z * z);
        return glm::dvec3(r * std::cos(a), r * std::sin(a), z);
    };
    auto world = std::make_unique<host::Scene>();
    world->width = width;
    world->height = height;
    world->camera.eye = {0, 0, 3.5};
    world->camera.look_at = {0, 0, 0};
    world->camera.fovy_degrees = 45;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 centre(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        host::Face f;
        for (int k = 0; k < 3; ++k)
            f.vertices.push_back(centre + 0.2 * unit_vector());
        f.material.color = {uniform(0.2, 1), uniform(0.2, 1), uniform(0.2, 1)};
        f.id = world->face_count++;
        world->faces.push_back(std::move(f));
    }
    RayScene out;
    out.name = fmt::format("random world {} tris {}x{}", count, width, height);
    out.world = std::move(world);
    out.screen = project_ids(*out.world);
    return out;
}

}  // namespace fb89::peers
