#include "host/raster/zbuffer.h"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "host/raster/span_emission.h"

namespace fb89::host {

void ZBuffer::prepare(const ScreenScene& scene, const PixelRect& window) {
    if (m_width != scene.width || m_height != scene.height) {
        m_width = scene.width;
        m_height = scene.height;
        const size_t band = static_cast<size_t>(m_width) * kBandRows;
        m_depth.assign(band, 0.0);  // meaningful only where m_face is not 0
        m_face.assign(band, 0);
        m_kept.clear();
    }
    if (!m_keep) return;
    if (m_kept.size() != static_cast<size_t>(m_width) * m_height)
        m_kept.assign(static_cast<size_t>(m_width) * m_height, 0);
    for (int y = window.y0; y < window.y1; ++y) {
        uint32_t* row = m_kept.data() + static_cast<size_t>(y) * m_width;
        std::fill(row + window.x0, row + window.x1, 0u);
    }
}

namespace {

// One row of the depth test: the shared plane at each centre x + 0.5 (carried exactly in
// a double), an empty pixel always taking the face. The plane is evaluated with the same
// operations, in the same order, as depth_at(), so results are bit-identical to it.
// Branch-free: which face wins a pixel is unpredictable, and branches on it cost more
// than the arithmetic. Returns the pixels won.
uint64_t depth_test_row(const DepthPlane& plane, int y, int xb, int xe, uint32_t mark,
                        double* __restrict depth, uint32_t* __restrict face) {
    const double a = plane.a, by = plane.b * (y + 0.5), c = plane.c;
    uint64_t written = 0;
    int x = xb;
#if defined(__SSE2__)
    // two pixels at a time
    const __m128d va = _mm_set1_pd(a), vby = _mm_set1_pd(by), vc = _mm_set1_pd(c);
    const __m128d two = _mm_set1_pd(2.0);
    const __m128i vmark = _mm_set1_epi32(static_cast<int>(mark));
    __m128d xc = _mm_set_pd(xb + 1.5, xb + 0.5);
    for (; x + 2 <= xe; x += 2) {
        __m128d z = _mm_add_pd(_mm_add_pd(_mm_mul_pd(va, xc), vby), vc);
        __m128d d = _mm_loadu_pd(depth + x);
        __m128i f = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(face + x));
        __m128i empty = _mm_cmpeq_epi32(f, _mm_setzero_si128());
        __m128d wins =
            _mm_or_pd(_mm_cmplt_pd(z, d), _mm_castsi128_pd(_mm_unpacklo_epi32(empty, empty)));
        _mm_storeu_pd(depth + x, _mm_or_pd(_mm_and_pd(wins, z), _mm_andnot_pd(wins, d)));
        __m128i wins32 = _mm_shuffle_epi32(_mm_castpd_si128(wins), _MM_SHUFFLE(2, 0, 2, 0));
        __m128i merged = _mm_or_si128(_mm_and_si128(wins32, vmark), _mm_andnot_si128(wins32, f));
        _mm_storel_epi64(reinterpret_cast<__m128i*>(face + x), merged);
        const int won = _mm_movemask_pd(wins);  // one bit per pixel
        written += static_cast<uint64_t>((won & 1) + (won >> 1));
        xc = _mm_add_pd(xc, two);
    }
#endif
    for (double xcs = x + 0.5; x < xe; ++x, xcs += 1.0) {
        double z = a * xcs + by + c;
        bool wins = (face[x] == 0) | (z < depth[x]);
        depth[x] = wins ? z : depth[x];
        face[x] = wins ? mark : face[x];
        written += wins;
    }
    return written;
}

}  // namespace

void ZBuffer::draw_face(const ScreenScene& scene, uint32_t index, const PixelRect& band,
                        ZBufferCounts& counts) {
    const ScreenFace& f = scene.faces[index];
    const EdgeFunction* edges = scene.edges_of(f);
    const int y0 = std::max(band.y0, f.bounds.y0), y1 = std::min(band.y1, f.bounds.y1);
    const int x_lo = std::max(band.x0, f.bounds.x0), x_hi = std::min(band.x1, f.bounds.x1);
    uint64_t tests = 0, written = 0;
    for (int y = y0; y < y1; ++y) {
        // coverage: this row's run of centres
        int xb = 0, xe = 0;
        if (!row_span(edges, f.point_count, y, x_lo, x_hi, xb, xe)) continue;
        const size_t row = static_cast<size_t>(y - band.y0) * m_width;  // band-local
        tests += static_cast<uint64_t>(xe - xb);
        // depth test
        written += depth_test_row(f.depth, y, xb, xe, index + 1, m_depth.data() + row,
                                  m_face.data() + row);
    }
    counts.depth_tests += tests;
    counts.pixels_written += written;
}

uint64_t ZBuffer::emit(const ScreenScene& scene, const PixelRect& band,
                       protocol::CommandSink& sink) {
    uint64_t spans = 0;
    for (int y = band.y0; y < band.y1; ++y) {
        uint32_t* row = m_face.data() + static_cast<size_t>(y - band.y0) * m_width;
        spans += emit_row_spans(scene, row, y, band.x0, band.x1, sink);
        if (m_keep)
            std::copy(row + band.x0, row + band.x1,
                      m_kept.data() + static_cast<size_t>(y) * m_width + band.x0);
        std::fill(row + band.x0, row + band.x1, 0u);
    }
    return spans;
}

void ZBuffer::render_window(const ScreenScene& scene, std::span<const uint32_t> faces,
                            const PixelRect& window, protocol::CommandSink& sink,
                            ZBufferCounts& counts) {
    prepare(scene, window);
    // bin faces into bands of rows, ascending within each band
    const int bands = (window.height() + kBandRows - 1) / kBandRows;
    if (m_bins.size() < static_cast<size_t>(bands)) m_bins.resize(static_cast<size_t>(bands));
    for (int b = 0; b < bands; ++b)
        m_bins[static_cast<size_t>(b)].clear();
    for (uint32_t index : faces) {
        const PixelRect& r = scene.faces[index].bounds;
        const int first = std::max(r.y0, window.y0), last = std::min(r.y1, window.y1) - 1;
        if (first > last || r.x1 <= window.x0 || r.x0 >= window.x1) continue;
        for (int b = (first - window.y0) / kBandRows; b <= (last - window.y0) / kBandRows; ++b)
            m_bins[static_cast<size_t>(b)].push_back(index);
        ++counts.faces;
    }
    // each band: depth-test its faces in a band-sized buffer that stays in cache, then
    // send its spans
    for (int b = 0; b < bands; ++b) {
        PixelRect band = window;
        band.y0 = window.y0 + b * kBandRows;
        band.y1 = std::min(window.y1, band.y0 + kBandRows);
        for (uint32_t index : m_bins[static_cast<size_t>(b)])
            draw_face(scene, index, band, counts);
        counts.spans += emit(scene, band, sink);
    }
}

void ZBuffer::render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) {
    ZBufferCounts counts;
    m_all.resize(scene.faces.size());
    for (uint32_t i = 0; i < m_all.size(); ++i)
        m_all[i] = i;
    render_window(scene, m_all, scene.screen(), sink, counts);
    stats.counters.add("depth_tests", counts.depth_tests);
    stats.counters.add("pixels_written", counts.pixels_written);
    stats.counters.add("spans", counts.spans);
    stats.counters.add("faces_rasterised", counts.faces);
}

}  // namespace fb89::host
