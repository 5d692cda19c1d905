// fb89 radiosity SCENE: the paper's §5 end to end. Load the scene, cut its faces into
// patches, decide intervisibility δ (flux tracing, or the decahedral hybrid), estimate form
// factors, solve for radiosity, then draw one flat face per patch through the Z-buffer into
// the in-memory buffer and hand the commands to the simulated controller, as `fb89 render`
// does. Every stage is timed (wall and CPU) apart; the counters (facing pairs, rays, volume
// queries) are the paper's.
//
// --ff chooses δ and the form-factor estimate together:
//   flux      δ by flux tracing, centre-to-centre point form (Eq. 5.2, corrected)
//   hybrid    δ by the decahedral hybrid, the same point form (so the same image as flux)
//   disk      δ by flux tracing, Wallace et al.'s disk form (bounded for close patches)
//   exact     δ by flux tracing, exact unoccluded polygon-to-polygon factors times δ
//   hemicube  the hemicube, its own occlusion (no δ)
// A scene with no emitting face is an error (exit 2): its radiosity is black everywhere.
// --adaptive T re-meshes where neighbouring patches differ by more than T (relative) and
// solves again, --adaptive-passes times or until nothing more is split.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/common.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "host/radiosity/exact.h"
#include "host/radiosity/form_factors.h"
#include "host/radiosity/hemicube.h"
#include "host/radiosity/mesh.h"
#include "host/radiosity/patch_scene.h"
#include "host/radiosity/solver.h"
#include "host/radiosity/visibility.h"
#include "host/raster/renderer.h"
#include "host/scene/projection.h"
#include "host/scene/scene_loader.h"
#include "host/trace/grid.h"
#include "host/trace/trace_scene.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_writer.h"

