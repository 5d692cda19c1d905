// fb89 command stream: the commands a host sends to the frame-buffer controller (version 1's
// tiling commands; version 3's depth commands, which move hidden-surface work to it).
//
// These are the decoded, in-memory forms. Their wire encoding (field widths, byte order,
// record layout) is fixed in docs/PROTOCOL.md and implemented in stream_writer/stream_reader.
// Each command is self-contained: it carries its own colour, so any subset of a stream is
// still a valid stream.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
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
const char* to_string(Opcode op);  // "FRAME_BEGIN", "FILL_RECT", ...

// --- the command table -------------------------------------------------------------------
// Each command's struct below is followed by its row, CommandInfo<C>, which every layer reads
// rather than spelling the command again: its opcode and name, the first stream format that
// carries it, its fields in wire order (docs/PROTOCOL.md) with the column of Python's command
// row that keeps each (python/convert.h), what follows the fields, its check, and its words
// on the controller's host port with the listing's handler (controller_sim/gsp_board.h).

// Where Python's command row keeps a field: one of its columns; a span's last pixel as the
// row's width (w = x1 - x + 1, h = 1); or a depth command's depth, beside the row.
enum class RowColumn : uint8_t { X, Y, W, H, Colour, Frame, SpanEnd, Z, Dzdx, Dzdy };

template <class C, class T>
struct Field {
    const char* name;
    T C::*member;
    RowColumn row;
};

// What follows a command's fields on the wire: nothing; a MARKER's text, with its u16 byte
// count before the fields; a FACE's points, 8 bytes each, with its u8 point count before the
// fields.
enum class Tail : uint8_t { None, Text, Points };

// A word the host writes into the controller's ring after the opcode word: field `field` of
// the row's fields (kPortCount: the tail's count) as a 16-bit word, as two (low first), or as
// the colour's palette index. A FACE's points follow as two long words each.
enum class PortForm : uint8_t { Word, Long, Colour };
struct PortWord {
    int8_t field;
    PortForm form;
};
inline constexpr int8_t kPortCount = -1;

template <class C>
struct CommandInfo;

struct Rgb {
    uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb&, const Rgb&) = default;
};
std::string to_string(Rgb c);  // "#rrggbb"

inline constexpr uint32_t kMaxFrameDimension = 16384;  // a frame's width and height

// Starts a frame: sets the framebuffer size and clears it to the background.
struct FrameBegin {
    uint32_t frame = 0;
    uint32_t width = 0;
    uint32_t height = 0;
    Rgb background;
    friend bool operator==(const FrameBegin&, const FrameBegin&) = default;
};
template <>
struct CommandInfo<FrameBegin> {
    static constexpr Opcode opcode = Opcode::FrameBegin;
    static constexpr const char* name = "FRAME_BEGIN";
    static constexpr uint16_t since = kUntimedVersion;
    static constexpr std::tuple fields{
        Field{"frame", &FrameBegin::frame, RowColumn::Frame},
        Field{"width", &FrameBegin::width, RowColumn::W},
        Field{"height", &FrameBegin::height, RowColumn::H},
        Field{"background", &FrameBegin::background, RowColumn::Colour}};
    static constexpr Tail tail = Tail::None;
    static constexpr std::array port{PortWord{0, PortForm::Word}, PortWord{1, PortForm::Word},
                                     PortWord{2, PortForm::Word}, PortWord{3, PortForm::Colour}};
    static constexpr const char* handler = "frame_begin";
    static std::optional<std::string> check(const FrameBegin& c);  // a size of 1..16384
};

// Fills the w x h rectangle whose top-left pixel is (x, y). May lie partly or wholly
// outside the framebuffer: the controller clips it.
struct FillRect {
    int32_t x = 0, y = 0;
    uint32_t w = 0, h = 0;
    Rgb color;
    friend bool operator==(const FillRect&, const FillRect&) = default;
};
template <>
struct CommandInfo<FillRect> {
    static constexpr Opcode opcode = Opcode::FillRect;
    static constexpr const char* name = "FILL_RECT";
    static constexpr uint16_t since = kUntimedVersion;
    static constexpr std::tuple fields{
        Field{"x", &FillRect::x, RowColumn::X}, Field{"y", &FillRect::y, RowColumn::Y},
        Field{"w", &FillRect::w, RowColumn::W}, Field{"h", &FillRect::h, RowColumn::H},
        Field{"color", &FillRect::color, RowColumn::Colour}};
    static constexpr Tail tail = Tail::None;
    static constexpr std::array port{PortWord{0, PortForm::Word}, PortWord{1, PortForm::Word},
                                     PortWord{2, PortForm::Word}, PortWord{3, PortForm::Word},
                                     PortWord{4, PortForm::Colour}};
    static constexpr const char* handler = "fill_rect";
};

