#include "host/trace/mlrta.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

#include "host/trace/nearest.h"
#include "host/trace/ray_packet.h"

namespace fb89::host {

namespace {

// A kd-tree cell: a node, its depth and its box.
struct Cell {
    uint32_t node;
    uint32_t depth;
    KdTree::Box box;
};

// Where a beam's rays start: a cell, then the cells put off, the next last. At most one cell
// a level is ever put off (a far child of the path's nodes), so the list fits the tree's depth.
struct Entry {
    Cell at;
    int pending = 0;
    std::array<Cell, KdTree::kMaxDepth + 1> later;  // the first `pending` set

    Entry() = default;
    Entry(const Entry& o) : at(o.at), pending(o.pending) {
        std::copy_n(o.later.begin(), o.pending, later.begin());
    }
    Entry& operator=(const Entry&) = delete;
};

// The convex hull of a tile's pixel rays between t = 0 and t = far: its box and its planes
// (the four sides, each through two neighbouring corner rays, and the near and far ends), each
// with its outward unit normal; planes of a flat hull are left out (the box stands for them).
struct Frustum {
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
    glm::dvec3 start[4];  // the corner rays' starts
    glm::dvec3 normal[6];
    double offset[6] = {};
    int planes = 0;
    double margin = 0;

    Ray corner[4];  // the rays through the corner pixels' centres

    Frustum(const TraceScene& scene, int x0, int y0, int x1, int y1, double far)
        : corner{scene.pixel_ray(x0, y0), scene.pixel_ray(x1, y0), scene.pixel_ray(x1, y1),
                 scene.pixel_ray(x0, y1)} {
        glm::dvec3 end[4];
        glm::dvec3 centre{0};
        for (int i = 0; i < 4; ++i) {
            start[i] = corner[i].origin;
            end[i] = corner[i].origin + far * corner[i].dir;
            lo = glm::min(lo, glm::min(start[i], end[i]));
            hi = glm::max(hi, glm::max(start[i], end[i]));
            centre += start[i] + end[i];
        }
        centre /= 8.0;
        margin = 16 * scene.tolerance();
        const double size = glm::length(hi - lo);
        auto plane = [&](const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
            glm::dvec3 n = glm::cross(a - p, b - p);
            const double length = glm::length(n);
            if (!(length > 0)) return;
            n /= length;
            double inside = glm::dot(n, centre - p);
            // the centre on the plane: a flat hull, whose box bounds it instead
            if (std::abs(inside) <= 1e-9 * size) return;
            if (inside > 0) n = -n;
            normal[planes] = n;
            offset[planes] = glm::dot(n, p);
            ++planes;
        };
        for (int i = 0; i < 4; ++i)
            plane(start[i], start[(i + 1) % 4], end[i]);
        plane(start[0], start[1], start[3]);
        plane(end[0], end[1], end[3]);
    }

    // False only when no ray of the tile enters `box`: it lies beyond the hull's box, or
    // wholly outside one of its planes, by more than the margin.
    bool overlaps(const KdTree::Box& box) const {
        for (int a = 0; a < 3; ++a)
            if (box.lo[a] > hi[a] + margin || box.hi[a] < lo[a] - margin) return false;
        for (int k = 0; k < planes; ++k) {
            const glm::dvec3& n = normal[k];
            const glm::dvec3 nearest{n.x > 0 ? box.lo.x : box.hi.x, n.y > 0 ? box.lo.y : box.hi.y,
                                     n.z > 0 ? box.lo.z : box.hi.z};
            if (glm::dot(n, nearest) - offset[k] > margin) return false;
        }
        return true;
    }
};

struct MlrtaBeamCounts {
    uint64_t beams = 0, beams_missed = 0, nodes = 0, entry_points = 0, entry_depth = 0,
             unordered = 0, settled = 0, filled = 0, pixels_by_beams = 0, pixels_by_rays = 0;
};

struct Frame {
    const TraceScene& scene;
    const RayTracer& tracer;
    const KdTree& kd;
    std::vector<uint32_t>& pixels;
    Mailbox& mailbox;                  // a piece listed in several leaves is tested once a ray
    double far;                        // no pixel ray meets a piece beyond it
    uint32_t hint = kNoFace;           // the piece the last primary ray hit
    std::vector<uint32_t> candidates;  // the entry leaf's pieces the beam may meet
    PacketTracer packet_tracer;        // the kernel level's; null: every ray goes alone
    PacketMailbox& packet_mailbox;
    TraceCounts rays;
    MlrtaBeamCounts beams;
    PacketCounts packets;
    RayTrace scratch;

