// Faces in screen space, ready for every raster method (docs/ARCHITECTURE.md "The shared
// raster rule"); screen_setup.h makes them from projected faces.
//
// x right, y down, row 0 at the top; pixel (x, y) is sampled at (x + 0.5, y + 0.5).
// Vertices are snapped to 1/256 pixel and kept as integers; every face is a convex polygon
// wound so that its interior is on the left of each edge in these coordinates' own sense
// (see coverage.h). Depth is the projected face's plane z = a*x + b*y + c, computed before
// snapping (host/scene/projection.h).
#pragma once

#include <cstdint>
#include <vector>

#include "host/scene/projection.h"
#include "protocol/command.h"
#include "protocol/coverage.h"

namespace fb89::host {

struct Scene;

// The raster rule's integers (protocol/coverage.h, shared with the controller's FACE).
using protocol::EdgeFunction;
using protocol::kSubpixel;
using protocol::kSubpixelBits;
using protocol::SnappedPoint;

// Pixel rectangle [x0, x1) x [y0, y1).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    long long area() const { return empty() ? 0 : (long long)width() * height(); }
};

struct ScreenFace {
    uint32_t id = 0;
    protocol::Rgb color;
    DepthPlane depth;
    uint32_t first_point = 0;  // into ScreenScene::points and ScreenScene::edges
    uint32_t point_count = 0;  // also the edge count
    PixelRect bounds;          // pixels whose centres the face may cover, clamped to the screen
};

struct ScreenScene {
    int width = 0;
    int height = 0;
    protocol::Rgb background;
    std::vector<ScreenFace> faces;  // in id order (pieces of one face adjacent)
    std::vector<SnappedPoint> points;
    std::vector<EdgeFunction> edges;  // edge i runs from points[i] to the face's next point
    uint32_t face_count = 0;          // distinct ids

    // The world scene this was projected from, for methods that trace rays in world space
    // (it must outlive this), and whether it was projected for the face-id pass.
    const Scene* world = nullptr;
    bool id_colors = false;

    PixelRect screen() const { return {0, 0, width, height}; }
    const SnappedPoint* points_of(const ScreenFace& f) const { return &points[f.first_point]; }
    const EdgeFunction* edges_of(const ScreenFace& f) const { return &edges[f.first_point]; }
};

}  // namespace fb89::host
