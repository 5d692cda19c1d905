// The hierarchical Z-buffer: Greene, Kass & Miller, "Hierarchical Z-Buffer Visibility",
// SIGGRAPH 93 -- the successor of the paper's §3 hybrid, image coherence (a depth pyramid)
// and object coherence (an octree) used together.
//
// The faces sit in an octree, walked front to back; the Z-buffer keeps, beside its depths, a
// pyramid whose every cell holds the farthest depth of the pixels below it (a pixel no face
// has covered yet counts as infinitely far). A node of the octree whose nearest depth lies
// beyond the pyramid's farthest over its screen rectangle is hidden with everything in it and
// skipped whole; each face of a node that survives is tested the same way before it is
// scan-converted, and the pixels of the faces drawn bring the pyramid's cells nearer.
//
// Ours differs from the paper's in six ways, each keeping the face-id buffer identical to the
// Z-buffer's (zbuffer.h) on every scene:
// - The octree is built in screen space (pixels in x and y, the depth plane's z), over the
//   ScreenScene every raster method shares, so that "front to back" is an order by depth and
//   the pyramid tests are made in the coordinates the depth test uses. A face lives in the
//   smallest node that holds its box; a node's tests use the tight box of what is in it, not
//   its cube, and its children are taken in the order of their nearest depths.
// - A face's nearest depth is its plane's least value over the corners of its pixel
//   rectangle, less a margin for the rounding of depth_at() (depth.h), so a culled face could
//   not have won a pixel: the test is conservative and there is nothing to forgive.
// - The depth test keeps the shared rule's tie to the lower id explicitly (nearer(), depth.h),
//   since faces come front to back rather than in id order.
// - The pyramid's finest level is a tile of 8 x 8 pixels, not the pixel; a tile is far while
//   it has an uncovered pixel, and a cell whose pixels faces changed is taken again only when
//   a test reads it (Greene's pyramid is brought up to date as each face is drawn): the
//   tests see the same values, so the same faces and nodes are culled.
// - The screen is worked in bands of 32 rows, as the Z-buffer works it (zbuffer.h), each with
//   its own depth and face buffers and its own pyramid, a few hundred KB that stay in cache:
//   the octree is walked once a band, over the nodes and faces that meet it, front to back.
//   The whole screen's buffers, met in the octree's order, cost the first version twice the
//   Z-buffer's time on scene A; banded, the culling is finer too (a face hidden in one band
//   and not in another is drawn only where it may be seen).
// - A band uses the hierarchy only where it can pay: where its faces' rectangles cover it at
//   least kHierarchyFromCover times over (the most depth complexity the band can have, from
//   set-up). Elsewhere every face that meets the band is drawn in id order, as the Z-buffer
//   draws it (the first to reach a depth keeps it), with no pyramid test and no tile marked: on the
//   paper's scenes (depth complexity 1.5-3.2) that is every band, and the octree and pyramid cost
//   nothing (counters hzb_bands_hierarchical and hzb_bands_direct say which way the bands went;
//   docs/RESULTS.md, "After the paper").
// Spans leave as the Z-buffer's do (band_spans.h), band by band, so the stream is the same.
#pragma once

#include <cstdint>
#include <vector>

#include "host/raster/renderer.h"

namespace fb89::host {

struct HzbCounts {
    uint64_t nodes_visited =
        0;  // octree nodes reached by the walk (counter hzb_nodes_visited, and so on)
    uint64_t nodes_culled = 0;        // of those, hidden in the pyramid with all they hold
    uint64_t face_tests = 0;          // a face of a surviving node tested in a band
    uint64_t faces_culled = 0;        // of those, hidden in the pyramid
    uint64_t faces_drawn = 0;         // faces scan-converted and depth-tested in some band
    uint64_t pyramid_tests = 0;       // pyramid cells compared with a nearest depth
    uint64_t depth_tests = 0;         // pixel centres a drawn face covered and tested
    uint64_t pixels_written = 0;      // tests that won
    uint64_t tiles_updated = 0;       // finest pyramid cells taken again for a test
    uint64_t spans = 0;               // DRAW_SPAN commands sent
    uint64_t bands_hierarchical = 0;  // bands worked with the pyramid's tests
    uint64_t bands_direct = 0;        // bands whose faces were all drawn, untested
};

class HierarchicalZBuffer final : public Renderer {
  public:
    std::string_view name() const override { return "hzb"; }
    // Builds the octree over this scene's faces (set-up, not hidden-surface time).
    void setup(const ScreenScene& scene) override;
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;

    const HzbCounts& counts() const { return m_counts; }
    std::size_t node_count() const { return m_nodes.size(); }

    static constexpr int kTileShift = 3;  // the pyramid's finest cell: 8 x 8 pixels
    static constexpr int kBandRows = 32;  // a band of the screen, worked as one
    static constexpr uint32_t kLeafFaces = 8;
    static constexpr int kMaxDepth = 16;
    // A band is worked with the pyramid when its faces' rectangles cover it this many times
    // over (the most depth complexity it can have); below, every face meeting it is drawn.
    static constexpr double kHierarchyFromCover = 8.0;

  private:
    struct Box {
        PixelRect rect;  // screen pixels
        double z0 = 0, z1 = 0;
    };
    struct Node {
        Box box;                                    // the tight box of its faces and its children's
        uint32_t first_face = 0, face_count = 0;    // into m_order, nearest first
        uint32_t first_child = 0, child_count = 0;  // into m_nodes, nearest first
    };

    void build(uint32_t index, std::vector<uint32_t>& faces, const Box& cube, int depth);
    void walk(const ScreenScene& scene, uint32_t node);
    void draw_band(const ScreenScene& scene, std::size_t band);
    PixelRect in_band(const PixelRect& r) const;
    bool hidden(const PixelRect& r, double z);
    bool cell_hidden(int level, int cx, int cy, const PixelRect& r, double z);
    template <bool Mark>
    void draw(const ScreenScene& scene, uint32_t index);
    void mark_levels();
    void refresh(int level, int cx, int cy);
    void reset_pyramid();

    const ScreenScene* m_scene = nullptr;
    std::vector<Box> m_face_box;  // each face's pixel rectangle and conservative depth range
    std::vector<Node> m_nodes;    // m_nodes[0] the root, when there are faces
    std::vector<uint32_t> m_order;
    std::vector<double> m_band_cover;  // each band's faces' rectangles over its pixels
    std::vector<uint32_t> m_band_first, m_band_faces;  // each band's faces, in id order

    int m_width = 0, m_height = 0;
    std::vector<double> m_depth;   // the band's; meaningful only where m_face is not 0
    std::vector<uint32_t> m_face;  // scene.faces index + 1, 0: none; padded (depth_rows.h)
    std::vector<uint32_t> m_color;
    std::vector<uint8_t> m_drawn;  // faces drawn in some band of this frame
    int m_band_y0 = 0, m_band_rows = 0;
    struct Level {
        int w = 0, h = 0;
        std::vector<double> far;     // the farthest depth below each cell
        std::vector<uint8_t> dirty;  // 1: a pixel below changed since `far` was taken
    };
    std::vector<Level> m_levels;         // [0]: tiles
    std::vector<uint32_t> m_dirty_list;  // tiles the face being drawn marked
    HzbCounts m_counts;
};

}  // namespace fb89::host
