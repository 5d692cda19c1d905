#include "host/trace/kd_tree.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "host/trace/grid.h"

namespace fb89::host {

namespace {

// The surface area heuristic's costs: a step through a node against one ray-piece test (the
// watertight test in double, several times a plane step), and the bonus for cutting off
// empty space (a fifth off, as Wald and Havran take it).
constexpr double kStepCost = 1, kTestCost = 8, kEmptyBonus = 0.8;
// Splits that cost more than a leaf taken in a row, at most.
constexpr int kBadRefines = 3;
// Planes tried besides the pieces' box edges: this many evenly spaced, less one, an axis.
constexpr int kEvenPlanes = 16;

double area(const KdTree::Box& b) {
    const glm::dvec3 e = b.hi - b.lo;
    return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

}  // namespace

struct KdTree::Build {
    KdTree& tree;
    const TraceScene& scene;
    double pad = 0;  // the scene's tolerance
    int max_depth = 0;
    std::vector<double> los, his;           // scratch for one axis
    std::vector<glm::dvec3> poly, clipped;  // scratch for one piece
    // The two children's pieces and their boxes, one set for each depth, kept from node to
    // node: a node fills its depth's, and the child reads them as its own, so the build
    // allocates only while a depth's lists grow (not four lists for every node).
    struct Halves {
        std::vector<uint32_t> left, right;
        std::vector<Box> left_boxes, right_boxes;
    };
    std::vector<Halves> halves;  // max_depth + 1 of them, never resized during the build

    // The box of the part of piece p inside `cell` grown by the tolerance, itself grown by
    // the tolerance; false when no part is inside. (Havran's "perfect splits": the pieces
    // are clipped to every cell, so a slanted face is listed only where it passes.)
    bool clip_box(uint32_t p, const Box& cell, Box& out) {
        const TraceFace& f = scene.faces()[p];
        const glm::dvec3* v = scene.vertices_of(f);
        poly.assign(v, v + f.vertex_count);
        for (int a = 0; a < 3 && !poly.empty(); ++a)
            for (int side = 0; side < 2 && !poly.empty(); ++side) {
                const double bound = side == 0 ? cell.lo[a] - pad : cell.hi[a] + pad;
                // signed: >= 0 inside
                auto inside = [&](const glm::dvec3& q) {
                    return side == 0 ? q[a] - bound : bound - q[a];
                };
                clipped.clear();
                for (size_t i = 0; i < poly.size(); ++i) {
                    const glm::dvec3& q0 = poly[i];
                    const glm::dvec3& q1 = poly[(i + 1) % poly.size()];
                    const double d0 = inside(q0), d1 = inside(q1);
                    if (d0 >= 0) clipped.push_back(q0);
                    if ((d0 >= 0) != (d1 >= 0)) {
                        glm::dvec3 x = q0 + (q1 - q0) * (d0 / (d0 - d1));
                        x[a] = bound;  // on the plane exactly
                        clipped.push_back(x);
                    }
                }
                poly.swap(clipped);
            }
        if (poly.empty()) return false;
        out.lo = glm::dvec3(INFINITY);
        out.hi = glm::dvec3(-INFINITY);
        for (const glm::dvec3& q : poly) {
            out.lo = glm::min(out.lo, q);
            out.hi = glm::max(out.hi, q);
        }
        out.lo -= pad;
        out.hi += pad;
        return true;
    }