    enum class Found { Leaf, Unordered, Nothing };

    // Walks the beam on from `e` to its entry point: the first leaf holding pieces it may
    // enter (or a node whose plane cuts the tile's starts); Nothing when it enters none.
    Found search(Entry& e, const Frustum& f) {
        const auto& nodes = kd.nodes();
        Cell cur = e.at;
        bool live = f.overlaps(cur.box);
        for (;;) {
            if (!live) {
                live = false;
                while (e.pending > 0 && !live) {
                    cur = e.later[--e.pending];
                    live = f.overlaps(cur.box);
                }
                if (!live) return Found::Nothing;
            }
            ++beams.nodes;
            const KdTree::Node& n = nodes[cur.node];
            if (n.leaf()) {
                if (n.count > 0) {
                    e.at = cur;
                    return Found::Leaf;
                }
                live = false;
                continue;
            }
            int side = 0;  // -1: every start below the plane; +1: above; 0: cut
            for (int i = 0; i < 4; ++i) {
                const int s = f.start[i][n.axis] < n.split ? -1 : f.start[i][n.axis] > n.split;
                side = i == 0 ? s : side == s ? side : 0;
            }
            if (side == 0) {
                e.at = cur;
                return Found::Unordered;
            }
            const Cell lower{cur.node + 1, cur.depth + 1, KdTree::lower(cur.box, n)};
            const Cell upper{n.index, cur.depth + 1, KdTree::upper(cur.box, n)};
            const Cell& near = side < 0 ? lower : upper;
            const Cell& far_cell = side < 0 ? upper : lower;
            const bool near_in = f.overlaps(near.box), far_in = f.overlaps(far_cell.box);
            if (near_in && far_in) e.later[e.pending++] = far_cell;
            if (near_in)
                cur = near;
            else if (far_in)
                cur = far_cell;
            else
                live = false;
        }
    }

    // One primary ray's nearest hit, from the beam's entry point on.
    Hit nearest_from(const Ray& ray, const Entry& e) {
        ++rays.rays;
        const Mailbox::Round seen = mailbox.begin();
        const RaySpace space(ray);
        Nearest nearest{scene, ray, space, 0, scene.primary_length()};
        const glm::dvec3 inv = inverse_direction(ray);
        auto test = [&, seen](std::span<const uint32_t> pieces) {
            for (uint32_t piece : pieces)
                if (seen.first_visit(piece)) nearest.test(piece);
        };
        // the piece the last ray hit, first: a neighbour's ray most often hits it too, and
        // then the leaf's pieces behind it fail on their plane's distance alone
        if (hint != kNoFace && seen.first_visit(hint)) nearest.test(hint);
        auto done = [&](double t_exit) { return nearest.best.t <= t_exit; };
        auto walk = [&](const Cell& c) {
            double t0 = 0, t1 = std::min(scene.primary_length(), nearest.best.t);
            return KdTree::clip(ray, inv, c.box, t0, t1) &&
                   kd.walk(ray, inv, c.node, t0, t1, test, done, rays.kd_nodes);
        };
        if (!walk(e.at))
            for (int k = e.pending - 1; k >= 0; --k)
                if (walk(e.later[k])) break;
        rays.face_tests += nearest.tests;
        rays.ties += nearest.ties;
        hint = nearest.best.piece;
        return nearest.best;
    }

