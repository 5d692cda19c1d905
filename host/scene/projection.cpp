#include "host/scene/projection.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "host/scene/clip.h"
#include "host/scene/polygon.h"

namespace fb89::host {

namespace {

uint8_t to_byte(double v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

protocol::Rgb shade(const Scene& scene, const Face& face, ColorMode mode) {
    if (mode == ColorMode::FaceId) return face_id_color(face.id);
    glm::dvec3 c = face.material.color;
    if (scene.projection == Projection::Perspective) {
        glm::dvec3 n = glm::normalize(newell_normal(face.vertices));
        if (glm::dot(n, scene.camera.eye - face.vertices[0]) < 0) n = -n;  // two-sided
        double diffuse = std::max(0.0, glm::dot(n, -scene.light.direction));
        c = c * (scene.light.ambient + (1.0 - scene.light.ambient) * diffuse);
    }
    c += face.material.emission;
    return {to_byte(c.r), to_byte(c.g), to_byte(c.b)};
}

// Depth plane through the projected (unsnapped) vertices: exact for a planar face.
DepthPlane depth_plane(const ProjectedVertex* v, size_t count) {
    double nx = 0, ny = 0, nz = 0;
    if (count == 3) {
        double ux = v[1].x - v[0].x, uy = v[1].y - v[0].y, uz = v[1].z - v[0].z;
        double wx = v[2].x - v[0].x, wy = v[2].y - v[0].y, wz = v[2].z - v[0].z;
        nx = uy * wz - uz * wy;
        ny = uz * wx - ux * wz;
        nz = ux * wy - uy * wx;
    } else {
        for (size_t i = 0; i < count; ++i) {
            const auto& a = v[i];
            const auto& b = v[(i + 1) % count];
            nx += (a.y - b.y) * (a.z + b.z);
            ny += (a.z - b.z) * (a.x + b.x);
            nz += (a.x - b.x) * (a.y + b.y);
        }
    }
    if (nz == 0) return {0, 0, v[0].z};  // edge-on: covers no pixel centre anyway
    DepthPlane p;
    p.a = -nx / nz;
    p.b = -ny / nz;
    p.c = v[0].z - p.a * v[0].x - p.b * v[0].y;
    return p;
}

}  // namespace

protocol::Rgb face_id_color(uint32_t id) {
    uint32_t v = id + 1;
    return {static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

uint32_t face_id_from_color(protocol::Rgb c) {
    return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | uint32_t{c.b};
}

ProjectedScene project_faces(const Scene& scene, ColorMode mode, Counters& counters) {
    ProjectedScene out;
    out.width = scene.width;
    out.height = scene.height;
    // in the face-id pass the background is id + 1 = 0, whatever the scene's colour
    out.background = mode == ColorMode::FaceId
                         ? protocol::Rgb{0, 0, 0}
                         : protocol::Rgb{to_byte(scene.background.r), to_byte(scene.background.g),
                                         to_byte(scene.background.b)};
    out.face_count = scene.face_count;
    out.world = &scene;
    out.id_colors = mode == ColorMode::FaceId;
    const double w = scene.width, h = scene.height;
    const bool perspective = scene.projection == Projection::Perspective;

    // clip planes: dot(plane, p) >= 0 keeps p
    std::vector<glm::dvec4> planes;
    glm::dmat4 clip_from_world(1.0);
    if (perspective) {
        const Camera& cam = scene.camera;
        clip_from_world =
            glm::perspective(glm::radians(cam.fovy_degrees), w / h, cam.near, cam.far) *
            glm::lookAt(cam.eye, cam.look_at, cam.up);
        double gx = 1 + 2 * kGuardBandPixels / w, gy = 1 + 2 * kGuardBandPixels / h;
        planes = {{0, 0, 1, 1},   {0, 0, -1, 1}, {1, 0, 0, gx},
                  {-1, 0, 0, gx}, {0, 1, 0, gy}, {0, -1, 0, gy}};
    } else {
        const double g = kGuardBandPixels;
        planes = {{0, 0, 1, 0},      {0, 0, -1, 1}, {1, 0, 0, g},
                  {-1, 0, 0, w + g}, {0, 1, 0, g},  {0, -1, 0, h + g}};
    }

    uint64_t clipped = 0, outside = 0;
    std::vector<glm::dvec4> poly, scratch, original;
    for (const Face& face : scene.faces) {
        // to clip space, then clip
        poly.clear();
        for (const auto& v : face.vertices)
            poly.push_back(perspective ? clip_from_world * glm::dvec4(v, 1.0) : glm::dvec4(v, 1.0));
        original = poly;
        if (!clip_polygon(poly, planes, scratch)) {
            ++outside;
            continue;
        }
        if (poly != original) ++clipped;

        // divide and viewport: x right, y down
        ProjectedFace f;
        f.id = face.id;
        f.color = shade(scene, face, mode);
        f.first_vertex = static_cast<uint32_t>(out.vertices.size());
        f.vertex_count = static_cast<uint32_t>(poly.size());
        for (const auto& p : poly) {
            if (perspective)
                out.vertices.push_back(
                    {(p.x / p.w + 1) * 0.5 * w, (1 - p.y / p.w) * 0.5 * h, (p.z / p.w + 1) * 0.5});
            else
                out.vertices.push_back({p.x, p.y, p.z});
        }
        f.depth = depth_plane(out.vertices_of(f), f.vertex_count);
        out.faces.push_back(f);
    }
    counters.add("faces_clipped", clipped);
    counters.add("faces_outside_frustum", outside);
    return out;
}

}  // namespace fb89::host
