// The simulated frame-buffer controller: a CommandSink that tiles commands into a
// framebuffer and counts what that would cost the modelled hardware.
//
// Shaped like a MAME device (controller.cpp): an opcode table, one exec_* per opcode and a
// list of what is not modelled. It reports only controller figures; host times are
// measured and reported elsewhere, always apart.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "controller_sim/board_memory.h"
#include "controller_sim/cost_model.h"
#include "controller_sim/framebuffer.h"
#include "controller_sim/profile.h"
#include "protocol/command_sink.h"

namespace fb89::controller {

// What one opcode did: summed over its commands.
struct OpcodeCounters {
    uint64_t commands = 0;
    uint64_t pixels = 0;   // pixels written (after clipping)
    uint64_t bytes = 0;    // modelled bytes on the bus
    uint64_t cycles = 0;   // modelled controller cycles
    uint64_t clipped = 0;  // commands cut by the framebuffer's edges
    uint64_t outside = 0;  // commands that wrote nothing (wholly outside, empty, or no frame)

    OpcodeCounters& operator+=(const OpcodeCounters& o);
    friend bool operator==(const OpcodeCounters&, const OpcodeCounters&) = default;
};

using PerOpcode = std::array<OpcodeCounters, protocol::kOpcodeCount>;  // by opcode_index

// What the depth commands' pixels did: every depth test, the nearer ones (drawn), and of the
// others those exactly as near as the word they met (kept by the lower id's rule: the ties
// the depth word's resolution makes).
struct DepthCounters {
    uint64_t tests = 0;
    uint64_t nearer = 0;
    uint64_t equal = 0;

    DepthCounters& operator+=(const DepthCounters& o) {
        tests += o.tests;
        nearer += o.nearer;
        equal += o.equal;
        return *this;
    }
    friend bool operator==(const DepthCounters&, const DepthCounters&) = default;
};
OpcodeCounters sum(const PerOpcode& ops);

// One frame, from its FRAME_BEGIN to its FRAME_END.
struct FrameResult {
    uint32_t frame = 0;  // the number FRAME_BEGIN carried
    uint32_t width = 0, height = 0;
    uint64_t first_command = 0;  // stream number of its FRAME_BEGIN
    uint64_t checksum = 0;       // Framebuffer::checksum() at FRAME_END
    // False when the next FRAME_BEGIN arrived before this frame's FRAME_END: the frame was
    // closed there, and its checksum taken then.
    bool complete = true;
    PerOpcode ops{};
    DepthCounters depth;
    uint32_t depth_bits = 0;  // the depth buffer's word, 0 when the frame had none
    double bus_busy_us = 0;
    double controller_busy_us = 0;
    double end_us = 0;  // when its last command finished, from its first command's start

    OpcodeCounters total() const { return sum(ops); }
};

// 1234567 -> "1,234,567", for the tables of the controller and the stream tools.
std::string grouped(uint64_t v);
// How the profile draws spans and clears a frame of width x height, in words for the
// summary ("drawn as: DRAW_SPAN by FILL XY of one row (TI's draw_line); FRAME_BEGIN clears
// through the VRAMs' serial registers (390 VRAM rows, TI's clear_page)").
std::string drawn_as_text(const CostProfile& p, uint32_t width, uint32_t height);

struct ControllerStats {
    CostProfile profile;
    std::vector<FrameResult> frames;  // closed frames, in order (when kept)
    uint64_t frames_closed = 0;       // closed frames, kept or not
    uint64_t frames_incomplete = 0;   // of those, closed by the next FRAME_BEGIN
    bool frame_open = false;          // a frame begun and not yet closed (a cut stream's last)
    PerOpcode totals{};               // every command, in frames or not
    PerOpcode unframed{};             // commands outside any frame (before the first, between)
    DepthCounters depth;              // every depth command's pixels
    double bus_busy_us = 0;           // every command
    double controller_busy_us = 0;    // every command
    double frames_end_us = 0;         // sum of the closed frames' end_us

    nlohmann::json to_json() const;
    // A table for humans: opcode, commands, pixels, bytes, cycles, modelled time, bus time.
    std::string summary() const;
};

class Controller final : public protocol::CommandSink {
  public:
    explicit Controller(CostProfile profile = default_profile());

    void frame_begin(const protocol::FrameBegin& c) override;
    void fill_rect(const protocol::FillRect& c) override;
    void draw_span(const protocol::DrawSpan& c) override;
    void marker(const protocol::Marker& c) override;
    void frame_end(const protocol::FrameEnd& c) override;
    // Version 3's depth commands. A DEPTH_SPAN or FACE in a frame without a DEPTH_CLEAR, or
    // any of them under a profile that does not price them, throws std::invalid_argument
    // naming the command (a replay then stops with exit 2).
    void depth_clear(const protocol::DepthClear& c) override;
    void depth_span(const protocol::DepthSpan& c) override;
    void face(const protocol::Face& c) override;

    // Executes any command through the opcode table.
    void execute(const protocol::Command& c);
    // Executes commands in order: the same framebuffer, counters and times as execute() on
    // each, faster. The open frame's FILL_RECTs, DRAW_SPANs and (once it has its depth
    // buffer) DEPTH_SPANs take a fast path that keeps
    // their counters and clocks in locals (execute_drawing); every other command goes
    // through execute(c). With an observer set, every command does. With `costs` (at least
    // as long as commands), each command's cost goes beside it, as last_cost() would give it.
    struct CommandCost;
    void execute(std::span<const protocol::Command> commands, std::span<CommandCost> costs = {});

