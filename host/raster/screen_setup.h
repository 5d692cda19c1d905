// Screen set-up: the raster rule's half of the set-up stage. Projected faces
// (host/scene/projection.h) are snapped to the 1/256-pixel grid, put in positive
// orientation, cut into convex pieces where snapping bent them, bounded by the pixel
// centres they may cover, and given their edge functions (coverage.h), so that every
// raster method decides pixels from the same integers.
#pragma once

#include <cstdint>
#include <vector>

#include "host/raster/screen_scene.h"
#include "host/scene/projection.h"
#include "host/stats.h"

namespace fb89::host {

// Snapped polygon in positive orientation with no repeated points; empty if it has no area.
std::vector<SnappedPoint> snap(const ProjectedVertex* vertices, uint32_t count);

// Snapping can bend a near-degenerate convex polygon; this cuts one into triangles by ear
// clipping.
std::vector<std::vector<SnappedPoint>> convex_pieces(std::vector<SnappedPoint> polygon);

// The pixels whose centres the snapped polygon may cover, clamped to the screen.
PixelRect pixel_bounds(const std::vector<SnappedPoint>& polygon, int width, int height);

// Counts faces without area after snapping, faces split by it and the pieces on screen.
ScreenScene setup_screen(const ProjectedScene& projected, Counters& counters);

// The whole set-up stage: project_faces() then setup_screen().
ScreenScene project_scene(const Scene& scene, ColorMode mode, Counters& counters);

}  // namespace fb89::host
