// fb89 replay STREAM: re-costs a recorded command stream under a controller profile without
// re-rendering (apitrace's `apitrace replay`). The stream is read in batches of commands
// into controller::Controller (command by command with --snapshot); it prints one row per frame
// (commands, pixels, cycles, modelled ms, bus ms, frame ms, checksum) and the controller's
// per-opcode summary.
//
//   --png F               the last complete frame as PNG
//   --png F --snapshot S  instead, the framebuffer right after each call in call set S,
//                         as F with the call number inserted: out.png -> out-000123.png
//   --stats F.json        {"stream": ..., "controller": <controller stats>, "benchmark": ...}
//   --benchmark           wall time of the replay (reading + executing), commands/s, Mpixels/s
//   --buffer N|unbounded  each frame also through the pipeline in time with a command buffer
//                         of N bytes (docs/COST_MODEL.md), from the send times a version-2
//                         stream carries; a version-1 stream has none, so every command is
//                         ready at 0, and the line says so
//   --timeline F          the last complete frame through that pipeline as trace-event JSON
//
// A truncated or corrupt stream: every complete frame is reported, then the StreamError on
// stderr, and exit 2 with no output file written or changed (the snapshots already taken
// wait beside their targets and are removed: protocol::OutputBatch). With --salvage
// what came before the error is kept: the last complete frame is written with --png, the
// snapshots taken before it are kept, --stats carries an "error" entry. A stream cut short or
// refused is then a warning, exit 0; a damaged one (version 4: a batch failing its checksum,
// none of whose commands is replayed) is still an error, exit 2, with the outputs written and
// what was dropped said.
#include <chrono>
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "controller_sim/timed_pipeline.h"
#include "frontend/gsp_replay.h"
#include "frontend/pipelines.h"
#include "frontend/stream_tools.h"
#include "protocol/output_file.h"

