// Fuzz target: host::load_obj (tinyobjloader underneath). The input is an OBJ file; text
// after a line "--mtl--" becomes "fuzz.mtl" beside it, for `mtllib fuzz.mtl`. Bad input
// must throw SceneError; a mesh that loads must hold only finite-sized polygons whose
// vertices came from the file.
#include <cstdint>
#include <string_view>

#include "host/scene/obj_loader.h"
#include "host/scene/scene_error.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    constexpr std::string_view kSplit = "\n--mtl--\n";
    const size_t split = text.find(kSplit);
    const size_t obj_size = split == std::string_view::npos ? size : split;
    const size_t mtl_at = split == std::string_view::npos ? size : split + kSplit.size();
    fb89::fuzz::write_scratch("fuzz.mtl", data + mtl_at, size - mtl_at);
    const auto path = fb89::fuzz::write_scratch("mesh.obj", data, obj_size);
    try {
        fb89::host::GeneratedPolygons polys = fb89::host::load_obj(path);
        for (const auto& p : polys)
            if (p.vertices.size() > obj_size) fb89::fuzz::finding("more vertices than bytes");
    } catch (const fb89::host::SceneError&) {
    }
    return 0;
}
