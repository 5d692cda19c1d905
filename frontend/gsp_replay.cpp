// Replay through the emulated GSP (see gsp_replay.h).
#include "frontend/gsp_replay.h"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "controller_sim/gsp_listing.h"
#include "frontend/stream_tools.h"

namespace fb89::frontend {

namespace {

// The first pixel where two frames differ, or "".
std::string difference(const controller::Framebuffer& gsp, const controller::Framebuffer& model) {
    if (gsp.width() != model.width() || gsp.height() != model.height())
        return fmt::format("the GSP's frame is {}x{}, the controller's {}x{}", gsp.width(),
                           gsp.height(), model.width(), model.height());
    if (std::equal(gsp.pixels().begin(), gsp.pixels().end(), model.pixels().begin())) return "";
    uint64_t differing = 0;
    std::string first;
    for (uint32_t y = 0; y < gsp.height(); ++y)
        for (uint32_t x = 0; x < gsp.width(); ++x)
            if (!(gsp.pixel(x, y) == model.pixel(x, y))) {
                if (differing++ == 0)
                    first = fmt::format("pixel ({}, {}): the GSP drew {}, the controller {}", x, y,
                                        protocol::to_string(gsp.pixel(x, y)),
                                        protocol::to_string(model.pixel(x, y)));
            }
    return differing ? fmt::format("{} pixels differ; the first, {}", grouped(differing), first)
                     : "";
}

}  // namespace

uint64_t GspReplayResult::executed_cycles() const {
    uint64_t s = polls.cycles();
    for (const auto& e : executed)
        s += e.cycles();
    return s;
}

uint64_t GspReplayResult::modelled_cycles() const {
    uint64_t s = 0;
    for (uint64_t c : model_cycles)
        s += c;
    return s;
}

GspReplayResult gsp_replay(protocol::StreamReader& reader, const controller::CostProfile& profile,
                           const GspReplayOptions& options) {
    if (profile.gsp.empty())
        throw std::invalid_argument(fmt::format(
            "profile {} has no listing (\"gsp\"): --gsp runs the executive of a profile that "
            "prices one (tms34010-50mhz, tms34010-isa)",
            profile.name));
    const bool builtin = options.listing_text.empty();
    const controller::Listing* listing =
        builtin ? &controller::builtin_listing(profile.gsp) : nullptr;
    const std::string file = builtin ? fmt::format("{}.asm", profile.gsp) : options.listing_file;
    controller::gsp::GspBoard board(
        profile, file, builtin ? listing->text : std::string_view(options.listing_text),
        options.board);
    controller::Controller ctl(profile);
    GspReplayResult r;
    std::vector<protocol::Command> batch(1024);
    double wall = 0;
    while (const std::size_t n = reader.read_batch(batch)) {
        std::size_t from = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const bool end = std::holds_alternative<protocol::FrameEnd>(batch[i]);
            if (!end && i + 1 < n) continue;
            const std::span<const protocol::Command> part(batch.data() + from, i + 1 - from);
            const auto start = std::chrono::steady_clock::now();
            board.execute(part);
            wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            ctl.execute(part);
            from = i + 1;
            if (end && board.has_frame() && !ctl.frames().empty()) {
                controller::Framebuffer frame = board.frame();
                const std::string d = difference(frame, ctl.framebuffer());
                ++r.frames;
                if (!d.empty()) {
                    if (r.frames_differing++ == 0)
                        r.first_difference = fmt::format("frame {} (ending at command {}): {}",
                                                         ctl.frames().back().frame,
                                                         board.commands_executed() - 1, d);
                }
                r.last_frame = std::move(frame);
            }
        }
    }
    r.executed = board.executed();
    r.polls = board.polls();
    for (int i = 0; i < protocol::kOpcodeCount; ++i)
        r.model_cycles[static_cast<std::size_t>(i)] =
            ctl.stats().totals[static_cast<std::size_t>(i)].cycles;
    r.trace = board.trace();
    r.instructions = board.cpu().counters().instructions;
    r.wall_s = wall;
    return r;
}

int64_t GspReplayResult::unexplained(int opcode_index) const {
    const auto i = static_cast<std::size_t>(opcode_index);
    return executed[i].unexplained(model_cycles[i]);
}

std::string GspReplayResult::summary(const controller::CostProfile& profile) const {
    std::string out = fmt::format(
        "the GSP executing {}.asm ({} instructions, {:.3f} s): cycles by opcode, executed "
        "beside the model's, and what execution knows that the model leaves out\n",
        profile.gsp, grouped(instructions), wall_s);
    const auto row = [&](std::string_view name, std::string commands, uint64_t x, std::string m,
                         int64_t diff, uint64_t misses, uint64_t overlapped, std::string rest) {
        out += fmt::format("{:<12} {:>9} {:>14} {:>14} {:>11} {:>11} {:>10} {:>11}\n", name,
                           commands, grouped(x), m, fmt::format("{:+}", diff), grouped(misses),
                           overlapped ? fmt::format("-{}", grouped(overlapped)) : "0", rest);
    };
    out += fmt::format("{:<12} {:>9} {:>14} {:>14} {:>11} {:>11} {:>10} {:>11}\n", "opcode",
                       "commands", "executed", "model", "difference", "cache miss", "queue",
                       "unexplained");
    for (int i = 0; i < protocol::kOpcodeCount; ++i) {
        const auto& e = executed[static_cast<std::size_t>(i)];
        const uint64_t m = model_cycles[static_cast<std::size_t>(i)];
        if (e.commands == 0 && m == 0) continue;
        row(protocol::to_string(protocol::kOpcodes[i]), grouped(e.commands), e.cycles(), grouped(m),
            static_cast<int64_t>(e.cycles()) - static_cast<int64_t>(m), e.cache_miss_states,
            e.queue_overlapped, fmt::format("{:+}", unexplained(i)));
    }
    row("(polls)", grouped(polls.commands), polls.cycles(), "-",
        static_cast<int64_t>(polls.cycles()), polls.cache_miss_states, polls.queue_overlapped,
        "the poll");
    const uint64_t x = executed_cycles(), m = modelled_cycles();
    out += fmt::format("{:<12} {:>9} {:>14} {:>14} {:>11}\n", "all", "", grouped(x), grouped(m),
                       fmt::format("{:+}", static_cast<int64_t>(x) - static_cast<int64_t>(m)));
    out += fmt::format(
        "cache miss: the instruction cache's misses (the model assumes every fetch hits); queue: "
        "a command's last write run beside the next command's loop (the model charges it "
        "whole); the poll: the executive reading the host's write pointer when it has caught "
        "up (the model has none)\n");
    out += fmt::format("frames: {} compared with the controller's, {}\n", frames,
                       frames_differing
                           ? fmt::format("{} differ: {}", frames_differing, first_difference)
                           : "every one equal pixel for pixel");
    return out;
}

std::string trace_text(const std::vector<controller::gsp::TracedInstruction>& trace) {
    std::string out;
    uint64_t total = 0;
    for (const auto& t : trace) {
        total += t.states;
        out += fmt::format("{:08X} {:>5} {:>7}  {:>4}  {}\n", t.address, t.states, total, t.line,
                           t.text);
    }
    return out;
}

}  // namespace fb89::frontend
