// Call-set parsing and matching (grammar in docs/PROTOCOL.md, "Call sets").
//
// A hand-written recursive-descent parser over the text: one function per grammar rule,
// each error naming the text (or `@file` and line) and the 1-based character it stopped
// at. Matching is a scan of the items; call sets are short, so no interval tree.
#include "protocol/call_set.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace fb89::protocol {

namespace {

constexpr int kMaxFileDepth = 8;  // @file inside @file, to stop cycles
constexpr std::size_t kMaxFileBytes = 1 << 20;

// The opcode's bit in a range's set; none for a byte that is no command's opcode.
uint8_t bit(Opcode op) {
    const int i = opcode_index(op);
    return static_cast<uint8_t>(i < 0 ? 0u : 1u << i);
}

struct Filter {
    const char* name;
    uint8_t opcodes;
};
const Filter kFilters[] = {
    {"fill", bit(Opcode::FillRect)},
    {"span", bit(Opcode::DrawSpan)},
    {"zspan", bit(Opcode::DepthSpan)},
    {"face", bit(Opcode::Face)},
    {"zclear", bit(Opcode::DepthClear)},
    {"draw", static_cast<uint8_t>(bit(Opcode::FillRect) | bit(Opcode::DrawSpan) |
                                  bit(Opcode::DepthSpan) | bit(Opcode::Face))},
    {"depth",
     static_cast<uint8_t>(bit(Opcode::DepthClear) | bit(Opcode::DepthSpan) | bit(Opcode::Face))},
    {"marker", bit(Opcode::Marker)},
    {"frame", static_cast<uint8_t>(bit(Opcode::FrameBegin) | bit(Opcode::FrameEnd))},
};
// The filters that only stand for others (written out by filter_names).
bool is_composite(std::string_view name) {
    return name == "draw" || name == "depth";
}

// "/fill /span ..." in the table's order.
std::string filter_list() {
    std::string out;
    for (const Filter& f : kFilters)
        out += (out.empty() ? "/" : " /") + std::string(f.name);
    return out;
}

bool is_word_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// "/fill/span" for a mask of FILL_RECT and DRAW_SPAN ("/draw" and "/depth" are written out).
std::string filter_names(uint8_t opcodes) {
    std::string out;
    for (const Filter& f : kFilters) {
        if (!is_composite(f.name) && (opcodes & f.opcodes) == f.opcodes)
            out += std::string("/") + f.name;
    }
    return out;
}

}  // namespace

// --- parser --------------------------------------------------------------------------

class CallSetParser {
  public:
    CallSetParser(std::string_view text, std::string origin, bool in_file, int depth)
        : m_text(text), m_origin(std::move(origin)), m_in_file(in_file), m_depth(depth) {}

    // set := item { separator item }; separator is ',' (and a newline in @files, where
    // empty items are allowed)
    void parse_set(CallSet& out) {
        skip_blanks();
        if (at_end() && !m_in_file) fail("empty call set");
        for (;;) {
            skip_blanks();
            if (at_end() || is_separator(peek())) {
                if (!m_in_file) fail("empty item");
            } else {
                parse_item(out);
                skip_blanks();
                if (!at_end() && !is_separator(peek()))
                    fail(fmt::format("expected ',' or '/', found '{}'", peek()));
            }
            if (at_end()) return;
            ++m_pos;  // the separator
        }
    }

