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
// The run itself, its checks and what is printed of it are frontend/radiosity_run.h's, shared
// with the Python module (fb89.radiosity); this file reads the options and writes the outputs.
#include <unistd.h>

#include <cstdint>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/commands.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "experiments/id_view.h"
#include "frontend/data_dir.h"
#include "frontend/radiosity_run.h"

namespace fb89::cli {

namespace {

namespace limits = frontend::limits;

struct RadiosityArgs {
    frontend::RadiosityRequest request;
    std::string png, ids, ids_view, stream, stats;
    bool quiet = false;
};

int run_radiosity_command(RadiosityArgs& args) {
    const frontend::RadiosityRequest& r = args.request;
    Console console{args.quiet};
    const bool stdout_taken = claims_stdout({{"--png", args.png},
                                             {"--ids", args.ids},
                                             {"--ids-view", args.ids_view},
                                             {"--stream", args.stream},
                                             {"--stats", args.stats}});
    controller::CostProfile profile = controller::load_profile(r.profile);
    args.request.progress = !args.quiet && isatty(STDERR_FILENO);
    const frontend::RadiosityRun run = frontend::run_radiosity(r);
    for (const std::string& note : frontend::radiosity_notes(r, run))
        console.note(note);

    // the controller tiles what the host decided; its cost is modelled, never timed
    controller::Controller ctl(profile);
    run.commands.replay_into(ctl);
    if (!args.png.empty()) {
        make_parent_dirs(args.png);
        controller::write_png(args.png, ctl.framebuffer());
    }
    if (!args.ids.empty() || !args.ids_view.empty())
        experiments::write_id_pngs(frontend::radiosity_id_buffer(run), args.ids, args.ids_view);
    if (!args.stream.empty()) frontend::write_radiosity_stream(r, run, args.stream);
    if (!args.stats.empty()) write_json(args.stats, frontend::radiosity_stats(r, run, ctl));

    if (!args.quiet && !stdout_taken) {
        fmt::print("{}", frontend::radiosity_summary(r, run));
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
    sub->add_option("scene", args->request.scene,
                    scene_argument_help("Scene with at least one emitting face: a .json file"))
        ->required();
    std::vector<std::string> ff_names;
    std::string ff_help = "Form factors:";
    for (const host::NamedFormFactorMethod& m : host::form_factor_methods()) {
        ff_names.emplace_back(m.name);
        ff_help +=
            fmt::format("{} {} ({})", ff_names.size() == 1 ? "" : ",", m.name, m.description);
    }
    sub->add_option("--ff", args->request.ff, ff_help)
        ->check(CLI::IsMember(ff_names))
        ->capture_default_str();
    CLI::Option* epsilon =
        sub->add_option("--epsilon", args->request.options.hierarchical.epsilon,
                        "Hierarchical: refine a link while the radiosity it may carry is above "
                        "this fraction of the largest emission (BF refinement)")
            ->check(frontend::cli_check(limits::kEpsilon))
            ->capture_default_str();
    CLI::Option* link_rays =
        sub->add_option("--link-rays", args->request.options.hierarchical.link_rays,
                        "Hierarchical: visibility rays per link (1: centre to centre)")
            ->check(frontend::cli_check(limits::kLinkRays))
            ->capture_default_str();
    CLI::Option* min_area =
        sub->add_option("--min-area", args->request.options.hierarchical.min_area,
                        "Hierarchical: elements of at most this area are not split (default: a "
                        "quarter of the patch area --patches asks for)")
            ->check(frontend::cli_check(limits::kMinArea));
    CLI::Option* shafts =
        sub->add_flag("--shaft-culling", args->request.options.hierarchical.shaft_culling,
                      "Hierarchical: a link whose shaft (Haines and Wallace 1991) no other "
                      "piece meets is clear without its rays; the same result, fewer rays");
    CLI::Option* max_links =
        sub->add_option("--max-links", args->request.options.hierarchical.max_links,
                        "Hierarchical: stop refining (with a note) at this many links")
            ->check(frontend::cli_check(limits::kMaxLinks))
            ->capture_default_str();
    sub->add_option("--patches", args->request.options.patches,
                    "About this many patches in all (scenes/README.md gives each scene's value)")
        ->check(frontend::cli_check(limits::kRadiosityPatches))
        ->capture_default_str();
    CLI::Option* res = sub->add_option("--hemicube-res", args->request.options.hemicube_res,
                                       "Hemicube: cells on a side of its top face")
                           ->check(frontend::cli_check(limits::kHemicubeRes))
                           ->capture_default_str();
    CLI::Option* solver =
        sub->add_option(
               "--solver", args->request.solver,
               "gauss-seidel (gathering sweeps) or progressive (shooting, Cohen et al. 1988)")
            ->check(CLI::IsMember({"gauss-seidel", "progressive"}))
            ->capture_default_str();
    sub->add_option("--tolerance", args->request.options.tolerance,
                    "Stop when what is still to change is below this fraction of the largest "
                    "emission")
        ->check(frontend::cli_check(limits::kSolverTolerance))
        ->capture_default_str();
    sub->add_option("--max-iterations", args->request.options.max_iterations,
                    "Gauss-Seidel sweeps at most; progressive: this many times N shots")
        ->check(frontend::cli_check(limits::kMaxIterations))
        ->capture_default_str();
    CLI::Option* adaptive =
        sub->add_option("--adaptive", args->request.options.adaptive,
                        "Re-mesh where neighbouring patches differ by more than this fraction, "
                        "and solve again")
            ->check(frontend::cli_check(limits::kAdaptive));
    CLI::Option* passes =
        sub->add_option("--adaptive-passes", args->request.options.adaptive_passes,
                        "With --adaptive: refinement passes at most")
            ->check(frontend::cli_check(limits::kAdaptivePasses))
            ->capture_default_str();
    sub->add_option("--exposure", args->request.options.exposure,
                    "Colour = radiosity x this, clamped (default: the brightest non-emitting "
                    "patch maps to 1)")
        ->check(frontend::cli_check(limits::kExposure));
    sub->add_option("--size", args->request.size, "Image size WxH, overriding the scene's");
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
    sub->add_option("--profile", args->request.profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([=, &exit_code] {
        frontend::RadiosityGiven given;
        given.hemicube_res = res->count() > 0;
        given.epsilon = epsilon->count() > 0;
        given.link_rays = link_rays->count() > 0;
        given.min_area = min_area->count() > 0;
        given.max_links = max_links->count() > 0;
        given.shaft_culling = shafts->count() > 0;
        given.solver = solver->count() > 0;
        given.adaptive = adaptive->count() > 0;
        given.adaptive_passes = passes->count() > 0;
        frontend::prepare_radiosity(args->request, given);
        args->request.scene = resolve_scene(args->request.scene);
        exit_code = run_radiosity_command(*args);
    });
}

}  // namespace fb89::cli