    const CostProfile& profile() const { return m_stats.profile; }
    const Framebuffer& framebuffer() const { return m_fb; }
    // The open frame's depth buffer (width x height words, row by row), empty without one.
    std::span<const uint32_t> depth_buffer() const { return m_depth; }
    const ControllerStats& stats() const { return m_stats; }
    const std::vector<FrameResult>& frames() const { return m_stats.frames; }
    bool in_frame() const { return m_in_frame; }
    // The frame being drawn so far (meaningful only while in_frame()).
    FrameResult open_frame() const;
    uint64_t commands_executed() const { return m_next_command; }
    // Modelled time so far, in µs: the closed frames' end times, plus the open frame's
    // time so far, plus the commands outside frames. Cheap (no checksum): a viewer paces
    // playback by it.
    double elapsed_us() const;
    // What the last command executed through execute(c) or a sink call cost: its modelled
    // bytes, bus time and execution time (the pipeline in time, timed_pipeline.h, takes them).
    struct CommandCost {
        uint32_t bytes = 0;
        double bus_us = 0, exec_us = 0;
    };
    const CommandCost& last_cost() const { return m_last_cost; }

    // Called after each command has executed, with its number (commands_executed() before
    // it) and the command; empty by default. A viewer hooks a Recorder here.
    using Observer = std::function<void(uint64_t number, const protocol::Command&)>;
    void set_observer(Observer observer) { m_observer = std::move(observer); }

    // The pixels the last command drew by a depth test (a DEPTH_SPAN's or FACE's nearer
    // pixels), as runs of one row (h = 1), left to right and row by row: a viewer's Recorder
    // attributes them to the command. Kept only after keep_depth_drawn(true), and only for
    // commands executed one at a time (execute(c), the sink calls; execute(span) then takes
    // no fast path); empty after any other command. Off (the default), depth_run pays one
    // untaken branch per run.
    void keep_depth_drawn(bool keep) {
        m_keep_drawn = keep;
        m_drawn.clear();
    }
    std::span<const PixelRect> depth_drawn() const {
        return m_drawn_after == m_next_command ? std::span<const PixelRect>(m_drawn)
                                               : std::span<const PixelRect>();
    }

  private:
    // What an exec_* function did; account() turns it into counters and time.
    struct Executed {
        uint64_t cycles = 0;
        uint64_t pixels = 0;
        bool clipped = false;
        bool outside = false;
        int64_t bytes = -1;  // the command's own bytes (a FACE's), -1: the opcode's
    };
    struct OpcodeEntry {
        const char* name;
        uint32_t bytes;  // modelled bytes, from the profile
        double bus_us;   // bus time of one command
    };
    static std::array<OpcodeEntry, protocol::kOpcodeCount> make_opcode_table(const CostProfile& p);

    Executed exec_frame_begin(const protocol::FrameBegin& c);
    Executed exec_fill_rect(const protocol::FillRect& c);
    Executed exec_draw_span(const protocol::DrawSpan& c);
    Executed exec_marker(const protocol::Marker& c);
    Executed exec_frame_end(const protocol::FrameEnd& c);
    Executed exec_depth_clear(const protocol::DepthClear& c);
    Executed exec_depth_span(const protocol::DepthSpan& c, DepthCounters& counts);
    Executed exec_face(const protocol::Face& c);
    // A depth command's checks: the profile prices it, and (but for DEPTH_CLEAR) the frame has
    // a depth buffer.
    void check_depth(protocol::Opcode op, bool needs_buffer) const;
    // Pixels x .. x+n-1 of row y (inside the frame), pixel x at depth z and each next dz more:
    // tested against the depth buffer, drawn where nearer; adds to the counters.
    void depth_run(uint32_t y, uint32_t x, uint32_t n, int64_t z, int64_t dz, protocol::Rgb color,
                   DepthCounters& counts);
    // keep_depth_drawn's record: the run's drawn pixels (all n when flags is null)
    void keep_drawn(uint32_t y, uint32_t x, uint32_t n, const uint8_t* flags);

    // One command: its exec_*, its accounting, and for FRAME_END the frame's close.
    void step(const protocol::FrameBegin& c);
    void step(const protocol::FillRect& c);
    void step(const protocol::DrawSpan& c);
    void step(const protocol::Marker& c);
    void step(const protocol::FrameEnd& c);
    void step(const protocol::DepthClear& c);
    void step(const protocol::DepthSpan& c);
    void step(const protocol::Face& c);
    // A sink call: step() alone, or through execute() when an observer wants the Command.
    template <class C>
    void submit_one(const C& c);

    // The fast path of execute(span): the open frame's drawing commands from commands[i]
    // on; returns the index of the first command it did not take.
    std::size_t execute_drawing(std::span<const protocol::Command> commands, std::size_t i,
                                CommandCost* costs);

    void account(protocol::Opcode opcode, const Executed& x);
    void close_frame(bool complete);

    std::array<OpcodeEntry, protocol::kOpcodeCount> m_opcodes;
    CycleCosts m_costs;
    double m_us_per_cycle;
    Framebuffer m_fb;
    BoardVector<uint32_t> m_depth;  // the open frame's depth buffer, after its DEPTH_CLEAR
    std::vector<uint8_t> m_nearer;  // a row's depth test: 1 where nearer (depth_run's)
    ControllerStats m_stats;
    bool m_in_frame = false;
    FrameResult m_frame;  // the open frame's counters
    Pipeline m_frame_pipe;
    CommandCost m_last_cost;
    Pipeline m_unframed_pipe;
    uint64_t m_next_command = 0;
    Observer m_observer;
    // keep_depth_drawn: the runs drawn, kept for the command after which m_next_command is
    // m_drawn_after
    bool m_keep_drawn = false;
    std::vector<PixelRect> m_drawn;
    uint64_t m_drawn_after = 0;
};

}  // namespace fb89::controller
