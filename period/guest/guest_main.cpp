// fb89_guest: fb89's own host code as one program for an emulated period host. It
// loads a scene, sets it up, runs one hidden-surface method into the in-memory buffer and
// writes the command stream, marking each phase for the counting plugin (phase_marker.h).
// `fb89 render --host sun3-60` runs it under qemu-m68k (period/isa.h); the options are render's,
// with thresholds already resolved to numbers.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "host/methods.h"
#include "host/radiosity/form_factors.h"
#include "host/radiosity/hierarchical.h"
#include "host/radiosity/mesh.h"
#include "host/radiosity/visibility.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "period/guest/phase_marker.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_writer.h"

// A send mark: the host has sent `commands` commands of the frame so far (a packet closed,
// or the frame ended). The counting plugin keeps the counts up to it, so that every
// command's send time can be priced (docs/HOST_COST_MODEL.md, "Send times"). The system
// call is made here, not through the C library, and this function lies in a section of
// its own, which the phase markers name to the plugin: its instructions are not counted.
// What is counted is what a real host's driver would do as well: count the commands into
// packets and call out when one is full.
// Each instruction set's own, in its folder (period/<isa>/send_mark.h, on the guest build's
// include path: cmake/guest.cmake).
#include "send_mark.h"

namespace {

using fb89::period::mark;
using fb89::period::Phase;
namespace host = fb89::host;
namespace protocol = fb89::protocol;

struct GuestArgs {
    std::string scene, method = "zbuffer", size, stream = "-";
    std::string window_test = "area", depth_estimate = "window";
    double threshold = host::kPaperThreshold;
    double beam_threshold = host::kDefaultBeamThreshold;
    int reflections = host::TraceOptions{}.max_reflections;
    double grid_density = host::BeamOptions{}.grid_density;
    std::string accel = "bvh";
    std::string packets = "on";
    int approx_min = 0;
    double approx_eps = 0;
    bool ids = false;
    std::string radiosity;  // flux, hybrid or hierarchical: §5 instead of a frame
    int patches = 800;
    double epsilon = host::HierarchicalOptions{}.epsilon;
    bool shaft_culling = false;
};

host::MethodOptions method_options(const GuestArgs& a) {
    host::MethodOptions o(host::method_named(a.method));
    o.warnock.window_test =
        a.window_test == "centres" ? host::WindowTest::Centres : host::WindowTest::Area;
    o.warnock.approx = {a.approx_min, a.approx_eps};
    o.hybrid.threshold = a.threshold;
    o.hybrid.depth =
        a.depth_estimate == "scene" ? host::DepthEstimate::Scene : host::DepthEstimate::Window;
    o.beam.threshold = a.beam_threshold;
    o.trace.max_reflections = a.reflections;
    o.beam.grid_density = a.grid_density;
    o.trace.accel = host::parse_accel(a.accel);
    o.trace.packets = a.packets == "on";
    return o;
}

// The paper's §5 table on this host: load, then mesh and grid (set-up), then intervisibility
// and centre form factors (the timed part, as experiment radiosity times it natively).
int run_radiosity(const GuestArgs& a) {
    mark(Phase::Load);
    const host::Scene scene = host::load_scene(a.scene);
    mark(Phase::Setup);
    const host::Mesh mesh = host::mesh_scene(scene, {host::patch_size_for(scene, a.patches), 64});
    const host::TraceScene trace(scene, true, 0);
    const host::UniformGrid grid(trace);
    const host::RadiosityWorld world{trace, grid};
    if (a.radiosity == "hierarchical") {
        // the roots, then links, rays and solving: the whole method is the timed part
        const host::Mesh roots =
            host::mesh_scene(scene, {std::numeric_limits<double>::infinity(), 64});
        host::HierarchicalOptions o;
        o.epsilon = a.epsilon;
        o.shaft_culling = a.shaft_culling;
        const double size = host::patch_size_for(scene, a.patches);
        o.min_area = size * size / 4;
        mark(Phase::HiddenSurface);
        const host::HierarchicalResult r = host::hierarchical_radiosity(roots, world, o);
        mark(Phase::Output);
        std::printf("leaves %llu links %llu rays %llu iterations %d\n",
                    static_cast<unsigned long long>(r.counts.leaves),
                    static_cast<unsigned long long>(r.counts.links),
                    static_cast<unsigned long long>(r.counts.rays), r.solution.iterations);
        return 0;
    }
    mark(Phase::HiddenSurface);
    host::VisibilityCounts counts;
    const host::Visibility delta = a.radiosity == "hybrid"
                                       ? host::decahedral_hybrid(mesh, world, {}, counts)
                                       : host::flux_tracing(mesh, world, counts);
    const std::vector<double> f =
        host::centre_form_factors(mesh, delta, host::CentreForm::PointToPoint);
    mark(Phase::Output);
    std::printf("patches %zu rays %llu queries %llu form_factors %zu\n", mesh.patches.size(),
                static_cast<unsigned long long>(counts.rays),
                static_cast<unsigned long long>(counts.queries), f.size());
    return 0;
}

int run(const GuestArgs& a) {
    if (!a.radiosity.empty()) return run_radiosity(a);
    const host::MethodOptions options = method_options(a);
    auto renderer = host::make_renderer(options);

    mark(Phase::Load);
    host::Scene scene = host::load_scene(a.scene);
    if (!a.size.empty() && std::sscanf(a.size.c_str(), "%dx%d", &scene.width, &scene.height) != 2)
        throw std::invalid_argument("--size: expected WxH, got '" + a.size + "'");

    mark(Phase::Setup);
    host::HostStats stats;
    const host::ScreenScene screen = host::project_scene(
        scene, a.ids ? host::ColorMode::FaceId : host::ColorMode::Shaded, stats.counters);
    renderer->setup(screen);

    mark(Phase::HiddenSurface);
    protocol::MemoryBuffer commands;
    commands.mark_packets(protocol::kSendPacketCommands, fb89_send_mark);
    host::render_frame(*renderer, screen, commands, stats);

    mark(Phase::Output);
    protocol::StreamWriter writer(
        a.stream,
        {{"scene", a.scene},
         {"method", a.method},
         {"resolution", fmt::format("{}x{}", screen.width, screen.height)},
         {"tool", std::string("fb89_guest ") + FB89_VERSION}},
        protocol::Timing::Untimed,
        host::method_info(host::method_named(a.method)).depth_commands
            ? protocol::Commands::Depth
            : protocol::Commands::Tiling);
    commands.replay_into(writer);
    writer.close();
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    mark(Phase::Startup);
    CLI::App app{"fb89's host code for the emulated MC68020 + MC68881: one method, one frame"};
    GuestArgs a;
    app.add_option("scene", a.scene, "Scene file")->required();
    app.add_option("--method,-m", a.method, "Hidden-surface method");
    app.add_option("--size", a.size, "Image size WxH, overriding the scene's");
    app.add_option("--window-test", a.window_test, "area or centres");
    app.add_option("--threshold", a.threshold, "Hybrid: Expr. 3.1 threshold");
    app.add_option("--depth-estimate", a.depth_estimate, "Hybrid: window or scene");
    app.add_option("--beam-threshold", a.beam_threshold, "Beam: Expr. 2.7 threshold");
    app.add_option("--reflections", a.reflections, "Raytrace and beam: mirror bounces");
    app.add_option("--grid-density", a.grid_density, "Beam: grid cells per piece");
    app.add_option("--accel", a.accel, "Raytrace, beam and mlrta: what rays walk, bvh, grid or kd")
        ->check(CLI::IsMember({"bvh", "grid", "kd"}));
    app.add_option("--packets", a.packets, "mlrta: rays in packets of eight, or one by one")
        ->check(CLI::IsMember({"on", "off"}));
    app.add_option("--approx-min", a.approx_min, "Approximate fills: smallest side");
    app.add_option("--approx-eps", a.approx_eps, "Approximate fills: centres missed");
    app.add_flag("--ids", a.ids, "Render the face-id pass instead of the shaded frame");
    app.add_option("--radiosity", a.radiosity,
                   "flux or hybrid: intervisibility and form factors instead of a frame; "
                   "hierarchical: hierarchical radiosity, solved")
        ->check(CLI::IsMember({"flux", "hybrid", "hierarchical"}));
    app.add_option("--epsilon", a.epsilon, "Hierarchical radiosity: BF refinement's epsilon");
    app.add_flag("--shaft-culling", a.shaft_culling,
                 "Hierarchical radiosity: links no piece can block cast no rays");
    app.add_option("--patches", a.patches, "Radiosity: about this many patches");
    app.add_option("--stream", a.stream, "Where the command stream goes ('-' for stdout)");
    try {
        app.parse(argc, argv);
        return run(a);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fb89_guest: error: %s\n", e.what());
        return 2;
    }
}
