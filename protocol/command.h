// fb89 command stream: the commands a host sends to the frame-buffer controller (version 1's
// tiling commands; version 3's depth commands, which move hidden-surface work to it).
//
// These are the decoded, in-memory forms. Their wire encoding (field widths, byte order,
// record layout) is fixed in docs/PROTOCOL.md and implemented in stream_writer/stream_reader.
// Each command is self-contained: it carries its own colour, so any subset of a stream is
// still a valid stream.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "protocol/coverage.h"

namespace fb89::protocol {

// The newest stream format this fb89 reads (docs/PROTOCOL.md): version 1, the commands;
// version 2, the commands with the host's send times; version 3, the depth commands too
// (with or without times, as its header's flags say); version 4, version 3 with checksums,
// so that a damaged stream is refused rather than replayed. fb89 writes version 4; asked for
// a stream without checksums, the oldest of versions 1 to 3 that carries it.
inline constexpr uint16_t kFormatVersion = 4;
inline constexpr uint16_t kUntimedVersion = 1;
inline constexpr uint16_t kTimedVersion = 2;
inline constexpr uint16_t kDepthVersion = 3;
inline constexpr uint16_t kChecksumVersion = 4;

enum class Opcode : uint8_t {
    FrameBegin = 0x01,
    FillRect = 0x02,
    DrawSpan = 0x03,
    Marker = 0x04,
    FrameEnd = 0x05,
    // version 3 (0x06 and 0x07 are version 2's time records)
    DepthClear = 0x08,
    DepthSpan = 0x09,
    Face = 0x0A,
};
inline constexpr int kOpcodeCount = 8;
// Every opcode, in the order of Command's alternatives and of per-opcode tables.
inline constexpr Opcode kOpcodes[kOpcodeCount] = {
    Opcode::FrameBegin, Opcode::FillRect,   Opcode::DrawSpan,  Opcode::Marker,
    Opcode::FrameEnd,   Opcode::DepthClear, Opcode::DepthSpan, Opcode::Face};

// Index 0..kOpcodeCount-1 of an opcode, for per-opcode tables.
inline constexpr int opcode_index(Opcode op) {
    const int v = static_cast<int>(op);
    return v <= 5 ? v - 1 : v - 3;
}
// The commands that need a depth buffer and stream format version 3.
inline constexpr bool is_depth_opcode(Opcode op) {
    return op == Opcode::DepthClear || op == Opcode::DepthSpan || op == Opcode::Face;
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

// --- version 3: depth (docs/PROTOCOL.md, "Depth commands") -------------------------------
// Depth travels as Z, an unsigned 32-bit fixed-point number: window depth z in [0, 1] times
// kDepthOne (protocol/depth_fixed.h), so that 28 bits below the point carry it and the far
// plane stays below the depth buffer's cleared value; a slope is Z per pixel, signed.

// Sizes the frame's depth buffer to the frame and clears every word to the far value. A
// frame's depth commands need one after its FRAME_BEGIN.
struct DepthClear {
    friend bool operator==(const DepthClear&, const DepthClear&) = default;
};

// Pixels x0..x1 (inclusive) of row y, each drawn where it is nearer than the depth buffer
// holds: pixel x0's depth is z, each pixel to the right dz more (z + dz * (x - x0), exact in
// integers). Clipped like DRAW_SPAN.
struct DepthSpan {
    int32_t y = 0;
    int32_t x0 = 0, x1 = 0;
    uint32_t z = 0;
    int32_t dz = 0;
    Rgb color;
    friend bool operator==(const DepthSpan&, const DepthSpan&) = default;
};

// A convex polygon the controller scan-converts itself by the coverage rule
// (protocol/coverage.h): its points on the 1/256-pixel grid in positive orientation, 3 to
// kMaxFacePoints of them. Each covered pixel's depth is z + dzdx * (x - x_ref) + dzdy *
// (y - y_ref), exact in integers, and it is drawn where that is nearer than the depth
// buffer holds. The controller clips it to the frame.
struct Face {
    Rgb color;
    int32_t x_ref = 0, y_ref = 0;  // the pixel whose centre has depth z
    uint32_t z = 0;
    int32_t dzdx = 0, dzdy = 0;
    std::vector<SnappedPoint> points;
    friend bool operator==(const Face&, const Face&) = default;
};
inline constexpr std::size_t kMaxFacePoints = 64;
// A point's coordinates lie within +-kMaxFaceCoordinate grid units (2^15 pixels: the
// guard band, host/scene/projection.h, with room to spare).
inline constexpr int64_t kMaxFaceCoordinate = int64_t{1} << 24;

using Command =
    std::variant<FrameBegin, FillRect, DrawSpan, Marker, FrameEnd, DepthClear, DepthSpan, Face>;

Opcode opcode_of(const Command& c);
std::string to_string(const Command& c);  // one line, e.g. "FILL_RECT x=0 y=0 w=4 h=4 #ff0000"

}  // namespace fb89::protocol
