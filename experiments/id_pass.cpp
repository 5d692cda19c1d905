#include "experiments/id_pass.h"

#include "controller_sim/controller.h"
#include "host/raster/screen_setup.h"
#include "protocol/memory_buffer.h"

namespace fb89::experiments {

controller::Framebuffer framebuffer_of(const host::Scene& scene, host::ColorMode mode,
                                       host::Renderer& renderer, uint32_t depth_bits) {
    host::HostStats stats;
    host::ScreenScene screen = host::project_scene(scene, mode, stats.counters);
    renderer.setup(screen);
    protocol::MemoryBuffer commands;
    host::render_frame(renderer, screen, commands, stats);
    // pixels do not depend on the cost profile but for the depth word: the ideal one costs
    // nothing to model
    controller::CostProfile ideal = controller::load_profile("ideal");
    ideal.depth_bits = depth_bits;
    controller::Controller ctl(std::move(ideal));
    commands.replay_into(ctl);
    return ctl.framebuffer();
}

controller::Framebuffer id_framebuffer(const host::Scene& scene, host::Renderer& renderer,
                                       uint32_t depth_bits) {
    return framebuffer_of(scene, host::ColorMode::FaceId, renderer, depth_bits);
}

}  // namespace fb89::experiments
