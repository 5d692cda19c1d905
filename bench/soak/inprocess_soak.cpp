// The in-process soak: each cycle loads its scene, projects it and sets up its method, then
// renders the frame twice, once into a stream file and once straight into a controller,
// reads the file back into a second controller, and holds the two to the same frames,
// checksums, pixels and per-opcode counts. Alternate rounds over the pairs replay through
// the batch path (as `fb89 replay` does) and command by command (as `fb89 diff` does).
#include <chrono>
#include <cstring>
#include <iostream>

#include <fmt/format.h>

#include "bench/soak/soak_modes.h"
#include "controller_sim/controller.h"
#include "host/methods.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"

namespace fb89::soak {

namespace {

struct Frames {
    uint64_t written = 0;      // commands the writer encoded
    bool indexed = false;      // the file ended with its frame index
    std::size_t received = 0;  // frames the replay closed
};

Frames record_and_replay(const Pair& pair, host::Renderer& renderer,
                         const host::ScreenScene& screen, const std::filesystem::path& stream,
                         bool batched, controller::Controller& replayed) {
    Frames f;
    {
        protocol::StreamWriter writer(
            stream.string(), {{"scene", pair.scene.string()}, {"method", pair.method}},
            protocol::Timing::Untimed,
            host::method_info(host::method_named(pair.method)).depth_commands
                ? protocol::Commands::Depth
                : protocol::Commands::Tiling);
        host::HostStats stats;
        host::render_frame(renderer, screen, writer, stats);
        writer.close();
        f.written = writer.command_count();
    }
    protocol::StreamReader reader(stream.string());
    if (batched) {
        std::vector<protocol::Command> batch(4096);
        while (const std::size_t n = reader.read_batch(batch))
            replayed.execute(std::span(batch).first(n));
    } else {
        protocol::Command c;
        while (reader.next(c))
            replayed.execute(c);
    }
    f.indexed = reader.frame_index().has_value() && reader.frame_index()->size() == 1;
    f.received = replayed.frames().size();
    return f;
}

// What differs between the direct and the replayed controller ("" when nothing does).
std::string difference(const controller::Controller& direct, const controller::Controller& replayed,
                       const Frames& f) {
    if (!f.indexed) return "the stream file has no frame index of one frame";
    if (direct.frames().size() != 1 || replayed.frames().size() != 1)
        return fmt::format("frames: {} direct, {} replayed", direct.frames().size(),
                           replayed.frames().size());
    const controller::FrameResult &a = direct.frames()[0], &b = replayed.frames()[0];
    if (direct.commands_executed() != replayed.commands_executed() ||
        direct.commands_executed() != f.written)
        return fmt::format("commands: {} direct, {} written, {} replayed",
                           direct.commands_executed(), f.written, replayed.commands_executed());
    if (a.checksum != b.checksum)
        return fmt::format("checksum {:016x} direct, {:016x} replayed", a.checksum, b.checksum);
    const controller::Framebuffer &fa = direct.framebuffer(), &fb = replayed.framebuffer();
    if (fa.width() != fb.width() || fa.height() != fb.height() ||
        std::memcmp(fa.pixels().data(), fb.pixels().data(), fa.pixels().size()) != 0)
        return "pixels differ under equal checksums";
    if (direct.stats().totals != replayed.stats().totals || a.ops != b.ops)
        return "per-opcode counts differ";
    if (!a.complete || !b.complete) return "a frame closed without its FRAME_END";
    return "";
}

void run_cycle(const Pair& pair, const controller::CostProfile& profile,
               const std::filesystem::path& stream, bool batched, SoakResult& r, int cycle) {
    const host::Scene scene = host::load_scene(pair.scene);
    host::Counters counters;
    const host::ScreenScene screen = host::project_scene(scene, host::ColorMode::Shaded, counters);
    std::unique_ptr<host::Renderer> renderer = host::make_renderer(host::method_named(pair.method));
    renderer->setup(screen);

    controller::Controller replayed(profile);
    const Frames f = record_and_replay(pair, *renderer, screen, stream, batched, replayed);
    controller::Controller direct(profile);
    host::HostStats stats;
    host::render_frame(*renderer, screen, direct, stats);

    r.frames_expected += 1;
    r.frames_received += std::min<std::size_t>(f.received, 1);
    r.commands_checked += f.written;
    const std::string problem = difference(direct, replayed, f);
    if (problem.empty()) return;
    if (f.received > 0) ++r.frames_mismatched;
    r.fail(fmt::format("cycle {} ({}, {}): {}", cycle, pair.label(),
                       batched ? "batched" : "one by one", problem));
}

}  // namespace

void report_progress(const SoakOptions& options, const SoakResult& r, const ResourceSample& s) {
    if (!options.progress) return;
    std::cerr << fmt::format("  {} cycle {}/{}: RSS {} KiB, {} fds, {} failures\n", r.mode, s.cycle,
                             options.cycles, s.rss_kib, s.fds, r.failure_count);
}

SoakResult run_inprocess(const SoakOptions& options) {
    SoakResult r = start_result("inprocess", options);
    r.watched = "fb89_soak";
    const WorkDir work(options);
    const std::filesystem::path stream = work.path() / "cycle.fb89s";
    const controller::CostProfile profile = controller::load_profile("ideal");
    const std::size_t pairs = options.scenes.size() * options.methods.size();
    const auto start = std::chrono::steady_clock::now();
    for (int c = 0; c < options.cycles; ++c) {
        const Pair pair = pair_of(options, c);
        const bool batched = (static_cast<std::size_t>(c) / pairs) % 2 == 0;
        try {
            run_cycle(pair, profile, stream, batched, r, c);
        } catch (const std::exception& e) {
            r.frames_expected += 1;
            r.fail(fmt::format("cycle {} ({}): {}", c, pair.label(), e.what()));
        }
        r.cycles = c + 1;
        if (is_sample_point(r.cycles, options.every, options.cycles)) {
            r.samples.push_back(sample_process(0, r.cycles));
            report_progress(options, r, r.samples.back());
        }
    }
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::filesystem::remove(stream);
    return r;
}

}  // namespace fb89::soak
