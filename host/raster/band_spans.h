// The Z-buffer's output: one resolved row of its face buffer turned into DRAW_SPAN
// commands, the row left zeroed for the next band.
//
// A span is a run of pixels of one colour: the same face, or adjacent faces whose colours
// are equal; pixels no face covers (0) are background and send nothing. These are the
// spans, in the same order, that emit_row_spans() (span_emission.h) sends. Rows are
// scanned for the places where the face changes, eight entries at a time where SSE2 is
// there (each block compared with itself shifted by one entry; a bit per change), so the
// work per row is one pass plus a step per run; colours come from a per-face table built
// while binning rather than from the scene's face records, which lie far apart in memory.
#pragma once

#include <algorithm>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "protocol/command_sink.h"

namespace fb89::host {

inline uint32_t packed_color(protocol::Rgb c) {
    return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b;
}
inline protocol::Rgb unpacked_color(uint32_t key) {
    return {static_cast<uint8_t>(key >> 16), static_cast<uint8_t>(key >> 8),
            static_cast<uint8_t>(key)};
}

// Runs of equal entries, merged into spans of equal colour.
class SpanMerger {
  public:
    SpanMerger(int y, const uint32_t* colors, protocol::CommandSink& sink)
        : m_y(y), m_colors(colors), m_sink(sink) {}

    // The run [start, end) of `face` (index + 1, 0: background), in row order.
    void run(uint32_t face, int start, int end) {
        if (face == 0) {
            flush();
            return;
        }
        const uint32_t key = m_colors[face - 1];
        if (m_open && key == m_key) {
            m_end = end;  // the run before was adjacent and of this colour
            return;
        }
        flush();
        m_open = true;
        m_key = key, m_start = start, m_end = end;
    }
    void flush() {
        if (!m_open) return;
        m_sink.draw_span({m_y, m_start, m_end - 1, unpacked_color(m_key)});
        ++m_spans;
        m_open = false;
    }
    uint64_t spans() const { return m_spans; }

  private:
    int m_y;
    const uint32_t* m_colors;
    protocol::CommandSink& m_sink;
    bool m_open = false;
    uint32_t m_key = 0;
    int m_start = 0, m_end = 0;
    uint64_t m_spans = 0;
};

// Sends the spans of row[x0, x1) (row y; entries are scene.faces index + 1, colors[i] the
// packed colour of face i) and zeroes those entries. Reads row[x1], which must exist.
// Returns the spans sent.
inline uint64_t emit_band_row(uint32_t* row, int y, int x0, int x1, const uint32_t* colors,
                              protocol::CommandSink& sink) {
    if (x0 >= x1) return 0;
    SpanMerger spans(y, colors, sink);
    uint32_t face = row[x0];
    int start = x0, x = x0;
#if defined(__SSE2__)
    for (; x + 8 <= x1; x += 8) {
        // where the face changes: bit i set when row[x + i] != row[x + i + 1]
        const __m128i* at = reinterpret_cast<const __m128i*>(row + x);
        const __m128i* after = reinterpret_cast<const __m128i*>(row + x + 1);
        const __m128i eq_lo = _mm_cmpeq_epi32(_mm_loadu_si128(at), _mm_loadu_si128(after));
        const __m128i eq_hi = _mm_cmpeq_epi32(_mm_loadu_si128(at + 1), _mm_loadu_si128(after + 1));
        const unsigned equal = static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(eq_lo))) |
                               static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(eq_hi))) << 4;
        unsigned change = equal ^ 0xFFu;
        if (x + 8 == x1) change &= 0x7Fu;  // row[x1] is not part of the row
        // each change ends a run
        for (; change != 0; change &= change - 1) {
            const int end = x + __builtin_ctz(change) + 1;
            spans.run(face, start, end);
            face = row[end];
            start = end;
        }
    }
#endif
    for (; x < x1; ++x) {
        if (x + 1 < x1 && row[x + 1] != face) {
            spans.run(face, start, x + 1);
            face = row[x + 1];
            start = x + 1;
        }
    }
    std::fill(row + x0, row + x1, 0u);
    spans.run(face, start, x1);
    spans.flush();
    return spans.spans();
}

}  // namespace fb89::host
