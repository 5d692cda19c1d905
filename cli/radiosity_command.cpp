// fb89 radiosity SCENE: the paper's §5 end to end. Load the scene, cut its faces into
// patches, decide intervisibility δ (flux tracing, or the decahedral hybrid), estimate form
// factors, solve for radiosity, then draw one flat face per patch through the Z-buffer into
// the in-memory buffer and hand the commands to the simulated controller, as `fb89 render`
// does (--ids / --ids-view: the patch scene's face-id buffer, one id per patch). Every
// stage is timed (wall and CPU) apart; the counters (facing pairs, rays, volume queries)
// are the paper's.
//
// --ff chooses δ and the form-factor estimate together:
//   flux      δ by flux tracing, centre-to-centre point form (Eq. 5.2, corrected)
//   hybrid    δ by the decahedral hybrid, the same point form (so the same image as flux)
//   disk      δ by flux tracing, Wallace et al.'s disk form (bounded for close patches)
//   exact     δ by flux tracing, exact unoccluded polygon-to-polygon factors times δ
//   hemicube  the hemicube, its own occlusion (no δ)
//   hierarchical  hierarchical radiosity (host/radiosity/hierarchical.h): BF-refined links
//             (--epsilon), --link-rays visibility rays each, elements no smaller than
//             --min-area (default: a quarter of the patch area --patches asks for); it
//             meshes and solves itself, so --solver and --adaptive do not apply;
//             --shaft-culling spares the rays of links whose shaft no other piece meets
// A scene with no emitting face is an error (exit 2): its radiosity is black everywhere.
// --adaptive T re-meshes where neighbouring patches differ by more than T (relative) and
// solves again, --adaptive-passes times or until nothing more is split.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "experiments/id_pass.h"
#include "experiments/id_view.h"
#include "experiments/progress.h"
#include "frontend/data_dir.h"
#include "host/methods.h"
#include "host/radiosity/pipeline.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_writer.h"