// Draws pixels x0..x1 (inclusive, x0 <= x1) of row y.
struct DrawSpan {
    int32_t y = 0;
    int32_t x0 = 0, x1 = 0;
    Rgb color;
    friend bool operator==(const DrawSpan&, const DrawSpan&) = default;
};
template <>
struct CommandInfo<DrawSpan> {
    static constexpr Opcode opcode = Opcode::DrawSpan;
    static constexpr const char* name = "DRAW_SPAN";
    static constexpr uint16_t since = kUntimedVersion;
    static constexpr std::tuple fields{Field{"y", &DrawSpan::y, RowColumn::Y},
                                       Field{"x0", &DrawSpan::x0, RowColumn::X},
                                       Field{"x1", &DrawSpan::x1, RowColumn::SpanEnd},
                                       Field{"color", &DrawSpan::color, RowColumn::Colour}};
    static constexpr Tail tail = Tail::None;
    // x before y, as the listing reads them
    static constexpr std::array port{PortWord{1, PortForm::Word}, PortWord{0, PortForm::Word},
                                     PortWord{2, PortForm::Word}, PortWord{3, PortForm::Colour}};
    // the profile's span_as may choose span_line instead (controller_sim/gsp_board.cpp)
    static constexpr const char* handler = "span_fill";
    static std::optional<std::string> check(const DrawSpan& c);  // x0 <= x1
};

// A label for a phase of rendering; executes as a no-op.
struct Marker {
    std::string text;
    friend bool operator==(const Marker&, const Marker&) = default;
};
inline constexpr std::size_t kMaxMarkerLength = 1024;
template <>
struct CommandInfo<Marker> {
    static constexpr Opcode opcode = Opcode::Marker;
    static constexpr const char* name = "MARKER";
    static constexpr uint16_t since = kUntimedVersion;
    static constexpr std::tuple<> fields{};
    static constexpr Tail tail = Tail::Text;
    static constexpr std::array<PortWord, 0> port{};
    static constexpr const char* handler = nullptr;            // never sent to the controller
    static std::optional<std::string> check(const Marker& c);  // kMaxMarkerLength bytes
};

