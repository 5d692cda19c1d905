// Cost profiles: the figures that turn the controller's work into cycles and bus time.
//
// A profile is data, not code: controller_sim/profiles/*.json are embedded into the library
// at build time (CMake generates profiles_embedded.cpp), so a recorded stream can be replayed
// under another controller without re-rendering. docs/COST_MODEL.md lists every field, its
// value in each built-in profile and where that value comes from ([EMU] = MAME's
// 34010gfx.hxx, [EST] = our estimate).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "controller_sim/gsp_listing.h"
#include "protocol/command.h"

namespace fb89::controller {

// A command buffer without a bound: the host never waits for room (the pipeline of protocol
// version 1).
inline constexpr uint64_t kUnboundedBuffer = std::numeric_limits<uint64_t>::max();

// How DRAW_SPAN is tiled: as a one-row fill (TI's draw_line for a horizontal line,
// EXTPRIMS/DRAWLINE.ASM) or as a vector draw with LINE.
enum class SpanAs { Line, Fill };
const char* to_string(SpanAs s);  // "line", "fill"

// How FRAME_BEGIN clears the frame: through the VRAMs' serial registers (TI's clear_page on
// its TIGA development board, TDB10/OEMPRIMS/CLEARPAG.ASM) or with one FILL over the frame
// (TI's clear_screen, CLEARSCR.ASM).
enum class ClearAs { SerialRegister, Fill };
const char* to_string(ClearAs c);  // "srt", "fill"

// The board the listing's serial-register clear is written for, TI's TIGA development
// board (TDB10/README.1ST; CLEARFRM.ASM): a VRAM row, the same row of every 256K x 4 part of
// its two banks, is 16,384 bits, and its 1 MB of VRAM is 512 such rows. A TMS34020 board
// with one 32-bit bank of the same parts has the same rows.
inline constexpr uint32_t kVramRowBits = 16384;
inline constexpr uint32_t kVramRows = 512;
// The VRAM rows a frame of width x height at bpp takes (its pitch the width rounded up to a
// power of two, as the listing's DPTCH).
uint64_t vram_rows(uint32_t width, uint32_t height, uint32_t bpp);

struct CostProfile {
    std::string name;
    std::string description;
    double f_cyc_hz = 0;     // machine states per second (a state is one local clock)
    uint32_t bpp = 8;        // bits per pixel the cost is modelled at (1, 2, 4, 8 or 16)
    uint32_t bus_bits = 16;  // the local bus's width: a word, what one memory cycle moves

    // The memory-cycle model, when "gsp" names a listing (docs/COST_MODEL.md, "The tiling as
    // memory cycles"): the per-command figures below are derived from these and the listing.
    // A profile without "gsp" gives the derived figures itself (C_cmd, C_setup, C_op, C_row,
    // C_line_setup, C_line_pix: the figures of the first cost model, MAME's).
    std::string gsp;                    // the command executive, controller_sim/gsp/NAME.asm
    Chip gsp_chip = Chip::Tms34010;     // whose instruction timings price it ("gsp_chip")
    uint32_t memory_cycle_states = 2;   // one local-memory cycle without wait states
    uint32_t wait_states = 0;           // LRDY's, per memory cycle
    uint32_t refresh_every_states = 0;  // a DRAM refresh cycle every N states (0: none)
    double screen_transfers_per_s = 0;  // VRAM memory-to-register cycles for the display
    uint32_t c_line_extra = 0;          // LINE's step beyond its pixel's memory cycles
    uint32_t row_states = 0;            // "C_row": what a FILL row costs beyond its words
    bool byte_strobes = false;          // a CAS per byte: 8-bit pixels written without a read
    uint32_t page_mode_states = 0;      // a page-mode cycle, the words of a row after the first
    // The chip's host port as its data sheet rates it; 0: from the TMS34010's strobe rule.
    double host_port_rated_bytes_per_s = 0;
    // Which end of the listing's estimated timings the figures were counted at (band_end).
    bool listing_dear = false, listing_cheap = false;

