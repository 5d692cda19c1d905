// The ray tracer's bounding volume hierarchy: a binary tree of boxes over the face pieces,
// built top-down by the surface area heuristic over binned centroids (Goldsmith and Salmon
// 1987; the binning of Wald 2007), walked nearer child first with a fixed-size stack.
//
// How ours differs from a renderer's BVH: it must find exactly the piece the watertight
// double-precision test (trace_scene.h) finds nearest, never one less. The boxes are kept
// in float, for small nodes and cheap slab tests, so each is rounded outward and padded by
// kPad of the scene's extent (its largest coordinate, eye included): far more than the
// rounding of a float ray and a float slab test, so a box never misses a ray that reaches
// its pieces. The slab test's exit is widened by a few float ulps as well (Ize 2013). The
// pieces themselves are tested in double, as before. Each piece sits in one leaf, so a ray
// tests a piece at most once and needs no mailbox.
//
// The uniform grid (grid.h) stays for what rays do not do: beam and decahedral volume
// queries scan cells.
//
// On x86-64 the walk runs on an 8-wide tree collapsed from the binary one (each node holds up
// to 8 children's boxes side by side, Wald et al. 2008's multi-BVH), its eight slab tests one
// vector operation each (8 floats: two SSE registers at the baseline level, one AVX register
// at x86-64-v3 and up; kernel_level.h). Every lane computes what the scalar test computes,
// in the same order, so the walk's hits and its node count are the same at every level. The
// period guests keep the binary walk, their portable path.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include <glm/vec3.hpp>

#include "host/trace/trace_scene.h"

namespace fb89::host {

class RayBvh {
  public:
    explicit RayBvh(const TraceScene& scene);

    struct Node {
        float bounds[6];  // the box: its low corner (x, y, z), then its high corner
        uint32_t index;   // a leaf's first entry in pieces(); an inner node's second child
        uint16_t count;   // pieces in a leaf; 0 for an inner node (its first child follows it)
        uint16_t axis;    // an inner node's split axis
    };
    static_assert(sizeof(Node) == 32);
    static float lo(const Node& n, int axis) { return n.bounds[axis]; }
    static float hi(const Node& n, int axis) { return n.bounds[3 + axis]; }

    // The 8-wide tree: each slot a child's box (empty slots hold an inverted box no ray
    // enters), and the child: an inner node's index in wide(), or a leaf's first entry in
    // pieces() and its count.
    static constexpr int kWidth = 8;
    struct alignas(32) WideNode {
        float lo[3][kWidth], hi[3][kWidth];
        uint32_t child[kWidth];
        uint16_t count[kWidth];  // pieces in a leaf slot; 0 for an inner or empty slot
        uint32_t used;           // slots in use: the first `used`, the rest empty
    };
    static_assert(sizeof(WideNode) == 256);
    static constexpr bool kWide =
#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
        true;
#else
        false;
#endif

    const std::vector<Node>& nodes() const {
        return m_nodes;
    }
    const std::vector<WideNode>& wide() const {
        return m_wide;
    }
    const std::vector<uint32_t>& pieces() const {
        return m_pieces;
    }
    // The deepest level from the root (1); the walk's stack is sized for kMaxDepth.
    int depth() const {
        return m_depth;
    }
    static constexpr int kMaxDepth = 64;
    static constexpr size_t kMaxLeaf = 1;  // pieces in a leaf at most, unless they cannot split
    static constexpr double kPad = 1e-5;   // of the scene's extent, around every box

    // A ray as the walk sees it: float origin and reciprocal direction (a component below
    // 1e-30 replaced by 1e-30 of its sign), and per axis which of a box's bounds it meets
    // first (`near`) and last (`far`), by the direction's sign.
    struct FloatRay {
        float origin[3], inv[3];
        uint8_t near[3], far[3];
        explicit FloatRay(const Ray& ray);
    };
    // Where the ray enters a node's box within [t0, t1], or false if it misses it there.
    static bool enters(const Node& n, const FloatRay& r, float t0, float t1, float& t_enter);

