// The one shared depth rule of every raster method (DESIGN.md "Screen space, coverage and
// depth"): a face's depth plane is evaluated directly at the pixel centre in double
// precision (never by accumulating increments), the nearer face wins, and on exact
// equality the lower id wins. Because Z-buffer, Warnock, scan-line and the hybrid all call
// these two functions, they produce the same face-id buffer.
#pragma once

#include <cstdint>

#include "host/raster/screen_scene.h"

namespace fb89::host {

inline double depth_at(const DepthPlane& p, int x, int y) {
    return p.a * (x + 0.5) + p.b * (y + 0.5) + p.c;
}

// Does a face at depth z with id `id` hide one at z_other with id_other?
inline bool nearer(double z, uint32_t id, double z_other, uint32_t id_other) {
    return z < z_other || (z == z_other && id < id_other);
}

}  // namespace fb89::host
