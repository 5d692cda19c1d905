// Our side of every side-by-side: one of our methods set up for the scene (untimed), the
// buffer its frames go to, the last frame's stats and the timed samples; and the median.
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "host/methods.h"
#include "host/raster/screen_scene.h"
#include "host/stats.h"
#include "protocol/memory_buffer.h"

namespace fb89::peers {

inline double median_of(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Ours {
    std::unique_ptr<host::Renderer> renderer;
    protocol::MemoryBuffer frame;
    host::HostStats stats;
    std::vector<double> samples;

    // Throws std::invalid_argument when the options are refused.
    Ours(const host::ScreenScene& scene, const host::MethodOptions& options)
        : renderer(host::make_renderer(options)) {
        renderer->setup(scene);
    }
    // One frame into the buffer; wall-clock ms, as render_frame times it.
    double render(const host::ScreenScene& scene) {
        frame.clear();
        stats = {};
        return host::render_frame(*renderer, scene, frame, stats).wall_ms;
    }
};

}  // namespace fb89::peers
