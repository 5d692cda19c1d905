#include "host/raster/scene_measures.h"

#include <unordered_set>

#include "host/raster/zbuffer.h"
#include "protocol/memory_buffer.h"

namespace fb89::host {

SceneMeasures measure_scene(const ScreenScene& scene) {
    ZBuffer zbuffer;
    zbuffer.keep_face_buffer(true);
    zbuffer.setup(scene);
    protocol::MemoryBuffer discard;
    HostStats stats;
    zbuffer.render(scene, discard, stats);

    SceneMeasures m;
    std::unordered_set<uint32_t> on_screen, visible;
    for (const auto& f : scene.faces)
        on_screen.insert(f.id);
    for (uint32_t index : zbuffer.face_buffer()) {
        if (index == 0) continue;
        ++m.covered_pixels;
        visible.insert(scene.faces[index - 1].id);
    }
    m.faces = on_screen.size();
    m.visible_faces = visible.size();
    m.face_pixels = stats.counters.get("depth_tests");
    if (m.covered_pixels) m.depth_complexity = double(m.face_pixels) / double(m.covered_pixels);
    if (m.visible_faces) m.mean_visible_face = double(m.covered_pixels) / double(m.visible_faces);
    m.screen_depth_complexity = double(m.face_pixels) / (double(scene.width) * scene.height);
    return m;
}

}  // namespace fb89::host