    // Whether the ray tracer follows a reflection from `hit`.
    bool reflects(Hit hit) const {
        return hit.piece != kNoFace && scene.faces()[hit.piece].mirror > 0 &&
               scene.max_reflections() > 0;
    }

    // A packet lane's path on from a mirror, as RayTracer::follow records it.
    struct Path {
        Ray ray;
        Hit hit;
        int count = 0;
        PathHit hits[kMaxReflections + 1];
    };
    std::array<Path, kPacketRays> paths;

    // RayTracer::follow for the lanes `lanes` of `paths`, each first hit a mirror: their
    // reflected rays go on together, a packet from the kd-tree's root (each lane with its own
    // tmin and its mirror left out, as the ray tracer's reflected rays), as long as their ray
    // spaces agree; a lane whose space differs goes alone through the ray tracer's structure.
    void follow(uint32_t lanes) {
        const PacketCell root{0, kd.bounds()};
        PacketQuery query;
        query.cells = {&root, 1};
        for (int depth = 0; lanes != 0; ++depth) {
            RayPacket packet;
            for (int i = 0; i < kPacketRays; ++i) {
                if (!(lanes >> i & 1)) continue;
                Path& q = paths[i];
                if (q.hit.piece == kNoFace) {  // it escaped
                    lanes &= ~(1u << i);
                    continue;
                }
                const TraceFace& f = scene.faces()[q.hit.piece];
                const glm::dvec3 p = q.ray.origin + q.hit.t * q.ray.dir;
                const double facing = glm::dot(f.normal, q.ray.dir);
                q.hits[q.count++] = {q.hit.piece, facing > 0};
                if (!(f.mirror > 0) || depth == scene.max_reflections()) {
                    lanes &= ~(1u << i);
                    continue;
                }
                const uint32_t mirror = q.hit.piece;
                q.ray = {p, q.ray.dir - 2.0 * facing * f.normal};
                ++rays.rays;
                const double least = scene.tolerance() / glm::length(q.ray.dir);
                if (!packet.set(i, q.ray, least, mirror))
                    q.hit = tracer.closest_hit(q.ray, least, mirror, rays);
            }
            if (packet.lanes == 0) continue;
            packet.fill_empty_lanes();
            PacketHits hits;
            packet_tracer(scene, kd, packet, query, packet_mailbox, hits, packets);
            for (int i = 0; i < kPacketRays; ++i)
                if (packet.lanes >> i & 1)
                    paths[i].hit = {hits.t[i], static_cast<uint32_t>(hits.piece[i])};
        }
    }

    // The tile's rays in packets (ray_packet.h), each a 4 x 2 block of its pixels, from
    // `query`'s cells; a ray whose watertight space differs from its packet's goes alone.
    template <class Alone>
    void trace_packets(int x0, int y0, int x1, int y1, PacketQuery query, Alone&& alone) {
        const int width = scene.width();
        for (int by = y0; by < y1; by += 2)
            for (int bx = x0; bx < x1; bx += 4) {
                RayPacket packet;
                Ray lane_ray[kPacketRays];
                uint32_t lanes = 0;
                for (int i = 0; i < kPacketRays; ++i) {
                    const int x = bx + i % 4, y = by + i / 4;
                    if (x >= x1 || y >= y1) continue;
                    lane_ray[i] = scene.pixel_ray(x, y);
                    lanes |= 1u << i;
                    if (packet_tracer) packet.set(i, lane_ray[i]);
                }
                PacketHits hits;
                if (packet.lanes != 0) {
                    packet.fill_empty_lanes();
                    query.hint = hint;
                    packet_tracer(scene, kd, packet, query, packet_mailbox, hits, packets);
                }
                uint32_t mirrored = 0;  // the packed lanes whose first hit is a mirror
                for (int i = 0; i < kPacketRays; ++i) {
                    if (!(lanes >> i & 1)) continue;
                    const bool packed = packet.lanes >> i & 1;
                    rays.rays += packed;
                    const Hit hit = packed ? Hit{hits.t[i], static_cast<uint32_t>(hits.piece[i])}
                                           : alone(lane_ray[i]);
                    hint = hit.piece;
                    const int x = bx + i % 4, y = by + i / 4;
                    if (packed && reflects(hit)) {
                        paths[i].ray = lane_ray[i];
                        paths[i].hit = hit;
                        paths[i].count = 0;
                        mirrored |= 1u << i;
                        continue;
                    }
                    pixels[static_cast<size_t>(y) * width + x] =
                        tracer.color_of(lane_ray[i], hit, scratch, rays);
                }
                if (mirrored == 0) continue;
                follow(mirrored);
                for (int i = 0; i < kPacketRays; ++i)
                    if (mirrored >> i & 1) {
                        const Path& q = paths[i];
                        const int x = bx + i % 4, y = by + i / 4;
                        pixels[static_cast<size_t>(y) * width + x] =
                            packed_pixel(traced_color(scene, q.hits, q.count));
                    }
            }
        beams.pixels_by_rays += static_cast<uint64_t>(x1 - x0) * (y1 - y0);
    }