  private:
    // item := '@' path | [ range ] { '/' suffix }
    void parse_item(CallSet& out) {
        if (peek() == '@') {
            ++m_pos;
            parse_file(out);
            return;
        }
        CallRange r;
        bool is_frame = false;
        if (peek() == '*') {
            ++m_pos;
        } else if (peek_word() == "frame") {
            m_pos += 5;
            r.opcodes = bit(Opcode::FrameEnd);  // apitrace: the calls that end frames
            is_frame = true;
        } else if (std::isdigit(static_cast<unsigned char>(peek()))) {
            parse_range(r);
        } else if (peek() != '/') {
            fail(fmt::format("expected a number, '*', 'frame', '/' or '@', found '{}'", peek()));
        }
        bool has_step = false;
        uint8_t opcodes = 0;
        while (peek() == '/') {
            if (is_frame) fail("'frame' takes no '/' suffix");
            ++m_pos;
            parse_suffix(r, has_step, opcodes);
        }
        if (opcodes != 0) r.opcodes = opcodes;
        out.m_ranges.push_back(r);
    }

    // range := N [ '-' [ N ] ]
    void parse_range(CallRange& r) {
        r.first = parse_number();
        r.last = r.first;
        if (peek() != '-') return;
        ++m_pos;
        if (!std::isdigit(static_cast<unsigned char>(peek()))) {
            r.last = kNoLastCall;  // "100-": open-ended
            return;
        }
        const std::size_t at = m_pos;
        r.last = parse_number();
        if (r.last < r.first)
            fail_at(at, fmt::format("range {}-{} ends before it starts", r.first, r.last));
    }

    // suffix := N (a step, at most once) | fill | span | draw | marker | frame
    void parse_suffix(CallRange& r, bool& has_step, uint8_t& opcodes) {
        const std::size_t at = m_pos;
        if (std::isdigit(static_cast<unsigned char>(peek()))) {
            if (has_step) fail_at(at, "a second step");
            r.step = parse_number();
            if (r.step == 0) fail_at(at, "step 0; a step is at least 1");
            has_step = true;
            return;
        }
        const std::string_view word = peek_word();
        for (const Filter& f : kFilters) {
            if (word == f.name) {
                m_pos += word.size();
                opcodes = static_cast<uint8_t>(opcodes | f.opcodes);
                return;
            }
        }
        fail(fmt::format("unknown filter '/{}'; expected a step or one of {}",
                         word.empty() ? std::string_view(m_text.substr(m_pos, 1)) : word,
                         filter_list()));
    }

    uint64_t parse_number() {
        const std::size_t at = m_pos;
        uint64_t v = 0;
        while (std::isdigit(static_cast<unsigned char>(peek()))) {
            const uint64_t d = static_cast<uint64_t>(peek() - '0');
            if (v > (kNoLastCall - 1 - d) / 10) fail_at(at, "number too large");
            v = v * 10 + d;
            ++m_pos;
        }
        return v;
    }

    // '@' path: the rest of the item, read as a call set of its own
    void parse_file(CallSet& out) {
        const std::size_t at = m_pos;
        while (!at_end() && !is_separator(peek()))
            ++m_pos;
        std::string path(m_text.substr(at, m_pos - at));
        while (!path.empty() && (path.back() == ' ' || path.back() == '\t' || path.back() == '\r'))
            path.pop_back();
        if (path.empty()) fail_at(at, "'@' needs a file name");
        if (m_depth >= kMaxFileDepth)
            fail_at(at, fmt::format("@{}: @files nested more than {} deep", path, kMaxFileDepth));
        std::error_code ec;
        if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
            fail_at(at, fmt::format("call-set file '{}' is not a regular file", path));
        std::ifstream in(path, std::ios::binary);
        if (!in) fail_at(at, fmt::format("cannot read call-set file '{}'", path));
        std::ostringstream ss;
        ss << in.rdbuf();
        std::string text = ss.str();
        if (text.size() > kMaxFileBytes)
            fail_at(at, fmt::format("call-set file '{}' is larger than 1 MiB", path));
        // comments run from '#' to the end of the line; blank them, keeping positions
        bool comment = false;
        for (char& c : text) {
            if (c == '#') comment = true;
            if (c == '\n') comment = false;
            if (comment) c = ' ';
        }
        CallSetParser(text, path, true, m_depth + 1).parse_set(out);
    }

