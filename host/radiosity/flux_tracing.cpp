// Flux tracing (the paper's §5; Christensen, Marks, Walsh and Friedell, TR-16-89): δ of a
// facing patch pair by one ray between the patches' centres, blocked by any face piece but
// the two the patches lie on. The paper's baseline, and the leaves of the decahedral hybrid.
//
// Ours: the ray runs from the centre of the lower-numbered patch to the other's, dir =
// c_q − c_p, and counts hits at t in (ε, 1 − ε), ε four scene tolerances over |dir| (a hit
// that close to an end is the patch's own surface or a face touching it there, REFERENCES.md
// "Ray casts must ignore the two end faces"). The test is the watertight two-sided one of
// TraceScene: back faces block, and a ray through a shared edge cannot slip between two
// faces. It walks the uniform grid and a crowded cell's own grid (walk_levels, as
// RayTracer::closest_hit does) and stops at the first hit anywhere in range: any hit blocks,
// the nearest is not needed. Pairs are enumerated element pair by element pair, with each
// element's patches sorted once into those in front of the other's plane (in_front), so the
// baseline pays for facing tests no more than the hybrid does.
#include <algorithm>
#include <span>
#include <vector>

#include <glm/geometric.hpp>

#include "host/radiosity/visibility.h"

namespace fb89::host {

namespace {

constexpr double kEndTolerances = 4;  // ε in scene tolerances

}  // namespace

FluxTracer::FluxTracer(const Mesh& mesh, const RadiosityWorld& world)
    : m_mesh(mesh),
      m_scene(world.scene),
      m_grid(world.grid),
      m_mailbox(world.scene.faces().size()) {}

Delta FluxTracer::trace(uint32_t p, uint32_t q) {
    if (p > q) std::swap(p, q);
    const Patch& a = m_mesh.patches[p];
    const Patch& b = m_mesh.patches[q];
    return blocked(a.centre, b.centre, m_mesh.elements[a.element].piece,
                   m_mesh.elements[b.element].piece)
               ? Delta::Hidden
               : Delta::Visible;
}

bool FluxTracer::blocked(const glm::dvec3& from, const glm::dvec3& to, uint32_t skip_a,
                         uint32_t skip_b) {
    const Mailbox::Round mailbox = m_mailbox.begin();
    const Ray ray{from, to - from};
    const double eps = kEndTolerances * m_scene.tolerance() / glm::length(ray.dir);
    const double tmin = eps, tmax = 1 - eps;
    const RaySpace space(ray);

    // any hit in (tmin, tmax) by a piece other than the two ends' blocks the ray
    bool hit = false;
    uint64_t tests = 0;
    auto test_list = [&, mailbox](std::span<const uint32_t> pieces) {
        for (uint32_t piece : pieces) {
            if (!mailbox.first_visit(piece) || piece == skip_a || piece == skip_b) continue;
            ++tests;
            double t;
            if (m_scene.intersect(ray, space, piece, tmin, t) && t < tmax) {
                hit = true;
                return;
            }
        }
    };
    const auto walked = m_grid.walk_levels(ray, tmin, tmax, test_list, [&](double) { return hit; });
    m_cells += walked.cells;  // the top level's, as the cost model was fitted (cells())
    m_face_tests += tests;
    return hit;
}

Visibility flux_tracing(const Mesh& mesh, const RadiosityWorld& world, VisibilityCounts& counts,
                        const WorkObserver& work) {
    Visibility delta(static_cast<uint32_t>(mesh.patches.size()));
    FluxTracer tracer(mesh, world);
    std::vector<uint32_t> front_a, front_b;
    uint64_t rays = 0;
    for (size_t ea = 0; ea < mesh.elements.size(); ++ea) {
        const Element& a = mesh.elements[ea];
        const uint32_t a_count = static_cast<uint32_t>(a.nu * a.nv);
        for (size_t eb = ea + 1; eb < mesh.elements.size(); ++eb) {
            const Element& b = mesh.elements[eb];
            const uint32_t b_count = static_cast<uint32_t>(b.nu * b.nv);
            // the patches of each in front of the other's plane
            front_b.clear();
            for (uint32_t q = b.first_patch; q < b.first_patch + b_count; ++q)
                if (in_front(a, mesh.patches[q].centre)) front_b.push_back(q);
            if (front_b.empty()) continue;
            front_a.clear();
            for (uint32_t p = a.first_patch; p < a.first_patch + a_count; ++p)
                if (in_front(b, mesh.patches[p].centre)) front_a.push_back(p);
            // one ray per facing pair
            for (uint32_t p : front_a)
                for (uint32_t q : front_b)
                    delta.set(p, q, tracer.trace(p, q));
            rays += front_a.size() * front_b.size();
        }
        if (work) {
            const uint64_t n = mesh.patches.size();
            work(pairs_before(n, a.first_patch + a_count), pairs_before(n, n));
        }
    }
    counts.facing_pairs += rays;
    counts.rays += rays;
    return delta;
}

}  // namespace fb89::host
