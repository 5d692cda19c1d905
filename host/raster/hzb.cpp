#include "host/raster/hzb.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include "host/raster/band_spans.h"
#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "host/raster/depth_rows.h"

namespace fb89::host {

namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

// A face's depth range over the centres of its pixel rectangle: the plane is linear, so its
// least and greatest values there are at the rectangle's corners; widened by a margin far
// above depth_at()'s rounding (a few units in the last place of its largest term), so that
// no centre's depth as depth_at() computes it lies outside.
void depth_range(const DepthPlane& p, const PixelRect& r, double& lo, double& hi) {
    lo = kFar;
    hi = -kFar;
    for (int x : {r.x0, r.x1 - 1})
        for (int y : {r.y0, r.y1 - 1}) {
            const double z = depth_at(p, x, y);
            lo = std::min(lo, z);
            hi = std::max(hi, z);
        }
    const double scale = std::abs(p.a) * (std::abs(r.x0) + std::abs(r.x1) + 1.0) +
                         std::abs(p.b) * (std::abs(r.y0) + std::abs(r.y1) + 1.0) + std::abs(p.c);
    const double margin = scale * 1e-12;
    lo -= margin;
    hi += margin;
}

PixelRect unite(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

}  // namespace

// --- the octree ---------------------------------------------------------------------------

void HierarchicalZBuffer::setup(const ScreenScene& scene) {
    m_scene = &scene;
    const std::size_t n = scene.faces.size();
    m_face_box.assign(n, Box{});
    std::vector<uint32_t> faces;
    faces.reserve(n);
    Box cube{{0, 0, scene.width, scene.height}, kFar, -kFar};
    for (uint32_t i = 0; i < n; ++i) {
        const ScreenFace& f = scene.faces[i];
        Box& b = m_face_box[i];
        b.rect = f.bounds;
        if (b.rect.empty()) continue;  // covers no centre on the screen: never drawn
        depth_range(f.depth, b.rect, b.z0, b.z1);
        cube.z0 = std::min(cube.z0, b.z0);
        cube.z1 = std::max(cube.z1, b.z1);
        faces.push_back(i);
    }
    m_nodes.clear();
    m_order.clear();
    m_order.reserve(faces.size());
    if (!faces.empty()) {
        m_nodes.emplace_back();
        build(0, faces, cube, 0);
    }

    m_width = scene.width;
    m_height = scene.height;
    // each band's cover: the pixels of its faces' rectangles in it over its own, the most
    // depth complexity it can have; and how many faces meet it, for its bin below
    const std::size_t bands = static_cast<std::size_t>((m_height + kBandRows - 1) / kBandRows);
    m_band_cover.assign(bands, 0.0);
    m_band_first.assign(bands + 1, 0);
    for (uint32_t f : m_order) {
        const PixelRect& r = m_face_box[f].rect;
        for (int y0 = r.y0 / kBandRows * kBandRows; y0 < r.y1; y0 += kBandRows) {
            const auto b = static_cast<std::size_t>(y0 / kBandRows);
            const int rows = std::min(r.y1, y0 + kBandRows) - std::max(r.y0, y0);
            m_band_cover[b] += static_cast<double>(rows) * (r.x1 - r.x0);
            ++m_band_first[b + 1];
        }
    }
    for (std::size_t b = 0; b < bands; ++b) {
        const int rows = std::min(kBandRows, m_height - static_cast<int>(b) * kBandRows);
        m_band_cover[b] /= static_cast<double>(rows) * std::max(1, m_width);
    }
    // and its faces, in id order as the Z-buffer takes them, for a band worked without the
    // pyramid
    for (std::size_t b = 1; b < m_band_first.size(); ++b)
        m_band_first[b] += m_band_first[b - 1];
    m_band_faces.assign(m_band_first.back(), 0);
    std::vector<uint32_t> at(m_band_first.begin(), m_band_first.end() - 1);
    std::vector<uint32_t> by_id(m_order);
    std::sort(by_id.begin(), by_id.end());
    for (uint32_t f : by_id) {
        const PixelRect& r = m_face_box[f].rect;
        for (int b = r.y0 / kBandRows; b * kBandRows < r.y1; ++b)
            m_band_faces[at[static_cast<std::size_t>(b)]++] = f;
    }
    const std::size_t pixels = static_cast<std::size_t>(m_width) * kBandRows;
    m_depth.assign(pixels + kDepthRowPad, 0.0);  // the kernels' padding past the last row
    m_face.assign(pixels + kDepthRowPad, 0);
    m_levels.clear();
    int w = (m_width + (1 << kTileShift) - 1) >> kTileShift;
    int h = kBandRows >> kTileShift;
    for (;;) {
        const std::size_t cells = static_cast<std::size_t>(w) * h;
        m_levels.push_back(Level{w, h, std::vector<double>(cells), std::vector<uint8_t>(cells)});
        if (w == 1 && h == 1) break;
        w = (w + 1) / 2;
        h = (h + 1) / 2;
    }
    m_dirty_list.clear();
}

// Makes m_nodes[index] the node of `faces` (each wholly inside `cube`) and, for those that
// fit wholly in one of its eight octants, its children.
void HierarchicalZBuffer::build(uint32_t index, std::vector<uint32_t>& faces, const Box& cube,
                                int depth) {
    std::vector<uint32_t> own;
    std::array<std::vector<uint32_t>, 8> octant;
    const bool split = faces.size() > kLeafFaces && depth < kMaxDepth;
    const int mx = (cube.rect.x0 + cube.rect.x1) / 2, my = (cube.rect.y0 + cube.rect.y1) / 2;
    const double mz = 0.5 * (cube.z0 + cube.z1);
    for (uint32_t f : faces) {
        const Box& b = m_face_box[f];
        int o = 0;
        bool fits = split;
        if (fits) {
            if (b.rect.x1 <= mx)
                o |= 0;
            else if (b.rect.x0 >= mx)
                o |= 1;
            else
                fits = false;
            if (b.rect.y1 <= my)
                o |= 0;
            else if (b.rect.y0 >= my)
                o |= 2;
            else
                fits = false;
            if (b.z1 <= mz)
                o |= 0;
            else if (b.z0 >= mz)
                o |= 4;
            else
                fits = false;
        }
        (fits ? octant[static_cast<std::size_t>(o)] : own).push_back(f);
    }
    faces.clear();
    faces.shrink_to_fit();

    // its own faces, nearest first
    std::sort(own.begin(), own.end(), [&](uint32_t a, uint32_t b) {
        return m_face_box[a].z0 < m_face_box[b].z0 ||
               (m_face_box[a].z0 == m_face_box[b].z0 && a < b);
    });
    Box box{{}, kFar, -kFar};
    for (uint32_t f : own) {
        box.rect = unite(box.rect, m_face_box[f].rect);
        box.z0 = std::min(box.z0, m_face_box[f].z0);
        box.z1 = std::max(box.z1, m_face_box[f].z1);
    }
    m_nodes[index].first_face = static_cast<uint32_t>(m_order.size());
    m_nodes[index].face_count = static_cast<uint32_t>(own.size());
    m_order.insert(m_order.end(), own.begin(), own.end());

    // its children, side by side: each built in its slot, then the block ordered nearest first
    // (stable: octant order among equals; a slot's own children lie in their own blocks)
    uint32_t count = 0;
    for (const std::vector<uint32_t>& in : octant)
        count += in.empty() ? 0 : 1;
    const uint32_t first = static_cast<uint32_t>(m_nodes.size());
    m_nodes.resize(m_nodes.size() + count);
    uint32_t slot = first;
    for (int o = 0; o < 8; ++o) {
        std::vector<uint32_t>& in = octant[static_cast<std::size_t>(o)];
        if (in.empty()) continue;
        Box c = cube;
        (o & 1 ? c.rect.x0 : c.rect.x1) = mx;
        (o & 2 ? c.rect.y0 : c.rect.y1) = my;
        (o & 4 ? c.z0 : c.z1) = mz;
        build(slot++, in, c, depth + 1);
    }
    const auto block = m_nodes.begin() + first;
    std::stable_sort(block, block + count,
                     [](const Node& a, const Node& b) { return a.box.z0 < b.box.z0; });
    for (uint32_t k = first; k < first + count; ++k) {
        box.rect = unite(box.rect, m_nodes[k].box.rect);
        box.z0 = std::min(box.z0, m_nodes[k].box.z0);
        box.z1 = std::max(box.z1, m_nodes[k].box.z1);
    }
    m_nodes[index].first_child = first;
    m_nodes[index].child_count = count;
    m_nodes[index].box = box;
}

// --- the pyramid --------------------------------------------------------------------------

void HierarchicalZBuffer::reset_pyramid() {
    for (Level& l : m_levels) {
        std::fill(l.far.begin(), l.far.end(), kFar);
        std::fill(l.dirty.begin(), l.dirty.end(), uint8_t{0});
    }
}

// Whether every centre of `r` (not empty, on the screen) lies behind a drawn depth nearer
// than z: the cells of the coarsest level at which r spans at most two in each direction,
// each hidden or its children over r all hidden, down to the tiles.
bool HierarchicalZBuffer::hidden(const PixelRect& r, double z) {
    if (r.empty()) return true;
    int level = 0;
    while (level + 1 < static_cast<int>(m_levels.size())) {
        const int s = kTileShift + level;
        if (((r.x1 - 1) >> s) - (r.x0 >> s) <= 1 && ((r.y1 - 1) >> s) - (r.y0 >> s) <= 1) break;
        ++level;
    }
    const int s = kTileShift + level;
    for (int cy = r.y0 >> s; cy <= (r.y1 - 1) >> s; ++cy)
        for (int cx = r.x0 >> s; cx <= (r.x1 - 1) >> s; ++cx)
            if (!cell_hidden(level, cx, cy, r, z)) return false;
    return true;
}

bool HierarchicalZBuffer::cell_hidden(int level, int cx, int cy, const PixelRect& r, double z) {
    const Level& l = m_levels[static_cast<std::size_t>(level)];
    const std::size_t at = static_cast<std::size_t>(cy) * l.w + cx;
    ++m_counts.pyramid_tests;
    // a cell's depths only come nearer, so a value not yet brought up to date is at least as
    // far as the true one: if it hides z, the true one does, and the cell need not be taken
    if (l.far[at] < z) return true;
    if (l.dirty[at]) {
        refresh(level, cx, cy);
        if (l.far[at] < z) return true;
    }
    if (level == 0) return false;
    const int s = kTileShift + level - 1;  // the children's cell side
    const Level& below = m_levels[static_cast<std::size_t>(level) - 1];
    for (int y = 2 * cy; y <= std::min(2 * cy + 1, below.h - 1); ++y) {
        if ((y << s) >= r.y1 || ((y + 1) << s) <= r.y0) continue;
        for (int x = 2 * cx; x <= std::min(2 * cx + 1, below.w - 1); ++x) {
            if ((x << s) >= r.x1 || ((x + 1) << s) <= r.x0) continue;
            if (!cell_hidden(level - 1, x, y, r, z)) return false;
        }
    }
    return true;
}

// The cells above the tiles the last face changed marked too; the tiles stay marked. A
// marked cell is brought up to date only when a test reads it (refresh), so a tile that many
// faces change before any test looks at it is taken once, and one no test reads never.
void HierarchicalZBuffer::mark_levels() {
    for (uint32_t t : m_dirty_list) {
        int cx = static_cast<int>(t % static_cast<uint32_t>(m_levels[0].w));
        int cy = static_cast<int>(t / static_cast<uint32_t>(m_levels[0].w));
        for (std::size_t level = 1; level < m_levels.size(); ++level) {
            cx /= 2;
            cy /= 2;
            uint8_t& d =
                m_levels[level].dirty[static_cast<std::size_t>(cy) * m_levels[level].w + cx];
            if (d) break;  // and so are the ones above it
            d = 1;
        }
    }
    m_dirty_list.clear();
}

// A marked cell taken again: a tile, the farthest of its depths (far while a pixel is
// uncovered); a cell above, the farthest of its children, each brought up to date first.
void HierarchicalZBuffer::refresh(int level, int cx, int cy) {
    Level& l = m_levels[static_cast<std::size_t>(level)];
    const std::size_t at = static_cast<std::size_t>(cy) * l.w + cx;
    if (!l.dirty[at]) return;
    l.dirty[at] = 0;
    double far = -kFar;
    if (level == 0) {
        ++m_counts.tiles_updated;
        const int x0 = cx << kTileShift, y0 = cy << kTileShift;
        const int x1 = std::min(m_width, x0 + (1 << kTileShift));
        const int y1 = std::min(m_band_rows, y0 + (1 << kTileShift));
        uint32_t uncovered = 0;
        for (int y = y0; y < y1; ++y) {
            const std::size_t row = static_cast<std::size_t>(y) * m_width;
            const double* depth = m_depth.data() + row;
            const uint32_t* face = m_face.data() + row;
            for (int x = x0; x < x1; ++x) {
                far = std::max(far, depth[x]);
                uncovered |= face[x] == 0 ? 1u : 0u;
            }
        }
        l.far[at] = uncovered ? kFar : far;
        return;
    }
    const Level& below = m_levels[static_cast<std::size_t>(level) - 1];
    for (int y = 2 * cy; y <= std::min(2 * cy + 1, below.h - 1); ++y)
        for (int x = 2 * cx; x <= std::min(2 * cx + 1, below.w - 1); ++x) {
            refresh(level - 1, x, y);
            far = std::max(far, below.far[static_cast<std::size_t>(y) * below.w + x]);
        }
    l.far[at] = far;
}

// --- drawing ------------------------------------------------------------------------------

namespace {

// One face: its rows' runs of centres by the coverage rule, each run depth-tested by the
// Z-buffer's kernel (depth_rows.h); the tiles of a run that won a centre are marked for
// mark_levels() (Mark). Under the pyramid (Mark) faces arrive front to back, not in id order,
// so a tie goes to the lower index by the test itself; in a direct band they arrive in id
// order, and the first to reach a depth keeps it, as in the Z-buffer. The wrappers below
// compile it once per kernel, as zbuffer.cpp does.
template <class DepthRow, bool Mark>
uint64_t draw_face(const ScreenScene& scene, uint32_t index, int band_y0, int band_rows,
                   double* depth_buffer, uint32_t* face_buffer, int width, int tiles_w,
                   uint8_t* dirty, std::vector<uint32_t>& dirty_list, uint64_t& tests) {
    const ScreenFace& f = scene.faces[index];
    const EdgeFunction* edges = scene.edges_of(f);
    constexpr int shift = HierarchicalZBuffer::kTileShift;
    uint64_t written = 0;
    const int y_end = std::min(f.bounds.y1, band_y0 + band_rows);
    for (int y = std::max(f.bounds.y0, band_y0); y < y_end; ++y) {
        int xb = 0, xe = 0;
        if (!row_span(edges, f.point_count, y, f.bounds.x0, f.bounds.x1, xb, xe)) continue;
        const int local = y - band_y0;  // the band buffers' row
        const std::size_t row = static_cast<std::size_t>(local) * static_cast<std::size_t>(width);
        tests += static_cast<uint64_t>(xe - xb);
        const uint64_t won = DepthRow::template test<Mark>(f.depth, y, xb, xe, index + 1,
                                                           depth_buffer + row, face_buffer + row);
        if (won == 0) continue;
        written += won;
        if constexpr (!Mark) continue;
        const uint32_t tile_row =
            static_cast<uint32_t>(local >> shift) * static_cast<uint32_t>(tiles_w);
        for (int tx = xb >> shift; tx <= (xe - 1) >> shift; ++tx) {
            const uint32_t t = tile_row + static_cast<uint32_t>(tx);
            if (!dirty[t]) {
                dirty[t] = 1;
                dirty_list.push_back(t);
            }
        }
    }
    return written;
}

#if defined(__SSE2__)
using HzbRowBaseline = DepthRowSse2;
#else
using HzbRowBaseline = DepthRowScalar;
#endif

template <bool Mark>
[[gnu::flatten]] uint64_t draw_face_baseline(const ScreenScene& scene, uint32_t index, int band_y0,
                                             int band_rows, double* depth, uint32_t* face,
                                             int width, int tiles_w, uint8_t* dirty,
                                             std::vector<uint32_t>& dirty_list, uint64_t& tests) {
    return draw_face<HzbRowBaseline, Mark>(scene, index, band_y0, band_rows, depth, face, width,
                                           tiles_w, dirty, dirty_list, tests);
}

#if defined(FB89_HAS_AVX2_KERNEL)
template <bool Mark>
[[gnu::target("avx2"), gnu::flatten]] uint64_t draw_face_avx2(
    const ScreenScene& scene, uint32_t index, int band_y0, int band_rows, double* depth,
    uint32_t* face, int width, int tiles_w, uint8_t* dirty, std::vector<uint32_t>& dirty_list,
    uint64_t& tests) {
    return draw_face<DepthRowAvx2, Mark>(scene, index, band_y0, band_rows, depth, face, width,
                                         tiles_w, dirty, dirty_list, tests);
}
#endif

}  // namespace

template <bool Mark>
void HierarchicalZBuffer::draw(const ScreenScene& scene, uint32_t index) {
    uint64_t tests = 0, written = 0;
#if defined(FB89_HAS_AVX2_KERNEL)
    if (has_avx2())
        written = draw_face_avx2<Mark>(scene, index, m_band_y0, m_band_rows, m_depth.data(),
                                       m_face.data(), m_width, m_levels[0].w,
                                       m_levels[0].dirty.data(), m_dirty_list, tests);
    else
#endif
        written = draw_face_baseline<Mark>(scene, index, m_band_y0, m_band_rows, m_depth.data(),
                                           m_face.data(), m_width, m_levels[0].w,
                                           m_levels[0].dirty.data(), m_dirty_list, tests);
    m_counts.depth_tests += tests;
    m_counts.pixels_written += written;
    m_drawn[index] = 1;
    if constexpr (Mark) mark_levels();
}

// A rectangle's part in the band, in the band buffers' rows (empty when it misses the band).
PixelRect HierarchicalZBuffer::in_band(const PixelRect& r) const {
    PixelRect local{r.x0, std::max(r.y0, m_band_y0) - m_band_y0, r.x1,
                    std::min(r.y1, m_band_y0 + m_band_rows) - m_band_y0};
    return local;
}

void HierarchicalZBuffer::walk(const ScreenScene& scene, uint32_t index) {
    const Node& node = m_nodes[index];
    const PixelRect rect = in_band(node.box.rect);
    if (rect.empty()) return;  // not in this band
    ++m_counts.nodes_visited;
    if (hidden(rect, node.box.z0)) {
        ++m_counts.nodes_culled;
        return;
    }
    for (uint32_t i = node.first_face; i < node.first_face + node.face_count; ++i) {
        const uint32_t f = m_order[i];
        const PixelRect face = in_band(m_face_box[f].rect);
        if (face.empty()) continue;
        ++m_counts.face_tests;
        if (hidden(face, m_face_box[f].z0)) {
            ++m_counts.faces_culled;
            continue;
        }
        draw<true>(scene, f);
    }
    for (uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c)
        walk(scene, c);
}

// A band where the hierarchy would not pay: every face that meets it drawn in id order, as
// the Z-buffer draws it, with no test of the pyramid and no tile marked.
void HierarchicalZBuffer::draw_band(const ScreenScene& scene, std::size_t band) {
    for (uint32_t i = m_band_first[band]; i < m_band_first[band + 1]; ++i)
        draw<false>(scene, m_band_faces[i]);
}

void HierarchicalZBuffer::render(const ScreenScene& scene, protocol::CommandSink& sink,
                                 HostStats& stats) {
    if (m_scene != &scene || m_width != scene.width || m_height != scene.height ||
        m_face_box.size() != scene.faces.size())
        setup(scene);
    m_counts = HzbCounts{};
    m_color.resize(scene.faces.size());
    for (std::size_t i = 0; i < scene.faces.size(); ++i)
        m_color[i] = packed_color(scene.faces[i].color);
    m_drawn.assign(scene.faces.size(), 0);
    // band by band: the octree walked over the band, then the band's spans (emission leaves
    // its rows zeroed for the next)
    for (m_band_y0 = 0; m_band_y0 < m_height; m_band_y0 += kBandRows) {
        m_band_rows = std::min(kBandRows, m_height - m_band_y0);
        const bool hierarchy =
            m_band_cover[static_cast<std::size_t>(m_band_y0 / kBandRows)] >= kHierarchyFromCover;
        (hierarchy ? m_counts.bands_hierarchical : m_counts.bands_direct) += 1;
        if (hierarchy) reset_pyramid();
        if (hierarchy && !m_nodes.empty())
            walk(scene, 0);
        else if (!hierarchy)
            draw_band(scene, static_cast<std::size_t>(m_band_y0 / kBandRows));
        for (int y = 0; y < m_band_rows; ++y)
            m_counts.spans += emit_band_row(m_face.data() + static_cast<std::size_t>(y) * m_width,
                                            m_band_y0 + y, 0, m_width, m_color.data(), sink);
    }
    for (uint8_t d : m_drawn)
        m_counts.faces_drawn += d;
    stats.counters.add("hzb_nodes_visited", m_counts.nodes_visited);
    stats.counters.add("hzb_nodes_culled", m_counts.nodes_culled);
    stats.counters.add("hzb_face_tests", m_counts.face_tests);
    stats.counters.add("hzb_faces_culled", m_counts.faces_culled);
    stats.counters.add("faces_rasterised", m_counts.faces_drawn);
    stats.counters.add("hzb_pyramid_tests", m_counts.pyramid_tests);
    stats.counters.add("depth_tests", m_counts.depth_tests);
    stats.counters.add("pixels_written", m_counts.pixels_written);
    stats.counters.add("hzb_tiles_updated", m_counts.tiles_updated);
    stats.counters.add("hzb_bands_hierarchical", m_counts.bands_hierarchical);
    stats.counters.add("hzb_bands_direct", m_counts.bands_direct);
    stats.counters.add("spans", m_counts.spans);
}

}  // namespace fb89::host