    // Walks the leaves whose boxes the ray crosses for tmin < t <= tmax, nearer boxes first;
    // test(piece) tests one piece; best() is the distance of the best hit so far, which
    // prunes boxes entered beyond it. Returns the nodes whose boxes were tested. `Lanes`: the
    // wide walk's vectors, 4 floats (SSE) or 8 (AVX); the same hits and count either way.
    template <int Lanes = 4, class Test, class Best>
    uint64_t walk(const Ray& ray, double tmin, double tmax, Test&& test, Best&& best) const;

    struct Box;
    struct Item;

  private:
    // Makes the node of items [first, last) and its subtrees; returns the deepest level.
    int build(std::vector<Item>& items, size_t first, size_t last, int depth, double pad);
    // The wide node of binary inner node `node`'s subtree; returns its index in m_wide.
    uint32_t collapse(uint32_t node);
    template <class Test, class Best>
    uint64_t walk_binary(const FloatRay& r, float t0, float t1, Test&& test, Best&& best) const;
    template <int Lanes, class Test, class Best>
    uint64_t walk_wide(const FloatRay& r, float t0, float t1, Test&& test, Best&& best) const;

    std::vector<Node> m_nodes;
    std::vector<WideNode> m_wide;
    std::vector<uint32_t> m_pieces;
    int m_depth = 0;
};

// 4 and 8 floats as one value, for the wide walk (GCC's vector extension: each operation
// compiled to the widest registers the calling function's instruction set has)
using Float4 = float __attribute__((vector_size(16)));
using Float8 = float __attribute__((vector_size(32)));
using Int4 = int32_t __attribute__((vector_size(16)));
using Int8 = int32_t __attribute__((vector_size(32)));

// Which of 4 lanes of comparison results are true, as 4 bits (movmskps on x86, the lanes'
// sign bits; lane by lane elsewhere).
inline unsigned lane_bits(Int4 m) {
#if defined(__SSE__)
    return static_cast<unsigned>(__builtin_ia32_movmskps(reinterpret_cast<Float4>(m)));
#else
    unsigned bits = 0;
    for (int k = 0; k < 4; ++k)
        bits |= (m[k] != 0 ? 1u : 0u) << k;
    return bits;
#endif
}

// A distance t >= 0 as a float no smaller than it, and one no larger (for pruning and box
// tests, where a float on the wrong side would lose a hit): the float nearest t is within
// half an ulp of it, so stepping 2^-22 of it outward always lands on the right side.
inline float float_up(double t) {
    if (!(t < 3.0e38)) return INFINITY;
    return static_cast<float>(t) * (1.0f + 0x1p-22f);
}
inline float float_down(double t) {
    return static_cast<float>(t) * (1.0f - 0x1p-22f);
}

inline bool RayBvh::enters(const Node& n, const FloatRay& r, float t0, float t1, float& t_enter) {
    // slabs, near and far planes chosen by the direction's signs; the exit widened by a few
    // ulps for the rounding of the products (Ize 2013)
    constexpr float kWiden = 1.0f + 8.0f * 0x1p-24f;
    for (int a = 0; a < 3; ++a) {
        const float near = (n.bounds[r.near[a]] - r.origin[a]) * r.inv[a];
        const float far = (n.bounds[r.far[a]] - r.origin[a]) * r.inv[a] * kWiden;
        t0 = near > t0 ? near : t0;
        t1 = far < t1 ? far : t1;
    }
    t_enter = t0;
    return t0 <= t1;
}

// The reciprocal in float: its error, a float ulp or two, is far below the boxes' padding.
inline RayBvh::FloatRay::FloatRay(const Ray& ray) {
    for (int a = 0; a < 3; ++a) {
        origin[a] = static_cast<float>(ray.origin[a]);
        const bool negative = std::signbit(ray.dir[a]);
        float d = static_cast<float>(ray.dir[a]);
        if (!(std::abs(d) >= 1e-30f)) d = negative ? -1e-30f : 1e-30f;
        inv[a] = 1.0f / d;
        near[a] = static_cast<uint8_t>(negative ? 3 + a : a);
        far[a] = static_cast<uint8_t>(negative ? a : 3 + a);
    }
}

template <int Lanes, class Test, class Best>
uint64_t RayBvh::walk(const Ray& ray, double tmin, double tmax, Test&& test, Best&& best) const {
    if (m_nodes.empty()) return 0;
    const FloatRay r(ray);
    const float t0 = float_down(tmin), t1 = float_up(tmax);
    float t_enter;
    // the root's box first: a ray that misses the scene costs one test
    if (!enters(m_nodes[0], r, t0, t1, t_enter)) return 1;
    if (m_nodes[0].count > 0) {  // the whole tree one leaf
        for (uint32_t i = m_nodes[0].index; i < m_nodes[0].index + m_nodes[0].count; ++i)
            test(m_pieces[i]);
        return 1;
    }
    if constexpr (kWide)
        return 1 + walk_wide<Lanes>(r, t0, t1, test, best);
    else
        return 1 + walk_binary(r, t0, t1, test, best);
}

template <class Test, class Best>
uint64_t RayBvh::walk_binary(const FloatRay& r, float t0, float t1, Test&& test,
                             Best&& best) const {
    struct Pending {
        uint32_t node;
        float t_enter;
    };
    Pending stack[kMaxDepth];
    int top = 0;
    uint64_t visited = 0;
    uint32_t at = 0;
    for (;;) {
        const Node& n = m_nodes[at];
        if (n.count > 0) {
            // leaf: its pieces
            for (uint32_t i = n.index; i < n.index + n.count; ++i)
                test(m_pieces[i]);
        } else {
            // inner: both children's boxes, the nearer now and the farther later
            const uint32_t a = at + 1, b = n.index;
            const float limit = std::min(t1, float_up(best()));
            float ta, tb;
            const bool hit_a = enters(m_nodes[a], r, t0, limit, ta);
            const bool hit_b = enters(m_nodes[b], r, t0, limit, tb);
            visited += 2;
            if (hit_a && hit_b) {
                const bool a_first = ta <= tb;
                stack[top++] = a_first ? Pending{b, tb} : Pending{a, ta};
                at = a_first ? a : b;
                continue;
            }
            if (hit_a || hit_b) {
                at = hit_a ? a : b;
                continue;
            }
        }
        // the next pending box not entered beyond the best hit found since it was pushed
        for (;;) {
            if (top == 0) return visited;
            const Pending p = stack[--top];
            if (p.t_enter <= float_up(best())) {
                at = p.node;
                break;
            }
        }
    }
}

template <int Lanes, class Test, class Best>
uint64_t RayBvh::walk_wide(const FloatRay& r, float t0, float t1, Test&& test, Best&& best) const {
    // `Lanes` floats as one value, the node's 8 slots in kWidth / Lanes of them: the compiler
    // keeps each in one register of the function's instruction set, lane by lane the same
    // arithmetic as enters()
    static_assert(kWidth % Lanes == 0);
    using fv = std::conditional_t<Lanes == 4, Float4, Float8>;
    using iv = std::conditional_t<Lanes == 4, Int4, Int8>;
    constexpr float kWiden = 1.0f + 8.0f * 0x1p-24f;
    struct Pending {
        uint32_t child;
        uint32_t count;  // pieces of a leaf; 0: an inner node
        float t_enter;
    };
    Pending stack[kMaxDepth * (kWidth - 1) + kWidth];
    int top = 0;
    uint64_t visited = 0;
    uint32_t at = 0;
    // the best hit so far as a float no nearer than it, which changes only when a leaf is
    // tested: kept between leaves at 8 lanes; at 4 (SSE2, each node two halves) worked out
    // again at each use, which measured 9% faster there on the random world (BENCHMARKS.md,
    // round 3, a sixth sitting)
    constexpr bool kKeepBound = Lanes == 8;
    float bound = float_up(best());
    const auto farthest = [&] { return kKeepBound ? bound : float_up(best()); };
    // a leaf: its pieces tested, the bound brought up to the best hit they leave
    const auto test_leaf = [&](uint32_t first, uint32_t count) {
        for (uint32_t i = first; i < first + count; ++i)
            test(m_pieces[i]);
        if constexpr (kKeepBound) bound = float_up(best());
    };
    for (;;) {
        // the node's slots: where the ray enters each box, within [t0, the best hit so far]
        const WideNode& n = m_wide[at];
        const float limit = std::min(t1, farthest());
        constexpr int kChunks = kWidth / Lanes;
        fv tn[kChunks];
        iv hit[kChunks];
        for (int c = 0; c < kChunks; ++c) {
            fv near_t = fv{} + t0, far_t = fv{} + limit;
            for (int a = 0; a < 3; ++a) {
                fv lo, hi;
                std::memcpy(&lo, &n.lo[a][c * Lanes], sizeof lo);
                std::memcpy(&hi, &n.hi[a][c * Lanes], sizeof hi);
                const bool negative = r.near[a] != a;
                const fv near = ((negative ? hi : lo) - r.origin[a]) * r.inv[a];
                const fv far = ((negative ? lo : hi) - r.origin[a]) * r.inv[a] * kWiden;
                near_t = near > near_t ? near : near_t;
                far_t = far < far_t ? far : far_t;
            }
            tn[c] = near_t;
            hit[c] = near_t <= far_t;
        }
        // the entries lane by lane, as a plain array; the hits too, at 8 lanes, and at 4 as
        // bits from movmskps: stored and read back lane by lane, they cost the SSE2 walk 4%
        // on the random world (BENCHMARKS.md, round 3, an eighth sitting); at 8 lanes the
        // bits measured no better
        float t_at[kWidth];
        int32_t hit_at[kWidth];
        unsigned hit_bits = 0;
        for (int c = 0; c < kChunks; ++c) {
            std::memcpy(&t_at[c * Lanes], &tn[c], sizeof tn[c]);
            if constexpr (Lanes == 4)
                hit_bits |= lane_bits(hit[c]) << (c * Lanes);
            else
                std::memcpy(&hit_at[c * Lanes], &hit[c], sizeof hit[c]);
        }
        // the boxes entered, farthest first (of equal entries, the higher slot last)
        unsigned order[kWidth];
        int hits = 0;
        visited += n.used;
        for (unsigned k = 0; k < kWidth; ++k) {
            if constexpr (Lanes == 4) {
                if (!(hit_bits >> k & 1u)) continue;
            } else {
                if (!hit_at[k]) continue;
            }
            int i = hits++;
            const float t = t_at[k];
            while (i > 0 && t_at[order[i - 1]] < t) {
                order[i] = order[i - 1];
                --i;
            }
            order[i] = k;
        }
        // all but the nearest pushed; the nearest taken at once, with no pop and no test
        // against the bound: it was entered within the bound, which holds (no leaf tested
        // since). Pushed and popped, it cost the random world 6-10% at 8 lanes (BENCHMARKS.md,
        // round 3, a seventh sitting).
        for (int i = 0; i + 1 < hits; ++i) {
            const unsigned k = order[i];
            stack[top++] = Pending{n.child[k], n.count[k], t_at[k]};
            // an inner node's first cache line asked for now, to be in cache when it is
            // popped: 1-4.5% at baseline (BENCHMARKS.md, round 3, an eighth sitting)
            if (n.count[k] == 0) __builtin_prefetch(&m_wide[n.child[k]]);
        }
        if (hits > 0) {
            const unsigned k = order[hits - 1];
            if (n.count[k] == 0) {
                at = n.child[k];
                continue;
            }
            test_leaf(n.child[k], n.count[k]);
        }
        // the next pending box not entered beyond the best hit found since it was pushed:
        // a leaf's pieces are tested, an inner node's slots next
        for (;;) {
            if (top == 0) return visited;
            const Pending& p = stack[--top];
            if (!(p.t_enter <= farthest())) continue;
            const uint32_t child = p.child, count = p.count;
            if (count == 0) {
                at = child;
                break;
            }
            test_leaf(child, count);
        }
    }
}

}  // namespace fb89::host
