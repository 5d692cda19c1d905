#include "host/radiosity/pipeline.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "host/radiosity/exact.h"
#include "host/radiosity/form_factors.h"
#include "host/radiosity/hemicube.h"
#include "host/radiosity/patch_scene.h"
#include "host/trace/grid.h"
#include "host/trace/trace_scene.h"

namespace fb89::host {

namespace {

constexpr std::array<NamedFormFactorMethod, 6> kFormFactorMethods{{
    {FormFactorMethod::Flux, "flux", "flux-traced δ, centre point form"},
    {FormFactorMethod::Hybrid, "hybrid", "δ by the decahedral hybrid, same form as flux"},
    {FormFactorMethod::Disk, "disk", "flux-traced δ, disk form (bounded for close patches)"},
    {FormFactorMethod::Exact, "exact", "flux-traced δ, exact polygon-to-polygon factors"},
    {FormFactorMethod::Hemicube, "hemicube", "the hemicube, with its own occlusion"},
    {FormFactorMethod::Hierarchical, "hierarchical",
     "hierarchical radiosity: BF-refined links, k rays each (Hanrahan et al. 1991)"},
}};

bool has_emitter(const Scene& scene) {
    for (const Face& f : scene.faces)
        if (f.material.emission.x > 0 || f.material.emission.y > 0 || f.material.emission.z > 0)
            return true;
    return false;
}

void check_size(const Mesh& mesh, const std::string& what) {
    if (mesh.patches.size() > static_cast<size_t>(kMaxPatches))
        throw std::invalid_argument(
            fmt::format("{}: the mesh has {} patches, more than {} (a dense form-factor "
                        "matrix of N² doubles)",
                        what, mesh.patches.size(), kMaxPatches));
}

std::vector<double> form_factors(const RadiosityOptions& o, const Mesh& mesh,
                                 const Visibility& delta, const WorkObserver& work) {
    HemicubeCounts hemicube;
    switch (o.form_factors) {
        case FormFactorMethod::Hemicube:
            return hemicube_form_factors(mesh, o.hemicube_res, hemicube, work);
        case FormFactorMethod::Exact:
            return exact_form_factors(mesh, delta, work);
        case FormFactorMethod::Disk:
            return centre_form_factors(mesh, delta, CentreForm::Disk, work);
        default:
            return centre_form_factors(mesh, delta, CentreForm::PointToPoint, work);
    }
}

// δ, F and B for the current mesh; times add up over adaptive passes.
void solve_mesh(const RadiosityOptions& o, const RadiosityWorld& world, RadiosityResult& run,
                const RadiosityObserver& observer) {
    auto announce = [&](std::string_view name) {
        if (observer.stage) observer.stage(name);
    };
    Stopwatch clock;
    Visibility delta;
    if (o.form_factors == FormFactorMethod::Hybrid) {
        announce("visibility (decahedral hybrid)");
        delta = decahedral_hybrid(run.mesh, world, {}, run.counts, observer.work);
    } else if (o.form_factors != FormFactorMethod::Hemicube) {
        announce("visibility (flux tracing)");
        delta = flux_tracing(run.mesh, world, run.counts, observer.work);
    }
    run.times.visibility += clock.elapsed();

    clock.restart();
    announce("form factors");
    const std::vector<double> F = form_factors(o, run.mesh, delta, observer.work);
    run.times.form_factors += clock.elapsed();

    clock.restart();
    announce("solving");
    // progressive: max_iterations times N shots, the work of that many sweeps
    const auto shots = static_cast<int>(std::min<int64_t>(
        static_cast<int64_t>(o.max_iterations) * static_cast<int64_t>(run.mesh.patches.size()),
        INT32_MAX));
    run.solution = o.solver == SolverKind::Progressive
                       ? solve_progressive(run.mesh, F, o.tolerance, shots)
                       : solve_gauss_seidel(run.mesh, F, o.tolerance, o.max_iterations);
    run.times.solving += clock.elapsed();
    run.rows = row_sums(F, run.mesh.patches.size());
    run.max_row_sum = run.rows.largest;
}

// Refine where radiosity changes fast and solve again, pass by pass, until nothing is split
// or the mesh would grow too large.
void refine_and_solve(const RadiosityOptions& o, const RadiosityWorld& world, RadiosityResult& run,
                      const RadiosityObserver& observer) {
    for (int pass = 0; o.adaptive > 0 && pass < o.adaptive_passes; ++pass) {
        Stopwatch clock;
        if (observer.stage) observer.stage("refining");
        Mesh refined = refine(run.mesh, run.solution.radiosity, o.adaptive, run.patch_size / 4);
        run.times.meshing += clock.elapsed();
        if (refined.patches.size() == run.mesh.patches.size()) return;
        if (refined.patches.size() > static_cast<size_t>(kMaxPatches)) {
            run.notes.push_back(
                fmt::format("adaptive pass {} would make {} patches, more than {}; stopped "
                            "refining",
                            pass + 1, refined.patches.size(), kMaxPatches));
            return;
        }
        run.mesh = std::move(refined);
        run.patches_per_pass.push_back(run.mesh.patches.size());
        solve_mesh(o, world, run, observer);
    }
}

// The uniform mesh, δ, a dense F and a solver; adaptive passes if asked. `clock` has timed
// the meshing stage so far.
void solve_uniform(const Scene& world, const RadiosityWorld& traced, const RadiosityOptions& o,
                   RadiosityResult& run, Stopwatch& clock, const RadiosityObserver& observer) {
    MeshOptions mesh_options;
    mesh_options.patch_size = run.patch_size;
    run.mesh = mesh_scene(world, mesh_options);
    check_size(run.mesh, "--patches " + std::to_string(o.patches));
    run.patches_per_pass.push_back(run.mesh.patches.size());
    run.times.meshing = clock.elapsed();

    solve_mesh(o, traced, run, observer);
    refine_and_solve(o, traced, run, observer);
}

// Roots one element a face piece; the hierarchy meshes and solves.
void solve_hierarchical(const Scene& world, const RadiosityWorld& traced, const RadiosityOptions& o,
                        RadiosityResult& run, Stopwatch& clock, const RadiosityObserver& observer) {
    MeshOptions roots;
    roots.patch_size = std::numeric_limits<double>::infinity();  // one patch an element
    const Mesh mesh = mesh_scene(world, roots);
    run.times.meshing = clock.elapsed();

    clock.restart();
    if (observer.stage) observer.stage("hierarchical radiosity (links, rays, solving)");
    HierarchicalOptions h = o.hierarchical;
    if (h.min_area == 0) h.min_area = run.patch_size * run.patch_size / 4;
    h.tolerance = o.tolerance;
    h.max_iterations = o.max_iterations;
    HierarchicalResult solved = hierarchical_radiosity(mesh, traced, h, observer.work);
    run.times.form_factors = clock.elapsed();
    run.mesh = std::move(solved.leaves);
    run.patches_per_pass.push_back(run.mesh.patches.size());
    run.solution = std::move(solved.solution);
    run.counts.rays = solved.counts.rays;
    run.rows = solved.rows;
    run.max_row_sum = solved.rows.largest;
    run.hierarchy = solved.counts;
    run.notes = std::move(solved.notes);
}

}  // namespace

std::span<const NamedFormFactorMethod> form_factor_methods() {
    return kFormFactorMethods;
}

std::optional<FormFactorMethod> form_factor_method_named(std::string_view name) {
    for (const auto& m : kFormFactorMethods)
        if (m.name == name) return m.method;
    return std::nullopt;
}

std::string_view to_string(FormFactorMethod method) {
    for (const auto& m : kFormFactorMethods)
        if (m.method == method) return m.name;
    return "?";
}

std::optional<SolverKind> solver_named(std::string_view name) {
    if (name == "gauss-seidel") return SolverKind::GaussSeidel;
    if (name == "progressive") return SolverKind::Progressive;
    return std::nullopt;
}

std::string_view to_string(SolverKind solver) {
    return solver == SolverKind::Progressive ? "progressive" : "gauss-seidel";
}

RadiosityResult solve_radiosity(const Scene& world, const RadiosityOptions& o,
                                const RadiosityObserver& observer) {
    if (world.projection != Projection::Perspective)
        throw std::invalid_argument("radiosity needs a perspective (world-space) scene");
    if (!has_emitter(world))
        throw std::invalid_argument(
            "no face emits light (a material \"emission\"), so its radiosity is black "
            "everywhere");
    RadiosityResult run;
    // the patch size, and the traced scene and grid the rays and queries run in: meshing
    Stopwatch clock;
    if (observer.stage) observer.stage("meshing");
    run.patch_size = patch_size_for(world, o.patches);
    const TraceScene trace(world, false, 0);
    const UniformGrid grid(trace);
    const RadiosityWorld traced{trace, grid};
    if (o.form_factors == FormFactorMethod::Hierarchical)
        solve_hierarchical(world, traced, o, run, clock, observer);
    else
        solve_uniform(world, traced, o, run, clock, observer);

    clock.restart();
    run.exposure =
        o.exposure > 0 ? o.exposure : automatic_exposure(run.mesh, run.solution.radiosity);
    run.patches = patch_scene(world, run.mesh, run.solution.radiosity, run.exposure);
    run.times.patch_scene = clock.elapsed();
    return run;
}

}  // namespace fb89::host
