// What tests of raster methods share: the face-id buffer a method's commands leave
// (fills and spans applied in order, colours decoded as id + 1).
#pragma once

#include <variant>
#include <vector>

#include "host/scene/generators.h"
#include "host/scene/projection.h"
#include "protocol/command.h"

namespace fb89::testing {

inline std::vector<uint32_t> ids_from_commands(const std::vector<protocol::Command>& commands,
                                               int width, int height) {
    std::vector<uint32_t> ids(static_cast<size_t>(width) * height, 0);
    for (const auto& c : commands) {
        if (const auto* r = std::get_if<protocol::FillRect>(&c)) {
            for (uint32_t y = 0; y < r->h; ++y)
                for (uint32_t x = 0; x < r->w; ++x)
                    ids[(r->y + y) * static_cast<size_t>(width) + r->x + x] =
                        host::face_id_from_color(r->color);
        } else if (const auto* d = std::get_if<protocol::DrawSpan>(&c)) {
            for (int x = d->x0; x <= d->x1; ++x)
                ids[static_cast<size_t>(d->y) * width + x] = host::face_id_from_color(d->color);
        }
    }
    return ids;
}

// A screen-space scene of seeded random triangles (generate_random_triangles), ids in order.
inline host::Scene random_scene(int width, int height, int count, double area, uint64_t seed) {
    host::Scene scene;
    scene.projection = host::Projection::Screen;
    scene.width = width;
    scene.height = height;
    for (auto& t : host::generate_random_triangles(width, height, count, area, seed)) {
        host::Face f;
        f.vertices = std::move(t.vertices);
        f.id = scene.face_count++;
        scene.faces.push_back(std::move(f));
    }
    return scene;
}

}  // namespace fb89::testing