    // The tile's rays from the beam's entry point on (its pieces `culled` when it is a leaf).
    void trace_rays(int x0, int y0, int x1, int y1, const Entry& e, bool culled) {
        std::array<PacketCell, KdTree::kMaxDepth + 2> cells;
        int count = 0;
        cells[count++] = {e.at.node, e.at.box};
        for (int k = e.pending - 1; k >= 0; --k)
            cells[count++] = {e.later[k].node, e.later[k].box};
        PacketQuery query;
        query.cells = {cells.data(), static_cast<size_t>(count)};
        query.tmax = scene.primary_length();
        if (culled) {
            query.entry_leaf = e.at.node;
            query.entry_pieces = candidates;
        }
        trace_packets(x0, y0, x1, y1, query, [&](const Ray& ray) { return nearest_from(ray, e); });
    }

    // Whether every ray of the tile hits `piece` first, inside `leaf`: the entry leaf, of
    // which `piece` is the only piece the beam may meet. Each test below is linear (or, for t,
    // monotone) over the tile's rays, so it holds for every ray when it holds at the four
    // corners; each is asked with a margin far above the rounding of the watertight test,
    // which then decides every ray as the geometry does:
    //   - every corner ray meets the piece's plane from one side, at 0 < t < the far plane;
    //   - its hit lies inside the leaf's box (so no cell after the leaf, in any ray's order,
    //     holds a nearer hit), by a margin;
    //   - it lies inside every edge of the piece: det(p - o, q - o, d), the edge function,
    //     has one sign at every corner and every edge.
    // A mirror the ray tracer follows is never covered: its pixels differ.
    bool covers(uint32_t piece, const Frustum& f, const KdTree::Box& leaf) const {
        const TraceFace& face = scene.faces()[piece];
        if (face.mirror > 0 && scene.max_reflections() > 0) return false;
        const double pad = 16 * scene.tolerance();
        const glm::dvec3* v = scene.vertices_of(face);
        int facing = 0, inside = 0;
        for (const Ray& ray : f.corner) {
            const double denom = glm::dot(face.normal, ray.dir);
            const double length = glm::length(ray.dir);
            if (!(std::abs(denom) > 1e-9 * length)) return false;
            const int side = denom > 0 ? 1 : -1;
            if (facing != 0 && side != facing) return false;
            facing = side;
            const double t = (face.plane - glm::dot(face.normal, ray.origin)) / denom;
            if (!(t > pad && t < scene.primary_length() - pad)) return false;
            const glm::dvec3 hit = ray.origin + t * ray.dir;
            for (int a = 0; a < 3; ++a)
                if (!(hit[a] > leaf.lo[a] + pad && hit[a] < leaf.hi[a] - pad)) return false;
            for (uint32_t i = 0; i < face.vertex_count; ++i) {
                const glm::dvec3 p = v[i] - ray.origin;
                const glm::dvec3 q = v[(i + 1) % face.vertex_count] - ray.origin;
                const double e = glm::dot(glm::cross(p, q), ray.dir);
                if (!(std::abs(e) > 1e-9 * glm::length(p) * glm::length(q) * length)) return false;
                const int edge_side = e > 0 ? 1 : -1;
                if (inside != 0 && edge_side != inside) return false;
                inside = edge_side;
            }
        }
        return true;
    }

