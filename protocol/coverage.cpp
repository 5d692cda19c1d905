#include "protocol/coverage.h"

namespace fb89::protocol {

void setup_edges(const SnappedPoint* p, uint32_t count, EdgeFunction* edges) {
    const int64_t half = kSubpixel / 2;  // pixel centres sit at +0.5
    for (uint32_t i = 0; i < count; ++i) {
        const SnappedPoint& a = p[i];
        const SnappedPoint& b = p[(i + 1) % count];
        EdgeFunction& e = edges[i];
        // interior on the left of a->b: normal (a.y - b.y, b.x - a.x)
        e.nx = a.y - b.y;
        e.ny = b.x - a.x;
        e.k0 = e.nx * (half - a.x) + e.ny * (half - a.y);
        // top-left rule: ties go to left edges (interior to the right) and to horizontal
        // top edges (interior below)
        bool owns_ties = e.nx > 0 || (e.nx == 0 && e.ny > 0);
        e.bias = owns_ties ? 0 : 1;
    }
}

bool covers(const EdgeFunction* edges, uint32_t count, int x, int y) {
    for (uint32_t i = 0; i < count; ++i) {
        const EdgeFunction& e = edges[i];
        int64_t value = e.nx * kSubpixel * x + e.ny * kSubpixel * y + e.k0;
        if (value < e.bias) return false;
    }
    return true;
}

}  // namespace fb89::protocol
