// The interface every hidden-surface method implements. A renderer decides what is
// visible and sends only what is not background to a CommandSink; FRAME_BEGIN and
// FRAME_END are sent by render_frame(), which also times the method.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "host/scene/screen_scene.h"
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

struct RenderOptions {
    std::string method = "zbuffer";
    std::string window_test = "area";       // Warnock and hybrid: "area" or "centres"
    double threshold = 0.04;                // hybrid: Expr. 3.1 threshold (the paper's 0.04)
    std::string depth_estimate = "window";  // hybrid: "window" or "scene"
    int approx_min_side = 0;                // Warnock and hybrid: approximate fills (0: exact)
    double approx_epsilon = 0;
    double beam_threshold = 1000;  // beam: Expr. 2.7 threshold (inf: down to pixels)
    int max_reflections = 8;       // raytrace and beam: mirror bounces followed
    double grid_density = 0.5;     // raytrace and beam: top-level grid cells per face piece
};

// Throws std::invalid_argument naming the known methods when `method` is unknown.
std::unique_ptr<Renderer> make_renderer(const RenderOptions& options);
std::vector<std::string> renderer_names();

// One frame: FRAME_BEGIN (size, background), a MARKER naming the method, the method's
// commands, FRAME_END. Returns the time taken and adds it to stats.hidden_surface.
Timing render_frame(Renderer& renderer, const ScreenScene& scene, protocol::CommandSink& sink,
                    HostStats& stats, uint32_t frame_number = 0);

}  // namespace fb89::host
