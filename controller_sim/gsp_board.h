// fb89's board with its GSP executing the command executive (gsp_cpu.h): the listing
// assembled and loaded at address 0, the registers set as its header says, and each
// command written into the ring as the host port would write its 16-bit words
// (docs/COST_MODEL.md, "Modelled bytes"), the executive then running until the ring is
// empty. Its frame is read back from the VRAM through the palette the host's driver keeps
// (a colour is an 8-bit index on the board: the first colour seen is 0, the next 1, ...).
// What each command cost is counted by its opcode, beside what is not any command's: the
// executive's poll of the host's write pointer when it has caught up with it.
// docs/COST_MODEL.md, "The GSP as code".
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "controller_sim/framebuffer.h"
#include "controller_sim/gsp_assembler.h"
#include "controller_sim/gsp_cpu.h"
#include "controller_sim/profile.h"
#include "protocol/command.h"

namespace fb89::controller::gsp {

// What the executed commands of one opcode cost, summed.
struct ExecutedCounters {
    uint64_t commands = 0;
    uint64_t instructions = 0;
    uint64_t states = 0;             // the instructions' states, memory and pixels included
    uint64_t host_states = 0;        // the host's words' memory cycles (the model's c_host_word)
    uint64_t cache_misses = 0;       // instruction-cache sub-segments fetched
    uint64_t cache_miss_states = 0;  // of states, what they cost
    uint64_t wraps = 0;              // commands that found the ring's end and went round
    // Of the write queue a command left at its end (charged to it, as the model charges
    // it), what the next command's loop ran beside before its first memory access: counted
    // in that next command's row, where execution is that much cheaper than the model.
    uint64_t queue_overlapped = 0;
    uint64_t cycles() const { return states + host_states; }
    // The executed cycles less the model's, less what the model leaves out (the cache's
    // misses, the queue run beside the next command): 0 when the two agree.
    int64_t unexplained(uint64_t model_cycles) const {
        return static_cast<int64_t>(cycles()) - static_cast<int64_t>(model_cycles) -
               static_cast<int64_t>(cache_miss_states) + static_cast<int64_t>(queue_overlapped);
    }
    ExecutedCounters& operator+=(const ExecutedCounters& o);
};

// One executed instruction of a traced command.
struct TracedInstruction {
    uint32_t address = 0;
    uint32_t states = 0;
    int line = 0;  // in the listing
    std::string text;
};

struct GspBoardOptions {
    // The ring's size in 16-bit words (at least the largest command's, 267 words).
    uint32_t ring_words = 1u << 17;
    // The most instructions one command may execute before it is called a loop that does
    // not end.
    uint64_t budget = uint64_t{1} << 28;
    bool cache = true;  // model the instruction cache
    // Trace the command of this number (as fb89 dump numbers them; MARKERs count).
    std::optional<uint64_t> trace;
};

class GspBoard {
  public:
    // `listing` is the executive's source (a built-in one's text or a user's file), named
    // `file` in errors; the profile says which FRAME_BEGIN and DRAW_SPAN handlers the
    // dispatch table names, the pixel size, the depth word and the memory's timing. Throws
    // AssemblyError for a listing that does not assemble, std::invalid_argument for a
    // profile the board cannot run (no listing's timing, a pixel size it has no frame for).
    GspBoard(const CostProfile& profile, std::string_view file, std::string_view listing,
             const GspBoardOptions& options = {});

    // Executes commands in order (writing them into the ring in batches as it has room).
    // Throws std::invalid_argument for a command the board cannot take (a frame larger than
    // its VRAM, more colours than the pixel holds) and GspFault, with the listing's line,
    // for a program that goes wrong.
    void execute(std::span<const protocol::Command> commands);

    // The frame the last FRAME_BEGIN sized, read back from the VRAM through the palette.
    Framebuffer frame() const;
    bool has_frame() const { return m_width > 0; }
    // By protocol::opcode_index.
    const std::array<ExecutedCounters, protocol::kOpcodeCount>& executed() const {
        return m_executed;
    }
    ExecutedCounters total() const;
    // The executive's polls of the host's write pointer (one a batch it waits for).
    const ExecutedCounters& polls() const { return m_polls; }
    const std::vector<TracedInstruction>& trace() const { return m_trace; }
    const Program& program() const { return m_program; }
    const Tms34010& cpu() const { return *m_cpu; }
    uint64_t commands_executed() const { return m_number; }

    // The host's words of a command (empty for a MARKER, which is not sent), colours as the
    // board's palette indices (assigned on first sight); throws std::invalid_argument for a
    // command the board cannot take.
    std::vector<uint16_t> words_of(const protocol::Command& c);

  private:
    uint16_t colour_word(protocol::Rgb c);
    void set_pitch(uint32_t width);
    // Runs the executive until it has read everything the host wrote.
    void run();
    // The listing's line of an address ("line N: text"), for errors and traces.
    std::string where(uint32_t address) const;

    CostProfile m_profile;
    std::string m_file;
    Program m_program;
    GspBoardOptions m_options;
    std::unique_ptr<Tms34010> m_cpu;
    uint32_t m_next = 0;                   // the executive's `next`
    uint32_t m_host_wp = 0;                // its HOST_WP
    uint32_t m_fpshift = 0, m_zpitch = 0;  // and FPSHIFT and ZPITCH
    uint32_t m_mode_width = 0;             // a width to set the pitch for, before a frame
    uint32_t m_ring_start = 0, m_ring_end = 0, m_write = 0;
    std::map<uint32_t, int> m_line_at;  // address -> index into m_program.lines
    std::vector<protocol::Rgb> m_palette;
    std::map<uint32_t, uint16_t> m_index;  // 0xRRGGBB -> palette index
    uint32_t m_width = 0, m_height = 0, m_pitch_bits = 0;
    // the commands written and not yet executed: their opcode, number and host words
    struct Pending {
        protocol::Opcode op;
        uint64_t number;
        uint32_t words;
    };
    std::vector<Pending> m_pending;
    std::size_t m_pending_next = 0;
    uint64_t m_number = 0;  // the next command's number
    std::array<ExecutedCounters, protocol::kOpcodeCount> m_executed{};
    ExecutedCounters m_polls;
    std::vector<TracedInstruction> m_trace;
};

}  // namespace fb89::controller::gsp
