#include "host/trace/trace_scene.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "host/scene/polygon.h"
#include "host/scene/projection.h"

namespace fb89::host {

namespace {

uint8_t trace_byte(double v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

// Both sides' flat colours, the way the raster pipeline shades the side facing the eye.
std::array<glm::dvec3, 2> local_colors(const Scene& scene, const Face& face,
                                       const glm::dvec3& normal) {
    std::array<glm::dvec3, 2> out;
    for (int side = 0; side < 2; ++side) {
        glm::dvec3 c = face.material.color;
        if (scene.projection == Projection::Perspective) {
            const glm::dvec3 n = side == 0 ? normal : -normal;
            const double diffuse = std::max(0.0, glm::dot(n, -scene.light.direction));
            c = c * (scene.light.ambient + (1.0 - scene.light.ambient) * diffuse);
        }
        out[side] = c + face.material.emission;
    }
    return out;
}

}  // namespace

TraceScene::TraceScene(const Scene& scene, bool id_colors, int max_reflections)
    : m_width(scene.width),
      m_height(scene.height),
      m_id_colors(id_colors),
      m_max_reflections(std::max(0, max_reflections)),
      m_background(id_colors ? glm::dvec3(0) : scene.background),
      m_face_count(scene.face_count),
      m_orthographic(scene.projection == Projection::Screen) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const Face& face : scene.faces) {
        TraceFace f;
        f.first_vertex = static_cast<uint32_t>(m_vertices.size());
        f.vertex_count = static_cast<uint32_t>(face.vertices.size());
        f.normal = glm::normalize(newell_normal(face.vertices));
        f.plane = glm::dot(f.normal, face.vertices[0]);
        f.id = face.id;
        f.mirror = face.material.mirror;
        f.local_color = local_colors(scene, face, f.normal);
        PieceBox box{face.vertices[0], face.vertices[0]};
        for (const auto& v : face.vertices) {
            m_vertices.push_back(v);
            box.lo = glm::min(box.lo, v);
            box.hi = glm::max(box.hi, v);
        }
        lo = glm::min(lo, box.lo);
        hi = glm::max(hi, box.hi);
        m_faces.push_back(f);
        m_boxes.push_back(box);
    }
    for (uint32_t p = 0; p < m_faces.size(); ++p)
        for (int side = 0; side < 2; ++side) {
            const PathHit only{p, side == 1};
            m_faces[p].end_color[side] = path_color(*this, &only, 1);
        }
    if (!m_orthographic) {
        const Camera& cam = scene.camera;
        m_eye = cam.eye;
        m_forward = glm::normalize(cam.look_at - cam.eye);
        const glm::dvec3 side = glm::normalize(glm::cross(m_forward, cam.up));
        const glm::dvec3 up = glm::cross(side, m_forward);
        const double half_h = std::tan(glm::radians(cam.fovy_degrees) / 2);
        const double half_w = half_h * m_width / m_height;
        m_right = side * half_w;
        m_up = up * half_h;
        m_near = cam.near;
        m_primary_length = cam.far - cam.near;
        m_column_dir.resize(static_cast<size_t>(std::max(m_width, 0)));
        for (int x = 0; x < m_width; ++x)
            m_column_dir[x] = m_forward + column_ndc(x) * m_right;
        m_row_ndc.resize(static_cast<size_t>(std::max(m_height, 0)));
        for (int y = 0; y < m_height; ++y)
            m_row_ndc[y] = row_ndc(y);
        lo = glm::min(lo, m_eye);
        hi = glm::max(hi, m_eye);
    }
    const double size = m_faces.empty() ? 1.0 : std::max(glm::length(hi - lo), 1e-30);
    m_tolerance = size * 1e-9;
}

protocol::Rgb path_color(const TraceScene& scene, const PathHit* hits, int count) {
    const auto& faces = scene.faces();
    if (scene.id_colors())
        return count == 0 ? protocol::Rgb{0, 0, 0} : face_id_color(faces[hits[count - 1].piece].id);
    glm::dvec3 c = scene.background();
    for (int i = count - 1; i >= 0; --i) {
        const TraceFace& f = faces[hits[i].piece];
        const glm::dvec3& local = f.local_color[hits[i].back ? 1 : 0];
        c = f.mirror > 0 ? (1.0 - f.mirror) * local + f.mirror * c : local;
    }
    return {trace_byte(c.r), trace_byte(c.g), trace_byte(c.b)};
}

}  // namespace fb89::host
