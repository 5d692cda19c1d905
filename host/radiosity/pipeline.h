// The paper's §5 pipeline as one typed unit: mesh a world-space scene into patches, decide
// intervisibility δ, estimate form factors, solve for radiosity, optionally refine where
// radiosity changes fast and solve again, and hand back the patches as a flat-shaded scene
// for any raster method. `fb89 radiosity` and the experiments share it.
//
// The form-factor choice decides δ and the estimate together:
//   Flux      δ by flux tracing, centre-to-centre point form (Eq. 5.2, corrected)
//   Hybrid    δ by the decahedral hybrid, the same point form (so the same result as Flux)
//   Disk      δ by flux tracing, Wallace et al.'s disk form (bounded for close patches)
//   Exact     δ by flux tracing, exact unoccluded polygon-to-polygon factors times δ
//   Hemicube  the hemicube, its own occlusion (no δ)
//   Hierarchical  Hanrahan et al.'s hierarchical radiosity (hierarchical.h): links between
//             elements of per-face trees, refined by BF until ε, k visibility rays a link;
//             it meshes as it goes (--patches only sets its smallest element) and solves itself
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "host/radiosity/hierarchical.h"
#include "host/radiosity/mesh.h"
#include "host/radiosity/solver.h"
#include "host/radiosity/visibility.h"
#include "host/scene/scene.h"
#include "host/stats.h"

namespace fb89::host {

enum class FormFactorMethod { Flux, Hybrid, Disk, Exact, Hemicube, Hierarchical };
enum class SolverKind { GaussSeidel, Progressive };

struct NamedFormFactorMethod {
    FormFactorMethod method;
    std::string_view name, description;
};
std::span<const NamedFormFactorMethod> form_factor_methods();
std::optional<FormFactorMethod> form_factor_method_named(std::string_view name);
std::string_view to_string(FormFactorMethod method);
std::optional<SolverKind> solver_named(std::string_view name);  // gauss-seidel, progressive
std::string_view to_string(SolverKind solver);

// A dense N x N form-factor matrix of doubles: 8192 patches take 512 MiB.
inline constexpr int kMaxPatches = 8192;

struct RadiosityOptions {
    FormFactorMethod form_factors = FormFactorMethod::Flux;
    int patches = 800;       // about this many patches in all
    int hemicube_res = 128;  // Hemicube: cells on a side of its top face
    SolverKind solver = SolverKind::GaussSeidel;
    double tolerance = 1e-4;    // of the largest emission
    int max_iterations = 1000;  // sweeps; progressive: this many times N shots
    double adaptive = 0;        // refine where neighbours differ by more (0: never)
    int adaptive_passes = 1;
    double exposure = 0;  // colour = radiosity x exposure (0: automatic)
    // Hierarchical: epsilon, link rays, budgets; its min_area 0 means a quarter of the
    // patch area `patches` asks for (elements down to half the patch side); tolerance and
    // max_iterations are taken from above
    HierarchicalOptions hierarchical;
};

struct RadiosityTimes {
    Timing meshing, visibility, form_factors, solving;
    Timing patch_scene;  // exposure and the patches as faces, the first step of drawing them
};

struct RadiosityResult {
    Mesh mesh;
    double patch_size = 0;
    std::vector<uint64_t> patches_per_pass;  // the first mesh, then each refinement
    VisibilityCounts counts;                 // summed over passes
    RadiositySolution solution;
    double max_row_sum = 0;  // of F; above 1 the point form over-estimates
    RowSums rows;            // of F: the largest, its patch, how many exceed 1
    double exposure = 0;
    RadiosityTimes times;
    std::optional<HierarchicalCounts> hierarchy;  // Hierarchical: its links and elements
    std::vector<std::string> notes;               // what a user should hear (refinement cut short)
    Scene patches;                                // one flat face per patch, coloured by radiosity
};

// Progress: stage(name) as each stage starts, then work(done, total) now and then inside
// the long ones (visibility, form factors). Either may be empty.
struct RadiosityObserver {
    std::function<void(std::string_view)> stage;
    WorkObserver work;
};

// Throws SceneError when the world is not a perspective scene or nothing in it emits, and
// std::invalid_argument when the mesh would exceed kMaxPatches (not Hierarchical, which keeps
// no matrix) or an option is out of range.
RadiosityResult solve_radiosity(const Scene& world, const RadiosityOptions& options,
                                const RadiosityObserver& observer = {});

}  // namespace fb89::host
