#include "host/raster/scanline.h"

#include <algorithm>
#include <cmath>

#include "host/raster/coverage.h"
#include "host/raster/depth.h"

namespace fb89::host {

namespace {

// Depth differences must exceed this fraction of the two planes' magnitudes
// (|a x| + |b y| + |c| at the segment's far end) before two centres may speak for those
// between them. depth_at() rounds three times, so each value is within 4e-16 of that
// magnitude of the exact plane; a difference checked at two centres and relied on at a
// third meets four such errors, and the margin is several hundred times their sum.
constexpr double kMargin = 1e-12;

uint32_t packed(protocol::Rgb c) {
    return (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b;
}

bool same_plane(const DepthPlane& p, const DepthPlane& q) {
    return p.a == q.a && p.b == q.b && p.c == q.c;
}

// Sorts a list that was sorted by last row's keys: each face moves only past the faces it
// overtook, so a coherent row costs one pass.
template <class Key>
void insertion_sort(std::vector<uint32_t>& list, Key key) {
    for (size_t i = 1; i < list.size(); ++i) {
        const uint32_t f = list[i];
        const int k = key(f);
        size_t j = i;
        for (; j > 0 && key(list[j - 1]) > k; --j)
            list[j] = list[j - 1];
        list[j] = f;
    }
}

}  // namespace

// Merges the row's resolved pieces into runs of equal colour and sends each as DRAW_SPAN;
// a gap (background) ends a run.
class ScanLine::SpanWriter {
  public:
    SpanWriter(protocol::CommandSink& sink, uint64_t& spans) : m_sink(sink), m_spans(spans) {}
    void start_row(int y) {
        m_y = y;
        m_open = false;
    }
    void add(int x_begin, int x_end, protocol::Rgb color) {
        const uint32_t key = packed(color);
        if (m_open && m_end == x_begin && m_key == key) {
            m_end = x_end;
            return;
        }
        finish_row();
        m_open = true;
        m_begin = x_begin;
        m_end = x_end;
        m_key = key;
        m_color = color;
    }
    void finish_row() {
        if (!m_open) return;
        m_sink.draw_span({m_y, m_begin, m_end - 1, m_color});
        ++m_spans;
        m_open = false;
    }

