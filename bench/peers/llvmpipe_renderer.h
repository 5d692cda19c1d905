// The raster peer: Mesa's llvmpipe through OSMesa (REFERENCES.md "Raster peer"), drawing a
// ScreenScene so that its face-id buffer can be compared with ours pixel for pixel and its
// frame time with our hidden-surface time.
//
// Set-up as REFERENCES.md prescribes: an OSMesaCreateContextAttribs context (RGBA, 24-bit
// depth, compat profile) made current on a width x height RGBA8 buffer; flat shading, no
// dither, no multisample, no blending, GL_LESS. Each face (a convex piece with snapped
// vertices) is one triangle fan; its vertices are given in NDC, x_ndc = 2x/W - 1 and
// y_ndc = 2y/H - 1 (GL's window y is our y, so with the default OSMESA_Y_UP buffer row r is
// our row r), z_ndc = 2z - 1 with z the face's depth plane at the vertex; its colour is
// id + 1 as 24-bit RGB. The vertex data is built once per scene and kept in a GL buffer
// object (set-up, like our projection); a frame is glClear, one glMultiDrawArrays of every
// fan in id order, glFinish. Set LP_NUM_THREADS before the first context is made.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "host/raster/screen_scene.h"

namespace fb89::peers {

class LlvmpipeRenderer {
  public:
    LlvmpipeRenderer();  // throws std::runtime_error when no context can be made
    ~LlvmpipeRenderer();
    LlvmpipeRenderer(const LlvmpipeRenderer&) = delete;
    LlvmpipeRenderer& operator=(const LlvmpipeRenderer&) = delete;

    // Set-up, untimed: sizes the buffer to the scene and uploads its fans.
    void upload(const host::ScreenScene& scene);

    // One frame of the uploaded scene; returns wall-clock ms from the first GL call to the
    // return of glFinish (reading the buffer is not included).
    double render();

    // The last frame's ids + 1 per pixel (0 where nothing was drawn), row 0 at the top.
    std::vector<uint32_t> face_ids() const;

    std::string renderer_string() const;  // GL_RENDERER and GL_VERSION, after upload()

  private:
    void* m_context = nullptr;  // OSMesaContext
    int m_width = 0, m_height = 0;
    std::vector<uint8_t> m_pixels;  // RGBA8, the OSMesa colour buffer
    unsigned m_vbo = 0;
    std::vector<int> m_first;  // per fan: first vertex and vertex count
    std::vector<int> m_count;
};

}  // namespace fb89::peers