    // A leaf or an inner node for `items` (with their boxes inside it, clip_box's) inside
    // `box`, at `index` (already in nodes); `bad`: splits taken in a row that cost more.
    void node(uint32_t index, const std::vector<uint32_t>& items, const std::vector<Box>& boxes,
              const Box& box, int depth, int bad) {
        tree.m_depth = std::max(tree.m_depth, depth);
        const double n = static_cast<double>(items.size());
        const double leaf_cost = kTestCost * n;
        double best_cost = INFINITY, best_split = 0;
        int best_axis = -1;
        if (items.size() > 1 && depth < max_depth) {
            const double whole = area(box);
            for (int a = 0; a < 3; ++a) {
                los.clear();
                his.clear();
                for (const Box& b : boxes) {
                    los.push_back(b.lo[a]);
                    his.push_back(b.hi[a]);
                }
                std::sort(los.begin(), los.end());
                std::sort(his.begin(), his.end());
                // every box edge strictly inside the node is a candidate plane; left of it
                // the pieces starting below it, right of it those ending above it
                auto consider = [&](double p) {
                    if (!(p > box.lo[a] && p < box.hi[a])) return;
                    const double left = static_cast<double>(
                        std::lower_bound(los.begin(), los.end(), p) - los.begin());
                    const double right = static_cast<double>(
                        his.end() - std::upper_bound(his.begin(), his.end(), p));
                    Box l = box, r = box;
                    l.hi[a] = p;
                    r.lo[a] = p;
                    double cost =
                        kStepCost + kTestCost * (area(l) * left + area(r) * right) / whole;
                    if (left == 0 || right == 0) cost *= kEmptyBonus;
                    if (cost < best_cost) {
                        best_cost = cost;
                        best_axis = a;
                        best_split = p;
                    }
                };
                double last = NAN;
                for (double p : los)
                    if (p != last) consider(last = p);
                last = NAN;
                for (double p : his)
                    if (p != last) consider(last = p);
                // and planes evenly spaced across the node: they cut off the empty space of a
                // room whose walls' edges all lie on its outline
                for (int k = 1; k < kEvenPlanes; ++k)
                    consider(box.lo[a] + (box.hi[a] - box.lo[a]) * k / kEvenPlanes);
            }
        }
        // a split that costs more than the leaf is taken a few times in a row (pbrt's "bad
        // refines"): deeper down, the pieces clipped to smaller cells may part
        if (best_cost >= leaf_cost) ++bad;
        Node& here = tree.m_nodes[index];
        if (best_axis < 0 || bad > kBadRefines) {
            here.axis = kLeaf;
            here.index = static_cast<uint32_t>(tree.m_pieces.size());
            here.count = static_cast<uint32_t>(items.size());
            tree.m_pieces.insert(tree.m_pieces.end(), items.begin(), items.end());
            return;
        }
        here.axis = static_cast<uint8_t>(best_axis);
        here.split = best_split;
        Box lb = box, rb = box;
        lb.hi[best_axis] = best_split;
        rb.lo[best_axis] = best_split;
        Halves& h = halves[static_cast<size_t>(depth)];
        h.left.clear();
        h.right.clear();
        h.left_boxes.clear();
        h.right_boxes.clear();
        Box clipped_box;
        for (size_t k = 0; k < items.size(); ++k) {
            if (boxes[k].lo[best_axis] < best_split && clip_box(items[k], lb, clipped_box)) {
                h.left.push_back(items[k]);
                h.left_boxes.push_back(clipped_box);
            }
            if (boxes[k].hi[best_axis] > best_split && clip_box(items[k], rb, clipped_box)) {
                h.right.push_back(items[k]);
                h.right_boxes.push_back(clipped_box);
            }
        }
        const uint32_t lower_index = static_cast<uint32_t>(tree.m_nodes.size());
        tree.m_nodes.emplace_back();
        node(lower_index, h.left, h.left_boxes, lb, depth + 1, bad);
        const uint32_t upper_index = static_cast<uint32_t>(tree.m_nodes.size());
        tree.m_nodes[index].index = upper_index;  // `here` may have moved
        tree.m_nodes.emplace_back();
        node(upper_index, h.right, h.right_boxes, rb, depth + 1, bad);
    }
};

KdTree::KdTree(const TraceScene& scene) {
    const PieceBox all = box_around_pieces(scene);
    m_bounds = {all.lo, all.hi};
    Build build{*this, scene, scene.tolerance(), 0, {}, {}, {}, {}, {}};
    std::vector<uint32_t> items;
    std::vector<Box> boxes;
    for (uint32_t p = 0; p < scene.faces().size(); ++p) {
        const PieceBox& b = scene.box(p);
        items.push_back(p);
        boxes.push_back({b.lo - build.pad, b.hi + build.pad});
    }
    const double n = static_cast<double>(std::max<size_t>(items.size(), 1));
    build.max_depth = std::min(kMaxDepth, static_cast<int>(12 + 1.3 * std::log2(n)));
    build.halves.resize(static_cast<size_t>(build.max_depth) + 1);
    m_nodes.emplace_back();
    build.node(0, items, boxes, m_bounds, 0, 0);
}

}  // namespace fb89::host
