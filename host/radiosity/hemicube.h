// The hemicube (Cohen and Greenberg 1985), the paper's baseline for form factors: a
// five-sided box over each patch centre, every other patch projected onto its faces and
// Z-buffered at `resolution` x `resolution` cells on the top face (half that high on the
// sides), each cell adding its precomputed delta form factor to the patch it sees.
#pragma once

#include <cstdint>
#include <vector>

#include "host/radiosity/mesh.h"
#include "host/radiosity/visibility.h"

namespace fb89::host {

// The dense N x N matrix of form_factors.h; occlusion comes from the hemicube's own
// Z-buffer over every patch of the mesh. `resolution` is even.
std::vector<double> hemicube_form_factors(const Mesh& mesh, int resolution);

// What the hemicubes cost, added once per call.
struct HemicubeCounts {
    uint64_t patches_rasterised = 0;  // (patch, hemicube face) pairs that covered a cell
    uint64_t cells_tested = 0;        // depth tests: cells covered by some patch
};
std::vector<double> hemicube_form_factors(const Mesh& mesh, int resolution, HemicubeCounts& counts,
                                          const WorkObserver& work = {});

}  // namespace fb89::host
