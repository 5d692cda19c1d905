// The coverage rule (DESIGN.md "Screen space, coverage and depth"), shared by the host's
// raster methods and the controller's FACE command (docs/PROTOCOL.md, version 3): pixel
// centres, 64-bit integer edge functions on the 1/256-pixel grid, and the top-left rule for
// exact ties (a centre on an edge belongs to the face only if the edge is a left edge, or a
// horizontal top edge, in x-right, y-down screen space). This is the rule Mesa's llvmpipe
// uses, so the conformance fixtures check it pixel for pixel. It lives here, below both the
// host and the controller, because a FACE's pixels are defined by it: one implementation,
// which both sides include.
//
// A face is convex, so the centres it covers in one row form one run; `row_span` finds that
// run with one exact integer division per edge, so no method loops over pixels to test
// coverage.
#pragma once

#include <cstdint>

namespace fb89::protocol {

inline constexpr int kSubpixelBits = 8;  // vertices on the 1/256-pixel grid
inline constexpr int64_t kSubpixel = int64_t{1} << kSubpixelBits;

struct SnappedPoint {
    int64_t x = 0, y = 0;  // in 1/256 pixel
    friend bool operator==(const SnappedPoint&, const SnappedPoint&) = default;
};

// The edge function of one polygon edge, evaluated at pixel centres:
// E(x, y) = nx * 256 * x + ny * 256 * y + k0 for pixel (x, y); the centre is covered when
// E >= bias, where bias is 0 for an edge the top-left rule gives the ties to, else 1.
struct EdgeFunction {
    int64_t nx = 0, ny = 0;
    int64_t k0 = 0;
    int64_t bias = 0;
};

// Edge functions of a convex polygon given in positive orientation (interior on the left of
// each edge in x-right, y-down coordinates' own sense). Of any other polygon, the centres on
// the inner side of every edge: none for one wound the other way.
void setup_edges(const SnappedPoint* points, uint32_t count, EdgeFunction* edges);

// Does the face cover the centre of pixel (x, y)?
bool covers(const EdgeFunction* edges, uint32_t count, int x, int y);

namespace detail {
inline int64_t floor_div(int64_t a, int64_t b) {  // b > 0
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}
inline int64_t ceil_div(int64_t a, int64_t b) {  // b > 0
    return a >= 0 ? (a + b - 1) / b : -((-a) / b);
}
}  // namespace detail

// The covered centres of row y within [x_lo, x_hi): sets [x_begin, x_end) and returns true
// when that run is not empty.
inline bool row_span(const EdgeFunction* edges, uint32_t count, int y, int x_lo, int x_hi,
                     int& x_begin, int& x_end) {
    int64_t lo = x_lo, hi = x_hi - 1;  // inclusive bounds while intersecting
    for (uint32_t i = 0; i < count && lo <= hi; ++i) {
        const EdgeFunction& e = edges[i];
        int64_t k = e.ny * kSubpixel * y + e.k0;  // E(x) = nx*256*x + k; need E >= bias
        if (e.nx > 0) {
            int64_t first = detail::ceil_div(e.bias - k, e.nx * kSubpixel);
            if (first > lo) lo = first;
        } else if (e.nx < 0) {
            int64_t last = detail::floor_div(k - e.bias, -e.nx * kSubpixel);
            if (last < hi) hi = last;
        } else if (k < e.bias) {
            return false;
        }
    }
    if (lo > hi) return false;
    x_begin = static_cast<int>(lo);
    x_end = static_cast<int>(hi + 1);
    return true;
}

}  // namespace fb89::protocol