namespace fb89::cli {

namespace {

// A dense N x N form-factor matrix of doubles: 8192 patches take 512 MiB.
constexpr int kMaxPatches = 8192;

struct RadiosityArgs {
    std::string scene;
    std::string ff = "flux";
    int patches = 800;
    int hemicube_res = 128;
    std::string solver = "gauss-seidel";
    double tolerance = 1e-4;
    int max_iterations = 1000;
    double adaptive = 0;
    int adaptive_passes = 1;
    double exposure = 0;
    std::string size;
    std::string png, stream, stats;
    std::string profile = std::string(controller::kDefaultProfile);
    bool quiet = false;
};

struct Stages {
    host::Timing load, meshing, visibility, form_factors, solving, rendering, end_to_end;
};

struct RadiosityRun {
    host::Scene world;
    host::Mesh mesh;
    double patch_size = 0;
    std::vector<uint64_t> patches_per_pass;  // the first mesh, then each refinement
    host::VisibilityCounts counts;           // summed over passes
    host::RadiositySolution solution;
    double max_row_sum = 0;
    double exposure = 0;
    Stages times;
    host::Counters counters;
    host::ScreenScene screen;
    protocol::MemoryBuffer commands;
    host::HostStats render_stats;
};

// Stage names on stderr while working, only when it is a terminal.
struct Progress {
    bool on = false;
    void stage(std::string_view name) const {
        if (on) fmt::print(stderr, "\rradiosity: {:<40}", name);
    }
    void done() const {
        if (on) fmt::print(stderr, "\r{:<52}\r", "");
    }
};

bool has_emitter(const host::Scene& scene) {
    for (const host::Face& f : scene.faces)
        if (f.material.emission.x > 0 || f.material.emission.y > 0 || f.material.emission.z > 0)
            return true;
    return false;
}

std::vector<double> form_factors(const RadiosityArgs& args, const host::Mesh& mesh,
                                 const host::Visibility& delta) {
    if (args.ff == "hemicube") return host::hemicube_form_factors(mesh, args.hemicube_res);
    if (args.ff == "exact") return host::exact_form_factors(mesh, delta);
    return host::centre_form_factors(
        mesh, delta, args.ff == "disk" ? host::CentreForm::Disk : host::CentreForm::PointToPoint);
}

// δ, F and B for the current mesh; times add up over adaptive passes.
void solve_mesh(const RadiosityArgs& args, const host::RadiosityWorld& world, RadiosityRun& run,
                const Progress& progress) {
    host::Stopwatch stage;
    host::Visibility delta;
    if (args.ff == "hybrid") {
        progress.stage("visibility (decahedral hybrid)");
        delta = host::decahedral_hybrid(run.mesh, world, {}, run.counts);
    } else if (args.ff != "hemicube") {
        progress.stage("visibility (flux tracing)");
        delta = host::flux_tracing(run.mesh, world, run.counts);
    }
    run.times.visibility += stage.elapsed();

    stage.restart();
    progress.stage("form factors");
    const std::vector<double> F = form_factors(args, run.mesh, delta);
    run.times.form_factors += stage.elapsed();

    stage.restart();
    progress.stage("solving");
    // progressive: --max-iterations times N shots, the work of that many sweeps
    const auto shots = static_cast<int>(std::min<int64_t>(
        static_cast<int64_t>(args.max_iterations) * static_cast<int64_t>(run.mesh.patches.size()),
        INT32_MAX));
    run.solution = args.solver == "progressive"
                       ? host::solve_progressive(run.mesh, F, args.tolerance, shots)
                       : host::solve_gauss_seidel(run.mesh, F, args.tolerance, args.max_iterations);
    run.times.solving += stage.elapsed();
    run.max_row_sum = host::max_row_sum(F, run.mesh.patches.size());
}

void check_size(const host::Mesh& mesh, const std::string& what) {
    if (mesh.patches.size() > static_cast<size_t>(kMaxPatches))
        throw UsageError(
            fmt::format("{}: the mesh has {} patches, more than {} (a dense form-factor "
                        "matrix of N² doubles)",
                        what, mesh.patches.size(), kMaxPatches));
}

host::Scene load_world(const RadiosityArgs& args) {
    host::Scene world = host::load_scene(args.scene);
    if (!args.size.empty()) {
        ImageSize size = parse_size(args.size);
        world.width = size.width;
        world.height = size.height;
    }
    if (world.projection != host::Projection::Perspective)
        throw UsageError(args.scene + ": radiosity needs a perspective (world-space) scene");
    if (!has_emitter(world))
        throw std::runtime_error(
            fmt::format("{}: no face emits light (a material \"emission\"), so its radiosity is "
                        "black everywhere",
                        args.scene));
    return world;
}

// --adaptive: refine where radiosity changes fast and solve again, pass by pass, until
// nothing is split or the mesh would grow too large.
void refine_and_solve(const RadiosityArgs& args, const host::RadiosityWorld& world,
                      RadiosityRun& run, const Console& console, const Progress& progress) {
    for (int pass = 0; args.adaptive > 0 && pass < args.adaptive_passes; ++pass) {
        host::Stopwatch stage;
        progress.stage("refining");
        host::Mesh refined =
            host::refine(run.mesh, run.solution.radiosity, args.adaptive, run.patch_size / 4);
        run.times.meshing += stage.elapsed();
        if (refined.patches.size() == run.mesh.patches.size()) return;
        if (refined.patches.size() > static_cast<size_t>(kMaxPatches)) {
            console.note(
                fmt::format("note: adaptive pass {} would make {} patches, more than {}; "
                            "stopped refining",
                            pass + 1, refined.patches.size(), kMaxPatches));
            return;
        }
        run.mesh = std::move(refined);
        run.patches_per_pass.push_back(run.mesh.patches.size());
        solve_mesh(args, world, run, progress);
    }
}

// The patches as flat faces, through the Z-buffer into the in-memory buffer.
void render_patches(const RadiosityArgs& args, RadiosityRun& run) {
    host::Stopwatch stage;
    run.exposure = args.exposure > 0 ? args.exposure
                                     : host::automatic_exposure(run.mesh, run.solution.radiosity);
    const host::Scene patches =
        host::patch_scene(run.world, run.mesh, run.solution.radiosity, run.exposure);
    std::unique_ptr<host::Renderer> renderer = host::make_renderer(host::RenderOptions{});
    run.screen = host::project_scene(patches, host::ColorMode::Shaded, run.render_stats.counters);
    renderer->setup(run.screen);
    run.render_stats.setup = stage.elapsed();
    host::render_frame(*renderer, run.screen, run.commands, run.render_stats);
    run.render_stats.end_to_end = run.render_stats.setup;
    run.render_stats.end_to_end += run.render_stats.hidden_surface;
    run.times.rendering = stage.elapsed();
}

// The paper's pipeline up to the solution, then the patches through the Z-buffer.
RadiosityRun run_radiosity(const RadiosityArgs& args, const Console& console) {
    Progress progress{!args.quiet && isatty(STDERR_FILENO)};
    RadiosityRun run;
    host::Stopwatch stage;
    run.world = load_world(args);
    run.times.load = stage.elapsed();

    // patches and the grid the rays and queries run in
    stage.restart();
    progress.stage("meshing");
    host::MeshOptions mesh_options;
    run.patch_size = host::patch_size_for(run.world, args.patches);
    mesh_options.patch_size = run.patch_size;
    run.mesh = host::mesh_scene(run.world, mesh_options);
    check_size(run.mesh, "--patches " + std::to_string(args.patches));
    const host::TraceScene trace(run.world, false, 0);
    const host::UniformGrid grid(trace);
    const host::RadiosityWorld world{trace, grid};
    run.patches_per_pass.push_back(run.mesh.patches.size());
    run.times.meshing = stage.elapsed();

    solve_mesh(args, world, run, progress);
    refine_and_solve(args, world, run, console, progress);
    run.counts.publish(run.counters);

    progress.stage("rendering");
    render_patches(args, run);
    progress.done();

    for (const host::Timing& t : {run.times.load, run.times.meshing, run.times.visibility,
                                  run.times.form_factors, run.times.solving, run.times.rendering})
        run.times.end_to_end += t;
    return run;
}

nlohmann::json timing_json(const host::Timing& t) {
    return {{"wall_ms", t.wall_ms}, {"cpu_ms", t.cpu_ms}};
}

nlohmann::json stats_json(const RadiosityArgs& args, const RadiosityRun& run,
                          const controller::Controller& ctl) {
    nlohmann::json j;
    j["tool"] = std::string("fb89 ") + FB89_VERSION;
    j["scene"] = {{"file", args.scene},
                  {"faces", run.world.face_count},
                  {"triangulated", run.world.triangulated},
                  {"dropped", run.world.dropped},
                  {"width", run.screen.width},
                  {"height", run.screen.height}};
    j["radiosity"] = {{"ff", args.ff},
                      {"patches_asked", args.patches},
                      {"patch_size", run.patch_size},
                      {"patches", run.mesh.patches.size()},
                      {"elements", run.mesh.elements.size()},
                      {"solver", args.solver},
                      {"tolerance", args.tolerance},
                      {"iterations", run.solution.iterations},
                      {"residual", run.solution.residual},
                      {"converged", run.solution.converged},
                      {"max_row_sum", run.max_row_sum},
                      {"exposure", run.exposure},
                      {"exposure_automatic", args.exposure == 0}};
    if (args.ff == "hemicube") j["radiosity"]["hemicube_res"] = args.hemicube_res;
    if (args.adaptive > 0)
        j["radiosity"]["adaptive"] = {{"threshold", args.adaptive},
                                      {"passes", args.adaptive_passes},
                                      {"patches_per_pass", run.patches_per_pass}};
    nlohmann::json counters = nlohmann::json::object();
    for (const auto& [name, value] : run.counters.items())
        counters[name] = value;
    j["host"] = {{"times",
                  {{"load", timing_json(run.times.load)},
                   {"meshing", timing_json(run.times.meshing)},
                   {"visibility", timing_json(run.times.visibility)},
                   {"form_factors", timing_json(run.times.form_factors)},
                   {"solving", timing_json(run.times.solving)},
                   {"rendering", timing_json(run.times.rendering)},
                   {"end_to_end", timing_json(run.times.end_to_end)}}},
                 {"counters", counters}};
    j["render"] = run.render_stats.to_json();
    j["render"]["method"] = "zbuffer";
    j["render"]["commands"] = run.commands.size();
    j["controller"] = ctl.stats().to_json();
    return j;
}

std::string summary(const RadiosityArgs& args, const RadiosityRun& run) {
    std::string out =
        fmt::format("scene {}: {} faces, {} patches in {} elements (patch size {:.4g}), {}x{}\n",
                    args.scene, run.world.face_count, run.mesh.patches.size(),
                    run.mesh.elements.size(), run.patch_size, run.screen.width, run.screen.height);
    if (run.patches_per_pass.size() > 1) {
        out += "adaptive:";
        for (uint64_t n : run.patches_per_pass)
            out += fmt::format(" {}", n);
        out += " patches\n";
    }
    out += fmt::format(
        "form factors {}, solver {}: {} {}, residual {:.3g}{}; largest row sum of F "
        "{:.4g}; exposure {:.4g}{}\n",
        args.ff, args.solver, run.solution.iterations,
        args.solver == "progressive" ? "shots" : "sweeps", run.solution.residual,
        run.solution.converged ? "" : " (NOT converged)", run.max_row_sum, run.exposure,
        args.exposure > 0 ? "" : " (automatic)");
    out += "host (wall / CPU):\n";
    auto line = [&](const char* name, const host::Timing& t) {
        out += fmt::format("  {:<16} {:>10.3f} ms {:>10.3f} ms\n", name, t.wall_ms, t.cpu_ms);
    };
    line("load", run.times.load);
    line("meshing", run.times.meshing);
    line("visibility", run.times.visibility);
    line("form factors", run.times.form_factors);
    line("solving", run.times.solving);
    line("rendering", run.times.rendering);
    line("end to end", run.times.end_to_end);
    out += "host counted operations:\n";
    for (const auto& [name, value] : run.counters.items())
        out += fmt::format("  {:<24} {:>14}\n", name, value);
    out += "render of the patches (zbuffer):\n";
    for (const auto& [name, value] : run.render_stats.counters.items())
        out += fmt::format("  {:<24} {:>14}\n", name, value);
    return out;
}

void write_stream(const RadiosityArgs& args, const RadiosityRun& run) {
    make_parent_dirs(args.stream);
    protocol::StreamWriter writer(
        args.stream, {{"scene", args.scene},
                      {"method", "radiosity " + args.ff + " + zbuffer"},
                      {"resolution", fmt::format("{}x{}", run.screen.width, run.screen.height)},
                      {"patches", std::to_string(run.mesh.patches.size())},
                      {"tool", std::string("fb89 ") + FB89_VERSION}});
    run.commands.replay_into(writer);
    writer.close();
}

int run_radiosity_command(const RadiosityArgs& args) {
    Console console{args.quiet};
    controller::CostProfile profile = controller::load_profile(args.profile);
    RadiosityRun run = run_radiosity(args, console);
    for (const auto& note : run.world.notes)
        console.note("note: " + note);
    if (!run.solution.converged)
        console.note(fmt::format(
            "note: the solver stopped after {} {} with residual {:.3g} (tolerance {}); the "
            "largest row sum of F is {:.4g}{}",
            run.solution.iterations, args.solver == "progressive" ? "shots" : "sweeps",
            run.solution.residual, args.tolerance, run.max_row_sum,
            run.max_row_sum > 1 ? " (> 1: try --ff disk, bounded for close patches)" : ""));

    // the controller tiles what the host decided; its cost is modelled, never timed
    controller::Controller ctl(profile);
    run.commands.replay_into(ctl);
    if (!args.png.empty()) {
        make_parent_dirs(args.png);
        controller::write_png(args.png, ctl.framebuffer());
    }
    if (!args.stream.empty()) write_stream(args, run);
    if (!args.stats.empty()) write_json(args.stats, stats_json(args, run, ctl));

    const bool stdout_taken = args.stats == "-" || args.stream == "-";
    if (!args.quiet && !stdout_taken) {
        fmt::print("{}", summary(args, run));
        fmt::print("controller ({}):\n{}", profile.name, ctl.stats().summary());
    }
    return kSuccess;
}

}  // namespace

void register_radiosity(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<RadiosityArgs>();
    CLI::App* sub = app.add_subcommand(
        "radiosity",
        "Radiosity (the paper's §5): patches, intervisibility, form factors, solve, "
        "and the result through the Z-buffer and controller");
    sub->add_option("scene", args->scene, "Scene file (.json) with at least one emitting face")
        ->required();
    sub->add_option("--ff", args->ff,
                    "Form factors: flux (flux-traced δ, centre point form), hybrid (δ by the "
                    "decahedral hybrid, same form), disk (flux δ, disk form), exact (flux δ, exact "
                    "polygon factors) or hemicube")
        ->check(CLI::IsMember({"flux", "hybrid", "hemicube", "exact", "disk"}))
        ->capture_default_str();
    sub->add_option("--patches", args->patches,
                    "About this many patches in all (scenes/README.md gives each scene's value)")
        ->check(CLI::Range(1, kMaxPatches))
        ->capture_default_str();
    CLI::Option* res = sub->add_option("--hemicube-res", args->hemicube_res,
                                       "Hemicube: cells on a side of its top face")
                           ->check(CLI::Range(4, 4096))
                           ->capture_default_str();
    sub->add_option("--solver", args->solver,
                    "gauss-seidel (gathering sweeps) or progressive (shooting, Cohen et al. 1988)")
        ->check(CLI::IsMember({"gauss-seidel", "progressive"}))
        ->capture_default_str();
    sub->add_option("--tolerance", args->tolerance,
                    "Stop when what is still to change is below this fraction of the largest "
                    "emission")
        ->check(CLI::Range(1e-15, 1.0))
        ->capture_default_str();
    sub->add_option("--max-iterations", args->max_iterations,
                    "Gauss-Seidel sweeps at most; progressive: this many times N shots")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    CLI::Option* adaptive =
        sub->add_option("--adaptive", args->adaptive,
                        "Re-mesh where neighbouring patches differ by more than this fraction, "
                        "and solve again")
            ->check(CLI::Range(1e-6, 1e6));
    CLI::Option* passes = sub->add_option("--adaptive-passes", args->adaptive_passes,
                                          "With --adaptive: refinement passes at most")
                              ->check(CLI::Range(1, 8))
                              ->capture_default_str();
    sub->add_option("--exposure", args->exposure,
                    "Colour = radiosity x this, clamped (default: the brightest non-emitting "
                    "patch maps to 1)")
        ->check(CLI::Range(1e-12, 1e12));
    sub->add_option("--size", args->size, "Image size WxH, overriding the scene's");
    sub->add_option("--png", args->png, "Write the controller's framebuffer as PNG");
    sub->add_option("--stream", args->stream, "Record the command stream ('-' for stdout)");
    sub->add_option("--stats", args->stats,
                    "Write host and controller figures as JSON ('-' for stdout)");
    sub->add_option("--profile", args->profile,
                    "Controller cost profile: a built-in name or a .json file")
        ->capture_default_str();
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([args, res, adaptive, passes, &exit_code] {
        if (res->count() > 0 && args->ff != "hemicube")
            throw UsageError("--hemicube-res: only --ff hemicube uses a hemicube");
        if (passes->count() > 0 && adaptive->count() == 0)
            throw UsageError("--adaptive-passes: needs --adaptive THRESHOLD");
        exit_code = run_radiosity_command(*args);
    });
}

}  // namespace fb89::cli
