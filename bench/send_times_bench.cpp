// What measuring send times costs (the pipeline in time, protocol/memory_buffer.h): a scene's
// hidden-surface pass into a MemoryBuffer with its packets timed against the same pass
// without, interleaved round by round (the order alternating), medians of CPU time, and the
// ratio. Issue 30 asks for under 2% of the demo Z-buffer's hidden-surface time.
//
//     build/bench/fb89_send_times_bench [SCENE.json] [METHOD] [ROUNDS]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "host/methods.h"
#include "host/raster/renderer.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "host/stats.h"
#include "protocol/memory_buffer.h"

int main(int argc, char** argv) {
    using namespace fb89;
    const std::string file = argc > 1 ? argv[1] : FB89_SOURCE_DIR "/scenes/demo.json";
    const std::string method = argc > 2 ? argv[2] : "zbuffer";
    const int rounds = argc > 3 ? std::atoi(argv[3]) : 201;
    try {
        const host::Scene scene = host::load_scene(file);
        host::Counters counters;
        const host::ScreenScene screen =
            host::project_scene(scene, host::ColorMode::Shaded, counters);
        auto renderer = host::make_renderer(host::MethodOptions(host::method_named(method)));
        renderer->setup(screen);
        protocol::MemoryBuffer buffer;
        std::vector<double> plain, timed;
        for (int r = -1; r < rounds; ++r) {  // round -1 warms up
            for (int k = 0; k < 2; ++k) {
                const bool with_times = (k + r) % 2 != 0;
                buffer.clear();
                if (with_times)
                    buffer.time_packets(protocol::kSendPacketCommands);
                else
                    buffer.time_packets(0);
                host::HostStats stats;
                const host::Timing t = host::render_frame(*renderer, screen, buffer, stats);
                if (with_times) (void)buffer.send_times_us();
                if (r >= 0) (with_times ? timed : plain).push_back(t.cpu_ms);
            }
        }
        const auto median = [](std::vector<double> v) {
            std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
            return v[v.size() / 2];
        };
        const double a = median(plain), b = median(timed);
        std::printf(
            "%s %s: hidden-surface %.4f ms plain, %.4f ms with send times (%zu commands, "
            "a clock read per %u): %+.2f%% (medians of %d interleaved rounds)\n",
            file.c_str(), method.c_str(), a, b, buffer.size(), protocol::kSendPacketCommands,
            100 * (b / a - 1), rounds);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fb89_send_times_bench: %s\n", e.what());
        return 2;
    }
    return 0;
}
