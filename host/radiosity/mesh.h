// Radiosity meshing (the paper's §5): every face of the scene cut into patches.
//
// Each face piece becomes one or more *elements*: a planar convex quadrilateral or
// triangle with a bilinear parametrization p(s, t) over [0,1]² (a triangle repeats its last
// corner, so its last row of patches are triangles and the rest trapezoids). A polygon of
// more than four corners is cut into a fan of triangles first. An element is meshed as a
// regular nu x nv grid of patches, patch (i, j) spanning s in [i/nu, (i+1)/nu] and t in
// [j/nv, (j+1)/nv]; every patch is convex and planar. The grid is what the decahedral
// queries split ("the larger face's patch grid into four", uneven halves where a count is
// odd), so a rectangle of patches [i0, i1) x [j0, j1) has a convex outline of its own
// (region_corners).
//
// Adaptive refinement (refine): after a solution, an element whose neighbouring patches
// differ by more than a relative threshold is cut into sub-elements, quadtree fashion over
// its patch grid: regions without a sharp change keep their patches as they were, and each
// patch beside a sharp change becomes a 2 x 2 element of its own. So the mesh grows only
// where radiosity changes fast (shadow edges, the light's surroundings), and a scene is
// modelled no finer than it needs. Neighbours are the patches of one face piece whose
// bounding boxes touch (a grid's eight neighbours, and patches across the borders of
// sub-elements, so a second pass refines a shadow edge again); sub-elements keep their
// element's face, piece and material.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "host/scene/scene.h"

namespace fb89::host {

struct Element {
    uint32_t piece = 0;                 // the face piece it lies on (in Scene::faces order)
    uint32_t face_id = 0;               // the scene face's id
    std::array<glm::dvec3, 4> corners;  // p(0,0), p(1,0), p(1,1), p(0,1)
    glm::dvec3 normal{0, 0, 1};         // unit, Newell's, the face's own orientation
    glm::dvec3 reflectance{0};          // the face's colour
    glm::dvec3 emission{0};
    int nu = 1, nv = 1;
    uint32_t first_patch = 0;  // patch (i, j) is first_patch + j * nu + i

    glm::dvec3 point(double s, double t) const;
    uint32_t patch(int i, int j) const { return first_patch + static_cast<uint32_t>(j * nu + i); }
};

struct Patch {
    uint32_t element = 0;
    int i = 0, j = 0;
    std::array<glm::dvec3, 4> corners;  // a triangle repeats its last corner
    int corner_count = 4;               // 3 or 4 distinct corners
    glm::dvec3 centre{0};               // the centroid
    double area = 0;
};

struct Mesh {
    std::vector<Element> elements;
    std::vector<Patch> patches;
};

struct MeshOptions {
    // Patches of about this many scene units on a side; each element side gets
    // max(1, round(length / patch_size)) patches.
    double patch_size = 1;
    int max_per_side = 64;
};

// Meshes every face of a perspective scene (faces of zero area are skipped).
Mesh mesh_scene(const Scene& scene, const MeshOptions& options);

// The patch size that gives about `target` patches in all for this scene.
double patch_size_for(const Scene& scene, int target);

// The outline of patches [i0, i1) x [j0, j1) of an element: four corners, the last two
// equal where the region reaches a triangle's apex.
std::array<glm::dvec3, 4> region_corners(const Element& e, int i0, int i1, int j0, int j1);

// The part s in [s0, s1] x t in [t0, t1] of an element's parameter square (the apex kept
// exact where the region reaches a triangle's).
std::array<glm::dvec3, 4> region_corners(const Element& e, double s0, double s1, double t0,
                                         double t1);

// A patch's corner count, area and centroid from its corners.
void set_shape(Patch& patch);

// Appends a one-patch element, the part [s0, s1] x [t0, t1] of `parent` (its face, piece and
// material): hierarchical radiosity's leaves as a mesh. Returns its index.
uint32_t add_region_element(Mesh& mesh, const Element& parent, double s0, double s1, double t0,
                            double t1);

// Which patches refine() splits: those with a neighbour (above) whose radiosity differs by more
// than `threshold` relative to the brighter of the two (max |B_a − B_b| over channels / the
// brighter one's largest channel). Pairs darker than 1/1000 of the brightest non-emitting patch are
// left alone, and so are patches whose longest side is at most `min_patch_size`.
std::vector<bool> patches_to_split(const Mesh& mesh, const std::vector<glm::dvec3>& radiosity,
                                   double threshold, double min_patch_size = 0);

// One pass of adaptive refinement (above): a new mesh, the same where nothing is split.
Mesh refine(const Mesh& mesh, const std::vector<glm::dvec3>& radiosity, double threshold,
            double min_patch_size = 0);

}  // namespace fb89::host
