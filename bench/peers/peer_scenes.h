// The scenes the llvmpipe harness and the peer tests render, each projected to screen space
// in face-id mode. Every vertex of every scene lies on screen (llvmpipe's clipper differs
// from ours at the borders, REFERENCES.md), so the face-id buffers can agree exactly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "host/scene/screen_scene.h"

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

// A scene file (.json or .tri), loaded and projected.
PeerScene file_scene(const std::filesystem::path& file);

}  // namespace fb89::peers
