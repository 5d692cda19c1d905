// The interface every hidden-surface method implements (host/methods.h builds them by name). A
// renderer decides what is visible and sends only what is not background to a CommandSink;
// FRAME_BEGIN and FRAME_END are sent by render_frame(), which also times the method.
#pragma once

#include <cstdint>
#include <string_view>

#include "host/raster/screen_scene.h"
#include "host/stats.h"
#include "protocol/command_sink.h"

namespace fb89::host {

class Renderer {
  public:
    virtual ~Renderer() = default;
    virtual std::string_view name() const = 0;
    // Set-up before the timed work: allocate buffers for this scene's size, build
    // acceleration structures. Timed as set-up, not as hidden-surface time.
    virtual void setup(const ScreenScene& scene) { (void)scene; }
    virtual void render(const ScreenScene& scene, protocol::CommandSink& sink,
                        HostStats& stats) = 0;
};

// One frame: FRAME_BEGIN (size, background), a MARKER naming the method, the method's
// commands, FRAME_END. Returns the time taken and adds it to stats.hidden_surface.
Timing render_frame(Renderer& renderer, const ScreenScene& scene, protocol::CommandSink& sink,
                    HostStats& stats, uint32_t frame_number = 0);

}  // namespace fb89::host
