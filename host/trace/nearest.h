// The nearest-hit rule every ray walk shares (the BVH's, the grid's, the kd-tree's): a piece
// hit at tmin < t <= tmax becomes the best when nearer than it, or as near and a lower piece --
// a tie, counted -- so the answer does not depend on the order a walk meets the pieces. Tests
// and ties are counted in locals, added to the frame's counts once a ray. A piece met again
// (a kd-tree lists it in every leaf it touches) is tested again, and counted, unless it is the
// best so far, whose distance is known.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "host/trace/trace_scene.h"

namespace fb89::host {

struct Nearest {
    const TraceScene& scene;
    const Ray& ray;
    const RaySpace& space;
    double tmin, tmax;
    Hit best{INFINITY, kNoFace};
    uint64_t tests = 0, ties = 0;

    void test(uint32_t piece) {
        if (piece == best.piece) return;  // the best so far, met again: its t is known
        ++tests;
        double t;
        if (!scene.intersect(ray, space, piece, tmin, t, std::min(best.t, tmax)) || t > best.t ||
            t > tmax)
            return;
        if (t == best.t) {
            ++ties;
            if (piece > best.piece) return;
        }
        best = {t, piece};
    }
};

}  // namespace fb89::host
