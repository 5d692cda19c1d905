#include "host/raster/zbuffer.h"

#include <algorithm>

#include "host/raster/band_spans.h"
#include "host/raster/coverage.h"
#include "host/raster/depth_rows.h"

namespace fb89::host {

void ZBuffer::prepare(const ScreenScene& scene, const PixelRect& window) {
    if (m_width != scene.width || m_height != scene.height) {
        m_width = scene.width;
        m_height = scene.height;
        const size_t band = static_cast<size_t>(m_width) * kBandRows;
        m_depth.assign(band + kDepthRowPad, 0.0);  // meaningful only where m_face is not 0
        m_face.assign(band + kDepthRowPad, 0);
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

// Fetches ahead of the face drawn: the record of the face `2 * ahead` on, and the edges
// of the one `ahead` on, whose record has arrived by then. Faces of one band lie far apart
// in the scene, so without this every face waits for memory. Always inlined: GCC 12 finds
// a separate helper free of side effects and drops the call, prefetches and all.
[[gnu::always_inline]] inline void fetch_ahead(const ScreenScene& scene,
                                               std::span<const uint32_t> bin, size_t i) {
    constexpr size_t ahead = 8;
    if (i + 2 * ahead < bin.size()) {
        const char* f = reinterpret_cast<const char*>(&scene.faces[bin[i + 2 * ahead]]);
        __builtin_prefetch(f);
        __builtin_prefetch(f + sizeof(ScreenFace) - 1);
    }
    if (i + ahead < bin.size()) {
        const ScreenFace& f = scene.faces[bin[i + ahead]];
        const char* e = reinterpret_cast<const char*>(scene.edges_of(f));
        for (size_t at = 0; at < f.point_count * sizeof(EdgeFunction) && at < 256; at += 64)
            __builtin_prefetch(e + at);
    }
}

// Draws the faces of one band (`band`, whose row band.y0 is row 0 of the band buffers
// `depth` and `face`, `width` entries a row): each row's run of covered centres, then its
// depth test. The wrappers below compile it once per depth kernel; flatten inlines the
// kernel, which an AVX2 kernel needs, since only a function compiled for AVX2 may inline it.
template <class DepthRow>
void draw_bin(const ScreenScene& scene, std::span<const uint32_t> bin, const PixelRect& band,
              double* depth, uint32_t* face, int width, ZBufferCounts& counts) {
    uint64_t tests = 0, written = 0;
    for (size_t i = 0; i < bin.size(); ++i) {
        fetch_ahead(scene, bin, i);
        const uint32_t index = bin[i];
        const ScreenFace& f = scene.faces[index];
        const EdgeFunction* edges = scene.edges_of(f);
        const int y0 = std::max(band.y0, f.bounds.y0), y1 = std::min(band.y1, f.bounds.y1);
        const int x_lo = std::max(band.x0, f.bounds.x0), x_hi = std::min(band.x1, f.bounds.x1);
        for (int y = y0; y < y1; ++y) {
            // coverage: this row's run of centres
            int xb = 0, xe = 0;
            if (!row_span(edges, f.point_count, y, x_lo, x_hi, xb, xe)) continue;
            const size_t row = static_cast<size_t>(y - band.y0) * static_cast<size_t>(width);
            tests += static_cast<uint64_t>(xe - xb);
            // depth test
            written += DepthRow::test(f.depth, y, xb, xe, index + 1, depth + row, face + row);
        }
    }
    counts.depth_tests += tests;
    counts.pixels_written += written;
}

#if defined(__SSE2__)
using DepthRowBaseline = DepthRowSse2;
#else
using DepthRowBaseline = DepthRowScalar;
#endif

[[gnu::flatten]] void draw_bin_baseline(const ScreenScene& scene, std::span<const uint32_t> bin,
                                        const PixelRect& band, double* depth, uint32_t* face,
                                        int width, ZBufferCounts& counts) {
    draw_bin<DepthRowBaseline>(scene, bin, band, depth, face, width, counts);
}

#if defined(FB89_HAS_AVX2_KERNEL)
[[gnu::target("avx2"), gnu::flatten]] void draw_bin_avx2(const ScreenScene& scene,
                                                         std::span<const uint32_t> bin,
                                                         const PixelRect& band, double* depth,
                                                         uint32_t* face, int width,
                                                         ZBufferCounts& counts) {
    draw_bin<DepthRowAvx2>(scene, bin, band, depth, face, width, counts);
}
#endif

}  // namespace

uint64_t ZBuffer::emit(const PixelRect& band, protocol::CommandSink& sink) {
    uint64_t spans = 0;
    for (int y = band.y0; y < band.y1; ++y) {
        uint32_t* row = m_face.data() + static_cast<size_t>(y - band.y0) * m_width;
        if (m_keep)
            std::copy(row + band.x0, row + band.x1,
                      m_kept.data() + static_cast<size_t>(y) * m_width + band.x0);
        spans += emit_band_row(row, y, band.x0, band.x1, m_color.data(), sink);
    }
    return spans;
}

// Puts each face that meets the window into the bin of every band it meets (ascending, as
// `faces` is) and its colour into the table emission reads. Returns the number of bands.
int ZBuffer::bin_faces(const ScreenScene& scene, std::span<const uint32_t> faces,
                       const PixelRect& window, ZBufferCounts& counts) {
    if (m_color.size() < scene.faces.size()) m_color.resize(scene.faces.size());
    const int bands = (window.height() + kBandRows - 1) / kBandRows;
    if (m_bins.size() < static_cast<size_t>(bands)) m_bins.resize(static_cast<size_t>(bands));
    for (int b = 0; b < bands; ++b)
        m_bins[static_cast<size_t>(b)].clear();
    uint64_t met = 0;
    for (uint32_t index : faces) {
        const ScreenFace& f = scene.faces[index];
        const PixelRect& r = f.bounds;
        const int first = std::max(r.y0, window.y0), last = std::min(r.y1, window.y1) - 1;
        if (first > last || r.x1 <= window.x0 || r.x0 >= window.x1) continue;
        for (int b = (first - window.y0) / kBandRows; b <= (last - window.y0) / kBandRows; ++b)
            m_bins[static_cast<size_t>(b)].push_back(index);
        m_color[index] = packed_color(f.color);
        ++met;
    }
    counts.faces += met;
    return bands;
}

void ZBuffer::draw_band(const ScreenScene& scene, int band_index, const PixelRect& band,
                        ZBufferCounts& counts) {
    const std::vector<uint32_t>& bin = m_bins[static_cast<size_t>(band_index)];
#if defined(FB89_HAS_AVX2_KERNEL)
    if (m_allow_avx2 && has_avx2()) {
        draw_bin_avx2(scene, bin, band, m_depth.data(), m_face.data(), m_width, counts);
        return;
    }
#endif
    draw_bin_baseline(scene, bin, band, m_depth.data(), m_face.data(), m_width, counts);
}

void ZBuffer::render_window(const ScreenScene& scene, std::span<const uint32_t> faces,
                            const PixelRect& window, protocol::CommandSink& sink,
                            ZBufferCounts& counts) {
    prepare(scene, window);
    const int bands = bin_faces(scene, faces, window, counts);
    // each band: depth-test its faces in a band-sized buffer that stays in cache, then
    // send its spans
    for (int b = 0; b < bands; ++b) {
        PixelRect band = window;
        band.y0 = window.y0 + b * kBandRows;
        band.y1 = std::min(window.y1, band.y0 + kBandRows);
        draw_band(scene, b, band, counts);
        counts.spans += emit(band, sink);
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
