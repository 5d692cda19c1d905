#include "host/scene/obj_loader.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include "host/scene/scene_error.h"

namespace fb89::host {

namespace {

// Elements of an OBJ that are not faces and that fb89 does not draw.
struct SkippedElements {
    size_t lines = 0, points = 0;
};

// The number of vertex references on an `f` line ("f 1/1 2/2 3/3" has 3).
size_t face_vertex_count(std::istringstream& words) {
    size_t n = 0;
    std::string word;
    while (words >> word) {
        if (word[0] == '#') break;
        ++n;
    }
    return n;
}

// Checks what tinyobjloader would read wrongly or drop without a word, line by line:
// a coordinate it cannot parse ("nan", "abc", a missing one) it reads as 0 and an
// overflowing one as inf; a face of fewer than 3 vertices it drops, which would move every
// later face's id. Both are errors naming the line. Lines and points are counted.
SkippedElements check_lines(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::string line;
    SkippedElements skipped;
    for (size_t number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string tag;
        if (!(words >> tag)) continue;
        if (tag == "l") ++skipped.lines;
        if (tag == "p") ++skipped.points;
        if (tag == "f") {
            const size_t n = face_vertex_count(words);
            if (n < 3)
                throw SceneError(fmt::format("{}: line {}: a face of {} {}; a face needs 3 or more",
                                             file.string(), number, n,
                                             n == 1 ? "vertex" : "vertices"));
        }
        if (tag != "v") continue;
        for (int k = 0; k < 3; ++k) {
            std::string word;
            words >> word;
            char* end = nullptr;
            const double x = std::strtod(word.c_str(), &end);
            if (word.empty() || *end != '\0' || !std::isfinite(x))
                throw SceneError(fmt::format(
                    "{}: line {}: vertex coordinate {}: expected a finite number, got '{}'",
                    file.string(), number, k + 1, word));
        }
    }
    return skipped;
}

}  // namespace

GeneratedPolygons load_obj(const std::filesystem::path& file, std::vector<std::string>* notes) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec))
        throw SceneError(fmt::format("{}: is a directory, not an OBJ file", file.string()));
    if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
        throw SceneError(
            fmt::format("{}: not a regular file (a device or a pipe could be "
                        "endless), not an OBJ file",
                        file.string()));
    if (!std::ifstream(file).good())
        throw SceneError(fmt::format("{}: cannot open the OBJ file", file.string()));
    const SkippedElements skipped = check_lines(file);
    if (notes && (skipped.lines || skipped.points))
        notes->push_back(
            fmt::format("{}: {} line and {} point element(s) skipped: fb89 draws "
                        "faces only",
                        file.string(), skipped.lines, skipped.points));
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // faces stay whole convex polygons
    config.vertex_color = false;
    config.mtl_search_path = file.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r'))
            why.pop_back();
        throw SceneError(fmt::format("{}: {}", file.string(), why.empty() ? "unreadable" : why));
    }
    const auto& attrib = reader.GetAttrib();
    const auto& materials = reader.GetMaterials();
    const size_t vertex_count = attrib.vertices.size() / 3;

    GeneratedPolygons out;
    for (const auto& shape : reader.GetShapes()) {
        size_t offset = 0;
        const auto& mesh = shape.mesh;
        for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            size_t n = mesh.num_face_vertices[f];
            GeneratedPolygon poly;
            for (size_t k = 0; k < n; ++k) {
                int vi = mesh.indices[offset + k].vertex_index;
                if (vi < 0 || static_cast<size_t>(vi) >= vertex_count)
                    throw SceneError(fmt::format("{}: shape '{}' face {} refers to vertex {} of {}",
                                                 file.string(), shape.name, f, vi + 1,
                                                 vertex_count));
                const tinyobj::real_t* p = &attrib.vertices[3 * static_cast<size_t>(vi)];
                poly.vertices.emplace_back(p[0], p[1], p[2]);
            }
            int mat = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
            if (mat >= 0 && static_cast<size_t>(mat) < materials.size()) {
                const auto& kd = materials[static_cast<size_t>(mat)].diffuse;
                poly.color = glm::dvec3(kd[0], kd[1], kd[2]);
            }
            out.push_back(std::move(poly));
            offset += n;
        }
    }
    return out;
}

}  // namespace fb89::host
