// Mesa llvmpipe through OSMesa: context, upload of a scene's fans, one timed frame, and
// the face-id buffer read back from the colour buffer (see llvmpipe_renderer.h).
#include "bench/peers/llvmpipe_renderer.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
// osmesa.h brings GL/gl.h; glext.h adds the buffer-object entry points libOSMesa exports.
#include <GL/glext.h>

#include <chrono>
#include <cstddef>
#include <stdexcept>

namespace fb89::peers {

namespace {

struct Vertex {
    float x, y, z;
    uint8_t rgba[4];
};

OSMesaContext context_of(void* p) {
    return static_cast<OSMesaContext>(p);
}

}  // namespace

LlvmpipeRenderer::LlvmpipeRenderer() {
    // attribute, value pairs; a 0 attribute ends the list
    // clang-format off
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                           OSMESA_DEPTH_BITS, 24,
                           OSMESA_STENCIL_BITS, 0,
                           OSMESA_ACCUM_BITS, 0,
                           OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                           0};
    // clang-format on
    m_context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!m_context) throw std::runtime_error("OSMesaCreateContextAttribs failed");
}

LlvmpipeRenderer::~LlvmpipeRenderer() {
    if (m_vbo) glDeleteBuffers(1, &m_vbo);
    OSMesaDestroyContext(context_of(m_context));
}

void LlvmpipeRenderer::upload(const host::ScreenScene& scene) {
    // size the buffer and make it current (again, if the size changed)
    if (scene.width != m_width || scene.height != m_height || m_pixels.empty()) {
        m_width = scene.width;
        m_height = scene.height;
        m_pixels.assign(static_cast<size_t>(m_width) * m_height * 4, 0);
        if (!OSMesaMakeCurrent(context_of(m_context), m_pixels.data(), GL_UNSIGNED_BYTE, m_width,
                               m_height))
            throw std::runtime_error("OSMesaMakeCurrent failed");
        glViewport(0, 0, m_width, m_height);
        glShadeModel(GL_FLAT);
        glDisable(GL_DITHER);
        glDisable(GL_MULTISAMPLE);
        glDisable(GL_BLEND);
        glDisable(GL_CULL_FACE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthRange(0.0, 1.0);
        glClearColor(0, 0, 0, 0);
        glClearDepth(1.0);
        if (!m_vbo) glGenBuffers(1, &m_vbo);
    }

    // one fan per face piece, in id order, vertices in NDC
    std::vector<Vertex> vertices;
    vertices.reserve(scene.points.size());
    m_first.clear();
    m_count.clear();
    const double sx = 2.0 / m_width, sy = 2.0 / m_height;
    for (const host::ScreenFace& f : scene.faces) {
        const uint32_t rgb = f.id + 1;
        const uint8_t r = static_cast<uint8_t>(rgb >> 16), g = static_cast<uint8_t>(rgb >> 8),
                      b = static_cast<uint8_t>(rgb);
        m_first.push_back(static_cast<int>(vertices.size()));
        m_count.push_back(static_cast<int>(f.point_count));
        const host::SnappedPoint* p = scene.points_of(f);
        for (uint32_t i = 0; i < f.point_count; ++i) {
            const double x = static_cast<double>(p[i].x) / host::kSubpixel;
            const double y = static_cast<double>(p[i].y) / host::kSubpixel;
            const double z = f.depth.a * x + f.depth.b * y + f.depth.c;
            vertices.push_back({static_cast<float>(x * sx - 1.0),
                                static_cast<float>(y * sy - 1.0),
                                static_cast<float>(2.0 * z - 1.0),
                                {r, g, b, 255}});
        }
    }

    // keep the fans in a buffer object, as a scene resident in the renderer
    glBindBuffer(GL_ARRAY_BUFFER, m_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.data(), GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(Vertex), reinterpret_cast<const void*>(0));
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex),
                   reinterpret_cast<const void*>(offsetof(Vertex, rgba)));
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("GL error while uploading a scene");
}

double LlvmpipeRenderer::render() {
    const auto start = std::chrono::steady_clock::now();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMultiDrawArrays(GL_TRIANGLE_FAN, m_first.data(), m_count.data(),
                      static_cast<GLsizei>(m_first.size()));
    glFinish();
    const auto end = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(end - start).count();
}

std::vector<uint32_t> LlvmpipeRenderer::face_ids() const {
    std::vector<uint32_t> ids(static_cast<size_t>(m_width) * m_height);
    for (size_t i = 0; i < ids.size(); ++i) {
        const uint8_t* p = &m_pixels[i * 4];
        ids[i] = (uint32_t{p[0]} << 16) | (uint32_t{p[1]} << 8) | p[2];
    }
    return ids;
}

std::string LlvmpipeRenderer::renderer_string() const {
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return std::string(renderer ? renderer : "?") + ", OpenGL " + (version ? version : "?");
}

}  // namespace fb89::peers

#undef GL_GLEXT_PROTOTYPES
