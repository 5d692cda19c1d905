// Scan-line hidden-surface removal in the manner of Watkins (1970) and Romney (1969): the
// "Romney scan-line algorithm" the paper's §2 (Fig. 2.1) times against Warnock.
//
// As in Watkins: an edge table buckets faces by their first row; an active list gains the
// faces that start in a row and loses them after their last; each row is cut at the
// active faces' edge crossings into segments, and visibility is decided once per segment,
// not per pixel.
//
// Ours differs in three ways that keep the face-id buffer identical to the Z-buffer's:
// - the crossings are not found by stepping edges with increments: each active face's
//   covered run of the row comes from the shared `row_span()` (coverage.h), so the
//   crossings are exactly the run ends [x_begin, x_end) under the top-left rule;
// - depth is compared with the shared `depth_at()`/`nearer()` (depth.h) at pixel centres.
//   The face nearest at a segment's first centre keeps the segment while every other
//   covering face stays behind it by a margin at both ends (planes are linear in x, so
//   the ends bound the interior and the margin absorbs rounding at interior centres);
// - where planes cross inside a segment (interpenetration), the segment is split at the
//   last centre the nearest face provably keeps, and resolution resumes there; where two
//   planes are within the margin (coplanar or touching), that one centre is decided
//   alone. Faces with bit-identical planes are ordered by id once for the whole segment.
// Runs of equal colour leave as DRAW_SPAN commands per row, exactly as the Z-buffer's do.
#pragma once

#include <cstdint>
#include <vector>

#include "host/raster/renderer.h"

namespace fb89::host {

struct ScanLineCounts {
    uint64_t active_face_rows = 0;   // faces on the active list, summed over rows
    uint64_t face_runs = 0;          // active faces whose row_span was not empty
    uint64_t segments = 0;           // spans between consecutive crossings with a face
    uint64_t segments_one_face = 0;  // of those, covered by one face: no depth needed
    uint64_t segments_split = 0;     // of those, split because planes cross or near-tie
    uint64_t pixels_resolved = 0;    // centres decided alone inside longer segments
    uint64_t depth_evaluations = 0;  // depth_at() calls
    uint64_t spans = 0;              // DRAW_SPAN commands sent
};

class ScanLine final : public Renderer {
  public:
    std::string_view name() const override { return "scanline"; }
    void setup(const ScreenScene& scene) override;
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;

    // The counts of the last render, also published into HostStats::counters.
    const ScanLineCounts& counts() const { return m_counts; }

  private:
    struct FaceRow {  // a face's covered centres [x_begin, x_end) in row `row`
        int x_begin = 0, x_end = 0;
        int row = -1;  // the run is this row's only when row == y; else x_* are stale keys
    };
    class SpanWriter;

    void build_edge_table(const ScreenScene& scene);
    void update_active_list(const ScreenScene& scene, int y);
    void resolve_row(const ScreenScene& scene, int y, SpanWriter& out);
    void resolve_segment(const ScreenScene& scene, int y, int x0, int x1, SpanWriter& out);
    int resolve_run(const ScreenScene& scene, int y, int cur, int x1, uint32_t& winner);

    std::vector<uint32_t> m_row_start;  // edge table: faces entering row y are
    std::vector<uint32_t> m_table;      // m_table[m_row_start[y] .. m_row_start[y + 1])
    std::vector<FaceRow> m_row_of;      // per face of the scene
    // the active list twice, as face indices: in order of x_begin and of x_end, kept sorted
    // from row to row by insertion, as Watkins kept his active edges in x order
    std::vector<uint32_t> m_by_begin, m_by_end;
    std::vector<uint32_t> m_entering, m_merged;  // faces entering this row; merge scratch
    std::vector<uint32_t> m_covering;            // faces covering the current segment
    std::vector<double> m_z_cur;                 // per covering face: depth at the current centre
    std::vector<double> m_z_last;  // per covering face: depth at the segment's last centre
    std::vector<double> m_scale;   // per covering face: |a x| + |b y| + |c| bound (margin)
    ScanLineCounts m_counts;
};

}  // namespace fb89::host