namespace fb89::cli {

namespace {

struct ReplayArgs {
    std::string stream;
    std::string profile = std::string(controller::kDefaultProfile);
    std::string png, snapshot, stats, buffer, timeline;
    bool benchmark = false;
    bool salvage = false;
    bool quiet = false;
    // --gsp: through the emulated GSP executing the executive (or --listing's)
    bool gsp = false;
    std::string listing;
    std::optional<uint64_t> gsp_trace;
    bool gsp_warm = false;
};

struct ReplayRun {
    std::optional<controller::Framebuffer> last_frame;  // at the last FRAME_END (--png only)
    uint64_t snapshots = 0;
    std::string last_snapshot;
    double wall_s = 0;
    std::optional<protocol::StreamError> error;
    // --buffer / --timeline: each complete frame through the pipeline in time from the
    // stream's send times (a version-1 stream has none: every command ready at 0); with
    // --timeline, the last one kept
    std::optional<FramePipelines> pipelines;
};

// Commands read and executed at a time by the replay loop: enough to leave the per-batch
// costs behind, few enough to stay in the cache (40 bytes each).
constexpr std::size_t kBatch = 4096;

// The replay loop with snapshots: read, execute, snapshot, one command at a time.
void replay_snapshots(const ReplayArgs& args, const protocol::CallSet& snapshots,
                      protocol::StreamReader& reader, controller::Controller& ctl, ReplayRun& run) {
    protocol::Command c;
    while (reader.next(c)) {
        ctl.execute(c);
        if (snapshots.contains(reader.command_number(), c)) {
            run.last_snapshot = snapshot_path(args.png, reader.command_number());
            if (run.snapshots++ == 0) make_parent_dirs(run.last_snapshot);
            controller::write_png(run.last_snapshot, ctl.framebuffer());
        }
    }
}

// The replay loop: read a batch, execute it (Controller::execute's batch path). A batch
// ends at a FRAME_END, where --png keeps the framebuffer. Timed as a whole for --benchmark.
void replay(const ReplayArgs& args, const protocol::CallSet& snapshots,
            protocol::StreamReader& reader, controller::Controller& ctl, ReplayRun& run) {
    const bool keep_last = !args.png.empty() && snapshots.empty();
    std::vector<protocol::Command> batch(kBatch);
    // with the pipeline: the batch's send times, and each command's cost as executed
    std::vector<int64_t> send_ns(run.pipelines ? kBatch : 0);
    std::vector<controller::Controller::CommandCost> costs(run.pipelines ? kBatch : 0);
    const auto start = std::chrono::steady_clock::now();
    try {
        if (!snapshots.empty()) {
            replay_snapshots(args, snapshots, reader, ctl, run);
        } else {
            while (const std::size_t n = reader.read_batch(batch, send_ns)) {
                ctl.execute(std::span(batch).first(n), costs);
                if (run.pipelines)
                    for (std::size_t i = 0; i < n; ++i)
                        run.pipelines->follow(batch[i], send_ns[i], costs[i],
                                              reader.frame_host_end_ns());
                if (keep_last && std::holds_alternative<protocol::FrameEnd>(batch[n - 1]))
                    run.last_frame = ctl.framebuffer();
            }
        }
    } catch (const protocol::StreamError& e) {
        run.error = e;
    }
    run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --salvage on a damaged stream: what was not replayed -- the damaged batch and everything after
// it, the frames the trailing index lists beyond those kept, a frame left open.
std::string dropped_text(const ReplayArgs& args, protocol::StreamReader& reader,
                         const controller::Controller& ctl, const protocol::StreamError& e) {
    std::string out = fmt::format("dropped {} and everything after it: the commands from {} on",
                                  e.batch() ? fmt::format("batch {}", *e.batch()) : "the batch",
                                  grouped(e.command()));
    std::error_code ec;
    const auto size = args.stream == "-" ? 0 : std::filesystem::file_size(args.stream, ec);
    if (args.stream != "-" && !ec && size > e.offset())
        out += fmt::format(", bytes {} to {} ({} bytes)", grouped(e.offset()), grouped(size - 1),
                           grouped(size - e.offset()));
    try {  // the index, when it is whole, says how many frames the stream had
        if (const auto index = reader.read_trailing_index())
            out += fmt::format("; the stream's frame index lists {} frame(s)", index->size());
    } catch (const protocol::StreamError&) {
    }
    if (ctl.in_frame())
        out += fmt::format("; frame {}, begun before the damage, is left open and not counted",
                           ctl.open_frame().frame);
    return out;
}

nlohmann::json benchmark_json(const ReplayRun& run, const controller::OpcodeCounters& all) {
    const double s = run.wall_s > 0 ? run.wall_s : 1e-9;
    return {{"wall_s", run.wall_s},
            {"commands", all.commands},
            {"pixels", all.pixels},
            {"commands_per_s", static_cast<double>(all.commands) / s},
            {"mpixels_per_s", static_cast<double>(all.pixels) / s / 1e6}};
}

nlohmann::json stats_json(const ReplayArgs& args, const protocol::StreamReader& reader,
                          const controller::Controller& ctl, const ReplayRun& run) {
    nlohmann::json j;
    j["tool"] = std::string("fb89 ") + FB89_VERSION;
    j["stream"] = {{"file", args.stream},
                   {"version", reader.version()},
                   {"properties", reader.properties()},
                   {"commands_read", ctl.commands_executed()}};
    j["controller"] = ctl.stats().to_json();
    if (args.benchmark) j["benchmark"] = benchmark_json(run, sum(ctl.stats().totals));
    if (run.error) {
        j["error"] = {{"message", run.error->what()},
                      {"offset", run.error->offset()},
                      {"command", run.error->command()}};
    }
    return j;
}

// --gsp: the stream through the emulated GSP beside the controller; the GSP's last frame
// is --png's. Exit 1 when a frame differs from the controller's.
int run_gsp_replay(const ReplayArgs& args) {
    if (!args.snapshot.empty() || !args.buffer.empty() || !args.timeline.empty() ||
        !args.stats.empty() || args.salvage || args.benchmark)
        throw UsageError(
            "--gsp replays whole frames through the emulated GSP and writes --png only; not "
            "with --snapshot, --buffer, --timeline, --stats, --salvage or --benchmark");
    const controller::CostProfile profile = controller::load_profile(args.profile);
    GspReplayOptions options;
    if (!args.listing.empty()) {
        options.listing_file = args.listing;
        options.listing_text = read_text_file(args.listing);
    }
    options.board.trace = args.gsp_trace;
    options.board.cache = !args.gsp_warm;
    protocol::StreamReader reader(args.stream);
    GspReplayResult r;
    try {
        r = gsp_replay(reader, profile, options);
    } catch (const protocol::StreamError& e) {
        report_stream_error(e);
        return kBadInput;
    } catch (const controller::gsp::GspFault& e) {
        throw std::runtime_error(fmt::format("{}: {}", args.stream, e.what()));
    }
    if (!args.png.empty()) {
        if (!r.last_frame)
            throw std::runtime_error(args.stream + ": no complete frame; " + args.png +
                                     " not written");
        make_parent_dirs(args.png);
        controller::write_png(args.png, *r.last_frame);
    }
    if (!args.quiet && args.png != "-") {
        fmt::print("{}\nprofile {}\n", header_line(reader), profile.name);
        fmt::print("{}", r.summary(profile));
        const double model_ms = modelled_ms(profile, r.modelled_cycles());
        const double executed_ms = modelled_ms(profile, r.executed_cycles());
        fmt::print("time: executed {:.3f} ms, the model's {:.3f} ms\n", executed_ms, model_ms);
        if (args.gsp_trace)
            fmt::print(
                "command {}, executed instruction by instruction (address, states, "
                "states so far, line):\n{}",
                *args.gsp_trace,
                r.trace.empty() ? "  (not executed: no such command, or one not sent)\n"
                                : trace_text(r.trace));
    }
    if (r.frames_differing) {
        std::cerr << fmt::format("fb89: {}: the GSP's frames differ from the controller's: {}\n",
                                 args.stream, r.first_difference);
        return kCheckFailed;
    }
    return kSuccess;
}

int run_replay(const ReplayArgs& args) {
    if (args.gsp || !args.listing.empty() || args.gsp_trace || args.gsp_warm) {
        if (!args.gsp) throw UsageError("--listing, --gsp-trace and --gsp-warm go with --gsp");
        return run_gsp_replay(args);
    }
    Console console{args.quiet};
    protocol::CallSet snapshots;
    const bool stdout_taken = claims_stdout(
        {{"--png", args.png}, {"--stats", args.stats}, {"--timeline", args.timeline}});
    if (!args.snapshot.empty()) {
        if (args.png.empty() || args.png == "-")
            throw UsageError("--snapshot needs --png F: snapshots are written as F-<call>.png");
        snapshots = parse_call_set_option("--snapshot", args.snapshot);
    }
    const controller::CostProfile profile = controller::load_profile(args.profile);
    protocol::StreamReader reader(args.stream);
    controller::Controller ctl(profile);

    ReplayRun run;
    std::optional<uint64_t> buffer = parse_buffer_option(args.buffer, args.profile);
    if (!buffer && !args.timeline.empty()) buffer = profile.command_buffer_bytes;
    if (buffer) run.pipelines.emplace(*buffer, !args.timeline.empty());
    if (buffer && !snapshots.empty())
        throw UsageError("--buffer and --timeline replay whole frames; not with --snapshot");
    replay(args, snapshots, reader, ctl, run);
    const bool write = !run.error || args.salvage;  // a failed replay leaves nothing

    // an output asked for and not written is a failure: the command writes none of them
    if (write && !args.png.empty() && snapshots.empty()) {
        if (!run.last_frame) {
            if (run.error)
                std::cerr << fmt::format("fb89: {}: {}; --salvage: no complete frame before it\n",
                                         run.error->damaged() ? "error" : "warning",
                                         run.error->what());
            throw std::runtime_error(args.stream + ": no complete frame; " + args.png +
                                     " not written");
        }
        make_parent_dirs(args.png);
        controller::write_png(args.png, *run.last_frame);
    }
    if (write && !snapshots.empty() && run.snapshots == 0)
        throw std::runtime_error(
            fmt::format("--snapshot {}: the call set matched no command of {}; no snapshot written",
                        args.snapshot, args.stream));
    if (write && !snapshots.empty())
        console.note(fmt::format("{} snapshot(s) written{}", run.snapshots,
                                 run.snapshots ? ", the last " + run.last_snapshot : ""));
    if (write && !args.timeline.empty())
        write_text(args.timeline, run.pipelines->last_frame_timeline(
                                      args.stream, args.timeline, send_times_of(reader), profile));
    if (write && !args.stats.empty()) write_json(args.stats, stats_json(args, reader, ctl, run));

    if (!args.quiet && !stdout_taken) {
        fmt::print("{}\nprofile {}\n", header_line(reader), profile.name);
        fmt::print("{}", frame_table(ctl));
        fmt::print("{}", ctl.stats().summary());
        const std::string sends =
            reader.timed() ? fmt::format("send times from the stream, {}", send_times_of(reader))
                           : "no send times in the stream: every command ready at 0";
        const std::size_t frames = run.pipelines ? run.pipelines->frames().size() : 0;
        for (std::size_t i = 0; i < frames; ++i) {
            const controller::PipelineFigures& p = run.pipelines->frames()[i];
            fmt::print(
                "pipeline, frame {} ({}; buffer {}): frame {:.3f} ms, host {:.3f} ms, {}, "
                "controller idle {:.3f} ms, buffer high water {} bytes\n",
                i, sends, controller::command_buffer_text(p.buffer_bytes), p.frame_us / 1e3,
                p.host_us / 1e3,
                controller::host_stall_text(p.buffer_bytes, p.host_stalled_us / 1e3),
                p.controller_idle_us / 1e3, p.high_water_bytes);
        }
        if (args.benchmark) {
            const controller::OpcodeCounters all = sum(ctl.stats().totals);
            const nlohmann::json b = benchmark_json(run, all);
            fmt::print(
                "benchmark: {} commands, {} pixels in {:.4f} s wall: {:.3f} M commands/s, "
                "{:.1f} Mpixels/s\n",
                grouped(all.commands), grouped(all.pixels), run.wall_s,
                b["commands_per_s"].get<double>() / 1e6, b["mpixels_per_s"].get<double>());
        }
    }
    if (run.error && args.salvage && run.error->damaged()) {
        // the outputs stand (the frames before the damage are good), the exit says the input
        // was damaged
        if (protocol::OutputBatch* outputs = protocol::OutputBatch::current()) outputs->publish();
        report_stream_error(*run.error);
        std::cerr << fmt::format(
            "fb89: {}: --salvage: kept the {} complete frame(s) before the damage{}; {}\n",
            args.stream, ctl.frames().size(),
            args.png.empty() && args.stats.empty() && args.timeline.empty()
                ? ""
                : " and wrote the outputs from them",
            dropped_text(args, reader, ctl, *run.error));
        return kBadInput;
    }
    if (run.error && args.salvage) {
        std::cerr << fmt::format(
            "fb89: warning: {}; --salvage: kept the {} complete frame(s) before it\n",
            run.error->what(), ctl.frames().size());
        return kSuccess;
    }
    if (run.error) {
        report_stream_error(*run.error);
        const bool has_outputs = !args.png.empty() || !args.stats.empty();
        std::cerr << fmt::format("fb89: {}: replayed {} complete frame(s) before the error{}\n",
                                 args.stream, ctl.frames().size(),
                                 has_outputs ? "; no output written (--salvage writes what "
                                               "was read before the error)"
                                             : "");
        return kBadInput;
    }
    return kSuccess;
}

}  // namespace

void register_replay(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ReplayArgs>();
    CLI::App* sub = app.add_subcommand(
        "replay", "Replay a recorded stream into the controller under a cost profile");
    sub->add_option("stream", args->stream, "Stream file ('-' for stdin)")->required();
    sub->add_option("--profile", args->profile, profile_option_help())
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_option("--png", args->png,
                    "Write the last complete frame as PNG (with --snapshot: the snapshots)");
    sub->add_option("--snapshot", args->snapshot,
                    "Call set: write F-<call>.png right after each of these calls "
                    "(e.g. 'frame', '100-200/10/span')");
    sub->add_option("--stats", args->stats,
                    "Write the controller's stats as JSON ('-' for stdout)");
    sub->add_option("--buffer", args->buffer,
                    "Also run each frame through the pipeline in time with a command buffer of "
                    "this many bytes, or unbounded, from the stream's send times (a version-1 "
                    "stream has none: every command ready at 0)");
    sub->add_option("--timeline", args->timeline,
                    "Write the last complete frame through the pipeline in time as Chrome "
                    "trace-event JSON (Perfetto, chrome://tracing)");
    sub->add_flag("--benchmark", args->benchmark,
                  "Time the replay (wall) and report commands/s and Mpixels/s");
    sub->add_flag("--salvage", args->salvage,
                  "On a truncated or corrupt stream, write what was read before the error (the "
                  "last complete frame, earlier snapshots, stats with an \"error\" entry): a "
                  "stream cut short or refused is then a warning, exit 0; a damaged one (a "
                  "batch failing its checksum) still exits 2, saying what was dropped");
    sub->add_flag("--gsp", args->gsp,
                  "Replay through the emulated TMS34010 executing the profile's executive "
                  "(its listing), beside the controller: each frame compared pixel for pixel "
                  "(exit 1 if one differs), each opcode's executed cycles beside the model's");
    sub->add_option("--listing", args->listing,
                    "With --gsp: run this TMS34010 listing (GSPA syntax) in place of the "
                    "profile's built-in one");
    sub->add_option("--gsp-trace", args->gsp_trace,
                    "With --gsp: print this command's executed instructions with their states "
                    "(commands numbered as fb89 dump numbers them)");
    sub->add_flag("--gsp-warm", args->gsp_warm,
                  "With --gsp: every instruction fetch hits the instruction cache, as the model "
                  "assumes (no misses counted)");
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([args, &exit_code] { exit_code = run_replay(*args); });
}

}  // namespace fb89::cli
