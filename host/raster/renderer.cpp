#include "host/raster/renderer.h"

#include <stdexcept>

#include "host/raster/scanline.h"
#include "host/raster/warnock.h"
#include "host/raster/zbuffer.h"

namespace fb89::host {

std::vector<std::string> renderer_names() {
    return {"zbuffer", "scanline", "warnock"};
}

std::unique_ptr<Renderer> make_renderer(const RenderOptions& options) {
    if (options.method == "zbuffer") return std::make_unique<ZBuffer>();
    if (options.method == "scanline") return std::make_unique<ScanLine>();
    if (options.method == "warnock") {
        if (options.window_test != "area" && options.window_test != "centres")
            throw std::invalid_argument("unknown window test '" + options.window_test +
                                        "' (known: area, centres)");
        return std::make_unique<Warnock>(options.window_test == "area" ? WindowTest::Area
                                                                       : WindowTest::Centres);
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
