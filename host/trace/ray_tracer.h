// The ray tracer embedded in the paper's hybrid (§4), and the `raytrace` method: one ray
// through each pixel centre, the nearest face by the BVH (bvh.h) and the watertight test
// (ties go to the lower piece, as the raster methods give them to the lower id), mirrors
// followed up to a reflection limit, flat Lambertian shading, no shadows. Ray-traced pixels
// leave as DRAW_SPAN runs of equal colour, row by row; background sends nothing.
//
// Each piece sits in one BVH leaf, so a ray tests it at most once. A reflected ray starts on the
// mirror and skips it; faces nearer than the scene's tolerance to its start are skipped too
// (the beam tracer counts any face that near as blocking, so both agree).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "host/raster/renderer.h"
#include "host/trace/bvh.h"
#include "host/trace/grid.h"
#include "host/trace/kd_tree.h"
#include "host/trace/kernel_level.h"
#include "host/trace/mailbox.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {

inline constexpr int kMaxReflections = 16;

// The structure rays find their nearest piece through: the BVH (bvh.h), the paper's: the
// uniform grid of Fujimoto et al. walked by 3DDDA, its crowded cells gridded again (grid.h),
// pieces met twice skipped by a mailbox, or the kd-tree the multi-level ray tracer's beams
// walk (kd_tree.h). The same hits every way.
enum class Accel { Bvh, Grid, Kd };
std::string_view accel_name(Accel accel);  // "bvh", "grid", "kd"
Accel parse_accel(std::string_view name);  // throws std::invalid_argument

// Counted in locals by kernels, published once per frame.
struct TraceCounts {
    uint64_t rays = 0;        // every ray traced: primary and reflected
    uint64_t nodes = 0;       // BVH nodes visited
    uint64_t cells = 0;       // grid cells visited (Accel::Grid: both levels)
    uint64_t kd_nodes = 0;    // kd-tree nodes visited (Accel::Kd)
    uint64_t face_tests = 0;  // ray-piece tests
    uint64_t ties = 0;        // a piece hit at exactly the best distance so far
    void publish(Counters& counters) const;
};

// What one pixel's ray saw: the faces along its path (mirrors, then the face finally seen),
// where it hit them, and how the last ray left when it hit nothing.
struct RayTrace {
    Ray primary;  // the pixel's ray
    int count = 0;
    PathHit hits[kMaxReflections + 1];
    glm::dvec3 points[kMaxReflections + 1];
    bool escaped = false;  // the last ray (primary or reflected) hit nothing
    Ray last;              // that last ray
    protocol::Rgb color;   // the path's colour (when count > 0)
};

class RayTracer {
  public:
    // With Accel::Grid, `grid` is the grid its rays walk (kept by the caller); else null.
    explicit RayTracer(const TraceScene& scene, const UniformGrid* grid = nullptr,
                       Accel accel = Accel::Bvh);

    // Nearest piece with tmin < t <= tmax, never `skip`.
    Hit closest_hit(const Ray& ray, double tmin, uint32_t skip, TraceCounts& counts,
                    double tmax = INFINITY) const;
    // The whole path of one primary ray, with its colour.
    void trace(const Ray& primary, RayTrace& out, TraceCounts& counts) const;
    void trace_pixel(int x, int y, RayTrace& out, TraceCounts& counts) const {
        trace(m_scene.pixel_ray(x, y), out, counts);
    }
    // Pixel (x, y)'s colour packed (packed_pixel; 0 for background), as trace_pixel gives
    // it, without keeping the path unless it meets a mirror (then in `scratch`).
    uint32_t pixel_color(int x, int y, RayTrace& scratch, TraceCounts& counts) const;
    // The same colour for a primary ray whose nearest hit is already known (the multi-level
    // ray tracer finds it from a beam's entry point).
    uint32_t color_of(const Ray& primary, Hit hit, RayTrace& scratch, TraceCounts& counts) const;

