// Z-buffer hidden-surface removal (Catmull 1974), the point-sampling half of the paper's
// §3 hybrid.
//
// Ours differs from a textbook Z-buffer in two ways that keep every method's face-id
// buffer identical: coverage comes from the shared edge-function rule one row at a time
// (coverage.h), and depth is the shared plane evaluated directly at each pixel centre in
// double precision with exact ties to the lower id (depth.h). Faces are drawn into a
// buffer of face indices; the result leaves as DRAW_SPAN runs of equal colour per row.
// It can render any subset of faces restricted to any window, which is how the
// Warnock/Z-buffer hybrid hands it windows.
//
// Faces are drawn in ascending id order, so the shared rule's tie case (equal depth, lower
// id wins) is met by keeping the first face at equal depth: the inner loop needs only a
// strict less-than. The window is worked in bands of rows, as a sort-middle tiler would
// (Molnar et al. 1994): faces are binned to the bands they meet, and each band is
// depth-tested in one band-sized pair of buffers (a few hundred KB, reused band after
// band, so they stay in cache instead of being fetched from memory every frame), then its
// spans leave and the band is zeroed (band_spans.h). The face buffer doubles as the depth
// buffer's "empty" mark, so the depth buffer is never cleared.
//
// Where the time goes, and what keeps it short: a band's faces lie far apart in the scene,
// so their records and edges are fetched several faces ahead of the one drawn; coverage is
// row_span() per row (an exact division per edge, cheap next to the pixels); the depth
// test is branch-free and four pixels wide where the CPU has AVX2, two with SSE2
// (depth_rows.h); span emission finds where the face changes eight entries at a
// time and takes colours from a per-face table built while binning.
#pragma once

#include <span>
#include <vector>

#include "host/raster/renderer.h"

namespace fb89::host {

struct ZBufferCounts {
    uint64_t depth_tests = 0;     // pixel centres a face covered and tested
    uint64_t pixels_written = 0;  // tests that won
    uint64_t spans = 0;           // DRAW_SPAN commands sent
    uint64_t faces = 0;           // faces (pieces) that met the window
};

class ZBuffer final : public Renderer {
  public:
    std::string_view name() const override { return "zbuffer"; }
    void setup(const ScreenScene& scene) override { prepare(scene, scene.screen()); }
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;

    // Renders scene.faces[i] for each i in `faces` (ascending), only inside `window`, and
    // sends that window's spans. Buffers outside the window are left alone.
    void render_window(const ScreenScene& scene, std::span<const uint32_t> faces,
                       const PixelRect& window, protocol::CommandSink& sink, ZBufferCounts& counts);

    // Keeps the resolved face buffer of each render (scene.faces index + 1 per pixel,
    // 0 = none) for inspection, at the cost of a clear per frame.
    void keep_face_buffer(bool keep) { m_keep = keep; }
    const std::vector<uint32_t>& face_buffer() const { return m_kept; }

    // For tests and benchmarks: whether the AVX2 depth test may be used where the CPU has
    // it (the default). The baseline kernel (SSE2, or scalar) gives identical results.
    void allow_avx2(bool allow) { m_allow_avx2 = allow; }

  private:
    void prepare(const ScreenScene& scene, const PixelRect& window);
    int bin_faces(const ScreenScene& scene, std::span<const uint32_t> faces,
                  const PixelRect& window, ZBufferCounts& counts);
    void draw_band(const ScreenScene& scene, int band_index, const PixelRect& band,
                   ZBufferCounts& counts);
    uint64_t emit(const PixelRect& band, protocol::CommandSink& sink);

    int m_width = 0, m_height = 0;
    // Buffers for one band of kBandRows rows, reused band after band: a few hundred KB
    // that stay in cache, where whole-screen buffers would be fetched from memory again
    // every frame. Padded past the last row for the vector kernels.
    static constexpr int kBandRows = 32;
    std::vector<double> m_depth;
    std::vector<uint32_t> m_face;               // all zero between bands
    std::vector<std::vector<uint32_t>> m_bins;  // faces meeting each band, ascending
    std::vector<uint32_t> m_kept;               // whole-screen face buffer, with m_keep
    bool m_keep = false;
    std::vector<uint32_t> m_all;
    std::vector<uint32_t> m_color;  // packed colour of each binned face, for emission
    bool m_allow_avx2 = true;
};

}  // namespace fb89::host
