// The kd-tree multi-level ray tracing walks (mlrta.h), and rays with `--accel kd`: axis-aligned
// planes cut the scene's box in two, again and again, each plane placed by the surface area
// heuristic over the pieces' box edges (MacDonald and Booth 1990; the O(n log² n) sweep of
// Wald and Havran 2006), with the empty-space bonus; a leaf lists every piece whose box
// touches it. A ray walks it front to back with a stack (Havran's TA_B-rec, 2000).
//
// How ours differs from a renderer's kd-tree: it must find exactly the piece the watertight
// double-precision test (trace_scene.h) finds nearest. Planes and boxes are kept in double, and
// each piece is listed by its box grown by the scene's tolerance (a billionth of its size, far
// more than the rounding of a ray's plane distances), so a hit near a plane is in the lists of
// the cells on both sides of it; a walk stops after a leaf only when its best hit lies no
// farther than the leaf's exit, as the grid's does. Pieces are not clipped to the cells (no
// "perfect splits"): a piece is listed in a few more leaves than it touches.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "host/trace/trace_scene.h"

namespace fb89::host {

class KdTree {
  public:
    explicit KdTree(const TraceScene& scene);

    static constexpr uint8_t kLeaf = 3;
    struct Node {
        double split = 0;    // an inner node's plane: axis coordinate
        uint32_t index = 0;  // an inner node's upper child (its lower child follows it); a
                             // leaf's first entry in pieces()
        uint32_t count = 0;  // a leaf's pieces
        uint8_t axis = kLeaf;
        bool leaf() const { return axis == kLeaf; }
    };
    struct Box {
        glm::dvec3 lo, hi;
    };
    // The two halves of `box` a node's plane makes.
    static Box lower(const Box& box, const Node& node) {
        Box b = box;
        b.hi[node.axis] = node.split;
        return b;
    }
    static Box upper(const Box& box, const Node& node) {
        Box b = box;
        b.lo[node.axis] = node.split;
        return b;
    }

    const std::vector<Node>& nodes() const { return m_nodes; }
    std::span<const uint32_t> leaf_pieces(const Node& leaf) const {
        return {m_pieces.data() + leaf.index, leaf.count};
    }
    const Box& bounds() const { return m_bounds; }  // the root's box
    int depth() const { return m_depth; }           // the deepest leaf's (the root's is 0)
    uint64_t entries() const { return m_pieces.size(); }

    // The tree's deepest level, and so a walk's stack.
    static constexpr int kMaxDepth = 40;

    // The part of the ray's [t0, t1] inside `box`; false when none.
    static bool clip(const Ray& ray, const glm::dvec3& inv, const Box& box, double& t0, double& t1);

    // Walks the subtree under `node` (whose box the ray crosses in [t0, t1]) front to back:
    // `test(pieces)` for each leaf met, then `done(t)` with t where the ray leaves that leaf;
    // true from it stops. Returns whether a `done` stopped it; counts the nodes visited.
    template <class Test, class Done>
    bool walk(const Ray& ray, const glm::dvec3& inv, uint32_t node, double t0, double t1,
              Test&& test, Done&& done, uint64_t& visited) const;

  private:
    struct Build;
    std::vector<Node> m_nodes;
    std::vector<uint32_t> m_pieces;
    Box m_bounds;
    int m_depth = 0;
};

// 1 / d per axis (infinity for 0), as the walks take it.
inline glm::dvec3 inverse_direction(const Ray& ray) {
    return {1.0 / ray.dir.x, 1.0 / ray.dir.y, 1.0 / ray.dir.z};
}

inline bool KdTree::clip(const Ray& ray, const glm::dvec3& inv, const Box& box, double& t0,
                         double& t1) {
    for (int a = 0; a < 3; ++a) {
        if (ray.dir[a] == 0) {
            if (ray.origin[a] < box.lo[a] || ray.origin[a] > box.hi[a]) return false;
            continue;
        }
        double ta = (box.lo[a] - ray.origin[a]) * inv[a], tb = (box.hi[a] - ray.origin[a]) * inv[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
    }
    return t0 <= t1;
}

template <class Test, class Done>
bool KdTree::walk(const Ray& ray, const glm::dvec3& inv, uint32_t node, double t0, double t1,
                  Test&& test, Done&& done, uint64_t& visited) const {
    struct Pending {
        uint32_t node;
        double t0, t1;
    };
    Pending stack[kMaxDepth + 1];
    int top = 0;
    uint32_t n = node;
    for (;;) {
        ++visited;
        const Node& nd = m_nodes[n];
        if (nd.leaf()) {
            test(leaf_pieces(nd));
            if (done(t1)) return true;
            if (top == 0) return false;
            --top;
            n = stack[top].node;
            t0 = stack[top].t0;
            t1 = stack[top].t1;
            continue;
        }
        const int a = nd.axis;
        const double o = ray.origin[a], d = ray.dir[a];
        // the near child holds the origin (on the plane: the side the ray runs into)
        const bool below = o < nd.split || (o == nd.split && d <= 0);
        const uint32_t near = below ? n + 1 : nd.index, far = below ? nd.index : n + 1;
        if (d == 0) {
            n = near;
            continue;
        }
        const double ts = (nd.split - o) * inv[a];
        if (ts >= t1 || ts <= 0) {
            n = near;  // the ray leaves the node, or runs away from the plane, before it
        } else if (ts <= t0) {
            n = far;  // the ray meets the plane before it enters the node
        } else {
            stack[top++] = {far, ts, t1};
            n = near;
            t1 = ts;
        }
    }
}

}  // namespace fb89::host
