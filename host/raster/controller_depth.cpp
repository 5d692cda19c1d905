#include "host/raster/controller_depth.h"

#include <algorithm>

#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "protocol/depth_fixed.h"

namespace fb89::host {

uint64_t send_depth_spans(const ScreenScene& scene, const ScreenFace& face,
                          protocol::CommandSink& sink, uint64_t& pixels) {
    const EdgeFunction* edges = scene.edges_of(face);
    // a slope past 32 bits moves depth by more than 8 a pixel: such a face's runs are a
    // pixel long, and need none
    const int32_t dz = protocol::slope_fixed(face.depth.a).value_or(0);
    uint64_t spans = 0;
    for (int y = face.bounds.y0; y < face.bounds.y1; ++y) {
        int xb = 0, xe = 0;
        if (!row_span(edges, face.point_count, y, face.bounds.x0, face.bounds.x1, xb, xe)) continue;
        sink.depth_span(
            {y, xb, xe - 1, protocol::depth_fixed(depth_at(face.depth, xb, y)), dz, face.color});
        ++spans;
        pixels += static_cast<uint64_t>(xe - xb);
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

// The pixel nearest the centroid of a convex polygon: inside it or next to it, so that its
// depth is the face's (within a pixel's step) and fits Z's range.
void reference_pixel(const SnappedPoint* p, uint32_t n, int32_t& x, int32_t& y) {
    int64_t sx = 0, sy = 0;
    for (uint32_t i = 0; i < n; ++i) {
        sx += p[i].x;
        sy += p[i].y;
    }
    const auto pixel = [&](int64_t sum) {  // floor(sum / n / 256)
        return static_cast<int32_t>(protocol::detail::floor_div(sum, int64_t{n} * kSubpixel));
    };
    x = pixel(sx);
    y = pixel(sy);
}

}  // namespace

void FaceSender::render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) {
    sink.depth_clear({});
    uint64_t sent = 0, fans = 0, as_spans = 0, spans = 0, pixels = 0;
    protocol::Face f;
    for (const ScreenFace& face : scene.faces) {
        if (face.bounds.empty()) continue;
        const auto dzdx = protocol::slope_fixed(face.depth.a);
        const auto dzdy = protocol::slope_fixed(face.depth.b);
        if (!dzdx || !dzdy) {  // the controller's slopes cannot carry it
            spans += send_depth_spans(scene, face, sink, pixels);
            ++as_spans;
            continue;
        }
        const SnappedPoint* p = scene.points_of(face);
        const uint32_t n = face.point_count;
        f.color = face.color;
        f.dzdx = *dzdx;
        f.dzdy = *dzdy;
        // fans of at most kMaxFacePoints points: 0, k, ..., k + kMaxFacePoints - 2
        const uint32_t most = static_cast<uint32_t>(protocol::kMaxFacePoints);
        for (uint32_t k = 1; k + 1 < n; k += most - 2) {
            const uint32_t end = std::min(n, k + most - 1);
            f.points.clear();
            f.points.push_back(p[0]);
            f.points.insert(f.points.end(), p + k, p + end);
            reference_pixel(f.points.data(), static_cast<uint32_t>(f.points.size()), f.x_ref,
                            f.y_ref);
            f.z = protocol::depth_fixed(depth_at(face.depth, f.x_ref, f.y_ref));
            sink.face(f);
            ++sent;
            if (k > 1) ++fans;
            if (end == n) break;
        }
    }
    stats.counters.add("faces_sent", sent);
    stats.counters.add("faces_split_in_fans", fans);
    stats.counters.add("faces_as_depth_spans", as_spans);
    stats.counters.add("depth_spans", spans);
}

}  // namespace fb89::host
