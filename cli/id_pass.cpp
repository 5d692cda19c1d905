#include "cli/id_pass.h"

#include "controller_sim/controller.h"
#include "host/scene/projection.h"
#include "protocol/memory_buffer.h"

namespace fb89::cli {

controller::Framebuffer id_framebuffer(const host::Scene& scene, host::Renderer& renderer) {
    host::HostStats stats;
    host::ScreenScene ids = host::project_scene(scene, host::ColorMode::FaceId, stats.counters);
    renderer.setup(ids);
    protocol::MemoryBuffer commands;
    host::render_frame(renderer, ids, commands, stats);
    // pixels do not depend on the cost profile: the ideal one costs nothing to model
    controller::Controller ctl(controller::load_profile("ideal"));
    commands.replay_into(ctl);
    return ctl.framebuffer();
}

}  // namespace fb89::cli
