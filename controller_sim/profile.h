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

#include "protocol/command.h"

namespace fb89::controller {

// A command buffer without a bound: the host never waits for room (the pipeline of protocol
// version 1).
inline constexpr uint64_t kUnboundedBuffer = std::numeric_limits<uint64_t>::max();

// How DRAW_SPAN is tiled: as a vector draw (the user's card) or as a one-row fill.
enum class SpanAs { Line, Fill };
const char* to_string(SpanAs s);  // "line", "fill"

struct CostProfile {
    std::string name;
    std::string description;
    double f_cyc_hz = 0;   // machine cycles per second
    uint32_t bpp = 8;      // bits per pixel the cost is modelled at (1, 2, 4, 8 or 16)
    uint32_t c_cmd = 0;    // per command: fetch and decode from the command ring
    uint32_t c_setup = 0;  // FILL set-up
    uint32_t c_op = 0;     // per 16-bit word written by FILL
    uint32_t c_row = 0;    // per FILL row
    SpanAs span_as = SpanAs::Line;
    uint32_t c_line_setup = 0;     // LINE set-up
    uint32_t c_line_pix = 0;       // per LINE pixel
    double b_bus_bytes_per_s = 0;  // host-to-controller bandwidth; +inf: "unlimited"
    double t_handshake_s = 0;      // per command sent
    // Bytes a command occupies on the modelled bus, by protocol::opcode_index. Fixed per
    // opcode whatever the file encoding; 0 means the command is not sent at all.
    std::array<uint32_t, protocol::kOpcodeCount> bytes{};
    // The controller's command buffer, in bytes (the pipeline in time, timed_pipeline.h):
    // "command_buffer_bytes", a number at least the largest command's bytes, or "unbounded"
    // (also when the field is absent).
    uint64_t command_buffer_bytes = kUnboundedBuffer;
    // Where each figure comes from: field name -> "[EMU] ..." or "[EST] ...".
    std::map<std::string, std::string> sources;
    // The range an estimated figure may lie in, and why ("bands"): field name -> band. Fields
    // that can have one: C_cmd, C_setup, C_op, C_row, C_line_setup, C_line_pix,
    // B_bus_bytes_per_s, t_handshake_s (low <= the figure <= high) and command_buffer_bytes
    // (low only: the smallest buffer it may be; its high end is the figure).
    struct Band {
        double low = 0, high = 0;
        std::string why;
    };
    std::map<std::string, Band> bands;

    // P: pixels per 16-bit word.
    uint32_t pixels_per_word() const { return 16 / bpp; }
    uint32_t bytes_of(protocol::Opcode op) const { return bytes[protocol::opcode_index(op)]; }

    nlohmann::json to_json() const;  // the same fields as the profile file
    std::string to_string() const;   // one line for logs and test messages
};

// The profile with every banded figure at the end of its band that makes the controller
// dearer (`dear`: more cycles, a slower bus, a longer handshake, the smaller buffer) or
// cheaper; figures without a band stay as they are. Its name gets " (dear end)" or
// " (cheap end)".
CostProfile band_end(const CostProfile& profile, bool dear);

// A command buffer's size as the profile file and the JSON outputs give it: "unbounded" or
// the number of bytes; and as text: "unbounded" or "N bytes".
nlohmann::json command_buffer_json(uint64_t bytes);
std::string command_buffer_text(uint64_t bytes);
// The host's stalls as a reader should read them: with an unbounded buffer the host only
// ever waits for the bus ("host waited for the bus 1.234 ms"); with a bounded one, for the
// bus or for room in the buffer ("host stalled 1.234 ms (bus or full buffer)").
std::string host_stall_text(uint64_t buffer_bytes, double stalled_ms);

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

// Parses profile JSON (comments allowed); `origin` names the text in errors. A missing
// "name" defaults to `default_name`.
CostProfile parse_profile(std::string_view json_text, std::string_view origin,
                          std::string_view default_name = "");

}  // namespace fb89::controller
