#include "bench/growth/ladder.h"

#include <cstring>
#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "protocol/output_file.h"

namespace fb89::growth {

namespace {

// Exact equality of points, bit for bit (the terrain computes each grid point once).
struct PointKey {
    uint64_t x, y, z;
    bool operator==(const PointKey&) const = default;
};
struct PointHash {
    size_t operator()(const PointKey& k) const {
        return k.x * 0x9E3779B97F4A7C15ull ^ (k.y + 0x632BE59BD9B4E019ull) * 31 ^ k.z;
    }
};
PointKey key_of(const glm::dvec3& p) {
    PointKey k;
    std::memcpy(&k.x, &p.x, 8);
    std::memcpy(&k.y, &p.y, 8);
    std::memcpy(&k.z, &p.z, 8);
    return k;
}

// Camera, light and image shared by every rung: the whole terrain in view from above its
// near edge, the far hills partly hidden by the near ones.
nlohmann::ordered_json scene_frame(const Rung& rung) {
    nlohmann::ordered_json scene;
    scene["name"] = fmt::format("growth terrain, {} faces", rung.faces());
    scene["description"] =
        "bench/growth's ladder: a seeded terrain seen in perspective (scripts/bench-growth)";
    scene["camera"] = {{"eye", {0, 2.0, 3.6}},
                       {"look_at", {0, -0.25, 0.1}},
                       {"fovy", 48},
                       {"near", 0.1},
                       {"far", 20}};
    scene["image"] = {{"width", 1024}, {"height", 780}};
    scene["background"] = {0.62, 0.74, 0.9};
    scene["light"] = {{"direction", {-0.5, -1, -0.35}}, {"ambient", 0.3}};
    return scene;
}

}  // namespace

host::TerrainOptions Rung::terrain() const {
    host::TerrainOptions t;
    t.cells_x = 2 * n;
    t.cells_z = n;
    t.size_x = 3;  // cells twice as deep as wide, square on screen near the middle
    t.size_z = 3;
    t.height = 0.6;
    t.seed = kLadderSeed;
    return t;
}

std::vector<Rung> ladder(uint64_t min_faces, uint64_t max_faces) {
    std::vector<Rung> rungs;
    for (int n = 1; n <= 4096; n *= 2) {
        Rung r{n};
        if (r.faces() >= min_faces && r.faces() <= max_faces) rungs.push_back(r);
    }
    return rungs;
}

std::filesystem::path write_scene(const Rung& rung, const std::filesystem::path& dir,
                                  const std::string& obj) {
    nlohmann::ordered_json scene = scene_frame(rung);
    const host::TerrainOptions t = rung.terrain();
    if (obj.empty()) {
        scene["objects"] = {{{"generator", "terrain"},
                             {"cells", {t.cells_x, t.cells_z}},
                             {"size", {t.size_x, t.size_z}},
                             {"height", t.height},
                             {"seed", t.seed}}};
    } else {
        scene["objects"] = {{{"obj", obj}, {"material", {{"color", {0.36, 0.5, 0.28}}}}}};
    }
    const auto file =
        dir / fmt::format("terrain_{}{}.json", rung.faces(), obj.empty() ? "" : "_obj");
    protocol::write_output(file, scene.dump(2) + "\n");
    return file;
}

std::string obj_text(const host::GeneratedPolygons& polygons, const std::string& comment) {
    std::unordered_map<PointKey, uint32_t, PointHash> index;
    std::string vertices, faces;
    fmt::format_to(std::back_inserter(vertices), "# {}\n", comment);
    for (const host::GeneratedPolygon& p : polygons) {
        faces += 'f';
        for (const glm::dvec3& v : p.vertices) {
            auto [it, added] = index.try_emplace(key_of(v), static_cast<uint32_t>(index.size()));
            if (added)  // as floats: what tinyobjloader reads back, written exactly
                fmt::format_to(std::back_inserter(vertices), "v {} {} {}\n",
                               static_cast<float>(v.x), static_cast<float>(v.y),
                               static_cast<float>(v.z));
            fmt::format_to(std::back_inserter(faces), " {}", it->second + 1);
        }
        faces += '\n';
    }
    return vertices + faces;
}

uint64_t write_obj(const Rung& rung, const std::filesystem::path& file) {
    const std::string text =
        obj_text(host::generate_terrain(rung.terrain()),
                 fmt::format("bench/growth terrain, {} faces, seed {}", rung.faces(), kLadderSeed));
    protocol::write_output(file, text);
    return text.size();
}

}  // namespace fb89::growth