    // The figures the cost model charges (derived, or given by a profile without "gsp").
    uint32_t c_cmd = 0;                // per command: the loop's fetch and dispatch
    uint32_t c_setup = 0;              // FILL_RECT's set-up, FILL's own included
    uint32_t c_frame_begin_setup = 0;  // FRAME_BEGIN's, before its clear's pixels (by FILL)
    ClearAs clear_as = ClearAs::Fill;  // "clear_as": "srt" or "fill" ("fill" when absent)
    // FRAME_BEGIN's through the serial registers: its row fill's, its memory-to-register
    // cycle's and its register-to-memory FILL's set-ups; and a frame too large for the
    // VRAM's, which goes on to the FILL clear
    uint32_t c_frame_begin_srt_setup = 0;
    uint32_t c_frame_begin_large_setup = 0;
    // TIGA's call around a primitive (the listing's TIGA_CALL), in C_cmd at the dear end of
    // the listing's band only; 0 without a listing
    uint32_t c_tiga_call = 0;
    uint32_t c_span_fill_setup = 0;  // DRAW_SPAN's as a one-row fill
    uint32_t c_frame_end_setup = 0;  // FRAME_END's
    uint32_t c_op = 0;               // per aligned word FILL writes
    uint32_t c_op_partial = 0;       // per partial word (read, modify, write)
    uint32_t c_row = 0;              // per FILL row (a page-mode row's first word's extra too)
    SpanAs span_as = SpanAs::Line;
    uint32_t c_line_setup = 0;        // DRAW_SPAN's as a line, LINE's own included
    uint32_t c_line_pix = 0;          // per LINE pixel
    uint32_t c_host_word = 0;         // per 16-bit host word: its memory cycle in the GSP's memory
    double stolen_share = 0;          // the share of the bus refresh takes from the GSP
    bool outside_pays_setup = false;  // a command outside the frame still loads and runs FILL

    // The depth commands (stream format version 3; docs/COST_MODEL.md, "Depth commands").
    // The depth buffer's word, in bits: 16 or 32 ("depth_bits"; 16 when absent).
    uint32_t depth_bits = 16;
    // Whether the profile prices them: one with a listing does, and one whose figures are
    // all zero (the ideal controller); any other refuses them.
    bool depth_priced = false;
    uint32_t c_zclear_setup = 0;     // DEPTH_CLEAR's set-up, FILL's own included
    uint32_t c_zspan_setup = 0;      // DEPTH_SPAN's set-up to its pixel loop
    uint32_t c_zspan_outside = 0;    // ... to where it finds nothing in the frame: above it,
    uint32_t c_zspan_below = 0;      // below it,
    uint32_t c_zspan_empty = 0;      // nothing left of the span in the frame's columns,
    uint32_t c_zspan_empty_cut = 0;  // the same after a cut on the left
    uint32_t c_zclip = 0;            // a span cut on the left: Z stepped to column 0
    uint32_t c_zpass = 0;            // a pixel nearer than the depth buffer: tested and written
    uint32_t c_zfail = 0;            // a pixel as near or farther: tested
    uint32_t c_zexit = 0;            // the loop's return
    uint32_t c_face_setup = 0;       // FACE's set-up
    uint32_t c_face_point = 0;       // an edge set up from a point (all but the last)
    uint32_t c_face_last = 0;        // the last point's edge, back to the first
    uint32_t c_face_row = 0;         // a row of the face's rows in the frame
    uint32_t c_face_edge = 0;        // an edge stepped to the row
    uint32_t c_face_span = 0;        // a row's run handed to the pixel loop, a span's set-up
    uint32_t c_face_empty = 0;       // a row with no covered centre
    uint32_t c_face_done = 0;        // the end of its rows
    // What the edge loop's data decide (the listing's FACE:* paths): an edge a row that is
    // level (no division; with N < 0 it empties the row), one whose quotient is beyond 32
    // bits (likewise), the extra of a nearer bound taken, and a level point's set-up
    uint32_t c_face_level = 0, c_face_level_none = 0;
    uint32_t c_face_far = 0, c_face_far_none = 0;
    uint32_t c_face_bound = 0;
    uint32_t c_face_level_point = 0;

    double b_bus_bytes_per_s = 0;  // the host side's bandwidth; +inf: "unlimited"
    // The chip's host port: no faster than its strobe spacing and the memory cycle each word
    // takes (+inf for a profile without "gsp").
    double host_port_bytes_per_s = std::numeric_limits<double>::infinity();
    double t_handshake_s = 0;  // per command sent
    // Bytes a command occupies on the modelled bus, by protocol::opcode_index. Fixed per
    // opcode whatever the file encoding; 0 means the command is not sent at all. The tiling
    // commands' are the profile's ("bytes"); the depth commands' follow from their 16-bit
    // words (kDepthClearBytes...), a FACE's fixed part here and kFacePointBytes a point more.
    std::array<uint32_t, protocol::kOpcodeCount> bytes{};
    // The controller's command buffer, in bytes (the pipeline in time, timed_pipeline.h):
    // "command_buffer_bytes", a number at least the largest command's bytes, or "unbounded"
    // (also when the field is absent).
    uint64_t command_buffer_bytes = kUnboundedBuffer;
    // Where each figure comes from: field name -> "[DS] ...", "[UG] ...", "[EMU] ..." or
    // "[EST] ...".
    std::map<std::string, std::string> sources;
    // The range an estimated figure may lie in, and why ("bands"): field name -> band. Fields
    // that can have one: the given cycle figures (C_*), wait_states, refresh_every_states,
    // screen_transfers_per_s, B_bus_bytes_per_s, t_handshake_s (low <= the figure <= high),
    // command_buffer_bytes (low only: the smallest buffer it may be; its high end is the
    // figure) and "gsp" (the listing's estimated timings, whose ends the table carries: a
    // band of {"why"} only).
    struct Band {
        double low = 0, high = 0;
        std::string why;
    };
    std::map<std::string, Band> bands;

