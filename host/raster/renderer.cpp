#include "host/raster/renderer.h"

#include <string>

namespace fb89::host {

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
