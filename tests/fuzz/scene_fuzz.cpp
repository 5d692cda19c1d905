// Fuzz target: host::load_scene on a JSON scene file (comments allowed). Beside it in the
// scratch directory lies "cube.obj", so that `"obj": "cube.obj"` loads. Bad input must throw
// SceneError (load_scene's one error type); nothing else may escape.
#include <cstdint>
#include <string_view>

#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

void write_cube() {
    static const bool written = [] {
        constexpr std::string_view kCube =
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
            "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
        fb89::fuzz::write_scratch("cube.obj", reinterpret_cast<const uint8_t*>(kCube.data()),
                                  kCube.size());
        return true;
    }();
    (void)written;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    write_cube();
    const auto path = fb89::fuzz::write_scratch("scene.json", data, size);
    try {
        fb89::host::Scene scene = fb89::host::load_scene(path);
        // every id but a dropped face's is drawn by at least one piece
        if (scene.faces.size() + scene.dropped < scene.face_count)
            fb89::fuzz::finding("fewer faces than ids");
        for (const auto& f : scene.faces)
            if (f.id >= scene.face_count) fb89::fuzz::finding("an id beyond face_count");
    } catch (const fb89::host::SceneError&) {
    }
    return 0;
}
