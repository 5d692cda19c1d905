// Building the harness's scenes: ideal scenes on a cell grid, random triangles kept on
// screen, and scene files (see peer_scenes.h).
#include "bench/peers/peer_scenes.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <fmt/format.h>

#include "host/scene/generators.h"
#include "host/scene/projection.h"
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
    return {fmt::format("ideal D={} Fv={}", layers, f_v), project_ids(scene)};
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
    return {fmt::format("random {}x{}px", count, area),
            project_ids(screen_scene_of(width, height, std::move(triangles)))};
}

PeerScene file_scene(const std::filesystem::path& file) {
    return {file.filename().string(), project_ids(host::load_scene(file))};
}

}  // namespace fb89::peers
