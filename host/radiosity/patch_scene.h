// A radiosity solution as a scene the raster pipeline can draw (the paper's Figs. 5.7 and
// 5.8): one flat face per patch, coloured by its radiosity, seen by the world scene's camera
// at its image size. The light's ambient is 1, so projection shows every colour unshaded
// (flat Lambertian with ambient 1 is the colour itself); nothing is emitted. Patches keep
// their element's winding; the raster pipeline is two-sided anyway. Where a coarse patch meets
// finer ones, their corners are added to its edges, so that no pixel between them is missed.
//
// Tone mapping: linear, colour = radiosity × exposure, clamped to [0, 1]. With exposure 0
// (automatic) the non-emitting patches map to 1 at the level that 99% of their area lies at
// or below (by each patch's largest channel): the brightest 1% of the lit surface (a window
// sill, a hot spot under a lamp) clips to full colour, as do the emitters. Taking the very
// brightest patch instead leaves most of a room dark whenever one small patch sits close
// to a light.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "host/radiosity/mesh.h"
#include "host/scene/scene.h"

namespace fb89::host {

// The area fraction of the non-emitting patches that the automatic exposure keeps unclipped.
inline constexpr double kExposedArea = 0.99;

// 1 / the radiosity level (largest channel) that kExposedArea of the non-emitting patches'
// area lies at or below (of all patches when every one emits); 1 when everything is black.
double automatic_exposure(const Mesh& mesh, const std::vector<glm::dvec3>& radiosity);

// Inserts into each face's edges the corners of other faces that lie inside them (a coarse
// patch beside finer ones, as hierarchical and adaptive meshes make): the T-junctions whose
// corners the raster pipeline would otherwise round apart, leaving pixels between the faces
// uncovered. The faces' shapes are unchanged; only collinear corners are added.
void close_t_junctions(std::vector<Face>& faces);

// Face k is patch k (id k, object = its element); face_count is the patch count. Its faces'
// T-junctions are closed (close_t_junctions), so patches that meet cover every pixel between
// them.
Scene patch_scene(const Scene& world, const Mesh& mesh, const std::vector<glm::dvec3>& radiosity,
                  double exposure = 0);

}  // namespace fb89::host
