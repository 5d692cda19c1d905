// What the stream tools (replay, dump, info, trim, diff) share: call-set options, seeking
// through the frame index, escaping text for a terminal, snapshot names, number format.
//
// Every tool streams through protocol::StreamReader command by command and never holds a
// whole stream in memory; a StreamError ends the reading, the tool reports what it has
// and then the error, and exits 2.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "controller_sim/controller.h"
#include "protocol/call_set.h"
#include "protocol/stream_reader.h"

namespace fb89::frontend {

// Parses a call set given to `option`; a CallSetError becomes a UsageError naming the option.
protocol::CallSet parse_call_set_option(const std::string& option, const std::string& text);

// Where a tool that needs only commands from `first_call` on starts reading: if the stream
// has a well-formed trailing index, seeks to the last frame starting at or before
// first_call. Returns the position (0-based, in stream order) of the frame seeked to, or
// nullopt when reading starts at the beginning.
std::optional<uint64_t> seek_to_call(protocol::StreamReader& reader, uint64_t first_call);
// Seeks to the frame at `position` in stream order (0-based) through the trailing index;
// false (reading unchanged) if there is no index or fewer frames.
bool seek_to_frame(protocol::StreamReader& reader, uint64_t position);

// Text with control characters, '\\' and bytes >= 0x7f escaped (\n, \t, \xNN): marker
// text is opaque bytes (docs/PROTOCOL.md) and must not reach a terminal raw.
std::string printable(std::string_view text);

// "out.png" and call 123 -> "out-000123.png" (at least six digits; the extension kept).
std::string snapshot_path(const std::string& png, uint64_t call);

// 1234567 -> "1,234,567"
std::string grouped(uint64_t v);

// Milliseconds the profile charges for `cycles`.
double modelled_ms(const controller::CostProfile& p, uint64_t cycles);

// Prints "fb89: error: <message>" on stderr; the message already names the stream, the
// byte offset and the command number.
void report_stream_error(const protocol::StreamError& e);

// One line describing the stream's header: name, version, the conventional properties and
// where a timed stream's send times come from.
std::string header_line(const protocol::StreamReader& reader);
// A timed stream's send times as its header names them: "measured on native", "counted on
// sun4-260"; "" for a stream without times.
std::string send_times_of(const protocol::StreamReader& reader);
// The same from a stream's header properties and whether it has send times.
std::string send_times_of(const protocol::Properties& properties, bool timed);

// A frame table for humans: frame, commands, pixels, cycles, modelled ms, bus ms, frame
// ms and checksum, one row per closed frame plus the open one (if any) marked "open".
std::string frame_table(const controller::Controller& ctl);

}  // namespace fb89::frontend