namespace fb89::cli {

namespace {

struct RadiosityArgs {
    std::string scene;
    std::string ff = std::string(host::to_string(host::RadiosityOptions{}.form_factors));
    host::RadiosityOptions options;
    std::string solver = std::string(host::to_string(host::RadiosityOptions{}.solver));
    std::string size;
    std::string png, ids, ids_view, stream, stats;
    std::string profile = std::string(controller::kDefaultProfile);
    bool quiet = false;
};

struct Stages {
    host::Timing load, rendering, end_to_end;
};

struct RadiosityRun {
    host::Scene world;
    host::RadiosityResult result;
    Stages times;
    host::Counters counters;
    host::ScreenScene screen;
    protocol::MemoryBuffer commands;
    host::HostStats render_stats;
};

host::Scene load_world(const RadiosityArgs& args) {
    host::Scene world = host::load_scene(args.scene);
    if (!args.size.empty()) {
        ImageSize size = parse_size(args.size);
        world.width = size.width;
        world.height = size.height;
    }
    if (world.projection != host::Projection::Perspective)
        throw UsageError(args.scene + ": radiosity needs a perspective (world-space) scene");
    return world;
}

// The patches as flat faces, through the Z-buffer into the in-memory buffer.
void render_patches(RadiosityRun& run) {
    host::Stopwatch stage;
    std::unique_ptr<host::Renderer> renderer = host::make_renderer(host::Method::ZBuffer);
    run.screen =
        host::project_scene(run.result.patches, host::ColorMode::Shaded, run.render_stats.counters);
    renderer->setup(run.screen);
    run.render_stats.setup = stage.elapsed();
    host::render_frame(*renderer, run.screen, run.commands, run.render_stats);
    run.render_stats.end_to_end = run.render_stats.setup;
    run.render_stats.end_to_end += run.render_stats.hidden_surface;
    run.times.rendering = run.result.times.patch_scene;
    run.times.rendering += stage.elapsed();
}

// The paper's pipeline up to the solution (host/radiosity/pipeline.h), then the patches
// through the Z-buffer.
RadiosityRun run_radiosity(const RadiosityArgs& args) {
    experiments::ProgressLine progress(!args.quiet && isatty(STDERR_FILENO));
    RadiosityRun run;
    host::Stopwatch stage;
    run.world = load_world(args);
    run.times.load = stage.elapsed();
    try {
        host::RadiosityObserver observer;
        observer.stage = [&](std::string_view name) {
            progress.start(fmt::format("radiosity: {}", name));
        };
        observer.work = [&](uint64_t done, uint64_t total) { progress.step(done, total); };
        run.result = host::solve_radiosity(run.world, args.options, observer);
    } catch (const std::invalid_argument& e) {
        progress.clear();
        throw UsageError(args.scene + ": " + e.what());
    }
    run.result.counts.publish(run.counters);
    progress.start("radiosity: rendering");
    render_patches(run);
    progress.clear();

    const host::RadiosityTimes& t = run.result.times;
    for (const host::Timing& each :
         {run.times.load, t.meshing, t.visibility, t.form_factors, t.solving, run.times.rendering})
        run.times.end_to_end += each;
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
                      {"patches_asked", args.options.patches},
                      {"patch_size", run.result.patch_size},
                      {"patches", run.result.mesh.patches.size()},
                      {"elements", run.result.mesh.elements.size()},
                      {"solver", args.solver},
                      {"tolerance", args.options.tolerance},
                      {"iterations", run.result.solution.iterations},
                      {"residual", run.result.solution.residual},
                      {"converged", run.result.solution.converged},
                      {"max_row_sum", run.result.max_row_sum},
                      {"exposure", run.result.exposure},
                      {"exposure_automatic", args.options.exposure == 0}};
    if (args.ff == "hemicube") j["radiosity"]["hemicube_res"] = args.options.hemicube_res;
    if (const auto& h = run.result.hierarchy) {
        j["radiosity"]["solver"] = "push-pull";
        j["radiosity"]["hierarchical"] = {
            {"epsilon", args.options.hierarchical.epsilon},
            {"link_rays", args.options.hierarchical.link_rays},
            {"roots", h->roots},
            {"elements", h->nodes},
            {"leaves", h->leaves},
            {"links", h->links},
            {"refinements", h->refinements},
            {"oracle_calls", h->oracle_calls},
            {"link_form_factors", h->form_factors},
            {"rays", h->rays},
            {"shaft_culling", args.options.hierarchical.shaft_culling},
            {"shafts", h->shafts},
            {"shafts_clear", h->shafts_clear},
            {"shaft_tests", h->shaft_tests},
            {"passes", h->passes},
            {"budget_hit", h->budget_hit}};
    }
    if (args.options.adaptive > 0)
        j["radiosity"]["adaptive"] = {{"threshold", args.options.adaptive},
                                      {"passes", args.options.adaptive_passes},
                                      {"patches_per_pass", run.result.patches_per_pass}};
    nlohmann::json counters = nlohmann::json::object();
    for (const auto& [name, value] : run.counters.items())
        counters[name] = value;
    j["host"] = {{"times",
                  {{"load", timing_json(run.times.load)},
                   {"meshing", timing_json(run.result.times.meshing)},
                   {"visibility", timing_json(run.result.times.visibility)},
                   {"form_factors", timing_json(run.result.times.form_factors)},
                   {"solving", timing_json(run.result.times.solving)},
                   {"rendering", timing_json(run.times.rendering)},
                   {"end_to_end", timing_json(run.times.end_to_end)}}},
                 {"counters", counters}};
    j["render"] = run.render_stats.to_json();
    j["render"]["method"] = "zbuffer";
    j["render"]["commands"] = run.commands.size();
    j["controller"] = ctl.stats().to_json();
    return j;
}

// Row sums of F above 1, flagged and explained: how many, by how much, where, and why.
std::string row_sum_flag(const RadiosityArgs& args, const RadiosityRun& run) {
    const host::RowSums& rows = run.result.rows;
    if (rows.above_one == 0) return "";
    const auto& mesh = run.result.mesh;
    const host::Patch& worst = mesh.patches[rows.largest_patch];
    const char* point_form =
        "The centre-to-centre point form over-counts patches close to one another for their "
        "size (it grows as 1/r^2 while a true factor cannot exceed 1), so an excess is "
        "expected along edges where walls meet and where small patches face larger ones "
        "nearby; --ff disk bounds it, and the solver may not converge when it is large.";
    const char* all_or_nothing =
        "Each factor is bounded, but delta is decided at patch centres, all or nothing: a "
        "patch partly hidden behind another counts whole, so both count and a row can exceed "
        "1 where faces stand in front of others; a finer mesh (--patches) lowers it.";
    const char* hemicube =
        "The hemicube's cells are counted whole, so a row can exceed 1 by the rounding of its "
        "resolution; a finer hemicube (--hemicube-res) lowers it.";
    const char* hierarchical =
        "A leaf gathers along its own links and its ancestors', each with the ancestor's mean "
        "factor: where a parent links a source whole, a leaf of it far from that source is "
        "credited the parent's mean, so single rows can exceed 1 while the light sent and "
        "absorbed balance; a smaller --epsilon links finer and lowers it.";
    const char* why = args.ff == "disk" || args.ff == "exact" ? all_or_nothing
                      : args.ff == "hemicube"                 ? hemicube
                      : args.ff == "hierarchical"             ? hierarchical
                                                              : point_form;
    return fmt::format(
        "! {} of {} rows of F sum above 1, the largest by {:.1f}% (patch {}, on face {}). A "
        "patch's row is the share of what it sends that reaches each other patch: at most 1 "
        "in a closed room, less where it is open. {}\n",
        rows.above_one, mesh.patches.size(), 100 * (rows.largest - 1), rows.largest_patch,
        mesh.elements[worst.element].face_id, why);
}

std::string summary(const RadiosityArgs& args, const RadiosityRun& run) {
    std::string out = fmt::format(
        "scene {}: {} faces, {} patches in {} elements (patch size {:.4g}), {}x{}\n", args.scene,
        run.world.face_count, run.result.mesh.patches.size(), run.result.mesh.elements.size(),
        run.result.patch_size, run.screen.width, run.screen.height);
    if (run.result.patches_per_pass.size() > 1) {
        out += "adaptive:";
        for (uint64_t n : run.result.patches_per_pass)
            out += fmt::format(" {}", n);
        out += " patches\n";
    }
    if (const auto& h = run.result.hierarchy)
        out += fmt::format(
            "hierarchy: {} root elements, {} elements, {} leaves, {} links, {} refinements, {} "
            "oracle calls, {} link factors, {} rays, {} passes{}\n",
            h->roots, h->nodes, h->leaves, h->links, h->refinements, h->oracle_calls,
            h->form_factors, h->rays, h->passes, h->budget_hit ? " (budget reached)" : "");
    out += fmt::format(
        "form factors {}, solver {}: {} {}, residual {:.3g}{}; largest row sum of F "
        "{:.4g}; exposure {:.4g}{}\n",
        args.ff, run.result.hierarchy ? "push-pull" : args.solver, run.result.solution.iterations,
        args.solver == "progressive" ? "shots" : "sweeps", run.result.solution.residual,
        run.result.solution.converged ? "" : " (NOT converged)", run.result.max_row_sum,
        run.result.exposure, args.options.exposure > 0 ? "" : " (automatic)");
    out += row_sum_flag(args, run);
    out += "host (wall / CPU):\n";
    auto line = [&](const char* name, const host::Timing& t) {
        out += fmt::format("  {:<16} {:>10.3f} ms {:>10.3f} ms\n", name, t.wall_ms, t.cpu_ms);
    };
    line("load", run.times.load);
    line("meshing", run.result.times.meshing);
    line("visibility", run.result.times.visibility);
    line("form factors", run.result.times.form_factors);
    line("solving", run.result.times.solving);
    line("rendering", run.times.rendering);
    line("end to end", run.times.end_to_end);
    out += "host counted operations:\n";
    out += run.counters.lines();
    out += "render of the patches (zbuffer):\n";
    out += run.render_stats.counters.lines();
    return out;
}

// The face-id buffer of the patch scene, as `render --ids` writes it (id + 1 as 24-bit RGB,
// 0 = background; one id per patch), through the same Z-buffer, and its false-colour view.
void write_id_buffers(const RadiosityArgs& args, const RadiosityRun& run) {
    std::unique_ptr<host::Renderer> renderer = host::make_renderer(host::Method::ZBuffer);
    experiments::write_id_pngs(experiments::id_framebuffer(run.result.patches, *renderer), args.ids,
                               args.ids_view);
}

void write_stream(const RadiosityArgs& args, const RadiosityRun& run) {
    make_parent_dirs(args.stream);
    protocol::StreamWriter writer(
        args.stream, {{"scene", args.scene},
                      {"method", "radiosity " + args.ff + " + zbuffer"},
                      {"resolution", fmt::format("{}x{}", run.screen.width, run.screen.height)},
                      {"patches", std::to_string(run.result.mesh.patches.size())},
                      {"tool", std::string("fb89 ") + FB89_VERSION}});
    run.commands.replay_into(writer);
    writer.close();
}

int run_radiosity_command(const RadiosityArgs& args) {
    Console console{args.quiet};
    const bool stdout_taken = claims_stdout({{"--png", args.png},
                                             {"--ids", args.ids},
                                             {"--ids-view", args.ids_view},
                                             {"--stream", args.stream},
                                             {"--stats", args.stats}});
    controller::CostProfile profile = controller::load_profile(args.profile);
    RadiosityRun run = run_radiosity(args);
    for (const auto& note : run.result.notes)
        console.note("note: " + note);
    for (const auto& note : run.world.notes)
        console.note("note: " + note);
    if (!run.result.solution.converged)
        console.note(fmt::format(
            "note: the solver stopped after {} {} with residual {:.3g} (tolerance {}); the "
            "largest row sum of F is {:.4g}{}",
            run.result.solution.iterations, args.solver == "progressive" ? "shots" : "sweeps",
            run.result.solution.residual, args.options.tolerance, run.result.max_row_sum,
            run.result.max_row_sum > 1 ? " (> 1: try --ff disk, bounded for close patches)" : ""));

    // the controller tiles what the host decided; its cost is modelled, never timed
    controller::Controller ctl(profile);
    run.commands.replay_into(ctl);
    if (!args.png.empty()) {
        make_parent_dirs(args.png);
        controller::write_png(args.png, ctl.framebuffer());
    }
    if (!args.ids.empty() || !args.ids_view.empty()) write_id_buffers(args, run);
    if (!args.stream.empty()) write_stream(args, run);
    if (!args.stats.empty()) write_json(args.stats, stats_json(args, run, ctl));

    if (!args.quiet && !stdout_taken) {
        fmt::print("{}", summary(args, run));
        fmt::print("{}", ctl.stats().summary());  // its first line names the profile
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
    sub->add_option("scene", args->scene,
                    scene_argument_help("Scene with at least one emitting face: a .json file"))
        ->required();
    std::vector<std::string> ff_names;
    std::string ff_help = "Form factors:";
    for (const host::NamedFormFactorMethod& m : host::form_factor_methods()) {
        ff_names.emplace_back(m.name);
        ff_help +=
            fmt::format("{} {} ({})", ff_names.size() == 1 ? "" : ",", m.name, m.description);
    }
    sub->add_option("--ff", args->ff, ff_help)
        ->check(CLI::IsMember(ff_names))
        ->capture_default_str();
    CLI::Option* epsilon =
        sub->add_option("--epsilon", args->options.hierarchical.epsilon,
                        "Hierarchical: refine a link while the radiosity it may carry is above "
                        "this fraction of the largest emission (BF refinement)")
            ->check(CLI::Range(0.0, 1e6))
            ->capture_default_str();
    CLI::Option* link_rays =
        sub->add_option("--link-rays", args->options.hierarchical.link_rays,
                        "Hierarchical: visibility rays per link (1: centre to centre)")
            ->check(CLI::Range(1, 4096))
            ->capture_default_str();
    CLI::Option* min_area =
        sub->add_option("--min-area", args->options.hierarchical.min_area,
                        "Hierarchical: elements of at most this area are not split (default: a "
                        "quarter of the patch area --patches asks for)")
            ->check(CLI::Range(1e-12, 1e12));
    CLI::Option* shafts =
        sub->add_flag("--shaft-culling", args->options.hierarchical.shaft_culling,
                      "Hierarchical: a link whose shaft (Haines and Wallace 1991) no other "
                      "piece meets is clear without its rays; the same result, fewer rays");
    CLI::Option* max_links =
        sub->add_option("--max-links", args->options.hierarchical.max_links,
                        "Hierarchical: stop refining (with a note) at this many links")
            ->check(CLI::Range(uint64_t{1}, uint64_t{200'000'000}))
            ->capture_default_str();
    sub->add_option("--patches", args->options.patches,
                    "About this many patches in all (scenes/README.md gives each scene's value)")
        ->check(CLI::Range(1, host::kMaxPatches))
        ->capture_default_str();
    CLI::Option* res = sub->add_option("--hemicube-res", args->options.hemicube_res,
                                       "Hemicube: cells on a side of its top face")
                           ->check(CLI::Range(4, 4096))
                           ->capture_default_str();
    CLI::Option* solver =
        sub->add_option(
               "--solver", args->solver,
               "gauss-seidel (gathering sweeps) or progressive (shooting, Cohen et al. 1988)")
            ->check(CLI::IsMember({"gauss-seidel", "progressive"}))
            ->capture_default_str();
    sub->add_option("--tolerance", args->options.tolerance,
                    "Stop when what is still to change is below this fraction of the largest "
                    "emission")
        ->check(CLI::Range(1e-15, 1.0))
        ->capture_default_str();
    sub->add_option("--max-iterations", args->options.max_iterations,
                    "Gauss-Seidel sweeps at most; progressive: this many times N shots")
        ->check(CLI::Range(1, 1000000))
        ->capture_default_str();
    CLI::Option* adaptive =
        sub->add_option("--adaptive", args->options.adaptive,
                        "Re-mesh where neighbouring patches differ by more than this fraction, "
                        "and solve again")
            ->check(CLI::Range(1e-6, 1e6));
    CLI::Option* passes = sub->add_option("--adaptive-passes", args->options.adaptive_passes,
                                          "With --adaptive: refinement passes at most")
                              ->check(CLI::Range(1, 8))
                              ->capture_default_str();
    sub->add_option("--exposure", args->options.exposure,
                    "Colour = radiosity x this, clamped (default: the brightest non-emitting "
                    "patch maps to 1)")
        ->check(CLI::Range(1e-12, 1e12));
    sub->add_option("--size", args->size, "Image size WxH, overriding the scene's");
    sub->add_option("--png", args->png, "Write the controller's framebuffer as PNG");
    sub->add_option("--ids", args->ids,
                    "Write the patch scene's face-id buffer as PNG (one id per patch; id + 1 as "
                    "24-bit RGB, 0 = background)");
    sub->add_option("--ids-view", args->ids_view,
                    "Write the patch scene's face-id buffer in false colour as PNG, for people: "
                    "each patch a distinct colour, background black");
    sub->add_option("--stream", args->stream, "Record the command stream ('-' for stdout)");
    sub->add_option("--stats", args->stats,
                    "Write host and controller figures as JSON ('-' for stdout)");
    sub->add_option("--profile", args->profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([=, &exit_code] {
        if (res->count() > 0 && args->ff != "hemicube")
            throw UsageError("--hemicube-res: only --ff hemicube uses a hemicube");
        const bool hierarchical = args->ff == "hierarchical";
        for (const CLI::Option* o : {epsilon, link_rays, min_area, max_links, shafts})
            if (o->count() > 0 && !hierarchical)
                throw UsageError(o->get_name() + ": only --ff hierarchical uses it");
        for (const CLI::Option* o : {solver, adaptive})
            if (o->count() > 0 && hierarchical)
                throw UsageError(o->get_name() +
                                 ": --ff hierarchical meshes and solves itself (gathering along "
                                 "its links with push-pull)");
        if (passes->count() > 0 && adaptive->count() == 0)
            throw UsageError("--adaptive-passes: needs --adaptive THRESHOLD");
        args->options.form_factors = *host::form_factor_method_named(args->ff);
        args->options.solver = *host::solver_named(args->solver);
        args->scene = resolve_scene(args->scene);
        exit_code = run_radiosity_command(*args);
    });
}

}  // namespace fb89::cli
