// The growth benchmark's scene ladder: one seeded terrain (host/scene/generators.h,
// `terrain`) seen in perspective from above its near edge, at 4^k times as many faces from
// rung to rung (1,024, 4,096, ... 1,048,576), as scene files the project's own loader reads:
// the generator itself, or the same terrain written as an indexed OBJ mesh and read back
// through host/scene/obj_loader. A terrain suits raster and ray methods alike: faces large
// near the camera and far below a pixel at the back, hills hiding what lies behind them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "host/scene/generators.h"

namespace fb89::growth {

inline constexpr uint64_t kLadderSeed = 1989;

// Rung n: a terrain of 2n x n cells, two triangles each, 4 n^2 faces.
struct Rung {
    int n = 0;
    uint64_t faces() const { return 4 * static_cast<uint64_t>(n) * static_cast<uint64_t>(n); }
    host::TerrainOptions terrain() const;
};

// The rungs with min_faces <= faces <= max_faces, n a power of two, smallest first.
std::vector<Rung> ladder(uint64_t min_faces, uint64_t max_faces);

// Writes the rung's scene file into `dir`: the terrain generator, or (with `obj`) an object
// reading `obj` (a file name beside the scene). Returns its path.
std::filesystem::path write_scene(const Rung& rung, const std::filesystem::path& dir,
                                  const std::string& obj = {});

// Writes the rung's terrain as an OBJ mesh (shared vertices, one `f` line per face);
// returns the file's size in bytes.
uint64_t write_obj(const Rung& rung, const std::filesystem::path& file);

// The OBJ text of any polygons: each distinct vertex once (exact equality), in order of
// first use, written so it reads back to the same single-precision value tinyobjloader keeps.
std::string obj_text(const host::GeneratedPolygons& polygons, const std::string& comment);

}  // namespace fb89::growth