    bool at_end() const { return m_pos >= m_text.size(); }
    char peek() const { return at_end() ? '\0' : m_text[m_pos]; }
    std::string_view peek_word() const {
        std::size_t end = m_pos;
        while (end < m_text.size() && is_word_char(m_text[end]))
            ++end;
        return m_text.substr(m_pos, end - m_pos);
    }
    bool is_separator(char c) const { return c == ',' || (m_in_file && c == '\n'); }
    void skip_blanks() {
        while (!at_end() && (peek() == ' ' || peek() == '\t' || peek() == '\r'))
            ++m_pos;
    }

    [[noreturn]] void fail(const std::string& what) { fail_at(m_pos, what); }
    [[noreturn]] void fail_at(std::size_t at, const std::string& what) {
        if (m_in_file) {
            const std::size_t line =
                1 + static_cast<std::size_t>(std::count(m_text.begin(), m_text.begin() + at, '\n'));
            const std::size_t line_start = m_text.rfind('\n', at == 0 ? 0 : at - 1);
            const std::size_t column =
                line_start == std::string_view::npos || at == 0 ? at + 1 : at - line_start;
            throw CallSetError(fmt::format("{}:{}:{}: {}", m_origin, line, column, what), at + 1);
        }
        throw CallSetError(fmt::format("call set '{}': at character {}: {}", m_text, at + 1, what),
                           at + 1);
    }

    std::string_view m_text;
    std::string m_origin;
    bool m_in_file;
    int m_depth;
    std::size_t m_pos = 0;
};

// --- matching ------------------------------------------------------------------------

bool CallRange::contains_number(uint64_t n) const {
    return n >= first && n <= last && (n - first) % step == 0;
}

bool CallRange::contains(uint64_t n, Opcode op) const {
    return (opcodes & bit(op)) != 0 && contains_number(n);
}

std::string CallRange::to_string() const {
    std::string out;
    if (opcodes == bit(Opcode::FrameEnd) && first == 0 && last == kNoLastCall && step == 1)
        return "frame";
    if (first == 0 && last == kNoLastCall)
        out = "*";
    else if (first == last)
        out = std::to_string(first);
    else if (last == kNoLastCall)
        out = fmt::format("{}-", first);
    else
        out = fmt::format("{}-{}", first, last);
    if (step != 1) out += fmt::format("/{}", step);
    if (opcodes != kAllOpcodes) out += filter_names(opcodes);
    return out;
}

CallSet CallSet::parse(std::string_view text) {
    CallSet set;
    CallSetParser(text, "", false, 0).parse_set(set);
    return set;
}

CallSet CallSet::all() {
    CallSet set;
    set.m_ranges.push_back(CallRange{});
    return set;
}

bool CallSet::contains(uint64_t number, Opcode op) const {
    return std::any_of(m_ranges.begin(), m_ranges.end(),
                       [&](const CallRange& r) { return r.contains(number, op); });
}

bool CallSet::contains_number(uint64_t number) const {
    return std::any_of(m_ranges.begin(), m_ranges.end(),
                       [&](const CallRange& r) { return r.contains_number(number); });
}

uint64_t CallSet::first() const {
    uint64_t f = kNoLastCall;
    for (const CallRange& r : m_ranges)
        f = std::min(f, r.first);
    return f;
}

uint64_t CallSet::last() const {
    uint64_t l = 0;
    for (const CallRange& r : m_ranges)
        l = std::max(l, r.last);
    return l;
}

bool CallSet::has_opcode_filter() const {
    return std::any_of(m_ranges.begin(), m_ranges.end(),
                       [](const CallRange& r) { return r.opcodes != CallRange::kAllOpcodes; });
}

std::string CallSet::to_string() const {
    std::string out;
    for (const CallRange& r : m_ranges) {
        if (!out.empty()) out += ',';
        out += r.to_string();
    }
    return out;
}

}  // namespace fb89::protocol
