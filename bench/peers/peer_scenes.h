// The scenes the llvmpipe harness and the peer tests render, each projected to screen space
// in face-id mode. Every vertex of every scene lies on screen (llvmpipe's clipper differs
// from ours at the borders, REFERENCES.md), so the face-id buffers can agree exactly.
// The Embree harness's scenes (RayScene) keep their world scene too, for the ray tracers.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "host/raster/screen_scene.h"
#include "host/scene/scene.h"

namespace fb89::peers {

struct PeerScene {
    std::string name;
    host::ScreenScene screen;
};

// The paper's ideal scene at width x height: an n x n grid of cells (n = sqrt(f_v)), each
// holding a face flush with its right and bottom borders and a half-pixel gap on its left
// and top, in `layers` layers at distinct depths. f_v must be a perfect square.
PeerScene ideal_scene(int width, int height, int layers, int f_v);

// `count` seeded random triangles of about `area` pixels at width x height, shaped as
// host::generate_random_triangles makes them (three directions around a centre, vertices on
// the 1/256 grid, vertex depths uniform in [0, 1], so they slope and cut through each
// other), except that each centre is drawn at least the triangle's radius from every border
// so all three vertices stay on screen.
PeerScene random_onscreen_triangles(int width, int height, int count, double area, uint64_t seed);

// A scene file (.json or .tri), loaded and projected; named by its stem ("A", "random_large_flat").
PeerScene file_scene(const std::filesystem::path& file);

// A world scene and its face-id projection (background black, so a miss reads as id + 1 =
// 0). The Scene lives on the heap because `screen.world` points at it.
struct RayScene {
    std::string name;
    std::unique_ptr<host::Scene> world;
    host::ScreenScene screen;
};

// A scene file rendered at width x height (the camera and field of view as the file gives
// them).
RayScene ray_file_scene(const std::filesystem::path& file, int width, int height);

// `count` seeded random triangles in the cube [-1, 1]^3 (centres uniform, vertices 0.2 from
// the centre in uniform random directions, random colours), seen from (0, 0, 3.5) looking at
// the origin with a 45 degree field of view.
RayScene random_world_triangles(int width, int height, int count, uint64_t seed);

}  // namespace fb89::peers