    // P: pixels per word of the local bus.
    uint32_t pixels_per_word() const { return bus_bits / bpp; }
    // What crosses the bus per second: the host's side or the chip's port, the slower.
    double bus_bytes_per_s() const {
        return b_bus_bytes_per_s < host_port_bytes_per_s ? b_bus_bytes_per_s
                                                         : host_port_bytes_per_s;
    }
    // The 16-bit host words of a command, each a memory cycle the GSP's bus gives the host.
    uint32_t host_words_of(protocol::Opcode op) const { return (bytes_of(op) + 1) / 2; }
    // The board memory the depth buffer takes for a frame: its rows at a pitch of the width
    // rounded up to a power of two (the listing shifts by the pitch), depth_bits a word.
    uint64_t depth_buffer_bytes(uint32_t width, uint32_t height) const;
    uint32_t bytes_of(protocol::Opcode op) const { return bytes[protocol::opcode_index(op)]; }
    // The largest tiling command's bytes: what a command buffer must hold at least (a depth
    // command too large for a buffer is refused where it comes, timed_pipeline.h).
    uint32_t largest_tiling_bytes() const;

    nlohmann::json to_json() const;  // the same fields as the profile file
    std::string to_string() const;   // one line for logs and test messages
};

// The profile with every banded figure at the end of its band that makes the controller
// dearer (`dear`: more cycles, a slower bus, a longer handshake, the smaller buffer, more
// refresh) or cheaper, and the derived figures counted again; figures without a band stay as
// they are. Its name gets " (dear end)" or " (cheap end)".
CostProfile band_end(const CostProfile& profile, bool dear);

// A command buffer's size as the profile file and the JSON outputs give it: "unbounded" or
// the number of bytes; and as text: "unbounded" or "N bytes".
nlohmann::json command_buffer_json(uint64_t bytes);
std::string command_buffer_text(uint64_t bytes);
// The host's stalls as a reader should read them: with an unbounded buffer the host only
// ever waits for the bus ("host waited for the bus 1.234 ms"); with a bounded one, for the
// bus or for room in the buffer ("host stalled 1.234 ms (bus or full buffer)").
std::string host_stall_text(uint64_t buffer_bytes, double stalled_ms);

// The depth commands' bytes on the host port: twice their words, as their rows in
// protocol/command.h lay them out (controller_sim/gsp/tms34010.asm's header reads them so);
// a FACE's fixed part, then each point's x and y as two words each.
inline constexpr uint32_t kDepthClearBytes =
    2 * protocol::kCommandRows[protocol::opcode_index(protocol::Opcode::DepthClear)].port_words;
inline constexpr uint32_t kDepthSpanBytes =
    2 * protocol::kCommandRows[protocol::opcode_index(protocol::Opcode::DepthSpan)].port_words;
inline constexpr uint32_t kFaceFixedBytes =
    2 * protocol::kCommandRows[protocol::opcode_index(protocol::Opcode::Face)].port_words;
inline constexpr uint32_t kFacePointBytes = 8;
static_assert(kDepthClearBytes == 2 && kDepthSpanBytes == 18 && kFaceFixedBytes == 22);

// A profile compiled into the library.
struct BuiltinProfile {
    std::string_view name;  // file stem, e.g. "tms34010-50mhz"
    std::string_view json;  // the file's text
};
std::span<const BuiltinProfile> builtin_profiles();  // defined in the generated file

inline constexpr std::string_view kDefaultProfile = "tms34010-50mhz";

// Names of the built-in profiles, sorted.
std::vector<std::string> list_profiles();

// A built-in profile by name, or a user JSON file when `name_or_path` contains a '/' or
// ends in ".json" (or names no built-in profile but an existing file). Throws
// std::runtime_error naming the file and the offending field.
CostProfile load_profile(std::string_view name_or_path);
CostProfile load_profile_file(const std::filesystem::path& path);
inline CostProfile default_profile() {
    return load_profile(kDefaultProfile);
}

// What the memory costs the listing's instructions in profile `p` (one with "gsp"): its
// memory cycle with wait states, its I/O cycle, a pixel written alone, the chip's timings.
MemoryTiming memory_timing(const CostProfile& p);

// Fills the figures the cost model charges: a "gsp" profile's from its listing and memory
// model, a profile without one's from its given figures by the first model's rules
// (parse_profile and band_end call it, so a band's end moves what follows from a figure).
void derive_figures(CostProfile& p);

// Parses profile JSON (comments allowed); `origin` names the text in errors. A missing
// "name" defaults to `default_name`.
CostProfile parse_profile(std::string_view json_text, std::string_view origin,
                          std::string_view default_name = "");

}  // namespace fb89::controller
