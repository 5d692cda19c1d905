// The `mlrta` method: multi-level ray tracing after Reshetov, Soupikov and Hurley, "Multi-Level
// Ray Tracing Algorithm" (SIGGRAPH 2005), the successor of §4's beam-ray hybrid. A beam of
// primary rays -- a tile of pixels, bounded by the rays through its corner pixels -- walks the
// kd-tree (kd_tree.h) once for all of its rays, to the first leaf holding pieces that it may
// enter: the entry point. Every ray of the beam then starts there instead of at the root,
// with the beam's list of the cells it put off for later. A beam that still has cells put off
// splits into four, each quarter going on from its parent's entry point, down to the smallest
// beam. A beam decides its pixels without a ray when it enters no piece's leaf (background),
// or when the only piece of its entry leaf it meets covers it: every corner ray hits that
// piece inside the leaf, well inside its edges (then every ray of the tile does, and nothing
// can lie nearer). A beam whose entry leaf is the only cell holding pieces it enters
// (settled) has its rays test that leaf's pieces alone, without a walk.
// A beam's rays go in packets of eight (ray_packet.h, a 4 x 2 block of pixels each): a packet
// walks the kd-tree from the beam's entry point with each lane's own interval, and tests a
// leaf's pieces on all its lanes at once, as many lanes an instruction as the CPU holds
// doubles (8 with AVX-512, 4 with AVX2, 2 with SSE2; kernel_level.h picks the level). The
// entry leaf's pieces are culled against the beam first (inverse frustum culling): a piece
// whose box lies outside the beam's hull is never tested by its rays. With
// TraceOptions::packets off (`--packets off`) every ray goes alone, scalar, from the entry
// point: what a machine without SIMD does better (docs/RESULTS.md).
// Mirrors are followed as the ray tracer follows them: a reflected ray is one ray, not a
// beam's, and goes through the ray tracer's own structure (its BVH, or with `--accel kd` the
// kd-tree from its root). Every pixel shows what `raytrace` shows
// (tests/host/trace/mlrta_test.cpp).
//
// Why the entry point is exact: every pixel ray of a tile lies in the convex hull of its
// corner rays between the near plane and the scene's farthest depth (a pixel's direction is
// bilinear in its position), so a cell whose box lies outside that hull (a separating plane
// of the hull or its box) is entered by none of them, and a plane whose side holds every
// corner ray's start holds every ray's start: the nearer child is nearer for all of them, and
// the beam's order of cells is each ray's front-to-back order. A ray skips a cell it does not
// cross; it stops when its best hit lies no farther than where it leaves the leaf tested. A
// covered tile's tests are linear over its rays (the edge functions det(p - o, q - o, d), the
// side and the hit point, which a pixel's ray makes as the same blend of the corners'), each
// asked with a margin far above the rounding of the watertight test.
//
// How ours differs from the paper's: beams are tiles that split in four (the paper's beams
// split where they must); the entry point is the first leaf holding pieces, never an inner
// node except where a plane cuts the tile's starts; a packet is eight rays in double, with the
// watertight test on every lane (the paper's are four rays in float); only primary rays go by
// beams and packets (a reflected ray goes alone).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "host/raster/renderer.h"
#include "host/trace/ray_packet.h"
#include "host/trace/ray_tracer.h"

namespace fb89::host {

// The first beams' side in pixels, and the smallest beam's: a beam no larger traces its rays.
inline constexpr int kMlrtaBeam = 32, kMlrtaMinBeam = 16;

class MultiLevelRayTracer final : public Renderer {
  public:
    explicit MultiLevelRayTracer(TraceOptions trace = {}) : m_trace_options(trace) {}
    std::string_view name() const override { return "mlrta"; }
    void setup(const ScreenScene& scene) override;
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;

  private:
    TraceOptions m_trace_options;
    TraceSetup m_trace;              // the scene, and the ray tracer mirrors' rays go through
    std::unique_ptr<KdTree> m_kd;    // the beams' and primary rays' tree
    std::vector<uint32_t> m_pixels;  // packed_pixel() per pixel, row by row
    Mailbox m_mailbox;
    PacketMailbox m_packet_mailbox;
};

}  // namespace fb89::host
