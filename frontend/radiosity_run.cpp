// `fb89 radiosity` as a library (frontend/radiosity_run.h): what the command line and the
// Python module share, from reading the scene to the summary the command prints.
#include "frontend/radiosity_run.h"

#include <memory>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "experiments/id_pass.h"
#include "experiments/progress.h"
#include "frontend/common.h"
#include "host/methods.h"
#include "host/scene/scene_loader.h"
#include "protocol/stream_writer.h"

namespace fb89::frontend {

namespace {

// An option as the front end spells it: --hemicube-res or hemicube_res.
std::string spelled(const RadiosityRequest& r, std::string_view option) {
    if (r.spelling == Spelling::Option) return std::string(option);
    std::string keyword(option.substr(2));
    for (char& c : keyword)
        if (c == '-') c = '_';
    return keyword;
}

// --ff hierarchical, or ff='hierarchical'
std::string ff_named(const RadiosityRequest& r, std::string_view name) {
    return r.spelling == Spelling::Option ? fmt::format("--ff {}", name)
                                          : fmt::format("ff='{}'", name);
}

host::Scene load_world(const RadiosityRequest& r) {
    host::Scene world = host::load_scene(r.scene);
    if (!r.size.empty()) {
        const ImageSize size = parse_size(r.size, r.spelling);
        world.width = size.width;
        world.height = size.height;
    }
    if (world.projection != host::Projection::Perspective)
        throw UsageError(r.scene + ": radiosity needs a perspective (world-space) scene");
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

nlohmann::json timing_json(const host::Timing& t) {
    return {{"wall_ms", t.wall_ms}, {"cpu_ms", t.cpu_ms}};
}

const char* kPointForm =
    "The centre-to-centre point form over-counts patches close to one another for their "
    "size (it grows as 1/r^2 while a true factor cannot exceed 1), so an excess is "
    "expected along edges where walls meet and where small patches face larger ones "
    "nearby; --ff disk bounds it, and the solver may not converge when it is large.";
const char* kAllOrNothing =
    "Each factor is bounded, but delta is decided at patch centres, all or nothing: a "
    "patch partly hidden behind another counts whole, so both count and a row can exceed "
    "1 where faces stand in front of others; a finer mesh (--patches) lowers it.";
const char* kHemicube =
    "The hemicube's cells are counted whole, so a row can exceed 1 by the rounding of its "
    "resolution; a finer hemicube (--hemicube-res) lowers it.";
const char* kHierarchical =
    "A leaf gathers along its own links and its ancestors', each with the ancestor's mean "
    "factor: where a parent links a source whole, a leaf of it far from that source is "
    "credited the parent's mean, so single rows can exceed 1 while the light sent and "
    "absorbed balance; a smaller --epsilon links finer and lowers it.";

// Row sums of F above 1, flagged and explained: how many, by how much, where, and why.
std::string row_sum_flag(const RadiosityRequest& r, const RadiosityRun& run) {
    const host::RowSums& rows = run.result.rows;
    if (rows.above_one == 0) return "";
    const auto& mesh = run.result.mesh;
    const host::Patch& worst = mesh.patches[rows.largest_patch];
    const char* why = r.ff == "disk" || r.ff == "exact" ? kAllOrNothing
                      : r.ff == "hemicube"              ? kHemicube
                      : r.ff == "hierarchical"          ? kHierarchical
                                                        : kPointForm;
    return fmt::format(
        "! {} of {} rows of F sum above 1, the largest by {:.1f}% (patch {}, on face {}). A "
        "patch's row is the share of what it sends that reaches each other patch: at most 1 "
        "in a closed room, less where it is open. {}\n",
        rows.above_one, mesh.patches.size(), 100 * (rows.largest - 1), rows.largest_patch,
        mesh.elements[worst.element].face_id, why);
}

const char* iterations_unit(const RadiosityRequest& r) {
    return r.solver == "progressive" ? "shots" : "sweeps";
}

}  // namespace

void prepare_radiosity(RadiosityRequest& r, const RadiosityGiven& given) {
    const auto method = host::form_factor_method_named(r.ff);
    if (!method) {
        std::vector<std::string> known;
        for (const host::NamedFormFactorMethod& m : host::form_factor_methods())
            known.emplace_back(m.name);
        throw UsageError(fmt::format("{}: '{}' is none of the form factors{}", spelled(r, "--ff"),
                                     r.ff, nearest_hint(r.ff, known)));
    }
    const auto solver = host::solver_named(r.solver);
    if (!solver)
        throw UsageError(fmt::format("{}: '{}': gauss-seidel or progressive{}",
                                     spelled(r, "--solver"), r.solver,
                                     nearest_hint(r.solver, {"gauss-seidel", "progressive"})));
    if (given.hemicube_res && r.ff != "hemicube")
        throw UsageError(spelled(r, "--hemicube-res") + ": only " + ff_named(r, "hemicube") +
                         " uses a hemicube");
    const bool hierarchical = r.ff == "hierarchical";
    const std::pair<bool, std::string_view> hierarchy_options[] = {
        {given.epsilon, "--epsilon"},
        {given.link_rays, "--link-rays"},
        {given.min_area, "--min-area"},
        {given.max_links, "--max-links"},
        {given.shaft_culling, "--shaft-culling"}};
    for (const auto& [is_given, option] : hierarchy_options)
        if (is_given && !hierarchical)
            throw UsageError(spelled(r, option) + ": only " + ff_named(r, "hierarchical") +
                             " uses it");
    const std::pair<bool, std::string_view> solver_options[] = {{given.solver, "--solver"},
                                                                {given.adaptive, "--adaptive"}};
    for (const auto& [is_given, option] : solver_options)
        if (is_given && hierarchical)
            throw UsageError(spelled(r, option) + ": " + ff_named(r, "hierarchical") +
                             " meshes and solves itself (gathering along its links with "
                             "push-pull)");
    if (given.adaptive_passes && !given.adaptive)
        throw UsageError(spelled(r, "--adaptive-passes") + ": needs " +
                         (r.spelling == Spelling::Option ? "--adaptive THRESHOLD" : "adaptive="));
    r.options.form_factors = *method;
    r.options.solver = *solver;
}

RadiosityRun run_radiosity(const RadiosityRequest& r) {
    experiments::ProgressLine progress(r.progress);
    RadiosityRun run;
    host::Stopwatch stage;
    run.world = load_world(r);
    run.times.load = stage.elapsed();
    try {
        host::RadiosityObserver observer;
        observer.stage = [&](std::string_view name) {
            progress.start(fmt::format("radiosity: {}", name));
        };
        observer.work = [&](uint64_t done, uint64_t total) { progress.step(done, total); };
        run.result = host::solve_radiosity(run.world, r.options, observer);
    } catch (const std::invalid_argument& e) {
        progress.clear();
        throw UsageError(r.scene + ": " + e.what());
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

std::vector<std::string> radiosity_notes(const RadiosityRequest& r, const RadiosityRun& run) {
    std::vector<std::string> out;
    for (const auto& note : run.result.notes)
        out.push_back("note: " + note);
    for (const auto& note : run.world.notes)
        out.push_back("note: " + note);
    const host::RadiositySolution& s = run.result.solution;
    if (!s.converged)
        out.push_back(fmt::format(
            "note: the solver stopped after {} {} with residual {:.3g} (tolerance {}); the "
            "largest row sum of F is {:.4g}{}",
            s.iterations, iterations_unit(r), s.residual, r.options.tolerance,
            run.result.max_row_sum,
            run.result.max_row_sum > 1 ? " (> 1: try --ff disk, bounded for close patches)" : ""));
    return out;
}

nlohmann::json radiosity_stats(const RadiosityRequest& r, const RadiosityRun& run,
                               const controller::Controller& ctl) {
    nlohmann::json j;
    j["tool"] = std::string("fb89 ") + FB89_VERSION;
    j["scene"] = {{"file", r.scene},
                  {"faces", run.world.face_count},
                  {"triangulated", run.world.triangulated},
                  {"dropped", run.world.dropped},
                  {"width", run.screen.width},
                  {"height", run.screen.height}};
    const host::RadiosityResult& res = run.result;
    j["radiosity"] = {{"ff", r.ff},
                      {"patches_asked", r.options.patches},
                      {"patch_size", res.patch_size},
                      {"patches", res.mesh.patches.size()},
                      {"elements", res.mesh.elements.size()},
                      {"solver", r.solver},
                      {"tolerance", r.options.tolerance},
                      {"iterations", res.solution.iterations},
                      {"residual", res.solution.residual},
                      {"converged", res.solution.converged},
                      {"max_row_sum", res.max_row_sum},
                      {"exposure", res.exposure},
                      {"exposure_automatic", r.options.exposure == 0}};
    if (r.ff == "hemicube") j["radiosity"]["hemicube_res"] = r.options.hemicube_res;
    if (const auto& h = res.hierarchy) {
        j["radiosity"]["solver"] = "push-pull";
        j["radiosity"]["hierarchical"] = {{"epsilon", r.options.hierarchical.epsilon},
                                          {"link_rays", r.options.hierarchical.link_rays},
                                          {"roots", h->roots},
                                          {"elements", h->nodes},
                                          {"leaves", h->leaves},
                                          {"links", h->links},
                                          {"refinements", h->refinements},
                                          {"oracle_calls", h->oracle_calls},
                                          {"link_form_factors", h->form_factors},
                                          {"rays", h->rays},
                                          {"shaft_culling", r.options.hierarchical.shaft_culling},
                                          {"shafts", h->shafts},
                                          {"shafts_clear", h->shafts_clear},
                                          {"shaft_tests", h->shaft_tests},
                                          {"passes", h->passes},
                                          {"budget_hit", h->budget_hit}};
    }
    if (r.options.adaptive > 0)
        j["radiosity"]["adaptive"] = {{"threshold", r.options.adaptive},
                                      {"passes", r.options.adaptive_passes},
                                      {"patches_per_pass", res.patches_per_pass}};
    nlohmann::json counters = nlohmann::json::object();
    for (const auto& [name, value] : run.counters.items())
        counters[name] = value;
    j["host"] = {{"times",
                  {{"load", timing_json(run.times.load)},
                   {"meshing", timing_json(res.times.meshing)},
                   {"visibility", timing_json(res.times.visibility)},
                   {"form_factors", timing_json(res.times.form_factors)},
                   {"solving", timing_json(res.times.solving)},
                   {"rendering", timing_json(run.times.rendering)},
                   {"end_to_end", timing_json(run.times.end_to_end)}}},
                 {"counters", counters}};
    j["render"] = run.render_stats.to_json();
    j["render"]["method"] = "zbuffer";
    j["render"]["commands"] = run.commands.size();
    j["controller"] = ctl.stats().to_json();
    return j;
}

std::string radiosity_summary(const RadiosityRequest& r, const RadiosityRun& run) {
    const host::RadiosityResult& res = run.result;
    std::string out =
        fmt::format("scene {}: {} faces, {} patches in {} elements (patch size {:.4g}), {}x{}\n",
                    r.scene, run.world.face_count, res.mesh.patches.size(),
                    res.mesh.elements.size(), res.patch_size, run.screen.width, run.screen.height);
    if (res.patches_per_pass.size() > 1) {
        out += "adaptive:";
        for (uint64_t n : res.patches_per_pass)
            out += fmt::format(" {}", n);
        out += " patches\n";
    }
    if (const auto& h = res.hierarchy)
        out += fmt::format(
            "hierarchy: {} root elements, {} elements, {} leaves, {} links, {} refinements, {} "
            "oracle calls, {} link factors, {} rays, {} passes{}\n",
            h->roots, h->nodes, h->leaves, h->links, h->refinements, h->oracle_calls,
            h->form_factors, h->rays, h->passes, h->budget_hit ? " (budget reached)" : "");
    out += fmt::format(
        "form factors {}, solver {}: {} {}, residual {:.3g}{}; largest row sum of F "
        "{:.4g}; exposure {:.4g}{}\n",
        r.ff, res.hierarchy ? "push-pull" : r.solver, res.solution.iterations, iterations_unit(r),
        res.solution.residual, res.solution.converged ? "" : " (NOT converged)", res.max_row_sum,
        res.exposure, r.options.exposure > 0 ? "" : " (automatic)");
    out += row_sum_flag(r, run);
    out += "host (wall / CPU):\n";
    auto line = [&](const char* name, const host::Timing& t) {
        out += fmt::format("  {:<16} {:>10.3f} ms {:>10.3f} ms\n", name, t.wall_ms, t.cpu_ms);
    };
    line("load", run.times.load);
    line("meshing", res.times.meshing);
    line("visibility", res.times.visibility);
    line("form factors", res.times.form_factors);
    line("solving", res.times.solving);
    line("rendering", run.times.rendering);
    line("end to end", run.times.end_to_end);
    out += "host counted operations:\n";
    out += run.counters.lines();
    out += "render of the patches (zbuffer):\n";
    out += run.render_stats.counters.lines();
    return out;
}

// Through the same Z-buffer as the image: one id per patch.
controller::Framebuffer radiosity_id_buffer(const RadiosityRun& run) {
    std::unique_ptr<host::Renderer> renderer = host::make_renderer(host::Method::ZBuffer);
    return experiments::id_framebuffer(run.result.patches, *renderer);
}

protocol::Properties radiosity_stream_header(const RadiosityRequest& r, const RadiosityRun& run) {
    return {{"scene", r.scene},
            {"method", "radiosity " + r.ff + " + zbuffer"},
            {"resolution", fmt::format("{}x{}", run.screen.width, run.screen.height)},
            {"patches", std::to_string(run.result.mesh.patches.size())},
            {"tool", std::string("fb89 ") + FB89_VERSION}};
}

void write_radiosity_stream(const RadiosityRequest& r, const RadiosityRun& run,
                            const std::string& path) {
    make_parent_dirs(path);
    protocol::StreamWriter writer(path, radiosity_stream_header(r, run));
    run.commands.replay_into(writer);
    writer.close();
}

}  // namespace fb89::frontend
