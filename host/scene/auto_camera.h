// The camera and light of a bare OBJ model (a `.obj` file given where a scene is expected):
// the model seen whole from the +x +y +z diagonal, lit from over the camera's left shoulder
// (scenes/README.md, "A bare OBJ model"). The camera follows gluLookAt + gluPerspective as
// every scene's does (host/scene/projection.h).
#pragma once

#include <string>

#include "host/scene/scene.h"

namespace fb89::host {

// The margin around the model: its bounding sphere fills 1 / kFrameMargin of the smaller
// half-angle of the view.
inline constexpr double kFrameMargin = 1.1;

// Sets `scene`'s camera, light and background to frame its faces (at least one, with a
// vertex apart from the others) in its image: the camera on the diagonal through the centre
// of their bounding box, fovy 45, at the distance where the bounding sphere (about that
// centre) fits both the image's height and its width with the margin, near and far just
// outside the sphere; a directional light from over the camera's left shoulder, ambient 0.3;
// a dark blue-grey background. Returns what it chose, as one line for the scene's notes.
std::string frame_automatically(Scene& scene);

}  // namespace fb89::host