  private:
    protocol::CommandSink& m_sink;
    uint64_t& m_spans;
    int m_y = 0, m_begin = 0, m_end = 0;
    uint32_t m_key = 0;
    protocol::Rgb m_color;
    bool m_open = false;
};

void ScanLine::setup(const ScreenScene& scene) {
    m_row_of.reserve(scene.faces.size());
    m_by_begin.reserve(scene.faces.size());
    m_by_end.reserve(scene.faces.size());
    m_merged.reserve(scene.faces.size());
}

void ScanLine::build_edge_table(const ScreenScene& scene) {
    // bucket faces by first row: a counting sort, filled backwards so each bucket keeps
    // id order; m_row_start[y] ends as the start of bucket y
    const size_t rows = static_cast<size_t>(std::max(scene.height, 0));
    m_row_start.assign(rows + 1, 0);
    for (const ScreenFace& f : scene.faces)
        if (!f.bounds.empty()) ++m_row_start[static_cast<size_t>(f.bounds.y0)];
    for (size_t y = 1; y <= rows; ++y)
        m_row_start[y] += m_row_start[y - 1];
    m_table.resize(m_row_start[rows]);
    for (size_t i = scene.faces.size(); i-- > 0;) {
        const PixelRect& b = scene.faces[i].bounds;
        if (!b.empty())
            m_table[--m_row_start[static_cast<size_t>(b.y0)]] = static_cast<uint32_t>(i);
    }
}

void ScanLine::update_active_list(const ScreenScene& scene, int y) {
    // enter: faces whose first row is y
    const auto row = static_cast<size_t>(y);
    m_entering.assign(m_table.begin() + m_row_start[row], m_table.begin() + m_row_start[row + 1]);
    for (uint32_t f : m_entering)
        m_row_of[f] = {scene.faces[f].bounds.x0, scene.faces[f].bounds.x1, -1};
    // coverage: each active face's run of centres in this row, from the shared rule
    uint64_t runs = 0;
    auto cover = [&](uint32_t f) {
        const ScreenFace& face = scene.faces[f];
        FaceRow& r = m_row_of[f];
        int xb = 0, xe = 0;
        if (!row_span(scene.edges_of(face), face.point_count, y, face.bounds.x0, face.bounds.x1, xb,
                      xe))
            return;
        r = {xb, xe, y};
        ++runs;
    };
    for (uint32_t f : m_by_begin)
        cover(f);
    for (uint32_t f : m_entering)
        cover(f);
    m_counts.face_runs += runs;
    // x order: old faces moved little since the last row; new ones are sorted and merged in
    auto begin_of = [this](uint32_t f) { return m_row_of[f].x_begin; };
    auto end_of = [this](uint32_t f) { return m_row_of[f].x_end; };
    insertion_sort(m_by_begin, begin_of);
    insertion_sort(m_by_end, end_of);
    if (m_entering.empty()) return;
    auto merge_in = [this](std::vector<uint32_t>& list, auto key) {
        auto less = [&](uint32_t f, uint32_t g) { return key(f) < key(g); };
        std::sort(m_entering.begin(), m_entering.end(), less);
        m_merged.resize(list.size() + m_entering.size());
        std::merge(list.begin(), list.end(), m_entering.begin(), m_entering.end(), m_merged.begin(),
                   less);
        list.swap(m_merged);
    };
    merge_in(m_by_begin, begin_of);
    merge_in(m_by_end, end_of);
}

void ScanLine::resolve_row(const ScreenScene& scene, int y, SpanWriter& out) {
    out.start_row(y);
    m_covering.clear();
    const size_t n = m_by_begin.size();
    auto skip_uncovered = [&](const std::vector<uint32_t>& list, size_t& i) {
        while (i < n && m_row_of[list[i]].row != y)
            ++i;
    };
    auto begin_at = [&](size_t i) { return m_row_of[m_by_begin[i]].x_begin; };
    auto end_at = [&](size_t i) { return m_row_of[m_by_end[i]].x_end; };
    size_t ib = 0, ie = 0;  // next run start, next run end
    skip_uncovered(m_by_begin, ib);
    skip_uncovered(m_by_end, ie);
    while (ie < n) {
        // the next crossing: where a run starts or ends
        const int x = ib < n ? std::min(begin_at(ib), end_at(ie)) : end_at(ie);
        // apply every crossing at x: runs ending there leave, runs starting there enter
        for (; ie < n && end_at(ie) == x; ++ie, skip_uncovered(m_by_end, ie)) {
            auto it = std::find(m_covering.begin(), m_covering.end(), m_by_end[ie]);
            *it = m_covering.back();
            m_covering.pop_back();
        }
        for (; ib < n && begin_at(ib) == x; ++ib, skip_uncovered(m_by_begin, ib))
            m_covering.push_back(m_by_begin[ib]);
        // the segment up to the next crossing has a constant set of covering faces
        if (m_covering.empty()) continue;
        const int next = ib < n ? std::min(begin_at(ib), end_at(ie)) : end_at(ie);
        resolve_segment(scene, y, x, next, out);
    }
    out.finish_row();
}

void ScanLine::resolve_segment(const ScreenScene& scene, int y, int x0, int x1, SpanWriter& out) {
    ++m_counts.segments;
    // one covering face: no depth needed
    if (m_covering.size() == 1) {
        ++m_counts.segments_one_face;
        out.add(x0, x1, scene.faces[m_covering[0]].color);
        return;
    }
    // every covering face's depth at the segment's last centre, and its scale for the margin
    const size_t k = m_covering.size();
    m_z_cur.resize(k);
    m_z_last.resize(k);
    m_scale.resize(k);
    for (size_t c = 0; c < k; ++c) {
        const DepthPlane& p = scene.faces[m_covering[c]].depth;
        m_z_last[c] = depth_at(p, x1 - 1, y);
        m_scale[c] = std::abs(p.a) * (x1 - 0.5) + std::abs(p.b) * (y + 0.5) + std::abs(p.c);
    }
    m_counts.depth_evaluations += k;
    // pieces: the nearest face keeps what it provably keeps, then resolution resumes
    int pieces = 0;
    for (int cur = x0; cur < x1; ++pieces) {
        uint32_t winner = 0;
        const int end = resolve_run(scene, y, cur, x1, winner);
        out.add(cur, end, scene.faces[winner].color);
        cur = end;
    }
    if (pieces > 1) ++m_counts.segments_split;
}

// From centre `cur` of the current segment (which ends before x1): picks the face nearest
// at cur and returns the end of the run of centres it wins for certain (at least cur + 1).
int ScanLine::resolve_run(const ScreenScene& scene, int y, int cur, int x1, uint32_t& winner) {
    const size_t k = m_covering.size();
    // nearest at cur: the shared rule, so this centre is decided exactly
    size_t best = 0;
    for (size_t c = 0; c < k; ++c) {
        m_z_cur[c] = depth_at(scene.faces[m_covering[c]].depth, cur, y);
        if (c > 0 && nearer(m_z_cur[c], scene.faces[m_covering[c]].id, m_z_cur[best],
                            scene.faces[m_covering[best]].id))
            best = c;
    }
    uint64_t evaluations = k;
    winner = m_covering[best];
    const DepthPlane& b = scene.faces[winner].depth;
    int last = x1 - 1;  // the last centre the winner keeps for certain
    for (size_t c = 0; c < k && last > cur; ++c) {
        const DepthPlane& o = scene.faces[m_covering[c]].depth;
        if (c == best || same_plane(o, b)) continue;  // equal depth everywhere: id decided
        const double margin = kMargin * (m_scale[best] + m_scale[c]);
        const double d_cur = m_z_cur[c] - m_z_cur[best];
        // near tie at cur: only this centre is certain
        if (!(d_cur > margin)) {
            last = cur;
            break;
        }
        // behind by the margin at both ends: behind everywhere between
        const double d_last = m_z_last[c] - m_z_last[best];
        if (d_last > margin) continue;
        // planes cross: the last centre still behind by the margin, checked, not trusted
        double t = (d_cur - margin) / (d_cur - d_last) * (x1 - 1 - cur);
        if (!(t >= 0)) t = 0;
        int cand = std::min(last, cur + static_cast<int>(std::floor(t)));
        for (; cand > cur; --cand) {
            evaluations += 2;
            if (depth_at(o, cand, y) - depth_at(b, cand, y) > margin) break;
        }
        last = cand;
    }
    m_counts.depth_evaluations += evaluations;
    if (last == cur && x1 - 1 > cur) ++m_counts.pixels_resolved;
    return last + 1;
}

void ScanLine::render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) {
    m_counts = {};
    build_edge_table(scene);
    m_row_of.assign(scene.faces.size(), {});
    m_by_begin.clear();
    m_by_end.clear();
    SpanWriter out(sink, m_counts.spans);
    auto last_row_done = [&](int y) {
        return [&scene, y](uint32_t f) { return scene.faces[f].bounds.y1 <= y + 1; };
    };
    for (int y = 0; y < scene.height; ++y) {
        // enter, coverage and x order
        update_active_list(scene, y);
        if (m_by_begin.empty()) continue;
        m_counts.active_face_rows += m_by_begin.size();
        // visibility of the row, segment by segment
        resolve_row(scene, y, out);
        // leave: faces whose last row this was
        std::erase_if(m_by_begin, last_row_done(y));
        std::erase_if(m_by_end, last_row_done(y));
    }
    stats.counters.add("scanline_active_face_rows", m_counts.active_face_rows);
    stats.counters.add("scanline_face_runs", m_counts.face_runs);
    stats.counters.add("scanline_segments", m_counts.segments);
    stats.counters.add("scanline_segments_one_face", m_counts.segments_one_face);
    stats.counters.add("scanline_segments_split", m_counts.segments_split);
    stats.counters.add("scanline_pixels_resolved", m_counts.pixels_resolved);
    stats.counters.add("scanline_depth_evaluations", m_counts.depth_evaluations);
    stats.counters.add("spans", m_counts.spans);
}

}  // namespace fb89::host