struct FrameEnd {
    friend bool operator==(const FrameEnd&, const FrameEnd&) = default;
};
template <>
struct CommandInfo<FrameEnd> {
    static constexpr Opcode opcode = Opcode::FrameEnd;
    static constexpr const char* name = "FRAME_END";
    static constexpr uint16_t since = kUntimedVersion;
    static constexpr std::tuple<> fields{};
    static constexpr Tail tail = Tail::None;
    static constexpr std::array<PortWord, 0> port{};
    static constexpr const char* handler = "frame_end";
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
template <>
struct CommandInfo<DepthClear> {
    static constexpr Opcode opcode = Opcode::DepthClear;
    static constexpr const char* name = "DEPTH_CLEAR";
    static constexpr uint16_t since = kDepthVersion;
    static constexpr std::tuple<> fields{};
    static constexpr Tail tail = Tail::None;
    static constexpr std::array<PortWord, 0> port{};
    static constexpr const char* handler = "depth_clear";
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
template <>
struct CommandInfo<DepthSpan> {
    static constexpr Opcode opcode = Opcode::DepthSpan;
    static constexpr const char* name = "DEPTH_SPAN";
    static constexpr uint16_t since = kDepthVersion;
    static constexpr std::tuple fields{Field{"y", &DepthSpan::y, RowColumn::Y},
                                       Field{"x0", &DepthSpan::x0, RowColumn::X},
                                       Field{"x1", &DepthSpan::x1, RowColumn::SpanEnd},
                                       Field{"z", &DepthSpan::z, RowColumn::Z},
                                       Field{"dz", &DepthSpan::dz, RowColumn::Dzdx},
                                       Field{"color", &DepthSpan::color, RowColumn::Colour}};
    static constexpr Tail tail = Tail::None;
    static constexpr std::array port{PortWord{1, PortForm::Word}, PortWord{0, PortForm::Word},
                                     PortWord{2, PortForm::Word}, PortWord{3, PortForm::Long},
                                     PortWord{4, PortForm::Long}, PortWord{5, PortForm::Colour}};
    static constexpr const char* handler = "depth_span";
    static std::optional<std::string> check(const DepthSpan& c);  // x0 <= x1
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
template <>
struct CommandInfo<Face> {
    static constexpr Opcode opcode = Opcode::Face;
    static constexpr const char* name = "FACE";
    static constexpr uint16_t since = kDepthVersion;
    static constexpr std::tuple fields{Field{"color", &Face::color, RowColumn::Colour},
                                       Field{"x_ref", &Face::x_ref, RowColumn::X},
                                       Field{"y_ref", &Face::y_ref, RowColumn::Y},
                                       Field{"z", &Face::z, RowColumn::Z},
                                       Field{"dzdx", &Face::dzdx, RowColumn::Dzdx},
                                       Field{"dzdy", &Face::dzdy, RowColumn::Dzdy}};
    static constexpr Tail tail = Tail::Points;
    static constexpr std::array port{
        PortWord{kPortCount, PortForm::Word}, PortWord{0, PortForm::Colour},
        PortWord{1, PortForm::Word},          PortWord{2, PortForm::Word},
        PortWord{3, PortForm::Long},          PortWord{4, PortForm::Long},
        PortWord{5, PortForm::Long}};
    static constexpr const char* handler = "face";
    // 3..kMaxFacePoints points within +-kMaxFaceCoordinate
    static std::optional<std::string> check(const Face& c);
};

using Command =
    std::variant<FrameBegin, FillRect, DrawSpan, Marker, FrameEnd, DepthClear, DepthSpan, Face>;
inline constexpr int kOpcodeCount = static_cast<int>(std::variant_size_v<Command>);

// A command's row as plain data, for what looks a command up by its opcode at run time.
struct CommandRow {
    Opcode opcode;
    const char* name;
    uint16_t since;  // the first stream format version that carries it
    Tail tail;
    const char* handler;  // the listing's label; nullptr: never sent to the controller
    uint32_t port_words;  // on the host port, the opcode's word included (a FACE's without
                          // its points); 0 for one never sent
};

namespace detail {
template <class C>
constexpr CommandRow row_of() {
    using I = CommandInfo<C>;
    uint32_t words = I::handler ? 1 : 0;
    for (const PortWord& w : I::port)
        words += w.form == PortForm::Long ? 2 : 1;
    return CommandRow{I::opcode, I::name, I::since, I::tail, I::handler, words};
}
template <std::size_t... I>
constexpr std::array<CommandRow, sizeof...(I)> rows(std::index_sequence<I...>) {
    return {row_of<std::variant_alternative_t<I, Command>>()...};
}
}  // namespace detail

// Every command's row, in the order of Command's alternatives and of per-opcode tables.
inline constexpr std::array<CommandRow, kOpcodeCount> kCommandRows =
    detail::rows(std::make_index_sequence<kOpcodeCount>{});

// Every opcode, in the same order.
inline constexpr std::array<Opcode, kOpcodeCount> kOpcodes = [] {
    std::array<Opcode, kOpcodeCount> out{};
    for (int i = 0; i < kOpcodeCount; ++i)
        out[i] = kCommandRows[i].opcode;
    return out;
}();

// Index 0..kOpcodeCount-1 of an opcode, for per-opcode tables; -1 for none.
inline constexpr int opcode_index(Opcode op) {
    for (int i = 0; i < kOpcodeCount; ++i)
        if (kOpcodes[i] == op) return i;
    return -1;
}
// The row of a command's opcode; nullptr for a byte that is none.
inline constexpr const CommandRow* command_row(uint8_t opcode) {
    const int i = opcode_index(static_cast<Opcode>(opcode));
    return i < 0 ? nullptr : &kCommandRows[i];
}
// The commands that need a depth buffer and stream format version 3.
inline constexpr bool is_depth_opcode(Opcode op) {
    const int i = opcode_index(op);
    return i >= 0 && kCommandRows[i].since >= kDepthVersion;
}

// Calls f(c.*member, field) for each of c's fields in wire order (c const or not).
template <class C, class F>
constexpr void for_each_field(C& c, F&& f) {
    std::apply([&](const auto&... field) { (f(c.*field.member, field), ...); },
               CommandInfo<std::remove_const_t<C>>::fields);
}

Opcode opcode_of(const Command& c);
// What is wrong with a command by its row's check ("x1 -3 < x0 0"), or nullopt if it is
// valid: what the stream format cannot carry.
std::optional<std::string> check_command(const Command& c);
std::string to_string(const Command& c);  // one line, e.g. "FILL_RECT x=0 y=0 w=4 h=4 #ff0000"

}  // namespace fb89::protocol