    // A covered tile: every pixel the piece's colour, as the ray tracer shades it, no ray.
    void fill(int x0, int y0, int x1, int y1, uint32_t piece, const Frustum& f) {
        const TraceFace& face = scene.faces()[piece];
        const uint32_t value =
            packed_pixel(face.end_color[glm::dot(face.normal, f.corner[0].dir) > 0 ? 1 : 0]);
        const int width = scene.width();
        for (int y = y0; y < y1; ++y)
            std::fill_n(&pixels[static_cast<size_t>(y) * width + x0], x1 - x0, value);
        ++beams.filled;
        beams.pixels_by_beams += static_cast<uint64_t>(x1 - x0) * (y1 - y0);
        hint = piece;
    }

    // A tile no ray of which can hit a piece (its beam entered no piece's leaf, or a settled
    // beam met none of its leaf's pieces): background, without a ray.
    void decide_background(int x0, int y0, int x1, int y1) {
        const int width = scene.width();
        for (int y = y0; y < y1; ++y)
            std::fill_n(&pixels[static_cast<size_t>(y) * width + x0], x1 - x0, 0u);
        beams.pixels_by_beams += static_cast<uint64_t>(x1 - x0) * (y1 - y0);
    }

    // A settled tile's rays, each testing the beam's candidates only: no walk.
    void trace_candidates(int x0, int y0, int x1, int y1) {
        PacketQuery query;
        query.tmax = scene.primary_length();
        query.entry_pieces = candidates;
        trace_packets(x0, y0, x1, y1, query, [&](const Ray& ray) {
            ++rays.rays;
            const RaySpace space(ray);
            Nearest nearest{scene, ray, space, 0, scene.primary_length()};
            if (hint != kNoFace &&
                std::find(candidates.begin(), candidates.end(), hint) != candidates.end())
                nearest.test(hint);
            for (uint32_t piece : candidates)
                if (piece != hint) nearest.test(piece);
            rays.face_tests += nearest.tests;
            rays.ties += nearest.ties;
            return nearest.best;
        });
    }

