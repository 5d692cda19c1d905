// A sea shell: a generating curve swept along a logarithmic helico-spiral (the `shell`
// generator), for the paper's image I, "Sea Shell and Mirrors" (§4, Fig. 4.12).
//
// The model is Raup's (D. M. Raup, "Geometric analysis of shell coiling: general problems",
// J. Paleontology 40, 1966) as Fowler, Meinhardt and Prusinkiewicz use it ("Modeling
// seashells", SIGGRAPH '92): the generating curve turns about the shell's axis and grows
// by the same factor, `growth`, every turn, while it moves along the axis in proportion to
// its distance from it (`translation`), so every part of the shell is a scaled and turned
// copy of every other. Ours differs: the generating curve is an ellipse in the plane through
// the axis (no tilt), there is no sculpture (ribs, spines) and no pigmentation, and the
// surface is emitted as triangles, two per cell, because a cell of a helico-spiral is
// twisted (its two edges across the tube are turned against each other), never a plane quad.
#pragma once

#include <cstddef>

#include "host/scene/generators.h"

namespace fb89::host {

struct ShellOptions {
    int turns = 4;               // whorls from the apex to the aperture
    int segments_per_turn = 24;  // steps along the spiral in one turn
    int sides = 12;              // steps around the tube (the generating curve)
    double growth = 2;           // scale factor per turn, >= 1 (1: a helix of constant tube)
    double size = 1;             // the aperture's outer radius from the axis
    double tube = 0.5;           // tube radius / distance of the tube's centre from the axis, < 1
    double translation = 1.5;    // drop along the axis / distance from it, for the tube's centre
    double aspect = 1;           // the generating curve's extent along the axis / across it
};

// 2 * turns * segments_per_turn * sides triangles and the apex cap.
size_t shell_face_count(const ShellOptions& o);

// The shell about the y axis: the apex is the smallest whorl, nearest the origin, and the
// shell grows downward (towards -y), coiling clockwise seen from above the apex (dextral).
// Face 0 closes the apex: the first generating curve, a planar convex polygon of `sides`
// vertices. Then cell (i, j), step i along the spiral and j around the tube, makes faces
// 1 + 2 * (i * sides + j) and the one after. The aperture is left open. Faces are wound
// consistently (normals out of the tube) and share their vertices exactly.
GeneratedPolygons generate_shell(const ShellOptions& o);

}  // namespace fb89::host
