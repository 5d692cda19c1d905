// Procedural scene objects: `box`, `quad`, the paper's ideal scene (§2, Fig. 2.3) and random
// triangles here; surfaces of revolution (`lathe`, `sphere`) in lathe.h; a sea shell swept
// along a logarithmic helico-spiral (`shell`, for the paper's image I, §4) in shell.h; copies
// of a group of parts (`array`, `scatter`) in copies.h; a seeded height field (`terrain`, the
// growth benchmark's scene ladder, bench/growth) here. Later methods add their own beside
// these.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "host/scene/json_fields.h"
#include "host/scene/scene.h"

namespace fb89::host {

struct GeneratedPolygon {
    std::vector<glm::dvec3> vertices;
    std::optional<glm::dvec3> color;  // overrides the object's material colour when set
};
using GeneratedPolygons = std::vector<GeneratedPolygon>;

// Axis-aligned box between two corners: 6 quads.
GeneratedPolygons generate_box(const glm::dvec3& lo, const glm::dvec3& hi);

// Parallelogram origin, origin+u, origin+u+v, origin+v split into nu x nv cells, each one
// quad or (with `triangles`) two triangles. Scene files may add "checker": two colours
// alternating cell by cell.
GeneratedPolygons generate_quad(const glm::dvec3& origin, const glm::dvec3& u, const glm::dvec3& v,
                                int nu, int nv, bool triangles);

// The ideal scene, in screen space: `layers` identical layers of square faces on a grid of
// cell x cell pixel cells; each face is flush with the right and bottom borders of its cell
// and leaves a `gap`-pixel gap on its left and top (the paper's ½ pixel). Layer k lies at
// depth (k + 1) / (layers + 1). Faces are numbered layer by layer, row by row.
GeneratedPolygons generate_ideal(int width, int height, int layers, double cell_w, double cell_h,
                                 double gap);

// The ideal scene as a whole screen-space scene of `width` x `height`: generate_ideal()'s
// faces, ids in their order, in the material's default colour.
Scene ideal_scene(int width, int height, int layers, double cell_w, double cell_h, double gap);

// `count` random triangles in screen space, each of about `area` pixels, centres uniform
// over the screen, vertex depths uniform in [0, 1] (so they slope and cut through each
// other). The same seed gives the same triangles.
GeneratedPolygons generate_random_triangles(int width, int height, int count, double area,
                                            uint64_t seed);

// A seeded height field over the xz plane, centred on the origin: cells_x x cells_z cells
// over size_x x size_z, each cell two triangles, 2 * cells_x * cells_z faces in all; cell
// (i, k), i along x and k along z, makes faces 2 * (k * cells_x + i) and the one after. The
// height is a sum of `octaves` fields of bumps (products of two sine waves across each
// other, turned by a random angle, with random phases), each of twice the frequency and half
// the amplitude of the one before, scaled so that it stays within
// +-height / 2; faces are coloured by height (grass, rock, snow) and wound with normals
// upward (+y). Neighbouring faces share their vertices exactly. The same seed gives the same
// terrain on every machine with the same libm.
struct TerrainOptions {
    int cells_x = 64;
    int cells_z = 32;
    double size_x = 4;
    double size_z = 2;
    double height = 0.5;
    int octaves = 6;
    uint64_t seed = 1;
};
size_t terrain_face_count(const TerrainOptions& o);
GeneratedPolygons generate_terrain(const TerrainOptions& o);

// Reads an object's generator fields and builds it. Errors name the field. The parts of an
// `array` or `scatter` are generator objects read by this same function.
GeneratedPolygons generate_from_json(const JsonFields& object, const Scene& scene);

}  // namespace fb89::host
