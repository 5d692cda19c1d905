#include "host/radiosity/hierarchical.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "host/radiosity/exact.h"
#include "host/radiosity/shaft.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {

namespace {

constexpr int kMaxDepth = 24;  // below this a node is not split, whatever its area

struct Link {
    uint32_t source = 0;
    double factor = 0;  // F_pq times the visibility: the share of p's light that q gives
};

struct HierarchyNode {
    uint32_t root = 0;  // the input element
    int depth = 0;
    double s0 = 0, s1 = 1, t0 = 0, t1 = 1;
    Patch shape;               // corners, area, centre
    double radius = 0;         // centre to the farthest corner
    PieceBox box{};            // its corners' bounding box
    uint32_t first_child = 0;  // children are contiguous
    uint32_t children = 0;     // 0, 2 or 4
    glm::dvec3 radiosity{0};   // the area average of its leaves'
    glm::dvec3 gathered{0};    // ρ Σ links, this sweep
    std::vector<Link> links;   // what this node gathers from
};

// A van der Corput radical inverse: the Halton sequence's coordinate in base `base`.
double radical_inverse(uint32_t i, uint32_t base) {
    double inverse = 1.0 / base, f = inverse, r = 0;
    for (; i > 0; i /= base, f *= inverse)
        r += f * static_cast<double>(i % base);
    return r;
}

// A per-link rotation in [0, 1), so that links do not all sample the same points.
double rotation(uint32_t p, uint32_t q, uint32_t salt) {
    uint64_t h = (static_cast<uint64_t>(p) << 32 | q) * 0x9E3779B97F4A7C15ull + salt;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

class Hierarchy {
  public:
    Hierarchy(const Mesh& mesh, const RadiosityWorld& world, const HierarchicalOptions& o)
        : m_mesh(mesh), m_options(o), m_rays(mesh, world), m_scene(world.scene) {
        // a shaft's slack: what the segment query trims off its ends, and rounding
        m_slack = 8 * world.scene.tolerance();
        for (const Element& e : mesh.elements)
            m_max_emission = std::max(m_max_emission, max_component(e.emission));
        for (uint32_t e = 0; e < mesh.elements.size(); ++e) {
            HierarchyNode n;
            n.root = e;
            set_region(n);
            n.radiosity = mesh.elements[e].emission;
            if (n.shape.area > 0) m_nodes.push_back(std::move(n));
        }
        m_roots = static_cast<uint32_t>(m_nodes.size());
        counts.roots = m_roots;
    }

    // Every ordered pair of roots, refined from the top.
    void link_roots(const WorkObserver& work) {
        for (uint32_t p = 0; p < m_roots; ++p) {
            for (uint32_t q = 0; q < m_roots; ++q)
                if (p != q) refine(p, q, nullptr);
            if (work) work(p + 1, m_roots);
        }
    }

    // Judges every link again with the current radiosities; true when any was split.
    bool rerefine() {
        bool split = false;
        const auto count = static_cast<uint32_t>(m_nodes.size());
        for (uint32_t p = 0; p < count; ++p) {
            std::vector<Link> links = std::move(m_nodes[p].links);
            m_nodes[p].links.clear();
            m_link_count -= links.size();
            const uint64_t before = counts.refinements;
            for (const Link& l : links)
                refine(p, l.source, &l);
            split |= counts.refinements != before;
        }
        return split;
    }

    // Gather and push-pull until the leaves settle; returns whether they did.
    bool solve(RadiositySolution& solution) {
        const double limit = m_options.tolerance * m_max_emission;
        for (int it = 0; it < m_options.max_iterations; ++it) {
            for (HierarchyNode& n : m_nodes) {
                glm::dvec3 sum{0};
                for (const Link& l : n.links)
                    sum += l.factor * m_nodes[l.source].radiosity;
                n.gathered = m_mesh.elements[n.root].reflectance * sum;
            }
            double change = 0;
            for (uint32_t r = 0; r < m_roots; ++r)
                push_pull(r, glm::dvec3(0), change);
            ++counts.solve_iterations;
            ++solution.iterations;
            solution.residual = m_max_emission > 0 ? change / m_max_emission : 0;
            if (change <= limit) return true;
        }
        return false;
    }

    void finish(HierarchicalResult& out) {
        counts.nodes = m_nodes.size();
        counts.links = m_link_count;
        for (uint32_t r = 0; r < m_roots; ++r)
            collect(r, 0, out);
        counts.leaves = out.leaves.patches.size();
        out.counts = counts;
    }

    HierarchicalCounts counts;
    bool budget_hit() const { return counts.budget_hit; }

  private:
    void set_region(HierarchyNode& n) const {
        n.shape.element = n.root;
        n.shape.corners = region_corners(m_mesh.elements[n.root], n.s0, n.s1, n.t0, n.t1);
        set_shape(n.shape);
        n.radius = 0;
        n.box = {n.shape.corners[0], n.shape.corners[0]};
        for (int k = 0; k < n.shape.corner_count; ++k) {
            const glm::dvec3& c = n.shape.corners[k];
            n.radius = std::max(n.radius, glm::length(c - n.shape.centre));
            n.box.lo = glm::min(n.box.lo, c);
            n.box.hi = glm::max(n.box.hi, c);
        }
    }

    // Whether no piece but the two nodes' own meets the shaft between them: then no segment
    // between them is blocked, and the link needs no rays.
    bool shaft_clear(const HierarchyNode& a, uint32_t skip_a, const HierarchyNode& b,
                     uint32_t skip_b) {
        ++counts.shafts;
        const Shaft shaft(a.box, b.box);
        const auto pieces = static_cast<uint32_t>(m_scene.faces().size());
        for (uint32_t piece = 0; piece < pieces; ++piece) {
            if (piece == skip_a || piece == skip_b) continue;
            ++counts.shaft_tests;
            if (shaft.may_meet(m_scene.box(piece), m_slack)) return false;
        }
        ++counts.shafts_clear;
        return true;
    }

    std::vector<glm::dvec3> polygon(const HierarchyNode& n) const {
        return {n.shape.corners.begin(), n.shape.corners.begin() + n.shape.corner_count};
    }

    // Whether any part of q lies in front of p's plane and any part of p in front of q's.
    bool exchange(const HierarchyNode& p, const HierarchyNode& q) const {
        const Element& ep = m_mesh.elements[p.root];
        const Element& eq = m_mesh.elements[q.root];
        auto some_in_front = [](const Element& e, const HierarchyNode& n) {
            for (int k = 0; k < n.shape.corner_count; ++k)
                if (in_front(e, n.shape.corners[k])) return true;
            return in_front(e, n.shape.centre);
        };
        return some_in_front(ep, q) && some_in_front(eq, p);
    }

    // The oracle's unoccluded estimate of F_pq, never below the truth by much: the disk form
    // between centres with each cosine raised by the angle the two nodes' extents subtend.
    double estimate(const HierarchyNode& p, const HierarchyNode& q) const {
        const glm::dvec3 r = q.shape.centre - p.shape.centre;
        const double d = glm::length(r);
        if (d <= p.radius + q.radius) return 1;  // close: anything is possible
        const double slack = (p.radius + q.radius) / d;
        const double cp =
            std::clamp(glm::dot(m_mesh.elements[p.root].normal, r) / d + slack, 0.0, 1.0);
        const double cq =
            std::clamp(-glm::dot(m_mesh.elements[q.root].normal, r) / d + slack, 0.0, 1.0);
        return std::min(1.0, q.shape.area * cp * cq / (std::numbers::pi * d * d + q.shape.area));
    }

    bool can_split(uint32_t n) {
        const HierarchyNode& node = m_nodes[n];
        if (node.children > 0) return true;
        if (node.depth >= kMaxDepth || node.shape.area <= m_options.min_area) return false;
        if (m_nodes.size() + 4 > m_options.max_nodes || m_link_count >= m_options.max_links) {
            counts.budget_hit = true;
            return false;
        }
        split(n);
        return true;
    }

    // Two children across the long side of a long node, else four.
    void split(uint32_t n) {
        const auto& c = m_nodes[n].shape.corners;
        const double along_s = std::max(glm::length(c[1] - c[0]), glm::length(c[2] - c[3]));
        const double along_t = std::max(glm::length(c[3] - c[0]), glm::length(c[2] - c[1]));
        const int ns = along_t > 2 * along_s ? 1 : 2;
        const int nt = along_s > 2 * along_t ? 1 : 2;
        const HierarchyNode& node = m_nodes[n];
        const uint32_t root = node.root;
        const int depth = node.depth + 1;
        const double s0 = node.s0, t0 = node.t0;
        const double ds = (node.s1 - node.s0) / ns, dt = (node.t1 - node.t0) / nt;
        const double s1 = node.s1, t1 = node.t1;
        const glm::dvec3 radiosity = node.radiosity;
        m_nodes[n].first_child = static_cast<uint32_t>(m_nodes.size());
        m_nodes[n].children = static_cast<uint32_t>(ns * nt);
        for (int j = 0; j < nt; ++j)
            for (int i = 0; i < ns; ++i) {
                HierarchyNode child;
                child.root = root;
                child.depth = depth;
                child.s0 = s0 + i * ds;
                child.s1 = i + 1 == ns ? s1 : child.s0 + ds;
                child.t0 = t0 + j * dt;
                child.t1 = j + 1 == nt ? t1 : child.t0 + dt;
                set_region(child);
                child.radiosity = radiosity;
                m_nodes.push_back(std::move(child));
            }
    }

    // Refine(p, q) of Hanrahan et al.: link here, or split the larger and refine its children.
    // `existing` is the link already made at this level (kept as it is when the oracle passes).
    void refine(uint32_t p, uint32_t q, const Link* existing) {
        if (!exchange(m_nodes[p], m_nodes[q])) return;
        ++counts.oracle_calls;
        const double f = estimate(m_nodes[p], m_nodes[q]);
        const double carried =
            max_component(m_mesh.elements[m_nodes[p].root].reflectance * m_nodes[q].radiosity) * f;
        if (carried > m_options.epsilon * m_max_emission) {
            const bool q_first = m_nodes[q].shape.area > m_nodes[p].shape.area;
            for (int attempt = 0; attempt < 2; ++attempt) {
                const bool split_q = q_first == (attempt == 0);
                const uint32_t n = split_q ? q : p;
                if (!can_split(n)) continue;
                ++counts.refinements;
                const uint32_t first = m_nodes[n].first_child, children = m_nodes[n].children;
                for (uint32_t c = first; c < first + children; ++c)
                    split_q ? refine(p, c, nullptr) : refine(c, q, nullptr);
                return;
            }
        }
        if (existing) {
            m_nodes[p].links.push_back(*existing);
            ++m_link_count;
            return;
        }
        make_link(p, q);
    }

    void make_link(uint32_t p, uint32_t q) {
        const HierarchyNode& a = m_nodes[p];
        const HierarchyNode& b = m_nodes[q];
        const double f = polygon_to_polygon(polygon(a), polygon(b));
        ++counts.form_factors;
        if (!(f > 0)) return;
        const Element& ea = m_mesh.elements[a.root];
        const Element& eb = m_mesh.elements[b.root];
        const int k = m_options.link_rays;
        if (m_options.shaft_culling && shaft_clear(a, ea.piece, b, eb.piece)) {
            m_nodes[p].links.push_back({q, f});
            ++m_link_count;
            return;
        }
        int clear = 0;
        for (int i = 0; i < k; ++i) {
            glm::dvec3 from = a.shape.centre, to = b.shape.centre;
            if (k > 1) {
                auto at = [&](const HierarchyNode& n, const Element& e, uint32_t base_s,
                              uint32_t base_t, uint32_t salt) {
                    const double u =
                        std::fmod(radical_inverse(static_cast<uint32_t>(i + 1), base_s) +
                                      rotation(p, q, salt),
                                  1.0);
                    const double v =
                        std::fmod(radical_inverse(static_cast<uint32_t>(i + 1), base_t) +
                                      rotation(p, q, salt + 1),
                                  1.0);
                    return e.point(n.s0 + u * (n.s1 - n.s0), n.t0 + v * (n.t1 - n.t0));
                };
                from = at(a, ea, 2, 3, 0);
                to = at(b, eb, 5, 7, 2);
            }
            ++counts.rays;
            clear += !m_rays.blocked(from, to, ea.piece, eb.piece);
        }
        if (clear == 0) return;
        // all clear: f itself, as shaft culling gives it
        m_nodes[p].links.push_back({q, clear == k ? f : f * clear / k});
        ++m_link_count;
    }

    // Radiosity gathered above a node is pushed down to its leaves; a node's radiosity is its
    // children's area average. `change` gathers the largest change at a leaf.
    glm::dvec3 push_pull(uint32_t n, const glm::dvec3& down, double& change) {
        HierarchyNode& node = m_nodes[n];
        const glm::dvec3 total = down + node.gathered;
        glm::dvec3 b;
        if (node.children == 0) {
            b = m_mesh.elements[node.root].emission + total;
            change = std::max(change, max_component(b - node.radiosity));
        } else {
            const uint32_t first = node.first_child, children = node.children;
            glm::dvec3 sum{0};
            double area = 0;
            for (uint32_t c = first; c < first + children; ++c) {
                const glm::dvec3 bc = push_pull(c, total, change);
                sum += m_nodes[c].shape.area * bc;
                area += m_nodes[c].shape.area;
            }
            b = area > 0 ? sum / area : total;
        }
        m_nodes[n].radiosity = b;
        return b;
    }

    // The leaves, in tree order, as one-patch elements; rows: each leaf's factors summed
    // with its ancestors'.
    void collect(uint32_t n, double above, HierarchicalResult& out) {
        const HierarchyNode& node = m_nodes[n];
        double row = above;
        for (const Link& l : node.links)
            row += l.factor;
        if (node.children == 0) {
            add_region_element(out.leaves, m_mesh.elements[node.root], node.s0, node.s1, node.t0,
                               node.t1);
            out.solution.radiosity.push_back(node.radiosity);
            if (row > out.rows.largest) {
                out.rows.largest = row;
                out.rows.largest_patch = out.leaves.patches.size() - 1;
            }
            out.rows.above_one += row > 1 + 1e-9;
            return;
        }
        for (uint32_t c = node.first_child; c < node.first_child + node.children; ++c)
            collect(c, row, out);
    }

    const Mesh& m_mesh;
    const HierarchicalOptions& m_options;
    FluxTracer m_rays;
    const TraceScene& m_scene;
    double m_slack = 0;
    std::vector<HierarchyNode> m_nodes;
    uint32_t m_roots = 0;
    uint64_t m_link_count = 0;
    double m_max_emission = 0;
};

}  // namespace

HierarchicalResult hierarchical_radiosity(const Mesh& mesh, const RadiosityWorld& world,
                                          const HierarchicalOptions& o, const WorkObserver& work) {
    if (!(o.epsilon >= 0)) throw std::invalid_argument("epsilon must be at least 0");
    if (!(o.min_area >= 0)) throw std::invalid_argument("the minimum area must be at least 0");
    if (o.link_rays < 1) throw std::invalid_argument("a link needs at least 1 ray");
    if (o.max_passes < 1) throw std::invalid_argument("at least 1 refinement pass");
    if (o.max_iterations < 1) throw std::invalid_argument("at least 1 iteration");
    HierarchicalResult out;
    Hierarchy tree(mesh, world, o);
    tree.link_roots(work);
    bool converged = tree.solve(out.solution);
    tree.counts.passes = 1;
    while (tree.counts.passes < o.max_passes && tree.rerefine()) {
        ++tree.counts.passes;
        converged = tree.solve(out.solution);
    }
    out.solution.converged = converged;
    if (tree.budget_hit())
        out.notes.push_back(fmt::format(
            "hierarchical radiosity reached its budget ({} elements, {} links): refinement "
            "stopped there, so some links are coarser than epsilon {} asks",
            o.max_nodes, o.max_links, o.epsilon));
    tree.finish(out);
    return out;
}

}  // namespace fb89::host
