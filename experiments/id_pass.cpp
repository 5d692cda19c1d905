#include "experiments/id_pass.h"

#include "controller_sim/controller.h"
#include "host/raster/screen_setup.h"
#include "protocol/memory_buffer.h"

namespace fb89::experiments {

controller::Framebuffer framebuffer_of(const host::Scene& scene, host::ColorMode mode,
                                       host::Renderer& renderer) {
    host::HostStats stats;
    host::ScreenScene screen = host::project_scene(scene, mode, stats.counters);
    renderer.setup(screen);
    protocol::MemoryBuffer commands;
    host::render_frame(renderer, screen, commands, stats);
    // pixels do not depend on the cost profile: the ideal one costs nothing to model
    controller::Controller ctl(controller::load_profile("ideal"));
    commands.replay_into(ctl);
    return ctl.framebuffer();
}

controller::Framebuffer id_framebuffer(const host::Scene& scene, host::Renderer& renderer) {
    return framebuffer_of(scene, host::ColorMode::FaceId, renderer);
}

}  // namespace fb89::experiments
