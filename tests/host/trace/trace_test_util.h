// What tests of the ray and beam tracers share: small world scenes built in code, and one
// frame of a method rendered to its face-id buffer or its image.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "controller_sim/controller.h"
#include "host/methods.h"
#include "host/raster/screen_setup.h"
#include "host/trace/beam_ray_hybrid.h"
#include "protocol/memory_buffer.h"
#include "tests/host/raster/raster_test_util.h"

namespace fb89::testing {

// A perspective scene looking from (0, 0, 5) at the origin, 45 degrees, at width x height.
inline host::Scene world_scene(int width, int height) {
    host::Scene s;
    s.width = width;
    s.height = height;
    s.camera.eye = {0, 0, 5};
    s.camera.look_at = {0, 0, 0};
    s.background = {0.1, 0.2, 0.3};
    s.light.direction = {-0.3, -0.5, -1};
    return s;
}

inline uint32_t add_face(host::Scene& s, std::vector<glm::dvec3> vertices, glm::dvec3 color,
                         double mirror = 0) {
    host::Face f;
    f.vertices = std::move(vertices);
    f.material.color = color;
    f.material.mirror = mirror;
    f.id = s.face_count++;
    s.faces.push_back(std::move(f));
    return s.faces.back().id;
}

// An axis-aligned square of side 2h in the plane z, centred at (cx, cy).
inline uint32_t add_square(host::Scene& s, double cx, double cy, double z, double h,
                           glm::dvec3 color, double mirror = 0) {
    return add_face(
        s, {{cx - h, cy - h, z}, {cx + h, cy - h, z}, {cx + h, cy + h, z}, {cx - h, cy + h, z}},
        color, mirror);
}

// Screen-space triangles with every vertex on a pixel centre, `cells` x `cells` squares of
// two triangles each, folded in depth so that no two neighbours are coplanar: a pixel ray
// (and a beam's corner) meets the mesh exactly on its shared edges and vertices. Colours
// vary by row and column.
inline host::Scene lattice_through_pixel_centres(int size, int cells) {
    host::Scene s;
    s.projection = host::Projection::Screen;
    s.width = s.height = size;
    const int step = (size - 1) / cells;
    auto v = [&](int i, int j) {
        return glm::dvec3(0.5 + i * step, 0.5 + j * step, 0.25 + 0.01 * ((i + 2 * j) % 3));
    };
    for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
            add_face(s, {v(i, j), v(i + 1, j), v(i + 1, j + 1)}, {0.1 * (i % 7), 0.5, 0.2});
            add_face(s, {v(i, j), v(i + 1, j + 1), v(i, j + 1)}, {0.5, 0.1 * (j % 7), 0.2});
        }
    return s;
}

struct Frame {
    std::vector<uint32_t> ids;    // id + 1 per pixel (face-id pass)
    std::vector<uint8_t> pixels;  // the shaded frame, as the controller holds it
    host::HostStats stats;        // of the shaded frame
    std::vector<uint8_t> beam_mask;
};

inline host::MethodOptions trace_options(const char* method, double threshold = 0.5,
                                         int reflections = 8) {
    host::MethodOptions o(host::method_named(method));
    o.beam.threshold = threshold;
    o.trace.max_reflections = reflections;
    return o;
}

// Both passes of one method: the face-id pass, then the shaded pass (with its counts).
inline Frame render_trace(const host::Scene& scene, const host::MethodOptions& options) {
    Frame out;
    auto renderer = host::make_renderer(options);
    {
        host::HostStats stats;
        host::ScreenScene ids = host::project_scene(scene, host::ColorMode::FaceId, stats.counters);
        renderer->setup(ids);
        protocol::MemoryBuffer commands;
        host::render_frame(*renderer, ids, commands, stats);
        out.ids = ids_from_commands(commands.commands(), scene.width, scene.height);
    }
    host::ScreenScene shaded =
        host::project_scene(scene, host::ColorMode::Shaded, out.stats.counters);
    renderer->setup(shaded);
    protocol::MemoryBuffer commands;
    host::render_frame(*renderer, shaded, commands, out.stats);
    controller::Controller ctl(controller::load_profile("ideal"));
    commands.replay_into(ctl);
    auto px = ctl.framebuffer().pixels();
    out.pixels.assign(px.begin(), px.end());
    if (auto* beam = dynamic_cast<host::BeamRayHybrid*>(renderer.get()))
        out.beam_mask = beam->beam_mask();
    return out;
}

}  // namespace fb89::testing
