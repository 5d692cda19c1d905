#include "host/raster/controller_depth.h"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "protocol/depth_fixed.h"

namespace fb89::host {

namespace {

// Is window depth z inside [0, 1], where depth_fixed() keeps it as it is (no hold)?
bool in_depth_range(double z) {
    return z >= 0 && z <= 1;
}

}  // namespace

// Each row's run as DEPTH_SPANs anchored where the exact rule is kept: the first pixel's Z is
// the plane's depth there, rounded, so that Z along the span is within half a unit plus half
// a unit a pixel of the exact depth (experiments/depth_agreement.h has the bound). A pixel
// whose centre lies a hair outside [0, 1] (a centre of the snapped polygon just past a
// clipped edge) would be held there, and a span stepped from a held anchor would carry the
// hold along: such pixels leave as spans of their own, and the run goes on from the next.
uint64_t send_depth_spans(const ScreenScene& scene, const ScreenFace& face,
                          protocol::CommandSink& sink, uint64_t& pixels) {
    const EdgeFunction* edges = scene.edges_of(face);
    // a slope past 32 bits moves depth by more than 8 a pixel: such a face's runs are a
    // pixel long in range; each pixel goes alone, anchored at its own depth
    const std::optional<int32_t> slope = protocol::slope_fixed(face.depth.a);
    const int32_t dz = slope.value_or(0);
    uint64_t spans = 0;
    for (int y = face.bounds.y0; y < face.bounds.y1; ++y) {
        int xb = 0, xe = 0;
        if (!row_span(edges, face.point_count, y, face.bounds.x0, face.bounds.x1, xb, xe)) continue;
        pixels += static_cast<uint64_t>(xe - xb);
        while (xb < xe) {
            const double z = depth_at(face.depth, xb, y);
            const int last = !slope || !in_depth_range(z) ? xb : xe - 1;
            sink.depth_span({y, xb, last, protocol::depth_fixed(z), dz, face.color});
            ++spans;
            xb = last + 1;
        }
    }
    return spans;
}

void DepthSpans::render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) {
    sink.depth_clear({});
    uint64_t spans = 0, pixels = 0, faces = 0;
    for (const ScreenFace& face : scene.faces) {
        if (face.bounds.empty()) continue;
        spans += send_depth_spans(scene, face, sink, pixels);
        ++faces;
    }
    stats.counters.add("faces_rasterised", faces);
    stats.counters.add("depth_spans", spans);
    stats.counters.add("pixels_covered", pixels);
}

namespace {

// Where a FACE's Z is given. The controller steps Z from there with the two rounded slopes,
// so a pixel's error grows with its distance from the anchor (half a unit, plus half a unit
// a pixel in x and in y): the anchor is a pixel the face covers on screen, within w - 1 and
// h - 1 of every pixel it draws, and a pixel whose depth is in [0, 1], so that its Z is not
// held. Found from the centroid outwards: its row held to the covered rows on screen, then
// rows above and below in turn; in each, the run's pixel nearest the centroid's column, else
// the run's middle. `covers` says whether the face covers any pixel on screen at all (one
// that does not draws nothing, and any anchor will do).
struct Anchor {
    bool found = false, covers = false;
    int32_t x = 0, y = 0;
};

Anchor face_anchor(const SnappedPoint* p, uint32_t n, const DepthPlane& plane, int width,
                   int height) {
    std::array<protocol::EdgeFunction, protocol::kMaxFacePoints> edges;
    protocol::setup_edges(p, n, edges.data());
    int64_t sx = 0, sy = 0, lo = p[0].y, hi = p[0].y;
    for (uint32_t i = 0; i < n; ++i) {
        sx += p[i].x;
        sy += p[i].y;
        lo = std::min(lo, p[i].y);
        hi = std::max(hi, p[i].y);
    }
    const int64_t half = kSubpixel / 2, whole = int64_t{n} * kSubpixel;
    const auto first =
        static_cast<int>(std::max<int64_t>(0, protocol::detail::ceil_div(lo - half, kSubpixel)));
    const auto last = static_cast<int>(
        std::min<int64_t>(height - 1, protocol::detail::floor_div(hi - half, kSubpixel)));
    Anchor a;
    a.x = static_cast<int32_t>(protocol::detail::floor_div(sx, whole));
    a.y = static_cast<int32_t>(protocol::detail::floor_div(sy, whole));
    if (first > last) return a;
    const int cy = std::clamp<int>(a.y, first, last);
    for (int d = 0; cy - d >= first || cy + d <= last; ++d)
        for (int side = 0; side < (d == 0 ? 1 : 2); ++side) {
            const int row = side == 0 ? cy - d : cy + d;
            int xb = 0, xe = 0;
            if (row < first || row > last ||
                !protocol::row_span(edges.data(), n, row, 0, width, xb, xe))
                continue;
            a.covers = true;
            for (const int col : {std::clamp<int>(a.x, xb, xe - 1), xb + (xe - xb) / 2})
                if (in_depth_range(depth_at(plane, col, row))) {
                    a.found = true;
                    a.x = col;
                    a.y = row;
                    return a;
                }
        }
    return a;
}

}  // namespace

