// From scene to screen: shading, the camera (gluLookAt + gluPerspective conventions),
// near/far and guard-band clipping, the perspective divide and each face's depth plane.
// It stops at clipped, projected polygons in pixels; snapping them to the raster grid and
// setting up their edges is the raster rule's (host/raster/screen_setup.h).
#pragma once

#include <cstdint>
#include <vector>

#include "host/scene/scene.h"
#include "host/stats.h"
#include "protocol/command.h"

namespace fb89::host {

// Pixels beyond each screen border kept by the guard band. Keeps every snapped coordinate
// within +-2^15 pixels (2^23 grid units), so edge functions stay far from 64-bit overflow.
inline constexpr double kGuardBandPixels = 8192;

enum class ColorMode {
    Shaded,  // flat Lambertian with the scene's light (screen-space scenes: unlit colour)
    FaceId,  // colour = id + 1 as a 24-bit number, unshaded: the face-id pass
};

protocol::Rgb face_id_color(uint32_t id);
uint32_t face_id_from_color(protocol::Rgb c);  // id + 1; 0 is background

struct ProjectedVertex {
    double x, y, z;  // pixels (x right, y down), pixels, window depth in [0, 1]
};

struct DepthPlane {
    double a = 0, b = 0, c = 0;  // z = a*x + b*y + c, x and y in pixels
};

// One face after clipping: its vertices in pixels, not yet snapped, and its depth plane
// through them (exact for a planar face).
struct ProjectedFace {
    uint32_t id = 0;
    protocol::Rgb color;
    DepthPlane depth;
    uint32_t first_vertex = 0;  // into ProjectedScene::vertices
    uint32_t vertex_count = 0;
};

struct ProjectedScene {
    int width = 0, height = 0;
    protocol::Rgb background;
    uint32_t face_count = 0;           // distinct ids of the scene
    std::vector<ProjectedFace> faces;  // in scene order, those left by the clip
    std::vector<ProjectedVertex> vertices;
    const Scene* world = nullptr;  // the scene projected (it must outlive this)
    bool id_colors = false;        // projected for the face-id pass

    const ProjectedVertex* vertices_of(const ProjectedFace& f) const {
        return &vertices[f.first_vertex];
    }
};

// Counts the faces it clipped and those wholly outside the view into `counters`.
ProjectedScene project_faces(const Scene& scene, ColorMode mode, Counters& counters);

}  // namespace fb89::host
