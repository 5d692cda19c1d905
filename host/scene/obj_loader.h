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

// Throws SceneError naming the file (and tinyobjloader's message) when it cannot be read;
// naming the file and line for a coordinate that is not a finite number, a face of fewer
// than 3 vertices, a vertex index that is not a whole number, is 0 or names no vertex, and
// for a line that is not text (binary bytes); and naming the file, what was read and the
// first line that is no OBJ statement for a file with no `f` line (garbage, another format,
// an empty file). What loads with a word of warning goes to `notes`, each naming the file
// and line: elements fb89 does not draw (`l` lines, `p` points), lines that are no OBJ
// statement (ignored), a material library (`mtllib`) that does not exist and a material
// (`usemtl`) that no library defines (their faces grey).
GeneratedPolygons load_obj(const std::filesystem::path& file,
                           std::vector<std::string>* notes = nullptr);

}  // namespace fb89::host
