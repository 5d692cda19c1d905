// Face-id buffer comparison with depth-tie classification, the id-boundary classification
// of the ray peer, and our ids read off the controller (see exactness.h).
#include "bench/peers/exactness.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "controller_sim/controller.h"
#include "host/raster/coverage.h"
#include "host/raster/depth.h"
#include "host/scene/projection.h"

namespace fb89::peers {

namespace {

// The plane of the piece of face `id` that covers pixel (x, y); pieces of one id are
// adjacent in scene.faces, starting at first_piece[id].
const host::DepthPlane& plane_at(const host::ScreenScene& scene,
                                 const std::vector<uint32_t>& first_piece, uint32_t id, int x,
                                 int y) {
    const uint32_t first = first_piece[id];
    for (uint32_t i = first; i < scene.faces.size() && scene.faces[i].id == id; ++i) {
        const host::ScreenFace& f = scene.faces[i];
        if (host::covers(scene.edges_of(f), f.point_count, x, y)) return f.depth;
    }
    return scene.faces[first].depth;  // no piece covers it: the other side drew it anyway
}

// |a x| + |b y| + |c| at the pixel centre: the size of the terms llvmpipe adds in floats.
double plane_terms(const host::DepthPlane& p, int x, int y) {
    return std::abs(p.a * (x + 0.5)) + std::abs(p.b * (y + 0.5)) + std::abs(p.c);
}

// An id mismatch at (x, y), ours a and llvmpipe's b (ids + 1): a depth tie, or real.
void classify_id_mismatch(const host::ScreenScene& scene, const std::vector<uint32_t>& first_piece,
                          uint32_t a, uint32_t b, int x, int y, Exactness& e) {
    ++e.id_mismatches;
    if (a > scene.face_count || b > scene.face_count) {
        ++e.real_mismatches;
        if (e.first.empty()) e.first = fmt::format("unknown id at ({}, {})", x, y);
        return;
    }
    const host::DepthPlane& pa = plane_at(scene, first_piece, a - 1, x, y);
    const host::DepthPlane& pb = plane_at(scene, first_piece, b - 1, x, y);
    const double dz = std::abs(host::depth_at(pa, x, y) - host::depth_at(pb, x, y));
    e.max_dz = std::max(e.max_dz, dz);
    if (dz < kDepthTie) {
        ++e.depth_ties;
        return;
    }
    ++e.real_mismatches;
    if (dz < kFloatUlps * (plane_terms(pa, x, y) + plane_terms(pb, x, y))) ++e.within_float_error;
    if (e.first.empty())
        e.first = fmt::format(
            "id at ({}, {}): ours id+1 {} (slope {:.3g}/px), llvmpipe {} (slope {:.3g}/px), "
            "|dz| {:.3g}",
            x, y, a, std::hypot(pa.a, pa.b), b, std::hypot(pb.a, pb.b), dz);
}

}  // namespace

Exactness compare_face_ids(const host::ScreenScene& scene, std::span<const uint32_t> ours,
                           std::span<const uint32_t> theirs) {
    std::vector<uint32_t> first_piece(scene.face_count + 1, 0);
    for (size_t i = scene.faces.size(); i-- > 0;)
        first_piece[scene.faces[i].id] = static_cast<uint32_t>(i);

    Exactness e;
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            const size_t i = static_cast<size_t>(y) * scene.width + x;
            const uint32_t a = ours[i], b = theirs[i];
            if (a == b) continue;
            if (a != 0 && b != 0) {
                classify_id_mismatch(scene, first_piece, a, b, x, y, e);
                continue;
            }
            // coverage: one side background
            ++e.coverage_mismatches;
            if (e.first.empty())
                e.first =
                    fmt::format("coverage at ({}, {}): ours id+1 {}, llvmpipe {}", x, y, a, b);
        }
    }
    return e;
}

namespace {

// Whether a neighbour of pixel (x, y) at one of the offsets holds an id other than `id`.
bool other_id_near(std::span<const uint32_t> ids, int width, int height, int x, int y, uint32_t id,
                   const int (*offsets)[2], int count) {
    for (int k = 0; k < count; ++k) {
        const int nx = x + offsets[k][0], ny = y + offsets[k][1];
        if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
        if (ids[static_cast<size_t>(ny) * width + nx] != id) return true;
    }
    return false;
}

}  // namespace

IdAgreement compare_with_boundaries(int width, int height, std::span<const uint32_t> ours,
                                    std::span<const uint32_t> theirs) {
    static constexpr int kEdges[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    static constexpr int kCorners[4][2] = {{-1, -1}, {1, -1}, {-1, 1}, {1, 1}};
    IdAgreement a;
    a.pixels = static_cast<uint64_t>(width) * height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            const uint32_t id = ours[i];
            if (id == theirs[i]) continue;
            ++a.differ;
            a.coverage += id == 0 || theirs[i] == 0;
            // an id boundary of ours: a neighbour with another id (a miss is an id too)
            if (other_id_near(ours, width, height, x, y, id, kEdges, 4)) {
                ++a.on_boundary;
            } else if (other_id_near(ours, width, height, x, y, id, kCorners, 4)) {
                ++a.diagonal;
            } else {
                ++a.interior;
                if (a.first_interior.empty())
                    a.first_interior =
                        fmt::format("({}, {}): ours id+1 {}, theirs {}", x, y, id, theirs[i]);
            }
        }
    }
    return a;
}

std::vector<uint32_t> controller_face_ids(const protocol::MemoryBuffer& frame) {
    controller::Controller ctl(controller::load_profile("ideal"));
    frame.replay_into(ctl);
    const controller::Framebuffer& fb = ctl.framebuffer();
    std::vector<uint32_t> ids(static_cast<size_t>(fb.width()) * fb.height());
    for (uint32_t y = 0; y < fb.height(); ++y)
        for (uint32_t x = 0; x < fb.width(); ++x)
            ids[static_cast<size_t>(y) * fb.width() + x] = host::face_id_from_color(fb.pixel(x, y));
    return ids;
}

}  // namespace fb89::peers