    // The tile [x0, x1) x [y0, y1), its rays starting from `parent` or from further in.
    void beam(int x0, int y0, int x1, int y1, const Entry& parent) {
        ++beams.beams;
        const Frustum f(scene, x0, y0, x1 - 1, y1 - 1, far);
        Entry e(parent);
        const Found found = search(e, f);
        if (found == Found::Nothing) {
            ++beams.beams_missed;
            decide_background(x0, y0, x1, y1);
            return;
        }
        ++beams.entry_points;
        beams.entry_depth += e.at.depth;
        beams.unordered += found == Found::Unordered;
        // drop the cells put off that this beam does not enter
        int kept = 0;
        for (int k = 0; k < e.pending; ++k)
            if (f.overlaps(e.later[k].box)) e.later[kept++] = e.later[k];
        e.pending = kept;
        const int w = x1 - x0, h = y1 - y0;
        if (found == Found::Leaf) {
            // the entry leaf's pieces the beam may meet
            candidates.clear();
            for (uint32_t piece : kd.leaf_pieces(kd.nodes()[e.at.node])) {
                const PieceBox& b = scene.box(piece);
                if (f.overlaps({b.lo, b.hi})) candidates.push_back(piece);
            }
            if (candidates.size() == 1 && covers(candidates[0], f, e.at.box)) {
                fill(x0, y0, x1, y1, candidates[0], f);
                return;
            }
            if (e.pending == 0) {
                // settled: the entry leaf is the only cell holding pieces the beam enters, so
                // a ray of it can hit only the candidates
                ++beams.settled;
                if (candidates.empty()) {
                    decide_background(x0, y0, x1, y1);
                    return;
                }
                trace_candidates(x0, y0, x1, y1);
                return;
            }
        }
        if (std::max(w, h) <= kMlrtaMinBeam) {
            trace_rays(x0, y0, x1, y1, e, found == Found::Leaf);
            return;
        }
        // four quarters (two halves of a strip one pixel wide or high)
        const int xm = w > 1 ? x0 + w / 2 : x1, ym = h > 1 ? y0 + h / 2 : y1;
        beam(x0, y0, xm, ym, e);
        if (xm < x1) beam(xm, y0, x1, ym, e);
        if (ym < y1) beam(x0, ym, xm, y1, e);
        if (xm < x1 && ym < y1) beam(xm, ym, x1, y1, e);
    }
};

}  // namespace

void MultiLevelRayTracer::setup(const ScreenScene& scene) {
    m_trace.build(scene, m_trace_options.max_reflections, 0, m_trace_options.accel);
    m_kd = std::make_unique<KdTree>(*m_trace.scene);
    m_pixels.assign(static_cast<size_t>(scene.width) * std::max(scene.height, 0), 0);
    m_mailbox = Mailbox(m_trace.scene->faces().size());
    m_packet_mailbox = PacketMailbox(m_trace.scene->faces().size());
}

void MultiLevelRayTracer::render(const ScreenScene& scene, protocol::CommandSink& sink,
                                 HostStats& stats) {
    const TraceScene& ts = *m_trace.scene;
    const KdTree& kd = *m_kd;
    // the farthest depth of the tree's box: no pixel ray meets a piece beyond it
    double far = 0;
    for (int k = 0; k < 8; ++k) {
        const KdTree::Box& b = kd.bounds();
        far = std::max(far, ts.ray_depth({k & 1 ? b.hi.x : b.lo.x, k & 2 ? b.hi.y : b.lo.y,
                                          k & 4 ? b.hi.z : b.lo.z}));
    }
    far = std::min(far * (1 + 1e-9) + ts.tolerance(), ts.primary_length());
    Frame frame{ts,
                *m_trace.tracer,
                kd,
                m_pixels,
                m_mailbox,
                far,
                kNoFace,
                {},
                m_trace_options.packets ? packet_tracer(m_trace.tracer->kernel_level()) : nullptr,
                m_packet_mailbox,
                {},
                {},
                {},
                {},
                {}};
    Entry root;
    root.at = {0, 0, kd.bounds()};
    for (int y = 0; y < scene.height; y += kMlrtaBeam)
        for (int x = 0; x < scene.width; x += kMlrtaBeam)
            frame.beam(x, y, std::min(x + kMlrtaBeam, scene.width),
                       std::min(y + kMlrtaBeam, scene.height), root);
    uint64_t spans = 0;
    for (int y = 0; y < scene.height; ++y)
        spans += emit_packed_row(&m_pixels[static_cast<size_t>(y) * scene.width], y, 0, scene.width,
                                 sink);
    frame.rays.face_tests += frame.packets.face_tests;
    frame.rays.ties += frame.packets.ties;
    frame.rays.publish(stats.counters);
    const MlrtaBeamCounts& b = frame.beams;
    Counters& c = stats.counters;
    c.add("beams", b.beams);
    c.add("beams_missed", b.beams_missed);
    c.add("beam_nodes_visited", b.nodes);
    c.add("entry_points", b.entry_points);
    c.add("entry_depth_total", b.entry_depth);
    c.add("entry_points_unordered", b.unordered);
    c.add("beams_settled", b.settled);
    c.add("beams_filled", b.filled);
    c.add("pixels_by_beams", b.pixels_by_beams);
    c.add("pixels_by_rays", b.pixels_by_rays);
    c.add("packets", frame.packets.packets);
    c.add("packet_nodes_visited", frame.packets.nodes);
    c.add("spans", spans);
}

}  // namespace fb89::host
