// fb89 render SCENE: load, project, run one hidden-surface method into the in-memory
// buffer (timed), then hand the commands to the simulated controller (modelled), and write
// what was asked for: PNG, face-id PNG, command stream, stats JSON. With --connect PATH
// the same commands then go, as a stream, to an `fb89 controller` process on that socket;
// the socket is opened only after the host has finished, so no host time includes it.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "experiments/beam_mask.h"
#include "experiments/depth_agreement.h"
#include "experiments/id_pass.h"
#include "experiments/id_view.h"
#include "experiments/period_runs.h"
#include "experiments/progress.h"
#include "frontend/calibration.h"
#include "frontend/data_dir.h"
#include "frontend/period_host.h"
#include "frontend/pipelines.h"
#include "host/methods.h"
#include "host/raster/scene_measures.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "host/trace/kernel_level.h"
#include "protocol/memory_buffer.h"
#include "protocol/socket_stream.h"
#include "protocol/stream_writer.h"

namespace fb89::cli {

namespace {

struct RenderArgs {
    std::string scene;
    std::string buffer;  // "": the profile's command buffer
    std::string method = "zbuffer";
    std::string window_test = "area";
    std::string threshold = "calibrated";
    std::string depth_estimate = "window";
    std::string beam_threshold = "calibrated";
    int reflections = host::TraceOptions{}.max_reflections;
    double grid_density = host::BeamOptions{}.grid_density;
    std::string accel = "bvh";
    std::string packets = "on";
    std::string mask;
    int approx_min_side = 0;
    double approx_epsilon = 0;
    std::string size;
    std::string png, ids, ids_view, stream, stats, connect, timeline;
    std::string profile = std::string(controller::kDefaultProfile);
    std::string host = "native";
    int repeat = 1;
    int classes = 0;
    bool untimed_stream = false;
    bool quiet = false;
};

// An option given for a method that does not read it is refused, not ignored; so is a grid
// density without the grid.
void refuse_options_the_method_ignores(const CLI::App& sub, const std::string& method,
                                       const std::string& accel) {
    struct Group {
        const char* option;
        host::OptionGroup group;
        const char* used_by;
    };
    static constexpr Group kGroups[] = {
        {"--window-test", host::kWindowOptions, "warnock and hybrid"},
        {"--approx-min", host::kWindowOptions, "warnock and hybrid"},
        {"--approx-eps", host::kWindowOptions, "warnock and hybrid"},
        {"--threshold", host::kHybridOptions, "hybrid"},
        {"--depth-estimate", host::kHybridOptions, "hybrid"},
        {"--reflections", host::kTraceOptions, "raytrace, beam and mlrta"},
        {"--accel", host::kTraceOptions, "raytrace, beam and mlrta"},
        {"--grid-density", host::kBeamOptions, "beam"},
        {"--beam-threshold", host::kBeamOptions, "beam"},
    };
    const host::MethodInfo& info = host::method_info(find_method(method));
    for (const Group& g : kGroups)
        if (sub.get_option(g.option)->count() > 0 && !info.uses(g.group))
            throw UsageError(fmt::format("{}: the {} method does not use it (only {} do)", g.option,
                                         info.name, g.used_by));
    if (sub.get_option("--grid-density")->count() > 0 && accel != "grid")
        throw UsageError(
            "--grid-density: only the uniform grid has cells (--accel grid); the "
            "beams query the BVH otherwise");
}

host::WindowTest window_test_named(const std::string& name) {
    if (name == "area") return host::WindowTest::Area;
    if (name == "centres") return host::WindowTest::Centres;
    throw std::invalid_argument("unknown window test '" + name + "' (known: area, centres)");
}

// The face-id pass: the same method through the same sink and controller, every face
// coloured id + 1 and unshaded, so the controller's framebuffer is the id buffer. Run once
// for --ids (exact) and --ids-view (false colour) alike, written when asked.
// A method that sends depth commands is held to the host Z-buffer's ids whether or not they
// are asked for, with the profile's depth word: the pixels where they differ are counted as
// ties (the fixed-point depth's) or as errors.
std::optional<experiments::DepthAgreement> id_pass(const RenderArgs& args, const host::Scene& scene,
                                                   host::Renderer& renderer, uint32_t depth_bits) {
    const bool asked = !args.ids.empty() || !args.ids_view.empty();
    const bool depth = host::method_info(host::method_named(args.method)).depth_commands;
    if (!asked && !depth) return std::nullopt;
    const controller::Framebuffer ids = experiments::id_framebuffer(scene, renderer, depth_bits);
    if (asked) experiments::write_id_pngs(ids, args.ids, args.ids_view);
    if (!depth) return std::nullopt;
    auto zbuffer = host::make_renderer(host::Method::ZBuffer);
    host::Counters counters;
    return experiments::depth_agreement(
        host::project_scene(scene, host::ColorMode::FaceId, counters),
        experiments::id_framebuffer(scene, *zbuffer), ids, depth_bits);
}

std::string agreement_line(const experiments::DepthAgreement& a) {
    return fmt::format(
        "ids against the host Z-buffer's ({}-bit depth word): {} of {} pixels differ: {} ties "
        "(faces within {:.2g} of each other in depth, the largest {:.2g}), {} covered "
        "differently, {} wrong\n",
        a.depth_bits, controller::grouped(a.differ), controller::grouped(a.pixels),
        controller::grouped(a.ties), a.tolerance, a.max_tie_dz, a.coverage, a.wrong);
}

// The paper's Figs. 4.7 and 4.10: the frame with the ray-traced pixels blacked out.
void write_beam_mask(const std::string& path, const controller::Framebuffer& frame,
                     const host::Renderer& renderer) {
    const auto& beam = dynamic_cast<const host::BeamRayHybrid&>(renderer);
    make_parent_dirs(path);
    controller::write_png(path, experiments::masked_by_beams(frame, beam.beam_mask()));
}

// The stream carries the frame's send times (format version 2) when it has them, unless
// asked not to (version 1: the same bytes every run, as measured times are not).
protocol::Timing stream_timing(const RenderArgs& args, const experiments::RenderResult& job) {
    return job.runs.front().send_us.empty() || args.untimed_stream ? protocol::Timing::Untimed
                                                                   : protocol::Timing::Timed;
}

// A method that sends depth commands needs format version 3.
protocol::Commands stream_commands(const RenderArgs& args) {
    return host::method_info(host::method_named(args.method)).depth_commands
               ? protocol::Commands::Depth
               : protocol::Commands::Tiling;
}

protocol::Properties stream_properties(const RenderArgs& args,
                                       const experiments::RenderResult& job) {
    // a bundled scene by its name: the stream's bytes do not depend on where the checkout is
    protocol::Properties p{
        {"scene", scene_display_name(args.scene)},
        {"method", args.method},
        {"resolution", fmt::format("{}x{}", job.screen.width, job.screen.height)},
        {"tool", std::string("fb89 ") + FB89_VERSION}};
    const experiments::MethodRun& run = job.runs.front();
    if (stream_timing(args, job) == protocol::Timing::Timed) {
        p[protocol::kPropertyHost] = args.host;
        p[protocol::kPropertySendTimes] = send_times_source(run.period.has_value());
    }
    return p;
}

void write_stream(const RenderArgs& args, const experiments::RenderResult& job) {
    make_parent_dirs(args.stream);
    protocol::StreamWriter writer(args.stream, stream_properties(args, job),
                                  stream_timing(args, job), stream_commands(args));
    experiments::write_commands(writer, job.runs.front());
    writer.close();
}

// --connect: streams the rendered commands to a controller process and waits for its
// answer. Returns the exit code; a controller that goes away is reported, never waited on.
int send_to_controller(const RenderArgs& args, const experiments::RenderResult& job,
                       const Console& console) {
    const auto start = std::chrono::steady_clock::now();
    const protocol::MemoryBuffer& commands = job.runs.front().commands;
    protocol::UniqueFd socket = protocol::connect_socket(args.connect);  // names the path
    protocol::StreamWriter writer(socket.get(), "socket " + args.connect,
                                  stream_properties(args, job), stream_timing(args, job),
                                  stream_commands(args));
    const std::size_t total = commands.size();
    try {
        experiments::write_commands(writer, job.runs.front());
        writer.close();
    } catch (const std::runtime_error& e) {
        fmt::print(stderr,
                   "fb89: error: the controller at {} went away mid-stream: {} of {} commands "
                   "had got through to the socket ({})\n",
                   args.connect, writer.commands_flushed(), total, e.what());
        return kBadInput;
    }
    std::optional<std::string> reply;
    std::string lost;  // why no answer came
    try {
        reply =
            protocol::finish_and_read_reply(socket.get(), args.connect, std::chrono::seconds(60));
        if (!reply) lost = "it closed the connection";
    } catch (const std::runtime_error& e) {
        lost = e.what();
    }
    if (!reply) {
        fmt::print(stderr,
                   "fb89: error: the controller at {} went away before acknowledging the stream "
                   "({}) after all {} commands were sent\n",
                   args.connect, lost, total);
        return kBadInput;
    }
    if (reply->rfind("ok", 0) != 0) {
        fmt::print(stderr, "fb89: error: the controller at {} refused the stream: {}\n",
                   args.connect, *reply);
        return kBadInput;
    }
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    console.note(
        fmt::format("controller at {}: {} ({} bytes sent in {:.3f} ms, apart from host "
                    "times)",
                    args.connect, *reply, writer.byte_count(), took.count()));
    return kSuccess;
}

nlohmann::json stats_json(const RenderArgs& args, const experiments::RenderResult& job,
                          const controller::Controller& ctl) {
    const experiments::MethodRun& run = job.runs.front();
    nlohmann::json j;
    j["tool"] = std::string("fb89 ") + FB89_VERSION;
    j["scene"] = {{"file", args.scene},
                  {"faces", job.scene.face_count},
                  {"triangulated", job.scene.triangulated},
                  {"dropped", job.scene.dropped},
                  {"width", job.screen.width},
                  {"height", job.screen.height}};
    j["method"] = args.method;
    if (args.method == "warnock" || args.method == "hybrid") j["window_test"] = args.window_test;
    if (args.method == "hybrid") {
        j["threshold"] = resolve_threshold(args.threshold, nullptr, args.host);
        j["depth_estimate"] = args.depth_estimate;
    }
    if (args.method == "beam") {
        const double t = resolve_beam_threshold(args.beam_threshold, nullptr, args.host);
        j["beam_threshold"] = std::isinf(t) ? nlohmann::json("inf") : nlohmann::json(t);
    }
    if (args.method == "mlrta") j["packets"] = args.packets;
    if (args.method == "beam" || args.method == "raytrace") {
        j["reflections"] = args.reflections;
        j["kernels"] = std::string(host::kernel_level_name(host::kernel_level()));
        j["accel"] = args.accel;
    }
    j["host"] = run.stats.to_json();
    j["host"]["commands"] = run.commands.size();
    host::SceneMeasures m = host::measure_scene(job.screen);
    j["scene"]["measures"] = {{"faces_on_screen", m.faces},
                              {"visible_faces", m.visible_faces},
                              {"covered_pixels", m.covered_pixels},
                              {"face_pixels", m.face_pixels},
                              {"depth_complexity", m.depth_complexity},
                              {"screen_depth_complexity", m.screen_depth_complexity},
                              {"mean_visible_face_px", m.mean_visible_face}};
    j["controller"] = ctl.stats().to_json();
    if (run.period) j["period_host"] = period_json(*run.period);
    if (run.pipeline)
        j["pipeline"] = pipeline_json(*run.pipeline, send_times_source(run.period.has_value()));
    return j;
}

int run_render(const RenderArgs& args) {
    Console console{args.quiet};
    const bool stdout_taken = claims_stdout({{"--png", args.png},
                                             {"--mask", args.mask},
                                             {"--ids", args.ids},
                                             {"--ids-view", args.ids_view},
                                             {"--stream", args.stream},
                                             {"--stats", args.stats},
                                             {"--timeline", args.timeline}});
    host::MethodOptions options;
    std::string threshold_source, beam_source;
    try {
        options.method = find_method(args.method);
        options.warnock.window_test = window_test_named(args.window_test);
        options.warnock.approx = {args.approx_min_side, args.approx_epsilon};
        options.hybrid.threshold = resolve_threshold(args.threshold, &threshold_source, args.host);
        options.hybrid.depth = args.depth_estimate == "scene" ? host::DepthEstimate::Scene
                                                              : host::DepthEstimate::Window;
        options.beam.threshold =
            resolve_beam_threshold(args.beam_threshold, &beam_source, args.host);
        options.trace.max_reflections = args.reflections;
        options.beam.grid_density = args.grid_density;
        options.trace.accel = host::parse_accel(args.accel);
        options.trace.packets = args.packets == "on";
        host::make_renderer(options);  // refuses options no renderer can take
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    if (!args.mask.empty() && options.method != host::Method::Beam)
        throw UsageError("--mask: only the beam method decides pixels by beams");
    // which threshold runs, and why: the first line of the report
    std::string threshold_line;
    if (options.method == host::Method::Hybrid)
        threshold_line = fmt::format("hybrid threshold {:.6g} ({})\n", options.hybrid.threshold,
                                     threshold_source);
    if (options.method == host::Method::Beam)
        threshold_line =
            fmt::format("beam threshold {:.6g} ({})\n", options.beam.threshold, beam_source);

    // the job: this scene, this method, timed here (and on a 1989 host, emulated once)
    experiments::RenderJob job;
    job.scene = args.scene;
    job.methods = {options};
    if (!args.size.empty()) job.size = parse_size(args.size);
    job.repeat = args.repeat;
    job.controller = args.profile;
    job.progress = !args.quiet && isatty(STDERR_FILENO);
    job.period = make_period_runs(HostArgs{args.host, 1, "", ""});
    job.check_frames = true;
    job.buffer_bytes = parse_buffer_option(args.buffer, args.profile);
    const experiments::RenderResult result = experiments::run_render_job(job);
    const experiments::MethodRun& run = result.runs.front();
    for (const auto& note : result.scene.notes)
        console.note("note: " + note);

    // the controller tiles what the host decided; its cost is modelled, never timed
    controller::Controller ctl(controller::load_profile(args.profile));
    run.commands.replay_into(ctl);

    // a controller process that goes away fails the command before any output is written
    if (!args.connect.empty()) {
        std::fflush(stdout);
        if (const int code = send_to_controller(args, result, console); code != kSuccess)
            return code;
    }
    if (!args.png.empty()) {
        make_parent_dirs(args.png);
        controller::write_png(args.png, ctl.framebuffer());
    }
    if (!args.mask.empty()) write_beam_mask(args.mask, ctl.framebuffer(), *run.renderer);
    const std::optional<experiments::DepthAgreement> agreement =
        id_pass(args, result.scene, *run.renderer, ctl.profile().depth_bits);
    const bool ids_asked = !args.ids.empty() || !args.ids_view.empty();
    if (!args.stream.empty()) write_stream(args, result);
    if (!args.stats.empty()) write_json(args.stats, stats_json(args, result, ctl));
    if (!args.timeline.empty())
        write_text(args.timeline, render_timeline(run, args.scene, args.method, args.host,
                                                  ctl.profile(), "--timeline"));

    if (!args.quiet && !stdout_taken) {
        fmt::print("{}", threshold_line);
        fmt::print("scene {}: {} faces ({}{} pieces on screen), {}x{}, method {}\n",
                   scene_display_name(args.scene), result.scene.face_count,
                   result.scene.dropped ? fmt::format("{} dropped, ", result.scene.dropped) : "",
                   result.screen.faces.size(), result.screen.width, result.screen.height,
                   args.method);
        // a 1989 host first: its phases are the host times this run is about
        if (run.period) {
            fmt::print("{}", period_summary(*run.period));
            if (args.classes > 0)
                for (auto phase : {period::Phase::Setup, period::Phase::HiddenSurface})
                    fmt::print("{}", period_classes(*run.period, phase, args.classes));
            fmt::print(
                "native run (this machine; it made the command stream the controller "
                "tiles):\n");
        }
        fmt::print("{}", run.stats.summary());
        fmt::print("{}", ctl.stats().summary());  // its first line names the profile
        fmt::print("{}",
                   split_line(run.period ? run.period->cost.profile : "native", run.host_frame_ms,
                              ctl.profile().name, run.controller.frame_ms));
        if (run.pipeline)
            fmt::print("{}", pipeline_line(*run.pipeline, run.controller.frame_ms,
                                           send_times_source(run.period.has_value())));
        if (agreement && ids_asked) fmt::print("{}", agreement_line(*agreement));
    }
    if (agreement) {
        const std::string note = experiments::z_fighting_note(*agreement);
        if (!note.empty()) console.note(note);
    }
    if (agreement && !agreement->exact()) {
        fmt::print(stderr, "fb89: error: {}", agreement_line(*agreement));
        return kCheckFailed;
    }
    return kSuccess;
}

}  // namespace

void register_render(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* sub = app.add_subcommand("render", "Render a scene with one hidden-surface method");
    sub->add_option(
           "scene", args->scene,
           scene_argument_help("Scene: a .json file, a bare .obj model (framed by an automatic "
                               "camera) or a .tri file of screen-space triangles"))
        ->required();
    sub->add_option("--method,-m", args->method, method_option_help("Hidden-surface method"))
        ->check(method_validator())
        ->capture_default_str();
    sub->add_option("--window-test", args->window_test,
                    "Warnock's window test: area (the paper's) or centres (sampling-aware)")
        ->capture_default_str();
    sub->add_option("--threshold", args->threshold,
                    "Hybrid: Expr. 3.1 threshold: a number, inf, paper (0.04) or calibrated "
                    "(this machine's, from fb89 calibrate; else the paper's)")
        ->capture_default_str();
    sub->add_option("--depth-estimate", args->depth_estimate,
                    "Hybrid: D in Expr. 3.1 from the window's faces or the whole scene's")
        ->check(CLI::IsMember({"window", "scene"}))
        ->capture_default_str();
    sub->add_option(
           "--beam-threshold", args->beam_threshold,
           fmt::format("Beam: Expr. 2.7 threshold: a number, inf (beams down to 4x4 "
                       "pixels, no F_w query) or calibrated (this machine's, from fb89 calibrate "
                       "--method beam; else the built-in {:g})",
                       host::kDefaultBeamThreshold))
        ->capture_default_str();
    sub->add_option("--reflections", args->reflections,
                    "Raytrace and beam: mirror bounces followed (0: primary visibility)")
        ->check(cli_check(limits::kReflections))
        ->capture_default_str();
    sub->add_option(
           "--grid-density", args->grid_density,
           "Beam with --accel grid: top-level cells per face piece of the uniform grid the rays "
           "walk and the beam queries scan (crowded cells get a grid of their own)")
        ->check(cli_check(limits::kGridDensity))
        ->capture_default_str();
    sub->add_option("--accel", args->accel,
                    "Raytrace, beam and mlrta: what rays find their nearest face through, and "
                    "beams the faces in their way: bvh, grid (the paper's: a uniform grid walked "
                    "by 3DDDA, Fujimoto et al.) or kd (the kd-tree mlrta's beams walk; raytrace "
                    "and mlrta only); the same frame every way")
        ->check(CLI::IsMember({"bvh", "grid", "kd"}))
        ->capture_default_str();
    sub->add_option("--packets", args->packets,
                    "Mlrta: its rays in packets of eight, as many lanes an instruction as the "
                    "CPU holds (on), or one by one (off: what a machine without SIMD does "
                    "better); the same frame either way")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    sub->add_option("--mask", args->mask,
                    "Beam: write the image with every pixel the ray tracer decided blacked out "
                    "(the paper's Figs. 4.7 and 4.10)");
    sub->add_option("--approx-min", args->approx_min_side,
                    "Approximate: fill windows of at least this side with a face covering all "
                    "but --approx-eps of their pixel centres (0: exact)")
        ->check(cli_check(limits::kApproxMin));
    sub->add_option("--approx-eps", args->approx_epsilon,
                    "Approximate: the fraction of a window's centres its face may miss")
        ->check(cli_check(limits::kApproxEps));
    sub->add_option("--size", args->size, "Image size WxH, overriding the scene's");
    sub->add_option("--png", args->png, "Write the controller's framebuffer as PNG");
    sub->add_option("--ids", args->ids,
                    "Write the face-id buffer as PNG (id + 1 as 24-bit RGB, 0 = background)");
    sub->add_option("--ids-view", args->ids_view,
                    "Write the face-id buffer in false colour as PNG, for people: each id a "
                    "distinct colour, background black");
    sub->add_option("--stream", args->stream,
                    "Record the command stream ('-' for stdout), with each command's send time "
                    "(format version 2)");
    auto* stream = sub->get_option("--stream");
    sub->add_flag("--untimed-stream", args->untimed_stream,
                  "With --stream: record it without send times (format version 1: the same "
                  "bytes every run)")
        ->needs(stream);
    sub->add_option("--connect", args->connect,
                    "Also stream the commands to `fb89 controller --listen PATH` on this socket");
    sub->add_option("--stats", args->stats,
                    "Write host and controller figures as JSON ('-' for stdout)");
    sub->add_option("--profile", args->profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_option("--buffer", args->buffer,
                    "The controller's command buffer in bytes, or unbounded, for the pipeline in "
                    "time (default: the profile's; docs/COST_MODEL.md)");
    sub->add_option("--timeline", args->timeline,
                    "Write the frame through the pipeline in time as Chrome trace-event JSON "
                    "(Perfetto, chrome://tracing): host, bus and controller lanes, host stalls, "
                    "the buffer's fill ('-' for stdout)");
    sub->add_option("--host", args->host,
                    host_option_help("Host the frame is timed on") + " (docs/HOST_COST_MODEL.md)")
        ->check(host_validator())
        ->capture_default_str();
    sub->add_option("--classes", args->classes,
                    "1989 host: also list the N instruction classes that take most of the "
                    "set-up and hidden-surface time")
        ->check(cli_check(limits::kClasses));
    sub->add_option("--repeat", args->repeat,
                    "Render the frame N times; hidden-surface time is the median")
        ->check(cli_check(limits::kRenderRepeat))
        ->capture_default_str();
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    add_isa_option(sub);
    sub->callback([args, sub, &exit_code] {
        refuse_options_the_method_ignores(*sub, args->method, args->accel);
        if (sub->get_option("--packets")->count() > 0 && args->method != "mlrta")
            throw UsageError("--packets: the " + args->method +
                             " method does not use it (only mlrta does)");
        args->scene = resolve_scene(args->scene);
        exit_code = run_render(*args);
    });
}

}  // namespace fb89::cli
