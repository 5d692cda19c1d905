// OBJ meshes through tinyobjloader: polygons kept whole (no triangulation by the loader),
// diffuse colours from an .mtl file when the scene gives no colour of its own. Polygons
// come in the file's face order (shape by shape, as the file lists them), one for every
// `f` line, so a face's place in the result is its index in the file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "host/scene/generators.h"

namespace fb89::host {

// Throws SceneError naming the file (and tinyobjloader's message) when it cannot be read,
// and naming the line for a coordinate that is not a finite number or a face of fewer than
// 3 vertices. Elements fb89 does not draw (`l` lines, `p` points) are counted in `notes`.
GeneratedPolygons load_obj(const std::filesystem::path& file,
                           std::vector<std::string>* notes = nullptr);

}  // namespace fb89::host
