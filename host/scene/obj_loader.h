// OBJ meshes through tinyobjloader: polygons kept whole (no triangulation by the loader),
// diffuse colours from an .mtl file when the scene gives no colour of its own.
#pragma once

#include <filesystem>

#include "host/scene/generators.h"

namespace fb89::host {

// Throws SceneError naming the file (and tinyobjloader's message) when it cannot be read.
GeneratedPolygons load_obj(const std::filesystem::path& file);

}  // namespace fb89::host
