// Call sets: which commands of a stream a tool acts on (`dump --calls`, `trim --calls`,
// `replay --snapshot`), after apitrace's call sets, e.g. `4`, `0,2,4`, `0-100/2`, `100-`,
// `frame`, `@calls.txt`, `0-1000/2/span`.
//
// The grammar is in docs/PROTOCOL.md, "Call sets". In short: a comma-separated list of
// items; an item is a range (`N`, `N-M`, `N-`, `*`, or `frame` = every FRAME_END) followed
// by suffixes: at most one step `/S` and any number of opcode filters `/fill`, `/span`,
// `/zspan`, `/face`, `/zclear`, `/draw` (fills, spans and faces), `/depth` (the depth
// commands), `/marker`, `/frame`. A command is in the set when any item matches it. Parsing
// never reads a stream; matching needs only the command's number and opcode, so tools
// decide command by command while they stream.
#pragma once

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/command.h"

namespace fb89::protocol {

// A call set that does not parse. The message names the text (or file and line) and the
// position, e.g. "call set '0-1x': at character 4: expected ',' or '/', found 'x'".
class CallSetError : public std::runtime_error {
  public:
    CallSetError(const std::string& message, std::size_t position)
        : std::runtime_error(message), m_position(position) {}
    std::size_t position() const { return m_position; }  // 1-based character in its text

  private:
    std::size_t m_position;
};

inline constexpr uint64_t kNoLastCall = std::numeric_limits<uint64_t>::max();

// One item: the numbers first..last (inclusive) with (n - first) % step == 0, restricted
// to the opcodes in `opcodes` (bit opcode_index(op)).
struct CallRange {
    uint64_t first = 0;
    uint64_t last = kNoLastCall;  // kNoLastCall: open-ended
    uint64_t step = 1;
    uint8_t opcodes = kAllOpcodes;

    static constexpr uint8_t kAllOpcodes = (1u << kOpcodeCount) - 1;
    bool contains(uint64_t number, Opcode op) const;
    bool contains_number(uint64_t number) const;  // ignores the opcode filter
    std::string to_string() const;                // canonical text, e.g. "0-100/2/span"
    friend bool operator==(const CallRange&, const CallRange&) = default;
};

class CallSet {
  public:
    // The empty set (matches nothing); use parse() for anything else.
    CallSet() = default;
    // Parses text as in docs/PROTOCOL.md; `@file` items are read relative to the current
    // directory. Throws CallSetError naming the text and position, or the file and line.
    static CallSet parse(std::string_view text);
    // Every command.
    static CallSet all();

    bool contains(uint64_t number, Opcode op) const;
    bool contains(uint64_t number, const Command& c) const {
        return contains(number, opcode_of(c));
    }
    // Ignoring opcode filters: for sets of frame numbers (`trim --frames`).
    bool contains_number(uint64_t number) const;

    bool empty() const { return m_ranges.empty(); }
    // The lowest number any item can match (kNoLastCall for the empty set).
    uint64_t first() const;
    // The highest number any item can match; kNoLastCall when some item is open-ended. A
    // tool streaming a stream may stop reading after it.
    uint64_t last() const;
    // Whether some item restricts opcodes (meaningless for frame sets).
    bool has_opcode_filter() const;

    const std::vector<CallRange>& ranges() const { return m_ranges; }
    std::string to_string() const;  // canonical, comma-separated; "" for the empty set

  private:
    std::vector<CallRange> m_ranges;
    friend class CallSetParser;
};

}  // namespace fb89::protocol
