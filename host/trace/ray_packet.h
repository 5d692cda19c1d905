// Packets of rays for multi-level ray tracing (mlrta.h), as Reshetov, Soupikov and Hurley
// trace a beam's rays: eight primary rays of a tile (a 4 x 2 block of pixels) walk the kd-tree
// together from the beam's entry point, each instruction working on all eight lanes, and test
// a leaf's pieces against all of them at once.
//
// Exact, lane by lane: each lane computes what the scalar walk and the watertight test
// (kd_tree.h, trace_scene.h) compute for its ray, in the same double operations in the same
// order (fb89 builds with -ffp-contract=off), so every lane finds the piece its ray finds
// alone:
//   - a lane keeps its own interval [t0, t1] at every node, as its ray does, and leaves a
//     subtree its ray would not enter;
//   - where the lanes' starts lie on both sides of a node's plane (their near children
//     differ) each side's lanes walk the node's subtree on their own, in their own order;
//   - a lane stops after a leaf when its best hit lies no farther than where it leaves the
//     leaf, as its ray does; the others go on;
//   - a piece listed in several leaves is tested once for each lane (a mailbox of lane masks).
// Where the watertight test's space differs between lanes (the axis a ray runs along most, or
// its sign) the packet is not formed; the caller traces those rays one by one.
//
// The width is eight lanes of double at every level; the instruction set (kernel_level.h)
// decides how many lanes an instruction holds: eight with AVX-512, four with AVX2, two with
// SSE2, one on the period guests (the compiler writes the lanes out one by one).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "host/trace/kd_tree.h"
#include "host/trace/kernel_level.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {

inline constexpr int kPacketRays = 8;

// Eight rays, structure of arrays, one a lane; `lanes` says which lanes hold one (bit i).
struct RayPacket {
    alignas(64) double origin[3][kPacketRays];
    alignas(64) double dir[3][kPacketRays];
    alignas(64) double tmin[kPacketRays];  // a hit counts at t > tmin
    alignas(64) double skip[kPacketRays];  // a piece the ray never sees, or kNoFace
    int kx = 0, ky = 1, kz = 2;  // RaySpace's axes, the same for every lane (the kernel works
                                 // out each lane's shear and 1 / d, eight at a time)
    uint32_t lanes = 0;

    // Puts `ray` in lane i; false (the lane left empty) when its RaySpace's axes differ from
    // those of the lanes already set.
    bool set(int i, const Ray& ray, double least = 0, uint32_t never = kNoFace);
    // Gives each empty lane a copy of a set lane's ray (at least one must be set): the kernel
    // works on every lane, and a lane left unset might hold a denormal that slows the others.
    void fill_empty_lanes();
};

inline bool RayPacket::set(int i, const Ray& ray, double least, uint32_t never) {
    int x, y, z;
    RaySpace::axes(ray.dir, x, y, z);
    if (lanes == 0) {
        kx = x;
        ky = y;
        kz = z;
    } else if (x != kx || y != ky || z != kz) {
        return false;
    }
    for (int k = 0; k < 3; ++k) {
        origin[k][i] = ray.origin[k];
        dir[k][i] = ray.dir[k];
    }
    tmin[i] = least;
    skip[i] = never;
    lanes |= 1u << i;
    return true;
}

// A cell the packet's rays start from: the beam's entry point, or a cell it put off.
struct PacketCell {
    uint32_t node;
    KdTree::Box box;
};

// What a packet's lanes found: lane i's nearest piece (kNoFace for none) and its t.
struct PacketHits {
    alignas(64) double t[kPacketRays];
    alignas(64) int64_t piece[kPacketRays];
};

struct PacketCounts {
    uint64_t packets = 0;     // packets traced
    uint64_t nodes = 0;       // kd-tree nodes visited by a packet (once for all its lanes)
    uint64_t face_tests = 0;  // ray-piece tests: a piece tested on k lanes counts k
    uint64_t ties = 0;        // as TraceCounts::ties, a lane each
};

// The packets' mailbox: per piece, the lanes of this packet that have tested it.
class PacketMailbox {
  public:
    explicit PacketMailbox(size_t pieces = 0) : m_seen(pieces) {}
    // A new packet: every piece untested on every lane.
    void begin();
    // The lanes of `lanes` that have not tested `piece` yet; marks them tested.
    uint32_t fresh(uint32_t piece, uint32_t lanes) {
        Seen& s = m_seen[piece];
        if (s.serial != m_serial) {
            s = {m_serial, lanes};
            return lanes;
        }
        const uint32_t out = lanes & ~s.lanes;
        s.lanes |= out;
        return out;
    }

  private:
    struct Seen {
        uint32_t serial = 0, lanes = 0;
    };
    std::vector<Seen> m_seen;
    uint32_t m_serial = 0;
};

// Traces a packet's lanes from `cells` (the walk's order: the entry point first, then the
// cells put off, nearest first), each lane from its tmin to `tmax`.
// `hint`, when set, is tested first on every lane (it only orders the tests). The entry
// leaf's pieces are `entry_pieces` when `entry_leaf` is that leaf's node (the beam has culled
// them: a piece no ray of the beam can meet is left out); with `cells` empty the lanes test
// `entry_pieces` alone (a settled beam: no walk).
struct PacketQuery {
    std::span<const PacketCell> cells;
    uint32_t entry_leaf = UINT32_MAX;
    std::span<const uint32_t> entry_pieces;
    uint32_t hint = kNoFace;
    double tmax = INFINITY;  // the lanes' greatest t (a primary ray's: the far plane)
};
using PacketTracer = void (*)(const TraceScene& scene, const KdTree& kd, const RayPacket& packet,
                              const PacketQuery& query, PacketMailbox& mailbox, PacketHits& hits,
                              PacketCounts& counts);
// The tracer for a kernel level (compiled for its instruction set).
PacketTracer packet_tracer(KernelLevel level);

}  // namespace fb89::host
