// fb89 command stream, version 1: the commands a host sends to the frame-buffer controller.
//
// These are the decoded, in-memory forms. Their wire encoding (field widths, byte order,
// record layout) is fixed in docs/PROTOCOL.md and implemented in stream_writer/stream_reader.
// Each command is self-contained: it carries its own colour, so any subset of a stream is
// still a valid stream.
#pragma once

#include <cstdint>
#include <string>
#include <variant>

namespace fb89::protocol {

// The newest stream format this fb89 reads (docs/PROTOCOL.md): version 1, the commands;
// version 2, the commands with the host's send times. A stream without times is written as
// version 1, so that every fb89 reads it.
inline constexpr uint16_t kFormatVersion = 2;
inline constexpr uint16_t kUntimedVersion = 1;
inline constexpr uint16_t kTimedVersion = 2;

enum class Opcode : uint8_t {
    FrameBegin = 0x01,
    FillRect = 0x02,
    DrawSpan = 0x03,
    Marker = 0x04,
    FrameEnd = 0x05,
};
inline constexpr int kOpcodeCount = 5;  // opcodes are 1..kOpcodeCount

// Index 0..kOpcodeCount-1 of an opcode, for per-opcode tables.
inline constexpr int opcode_index(Opcode op) {
    return static_cast<int>(op) - 1;
}
const char* to_string(Opcode op);  // "FRAME_BEGIN", "FILL_RECT", ...

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};
std::string to_string(Rgb c);  // "#rrggbb"

// Starts a frame: sets the framebuffer size and clears it to the background.
struct FrameBegin {
    uint32_t frame = 0;
    uint32_t width = 0;
    uint32_t height = 0;
    Rgb background;
    friend bool operator==(const FrameBegin&, const FrameBegin&) = default;
};

// Fills the w x h rectangle whose top-left pixel is (x, y). May lie partly or wholly
// outside the framebuffer: the controller clips it.
struct FillRect {
    int32_t x = 0, y = 0;
    uint32_t w = 0, h = 0;
    Rgb color;
    friend bool operator==(const FillRect&, const FillRect&) = default;
};

// Draws pixels x0..x1 (inclusive, x0 <= x1) of row y.
struct DrawSpan {
    int32_t y = 0;
    int32_t x0 = 0, x1 = 0;
    Rgb color;
    friend bool operator==(const DrawSpan&, const DrawSpan&) = default;
};

// A label for a phase of rendering; executes as a no-op.
struct Marker {
    std::string text;
    friend bool operator==(const Marker&, const Marker&) = default;
};
inline constexpr std::size_t kMaxMarkerLength = 1024;

struct FrameEnd {
    friend bool operator==(const FrameEnd&, const FrameEnd&) = default;
};

using Command = std::variant<FrameBegin, FillRect, DrawSpan, Marker, FrameEnd>;

Opcode opcode_of(const Command& c);
std::string to_string(const Command& c);  // one line, e.g. "FILL_RECT x=0 y=0 w=4 h=4 #ff0000"

}  // namespace fb89::protocol
