#include "host/methods.h"

#include <array>
#include <stdexcept>

#include "host/raster/controller_depth.h"
#include "host/raster/hzb.h"
#include "host/raster/scanline.h"
#include "host/raster/zbuffer.h"
#include "host/trace/mlrta.h"

namespace fb89::host {

namespace {

constexpr std::array<MethodInfo, 10> kMethods{{
    {Method::ZBuffer, "zbuffer", "Z-buffer: depth test per pixel, spans of equal colour", 0},
    {Method::ScanLine, "scanline", "Watkins scan-line: active faces per row, depth per segment", 0},
    {Method::Warnock, "warnock", "Warnock window sampling (§1, §2): fills from the thinker",
     kWindowOptions},
    {Method::Hybrid, "hybrid",
     "Warnock/Z-buffer hybrid (§3): Expr. 3.1 hands windows to the Z-buffer",
     kWindowOptions | kHybridOptions},
    {Method::RayTrace, "raytrace",
     "ray tracer: one ray per pixel, the nearest face found through a BVH "
     "[--accel grid: a uniform grid, as in 1989]",
     kTraceOptions},
    {Method::Beam, "beam",
     "beam-ray hybrid (§4): beams query the rays' BVH and fill windows, Expr. 2.7 hands to rays "
     "[--accel grid: rays and beams walk a uniform grid, as in 1989]",
     kTraceOptions | kBeamOptions},
    {Method::DepthSpans, "zspans",
     "host scan-converts, controller tests depth: DEPTH_SPANs, no depth test on the host", 0, true},
    {Method::Faces, "faces",
     "host projects and clips only: FACEs the controller scan-converts and depth-tests", 0, true},
    {Method::Hzb, "hzb",
     "hierarchical Z-buffer (Greene et al. 1993): an octree front to back, culled in a depth "
     "pyramid; the Z-buffer's spans",
     0},
    {Method::Mlrta, "mlrta",
     "multi-level ray tracing (Reshetov et al. 2005): beams of rays find their entry point in a "
     "kd-tree, split where their rays part; the ray tracer's frame",
     kTraceOptions},
}};

}  // namespace

std::span<const MethodInfo> methods() {
    return kMethods;
}

const MethodInfo& method_info(Method method) {
    for (const MethodInfo& m : kMethods)
        if (m.method == method) return m;
    throw std::invalid_argument("unknown method");
}

Method method_named(std::string_view name) {
    std::string known;
    for (const MethodInfo& m : kMethods) {
        if (m.name == name) return m.method;
        known += (known.empty() ? "" : ", ") + std::string(m.name);
    }
    throw std::invalid_argument("unknown method '" + std::string(name) + "' (known: " + known +
                                ")");
}

std::vector<std::string> renderer_names() {
    std::vector<std::string> names;
    for (const MethodInfo& m : kMethods)
        names.emplace_back(m.name);
    return names;
}

void validate(const MethodOptions& o) {
    const MethodInfo& info = method_info(o.method);
    if (info.uses(kWindowOptions)) {
        const Approximation& a = o.warnock.approx;
        if (a.min_side < 0 || !(a.epsilon >= 0 && a.epsilon < 1))
            throw std::invalid_argument("approximation needs a side >= 0 and 0 <= epsilon < 1");
    }
    if (info.uses(kHybridOptions) && !(o.hybrid.threshold >= 0))
        throw std::invalid_argument("the hybrid's threshold must be >= 0 (inf for pure Warnock)");
    if (info.uses(kTraceOptions)) {
        if (o.trace.max_reflections < 0 || o.trace.max_reflections > kMaxReflections)
            throw std::invalid_argument("the reflection limit must be 0 to " +
                                        std::to_string(kMaxReflections));
        if (o.method == Method::Beam && o.trace.accel == Accel::Kd)
            throw std::invalid_argument(
                "accel kd: the beam method's beams query a BVH or a grid (mlrta walks a kd-tree)");
        if (o.method == Method::Mlrta && o.trace.accel == Accel::Grid)
            throw std::invalid_argument("accel grid: mlrta's beams and rays walk a kd-tree");
    }
    if (info.uses(kBeamOptions) &&
        !(o.beam.grid_density >= kMinGridDensity && o.beam.grid_density <= kMaxGridDensity))
        throw std::invalid_argument("the grid density must be in [" +
                                    std::to_string(kMinGridDensity) + ", " +
                                    std::to_string(kMaxGridDensity) + "] cells per piece");
    if (info.uses(kBeamOptions) && !(o.beam.threshold >= 0))
        throw std::invalid_argument(
            "the beam threshold must be >= 0 (inf for beams down to single pixels)");
}

std::unique_ptr<Renderer> make_renderer(const MethodOptions& o) {
    validate(o);
    switch (o.method) {
        case Method::ZBuffer:
            return std::make_unique<ZBuffer>();
        case Method::ScanLine:
            return std::make_unique<ScanLine>();
        case Method::Warnock:
            return std::make_unique<Warnock>(o.warnock);
        case Method::Hybrid:
            return std::make_unique<Hybrid>(o.hybrid, o.warnock);
        case Method::RayTrace:
            return std::make_unique<RayTraceRenderer>(o.trace);
        case Method::Beam:
            return std::make_unique<BeamRayHybrid>(o.beam, o.trace);
        case Method::DepthSpans:
            return std::make_unique<DepthSpans>();
        case Method::Faces:
            return std::make_unique<FaceSender>();
        case Method::Hzb:
            return std::make_unique<HierarchicalZBuffer>();
        case Method::Mlrta:
            return std::make_unique<MultiLevelRayTracer>(o.trace);
    }
    throw std::invalid_argument("unknown method");
}

}  // namespace fb89::host
