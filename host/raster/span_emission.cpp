#include "host/raster/span_emission.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace fb89::host {

namespace {

uint32_t packed_rgb(protocol::Rgb c) {
    return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b;
}

// First x in [x, end) whose entry differs from `value`. Runs are long (tens of pixels), so
// four entries are compared at a time where SSE2 is there.
int skip_equal(const uint32_t* row, int x, int end, uint32_t value) {
#if defined(__SSE2__)
    const __m128i v = _mm_set1_epi32(static_cast<int>(value));
    for (; x + 4 <= end; x += 4) {
        __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + x));
        if (_mm_movemask_epi8(_mm_cmpeq_epi32(four, v)) != 0xFFFF) break;
    }
#endif
    while (x < end && row[x] == value)
        ++x;
    return x;
}

}  // namespace

uint64_t emit_row_spans(const ScreenScene& scene, const uint32_t* row, int y, int x0, int x1,
                        protocol::CommandSink& sink) {
    uint64_t spans = 0;
    int x = skip_equal(row, x0, x1, 0);  // background sends nothing
    while (x < x1) {
        // a run: the same face, or faces of the same colour
        const uint32_t face = row[x];
        const protocol::Rgb color = scene.faces[face - 1].color;
        const uint32_t key = packed_rgb(color);
        const int start = x;
        x = skip_equal(row, x, x1, face);
        while (x < x1 && row[x] != 0 && packed_rgb(scene.faces[row[x] - 1].color) == key)
            x = skip_equal(row, x, x1, row[x]);
        sink.draw_span({y, start, x - 1, color});
        ++spans;
        x = skip_equal(row, x, x1, 0);
    }
    return spans;
}

}  // namespace fb89::host
