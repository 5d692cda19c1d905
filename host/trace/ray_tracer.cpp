#include "host/trace/ray_tracer.h"

#include "host/trace/kernel_level.h"
#include "host/trace/nearest.h"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

namespace fb89::host {

std::string_view accel_name(Accel accel) {
    return accel == Accel::Grid ? "grid" : accel == Accel::Kd ? "kd" : "bvh";
}

Accel parse_accel(std::string_view name) {
    if (name == "bvh") return Accel::Bvh;
    if (name == "grid") return Accel::Grid;
    if (name == "kd") return Accel::Kd;
    throw std::invalid_argument("expected bvh, grid or kd, got '" + std::string(name) + "'");
}

void TraceCounts::publish(Counters& counters) const {
    counters.add("rays", rays);
    if (cells > 0) counters.add("cells_visited", cells);
    if (kd_nodes > 0) counters.add("kd_nodes_visited", kd_nodes);
    if (nodes > 0 || (cells == 0 && kd_nodes == 0)) counters.add("bvh_nodes_visited", nodes);
    counters.add("ray_face_tests", face_tests);
    counters.add("ray_ties", ties);
}

namespace {

// Nearest (nearest.h) with its tests and ties added to the frame's counts.
Hit counted(const Nearest& nearest, TraceCounts& counts) {
    counts.face_tests += nearest.tests;
    counts.ties += nearest.ties;
    return nearest.best;
}

// The nearest piece with tmin < t <= tmax, never `skip`: the BVH walk and the watertight test.
// Inlined whole into each level's entry point below (flatten), so that each is compiled for
// its instruction set; the floating-point operations are the same at every level.
template <int Lanes>
inline Hit closest_hit_body(const RayBvh& bvh, const TraceScene& scene, const Ray& ray, double tmin,
                            uint32_t skip, TraceCounts& counts, double tmax) {
    const RaySpace space(ray);
    Nearest nearest{scene, ray, space, tmin, tmax};
    counts.nodes += bvh.walk<Lanes>(
        ray, tmin, tmax,
        [&](uint32_t piece) {
            if (piece != skip) nearest.test(piece);
        },
        [&] { return nearest.best.t; });
    return counted(nearest, counts);
}

using ClosestHit = Hit (*)(const RayBvh&, const TraceScene&, const Ray&, double, uint32_t,
                           TraceCounts&, double);

// Each entry point on x86-64 (where the wide walk runs) starts a 64-byte line, so its hot loops
// sit at the same places in the instruction cache's lines whatever code precedes it in the
// binary: the AVX2 walk's time on the random world moved by 6% with the padding of an
// unrelated change before it (BENCHMARKS.md, round 3, a sixth sitting). Elsewhere 1, which
// leaves a function's alignment as it was: the period guests keep their layout.
constexpr int kEntryAlign = RayBvh::kWide ? 64 : 1;

[[gnu::flatten, gnu::aligned(kEntryAlign)]] Hit closest_hit_baseline(
    const RayBvh& bvh, const TraceScene& scene, const Ray& ray, double tmin, uint32_t skip,
    TraceCounts& counts, double tmax) {
    return closest_hit_body<4>(bvh, scene, ray, tmin, skip, counts, tmax);
}

#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
[[gnu::flatten, gnu::aligned(kEntryAlign), gnu::target("arch=x86-64-v3")]] Hit closest_hit_v3(
    const RayBvh& bvh, const TraceScene& scene, const Ray& ray, double tmin, uint32_t skip,
    TraceCounts& counts, double tmax) {
    return closest_hit_body<8>(bvh, scene, ray, tmin, skip, counts, tmax);
}

[[gnu::flatten, gnu::aligned(kEntryAlign), gnu::target("arch=x86-64-v4")]] Hit closest_hit_v4(
    const RayBvh& bvh, const TraceScene& scene, const Ray& ray, double tmin, uint32_t skip,
    TraceCounts& counts, double tmax) {
    return closest_hit_body<8>(bvh, scene, ray, tmin, skip, counts, tmax);
}
#endif

ClosestHit closest_hit_for(KernelLevel level) {
#if defined(__x86_64__) && !defined(FB89_PORTABLE_KERNELS)
    if (level == KernelLevel::V4) return closest_hit_v4;
    if (level == KernelLevel::V3) return closest_hit_v3;
#endif
    (void)level;
    return closest_hit_baseline;
}

}  // namespace

RayTracer::RayTracer(const TraceScene& scene, const UniformGrid* grid, Accel accel)
    : m_scene(scene),
      m_grid(grid),
      m_bvh(grid || accel == Accel::Kd ? std::nullopt
                                       : std::optional<RayBvh>(std::in_place, scene)),
      m_kd(!grid && accel == Accel::Kd ? std::optional<KdTree>(std::in_place, scene)
                                       : std::nullopt),
      m_level(host::kernel_level()),
      m_mailbox(grid || accel == Accel::Kd ? scene.faces().size() : 0) {}

Hit RayTracer::closest_hit(const Ray& ray, double tmin, uint32_t skip, TraceCounts& counts,
                           double tmax) const {
    if (m_grid) return closest_hit_grid(ray, tmin, skip, counts, tmax);
    if (m_kd) return closest_hit_kd(ray, tmin, skip, counts, tmax);
    return closest_hit_for(m_level)(*m_bvh, m_scene, ray, tmin, skip, counts, tmax);
}

Hit RayTracer::closest_hit_grid(const Ray& ray, double tmin, uint32_t skip, TraceCounts& counts,
                                double tmax) const {
    const Mailbox::Round mailbox = m_mailbox.begin();
    const RaySpace space(ray);
    Nearest nearest{m_scene, ray, space, tmin, tmax};
    auto test_list = [&, mailbox](std::span<const uint32_t> pieces) {
        for (uint32_t piece : pieces)
            if (mailbox.first_visit(piece) && piece != skip) nearest.test(piece);
    };
    // a hit beyond a cell may yet be beaten by a piece in a later cell: stop only past it
    const auto walked = m_grid->walk_levels(
        ray, tmin, tmax, test_list, [&](double t_exit) { return nearest.best.t <= t_exit; });
    counts.cells += walked.cells + walked.sub_cells;
    return counted(nearest, counts);
}

Hit RayTracer::closest_hit_kd(const Ray& ray, double tmin, uint32_t skip, TraceCounts& counts,
                              double tmax) const {
    const Mailbox::Round mailbox = m_mailbox.begin();
    const RaySpace space(ray);
    Nearest nearest{m_scene, ray, space, tmin, tmax};
    const glm::dvec3 inv = inverse_direction(ray);
    double t0 = tmin, t1 = tmax;
    if (KdTree::clip(ray, inv, m_kd->bounds(), t0, t1))
        m_kd->walk(
            ray, inv, 0, t0, t1,
            [&, mailbox](std::span<const uint32_t> pieces) {
                for (uint32_t piece : pieces)
                    if (mailbox.first_visit(piece) && piece != skip) nearest.test(piece);
            },
            [&](double t_exit) { return nearest.best.t <= t_exit; }, counts.kd_nodes);
    return counted(nearest, counts);
}

Hit RayTracer::primary_hit(const Ray& primary, TraceCounts& counts) const {
    ++counts.rays;
    return closest_hit(primary, 0, kNoFace, counts, m_scene.primary_length());
}

void RayTracer::trace(const Ray& primary, RayTrace& out, TraceCounts& counts) const {
    follow(primary, primary_hit(primary, counts), out, counts);
}

uint32_t RayTracer::pixel_color(int x, int y, RayTrace& scratch, TraceCounts& counts) const {
    const Ray ray = m_scene.pixel_ray(x, y);
    return color_of(ray, primary_hit(ray, counts), scratch, counts);
}

void RayTracer::follow(const Ray& primary, Hit hit, RayTrace& out, TraceCounts& counts) const {
    out.primary = primary;
    out.count = 0;
    out.escaped = false;
    Ray ray = primary;
    for (int depth = 0;; ++depth) {
        if (hit.piece == kNoFace) {
            out.escaped = true;
            out.last = ray;
            break;
        }
        const TraceFace& f = m_scene.faces()[hit.piece];
        const glm::dvec3 p = ray.origin + hit.t * ray.dir;
        const double facing = glm::dot(f.normal, ray.dir);
        out.hits[out.count] = {hit.piece, facing > 0};
        out.points[out.count] = p;
        ++out.count;
        if (!(f.mirror > 0) || depth == m_scene.max_reflections()) break;
        // reflect: the next ray starts on the mirror and never sees it again
        const uint32_t mirror = hit.piece;
        ray = {p, ray.dir - 2.0 * facing * f.normal};
        ++counts.rays;
        hit = closest_hit(ray, m_scene.tolerance() / glm::length(ray.dir), mirror, counts);
    }
    if (out.count > 0) out.color = traced_color(m_scene, out.hits, out.count);
}

uint64_t emit_packed_row(const uint32_t* row, int y, int x0, int x1, protocol::CommandSink& sink) {
    uint64_t spans = 0;
    int x = x0;
    while (x < x1) {
        const uint32_t value = row[x];
        int end = x + 1;
        while (end < x1 && row[end] == value)
            ++end;
        if (value != 0) {
            const protocol::Rgb c{static_cast<uint8_t>(value >> 16),
                                  static_cast<uint8_t>(value >> 8), static_cast<uint8_t>(value)};
            sink.draw_span({y, x, end - 1, c});
            ++spans;
        }
        x = end;
    }
    return spans;
}

void TraceSetup::build(const ScreenScene& screen, int max_reflections, double grid_density,
                       Accel accel) {
    if (!screen.world)
        throw std::logic_error("tracing needs the world scene the screen scene came from");
    scene = std::make_unique<TraceScene>(*screen.world, screen.id_colors, max_reflections);
    grid.reset();
    if (grid_density > 0 || accel == Accel::Grid)
        grid = std::make_unique<UniformGrid>(*scene,
                                             grid_density > 0 ? grid_density : kDefaultGridDensity);
    tracer =
        std::make_unique<RayTracer>(*scene, accel == Accel::Grid ? grid.get() : nullptr, accel);
}

void RayTraceRenderer::setup(const ScreenScene& scene) {
    // rays need no grid, unless they walk it
    m_trace.build(scene, m_options.max_reflections, 0, m_options.accel);
    m_row.assign(static_cast<size_t>(scene.width), 0);
}

void RayTraceRenderer::render(const ScreenScene& scene, protocol::CommandSink& sink,
                              HostStats& stats) {
    TraceCounts counts;
    uint64_t spans = 0;
    RayTrace path;
    for (int y = 0; y < scene.height; ++y) {
        for (int x = 0; x < scene.width; ++x) {
            m_row[x] = m_trace.tracer->pixel_color(x, y, path, counts);
        }
        spans += emit_packed_row(m_row.data(), y, 0, scene.width, sink);
    }
    counts.publish(stats.counters);
    stats.counters.add("pixels_by_rays", static_cast<uint64_t>(scene.width) * scene.height);
    stats.counters.add("spans", spans);
}

}  // namespace fb89::host