namespace {

// A face as FACE commands: fans of at most kMaxFacePoints points (0, k, ..., k +
// kMaxFacePoints - 2), each anchored (face_anchor). False, with `fans` unfinished, when a fan
// covers pixels on screen but none whose depth is in [0, 1]: a sliver on the near or the far
// plane, which goes as DEPTH_SPANs instead.
bool face_fans(const ScreenScene& scene, const ScreenFace& face, int32_t dzdx, int32_t dzdy,
               std::vector<protocol::Face>& fans) {
    const SnappedPoint* p = scene.points_of(face);
    const uint32_t n = face.point_count;
    const uint32_t most = static_cast<uint32_t>(protocol::kMaxFacePoints);
    fans.clear();
    for (uint32_t k = 1; k + 1 < n; k += most - 2) {
        const uint32_t end = std::min(n, k + most - 1);
        protocol::Face& f = fans.emplace_back();
        f.color = face.color;
        f.dzdx = dzdx;
        f.dzdy = dzdy;
        f.points.push_back(p[0]);
        f.points.insert(f.points.end(), p + k, p + end);
        const Anchor a = face_anchor(f.points.data(), static_cast<uint32_t>(f.points.size()),
                                     face.depth, scene.width, scene.height);
        if (a.covers && !a.found) return false;
        f.x_ref = a.x;
        f.y_ref = a.y;
        f.z = protocol::depth_fixed(depth_at(face.depth, f.x_ref, f.y_ref));
        if (end == n) break;
    }
    return true;
}

}  // namespace

void FaceSender::render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) {
    sink.depth_clear({});
    uint64_t sent = 0, fans = 0, as_spans = 0, spans = 0, pixels = 0;
    std::vector<protocol::Face> pieces;
    for (const ScreenFace& face : scene.faces) {
        if (face.bounds.empty()) continue;
        const auto dzdx = protocol::slope_fixed(face.depth.a);
        const auto dzdy = protocol::slope_fixed(face.depth.b);
        // the controller's slopes cannot carry it, or it has no pixel to anchor Z at
        if (!dzdx || !dzdy || !face_fans(scene, face, *dzdx, *dzdy, pieces)) {
            spans += send_depth_spans(scene, face, sink, pixels);
            ++as_spans;
            continue;
        }
        for (const protocol::Face& f : pieces)
            sink.face(f);
        sent += pieces.size();
        fans += pieces.size() - 1;
    }
    stats.counters.add("faces_sent", sent);
    stats.counters.add("faces_split_in_fans", fans);
    stats.counters.add("faces_as_depth_spans", as_spans);
    stats.counters.add("depth_spans", spans);
}

}  // namespace fb89::host