    const TraceScene& scene() const { return m_scene; }
    const RayBvh& bvh() const { return *m_bvh; }     // with the BVH only
    const KdTree& kd_tree() const { return *m_kd; }  // with Accel::Kd only
    // The instruction set its inner loop runs with (kernel_level.h), fixed at construction.
    KernelLevel kernel_level() const { return m_level; }

  private:
    // A primary ray's nearest hit: from its start on the near plane to the far plane.
    Hit primary_hit(const Ray& primary, TraceCounts& counts) const;
    // The path on from the primary ray's hit.
    void follow(const Ray& primary, Hit hit, RayTrace& out, TraceCounts& counts) const;

    // The grid's closest hit (Accel::Grid): both levels, a mailbox against repeats.
    Hit closest_hit_grid(const Ray& ray, double tmin, uint32_t skip, TraceCounts& counts,
                         double tmax) const;

    const TraceScene& m_scene;
    // The kd-tree's closest hit (Accel::Kd).
    Hit closest_hit_kd(const Ray& ray, double tmin, uint32_t skip, TraceCounts& counts,
                       double tmax) const;

    const UniformGrid* m_grid;    // rays walk it when set; else the BVH or the kd-tree
    std::optional<RayBvh> m_bvh;  // built when rays walk it
    std::optional<KdTree> m_kd;   // built when rays walk it
    KernelLevel m_level;
    mutable Mailbox m_mailbox;
};

// A pixel as the renderers keep it before sending: 0 is background (sends nothing), else
// the colour packed as 0x01RRGGBB.
inline uint32_t packed_pixel(protocol::Rgb c) {
    return 0x1000000u | (uint32_t{c.r} << 16) | (uint32_t{c.g} << 8) | c.b;
}
// Inline: the common path (nothing hit, or a face that ends the path) is taken once a pixel.
inline uint32_t RayTracer::color_of(const Ray& ray, Hit hit, RayTrace& scratch,
                                    TraceCounts& counts) const {
    if (hit.piece == kNoFace) return 0;
    const TraceFace& f = m_scene.faces()[hit.piece];
    // the common path: a face that is no mirror (or no reflection followed) ends it
    if (!(f.mirror > 0) || m_scene.max_reflections() == 0)
        return packed_pixel(f.end_color[glm::dot(f.normal, ray.dir) > 0 ? 1 : 0]);
    follow(ray, hit, scratch, counts);
    return packed_pixel(scratch.color);
}

// Sends row y's pixels x0..x1-1 as DRAW_SPAN runs of equal colour; returns the spans sent.
uint64_t emit_packed_row(const uint32_t* row, int y, int x0, int x1, protocol::CommandSink& sink);

// The scene built for tracing at set-up: world faces, tracer and (with a grid density above
// 0, for the beams, or for rays with Accel::Grid) the grid.
struct TraceSetup {
    std::unique_ptr<TraceScene> scene;
    std::unique_ptr<UniformGrid> grid;
    std::unique_ptr<RayTracer> tracer;
    // Builds from the world scene a ScreenScene was projected from (its `world`).
    void build(const ScreenScene& screen, int max_reflections, double grid_density,
               Accel accel = Accel::Bvh);
};

// Top-level grid density accepted, in cells per face piece.
inline constexpr double kMinGridDensity = 0.01, kMaxGridDensity = 1000;

struct TraceOptions {
    int max_reflections = 8;  // mirror bounces followed (0: primary visibility)
    Accel accel = Accel::Bvh;
    bool packets = true;  // mlrta: its rays in packets of eight (ray_packet.h), or one by one
};

// `raytrace`: the ray tracer alone.
class RayTraceRenderer final : public Renderer {
  public:
    explicit RayTraceRenderer(TraceOptions options = {}) : m_options(options) {}
    std::string_view name() const override { return "raytrace"; }
    void setup(const ScreenScene& scene) override;
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;

  private:
    TraceOptions m_options;
    TraceSetup m_trace;
    std::vector<uint32_t> m_row;
};

}  // namespace fb89::host
