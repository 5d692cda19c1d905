// Fuzz target: the `.tri` screen-space triangle-set loader (host::parse_tri, what
// load_scene uses for a .tri file; the conformance fixtures' format). Bad input must throw
// SceneError naming the file; nothing else may escape. A set that loads must be a screen
// scene of the allowed size whose faces are triangles with finite coordinates and valid ids,
// and whose counts (faces, distinct ids, dropped triangles and their notes) agree.
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <string_view>

#include "host/scene/polygon.h"
#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using fb89::fuzz::finding;

void check(const fb89::host::Scene& scene, std::string_view text) {
    if (scene.projection != fb89::host::Projection::Screen) finding("not a screen scene");
    if (scene.width < 1 || scene.width > 16384 || scene.height < 1 || scene.height > 16384)
        finding("size outside [1, 16384]");
    std::set<uint32_t> ids;
    for (const auto& f : scene.faces) {
        if (f.vertices.size() != 3) finding("a face that is not a triangle");
        if (f.id >= (1u << 24) - 1) finding("an id beyond 16777214");
        for (const auto& v : f.vertices)
            for (int i = 0; i < 3; ++i)
                if (!std::isfinite(v[i]) || std::abs(v[i]) > fb89::host::kMaxCoordinate)
                    finding("a coordinate that is not finite or too large");
        ids.insert(f.id);
    }
    // a dropped triangle's id counts too (it stays the triangle's own, unused)
    if (scene.face_count < ids.size() || scene.face_count > ids.size() + scene.dropped)
        finding("face_count outside [drawn ids, drawn ids + dropped]");
    if (scene.notes.size() != scene.dropped) finding("a dropped triangle without its note");
    // Each triangle and the header take a line of their own.
    size_t lines = 1;
    for (char c : text)
        lines += c == '\n';
    if (scene.faces.size() + scene.dropped + 1 > lines) finding("more triangles than lines");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    static const std::string kName = "fuzz.tri";
    try {
        check(fb89::host::parse_tri(text, kName), text);
    } catch (const fb89::host::SceneError& e) {
        if (std::string_view(e.what()).find(kName) == std::string_view::npos)
            finding("a SceneError that does not name the file");
    }
    return 0;
}
