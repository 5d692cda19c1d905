#include "host/raster/renderer.h"

#include <stdexcept>

#include "host/raster/hybrid.h"
#include "host/raster/scanline.h"
#include "host/raster/warnock.h"
#include "host/raster/zbuffer.h"
#include "host/trace/beam_ray_hybrid.h"
#include "host/trace/ray_tracer.h"

namespace fb89::host {

std::vector<std::string> renderer_names() {
    return {"zbuffer", "scanline", "warnock", "hybrid", "raytrace", "beam"};
}

namespace {

WindowTest window_test_of(const RenderOptions& o) {
    if (o.window_test == "area") return WindowTest::Area;
    if (o.window_test == "centres") return WindowTest::Centres;
    throw std::invalid_argument("unknown window test '" + o.window_test +
                                "' (known: area, centres)");
}

Approximation approximation_of(const RenderOptions& o) {
    if (o.approx_min_side < 0 || !(o.approx_epsilon >= 0 && o.approx_epsilon < 1))
        throw std::invalid_argument("approximation needs a side >= 0 and 0 <= epsilon < 1");
    return {o.approx_min_side, o.approx_epsilon};
}

}  // namespace

std::unique_ptr<Renderer> make_renderer(const RenderOptions& options) {
    if (options.method == "zbuffer") return std::make_unique<ZBuffer>();
    if (options.method == "scanline") return std::make_unique<ScanLine>();
    if (options.method == "warnock")
        return std::make_unique<Warnock>(window_test_of(options), approximation_of(options));
    if (options.method == "hybrid") {
        HybridOptions h;
        if (!(options.threshold >= 0))
            throw std::invalid_argument(
                "the hybrid's threshold must be >= 0 (inf for pure Warnock)");
        h.threshold = options.threshold;
        if (options.depth_estimate != "window" && options.depth_estimate != "scene")
            throw std::invalid_argument("unknown depth estimate '" + options.depth_estimate +
                                        "' (known: window, scene)");
        h.depth = options.depth_estimate == "scene" ? DepthEstimate::Scene : DepthEstimate::Window;
        h.window_test = window_test_of(options);
        h.approx = approximation_of(options);
        return std::make_unique<Hybrid>(h);
    }
    if (options.method == "raytrace" || options.method == "beam") {
        if (options.max_reflections < 0 || options.max_reflections > kMaxReflections)
            throw std::invalid_argument("the reflection limit must be 0 to " +
                                        std::to_string(kMaxReflections));
        if (!(options.grid_density > 0 && options.grid_density <= 1000))
            throw std::invalid_argument("the grid density must be in (0, 1000] cells per piece");
        TraceOptions t;
        t.max_reflections = options.max_reflections;
        t.grid_density = options.grid_density;
        if (options.method == "raytrace") return std::make_unique<RayTraceRenderer>(t);
        if (!(options.beam_threshold >= 0))
            throw std::invalid_argument(
                "the beam threshold must be >= 0 (inf for beams down to single pixels)");
        return std::make_unique<BeamRayHybrid>(BeamOptions{options.beam_threshold, t});
    }
    std::string known;
    for (const auto& n : renderer_names())
        known += (known.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown method '" + options.method + "' (known: " + known + ")");
}

Timing render_frame(Renderer& renderer, const ScreenScene& scene, protocol::CommandSink& sink,
                    HostStats& stats, uint32_t frame_number) {
    Stopwatch clock;
    sink.frame_begin({frame_number, static_cast<uint32_t>(scene.width),
                      static_cast<uint32_t>(scene.height), scene.background});
    sink.marker({std::string(renderer.name())});
    renderer.render(scene, sink, stats);
    sink.frame_end({});
    Timing taken = clock.elapsed();
    stats.hidden_surface += taken;
    return taken;
}

}  // namespace fb89::host
