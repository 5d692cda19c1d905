#include "host/trace/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/common.hpp>

namespace fb89::host {

struct RayBvh::Box {
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
    void add(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void add(const Box& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return !(lo.x <= hi.x); }
    double area() const {
        if (empty()) return 0;
        const glm::dvec3 d = hi - lo;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

// What the build knows of a piece: its box and the box's centre.
struct RayBvh::Item {
    Box box;
    glm::dvec3 centre;
    uint32_t piece;
};

namespace {

using Box = RayBvh::Box;
using Item = RayBvh::Item;

constexpr int kBins = 16;

// The bin of a centroid coordinate c in [lo, lo + extent].
int bin_of(double c, double lo, double extent) {
    return std::min(kBins - 1, static_cast<int>((c - lo) / extent * kBins));
}

// Items whose centroid falls in a bin below `bin` on `axis` go to the first child.
struct Split {
    int axis = -1;
    int bin = 0;
    double lo = 0, extent = 0;  // the centroids' range on that axis
    double cost = INFINITY;
};

// The cheapest of kBins - 1 planes per axis through the centroids' range, by the surface
// area heuristic (pieces times area on each side); axis -1 when the centroids coincide.
Split best_split(const std::vector<Item>& items, size_t first, size_t last) {
    Box centres;
    for (size_t i = first; i < last; ++i)
        centres.add(items[i].centre);
    Split best;
    for (int a = 0; a < 3; ++a) {
        const double lo = centres.lo[a], extent = centres.hi[a] - lo;
        if (!(extent > 0)) continue;
        std::array<Box, kBins> bins;
        std::array<size_t, kBins> counts{};
        for (size_t i = first; i < last; ++i) {
            const int b = bin_of(items[i].centre[a], lo, extent);
            bins[b].add(items[i].box);
            ++counts[b];
        }
        // areas and counts to the right of each plane, then sweep from the left
        std::array<double, kBins> right_area{};
        std::array<size_t, kBins> right_count{};
        Box acc;
        size_t n = 0;
        for (int b = kBins - 1; b > 0; --b) {
            acc.add(bins[b]);
            n += counts[b];
            right_area[b] = acc.area();
            right_count[b] = n;
        }
        acc = Box{};
        n = 0;
        for (int b = 1; b < kBins; ++b) {
            acc.add(bins[b - 1]);
            n += counts[b - 1];
            const double cost = acc.area() * static_cast<double>(n) +
                                right_area[b] * static_cast<double>(right_count[b]);
            if (n > 0 && right_count[b] > 0 && cost < best.cost) best = {a, b, lo, extent, cost};
        }
    }
    return best;
}

// The box as floats no smaller than it, padded by `pad`.
void store_box(RayBvh::Node& node, const Box& b, double pad) {
    for (int a = 0; a < 3; ++a) {
        const auto lo = static_cast<float>(b.lo[a] - pad), hi = static_cast<float>(b.hi[a] + pad);
        node.bounds[a] =
            static_cast<double>(lo) > b.lo[a] - pad ? std::nextafter(lo, -INFINITY) : lo;
        node.bounds[3 + a] =
            static_cast<double>(hi) < b.hi[a] + pad ? std::nextafter(hi, INFINITY) : hi;
    }
}

}  // namespace

RayBvh::RayBvh(const TraceScene& scene) {
    const auto& faces = scene.faces();
    if (faces.empty()) return;
    std::vector<Item> items(faces.size());
    double extent = 0;
    for (uint32_t p = 0; p < faces.size(); ++p) {
        const PieceBox& b = scene.box(p);
        items[p].box.lo = b.lo;
        items[p].box.hi = b.hi;
        // the largest coordinate of any vertex: the larger magnitude of the box's two ends
        const glm::dvec3 far = glm::max(glm::abs(b.lo), glm::abs(b.hi));
        extent = std::max({extent, far.x, far.y, far.z});
        items[p].centre = 0.5 * (items[p].box.lo + items[p].box.hi);
        items[p].piece = p;
    }
    for (int y = 0; y < scene.height(); y += std::max(1, scene.height() - 1))
        for (int x = 0; x < scene.width(); x += std::max(1, scene.width() - 1)) {
            const glm::dvec3 o = scene.pixel_ray(x, y).origin;
            extent = std::max({extent, std::abs(o.x), std::abs(o.y), std::abs(o.z)});
        }
    const double pad = kPad * std::max(extent, 1e-30);

    m_depth = build(items, 0, items.size(), 1, pad);
    if (kWide && m_nodes[0].count == 0) collapse(0);
}

uint32_t RayBvh::collapse(uint32_t node) {
    const auto wide = static_cast<uint32_t>(m_wide.size());
    m_wide.emplace_back();
    // the node's children, then again and again the largest inner one opened into its two,
    // until the slots are full or every child is a leaf
    auto area = [&](uint32_t i) {
        const Node& n = m_nodes[i];
        const double dx = double(n.bounds[3]) - n.bounds[0], dy = double(n.bounds[4]) - n.bounds[1],
                     dz = double(n.bounds[5]) - n.bounds[2];
        return dx * dy + dy * dz + dz * dx;
    };
    std::vector<uint32_t> slots = {node + 1, m_nodes[node].index};
    while (slots.size() < static_cast<size_t>(kWidth)) {
        int open = -1;
        for (size_t k = 0; k < slots.size(); ++k)
            if (m_nodes[slots[k]].count == 0 && (open < 0 || area(slots[k]) > area(slots[open])))
                open = static_cast<int>(k);
        if (open < 0) break;
        const uint32_t inner = slots[open];
        slots[open] = inner + 1;
        slots.insert(slots.begin() + open + 1, m_nodes[inner].index);
    }
    WideNode w{};
    for (int k = 0; k < kWidth; ++k) {
        for (int a = 0; a < 3; ++a) {
            w.lo[a][k] = INFINITY;  // an empty slot: a box no ray enters
            w.hi[a][k] = -INFINITY;
        }
        w.child[k] = UINT32_MAX;
    }
    w.used = static_cast<uint32_t>(slots.size());
    for (size_t k = 0; k < slots.size(); ++k) {
        const Node& n = m_nodes[slots[k]];
        for (int a = 0; a < 3; ++a) {
            w.lo[a][k] = n.bounds[a];
            w.hi[a][k] = n.bounds[3 + a];
        }
        w.count[k] = n.count;
        w.child[k] = n.count > 0 ? n.index : 0;  // inner: set below, once collapsed
    }
    m_wide[wide] = w;
    for (size_t k = 0; k < slots.size(); ++k)
        if (m_nodes[slots[k]].count == 0) {
            const uint32_t child = collapse(slots[k]);
            m_wide[wide].child[k] = child;
        }
    return wide;
}

int RayBvh::build(std::vector<Item>& items, size_t first, size_t last, int depth, double pad) {
    // this node, then its first child's subtree right after it, then its second child's
    const auto node = static_cast<uint32_t>(m_nodes.size());
    m_nodes.push_back({});
    Box box;
    for (size_t i = first; i < last; ++i)
        box.add(items[i].box);
    store_box(m_nodes[node], box, pad);
    const size_t count = last - first;
    const Split split =
        count > kMaxLeaf && depth < kMaxDepth ? best_split(items, first, last) : Split{};
    // a leaf when the pieces are few, cannot be told apart, or splitting costs more
    if (split.axis < 0 || split.cost >= box.area() * static_cast<double>(count)) {
        if (count > std::numeric_limits<uint16_t>::max())
            throw std::length_error("RayBvh: more than 65535 pieces in one leaf");
        m_nodes[node].index = static_cast<uint32_t>(m_pieces.size());
        m_nodes[node].count = static_cast<uint16_t>(count);
        for (size_t i = first; i < last; ++i)
            m_pieces.push_back(items[i].piece);
        return depth;
    }
    const auto mid =
        std::partition(items.begin() + static_cast<std::ptrdiff_t>(first),
                       items.begin() + static_cast<std::ptrdiff_t>(last), [&](const Item& it) {
                           return bin_of(it.centre[split.axis], split.lo, split.extent) < split.bin;
                       });
    const auto m = static_cast<size_t>(mid - items.begin());
    m_nodes[node].axis = static_cast<uint16_t>(split.axis);
    const int low = build(items, first, m, depth + 1, pad);
    m_nodes[node].index = static_cast<uint32_t>(m_nodes.size());
    const int high = build(items, m, last, depth + 1, pad);
    return std::max(low, high);
}

}  // namespace fb89::host
