// TMS34010 assembly into words (see gsp_assembler.h).
//
// Two passes and a relaxation: the first reads every line and takes the symbols; then every
// instruction is encoded at the addresses the last round gave, until no length changes. A
// jump starts short and grows only (so the rounds end), as GSPA's short forms come out where
// they reach. Encodings: SPVS002C's instruction set summary, with the field layout of the
// User's Guide (SPVU001A Appendix A): Rs in bits 8-5, the file in bit 4, Rd in bits 3-0, the
// field size in bit 9; checked word for word against GSPA 2.00 (tests/golden/gsp/).
#include "controller_sim/gsp_assembler.h"

#include "controller_sim/gsp_listing_text.h"
#include "controller_sim/gsp_opcodes.h"

#include <algorithm>
#include <cctype>
#include <optional>

#include <fmt/format.h>

namespace fb89::controller::gsp {

AssemblyError::AssemblyError(const std::string& file, int line, const std::string& what)
    : std::runtime_error(fmt::format("{} line {}: {}", file, line, what)), m_line(line) {}

namespace {

using listing_text::trim;
using listing_text::upper;

struct Reg {
    int file = 0;  // 0: A, 1: B
    int n = 0;     // 0-14, 15 for SP
    bool sp = false;
};

// JRcc's condition code for the mnemonic's tail, or -1.
int condition_code(std::string_view cc) {
    for (const Condition& c : kConditionCodes)
        if (c.name == cc) return c.code;
    return -1;
}

// An operand's form.
enum class Mode { Reg, Indirect, PostInc, PreDec, Displaced, Absolute, Value, IndirectXY };

struct Operand {
    Mode mode = Mode::Value;
    Reg reg;
    std::string expr;  // the address, displacement or value
};

struct Line {
    int number = 0;
    std::string text;
    std::string label;
    std::string mnemonic;  // upper case; "" for none
    std::vector<std::string> operands;
    int section = 0;  // 0: .text, 1: .data
};

struct Value {
    int64_t v = 0;
    bool relocatable = false;  // a label's address
};

class Assembler {
  public:
    Assembler(std::string_view file, std::string_view source) : m_file(file) { read(source); }

    Program run() {
        // the lengths start at their shortest; each round encodes at the last round's
        // addresses and may lengthen a jump
        std::vector<size_t> lengths(m_lines.size(), 0);
        for (int round = 0;; ++round) {
            if (round > 64) fail(0, "the jumps' lengths do not settle");
            place(lengths);
            bool changed = false;
            for (size_t i = 0; i < m_lines.size(); ++i) {
                const size_t n = words_of(i, true, lengths[i]).size();
                if (n > lengths[i]) {
                    lengths[i] = n;
                    changed = true;
                }
            }
            if (!changed) break;
        }
        place(lengths);
        Program p;
        p.name = m_file;
        p.labels = m_labels;
        for (const auto& [name, v] : m_symbols)
            p.symbols[name] = v.v;
        p.text_bits = m_section_bits[0];
        p.data_bits = m_section_bits[1];
        for (size_t i = 0; i < m_lines.size(); ++i) {
            AssembledLine out;
            out.line = m_lines[i].number;
            out.text = m_lines[i].text;
            out.address = m_address[i];
            out.words = words_of(i, false, lengths[i]);
            out.code = !m_lines[i].mnemonic.empty() && m_lines[i].mnemonic[0] != '.';
            p.lines.push_back(std::move(out));
        }
        return p;
    }

  private:
    std::string m_file;
    std::vector<Line> m_lines;
    std::map<std::string, Value, std::less<>> m_symbols;  // .equ/.set numbers
    std::map<std::string, Reg, std::less<>> m_registers;  // .set registers
    std::map<std::string, uint32_t> m_labels;
    std::vector<uint32_t> m_address;
    uint32_t m_section_bits[2] = {0, 0};
    int m_line = 0;  // the line being encoded, for errors

    [[noreturn]] void fail(int line, const std::string& what) const {
        throw AssemblyError(m_file, line, what);
    }
    [[noreturn]] void fail(const std::string& what) const { fail(m_line, what); }

    std::optional<Reg> reg_named(std::string_view s) const {
        const std::string u = upper(trim(s));
        if (u == "SP") return Reg{0, 15, true};
        if (const auto it = m_registers.find(u); it != m_registers.end()) return it->second;
        for (size_t i = 0; i < std::size(listing_text::kBFileNames); ++i)
            if (u == listing_text::kBFileNames[i]) return Reg{1, static_cast<int>(i), false};
        if (u.size() < 2 || u.size() > 3 || (u[0] != 'A' && u[0] != 'B')) return std::nullopt;
        if (!std::all_of(u.begin() + 1, u.end(), [](char c) { return std::isdigit(c) != 0; }))
            return std::nullopt;
        const int n = std::stoi(u.substr(1));
        if (n > 14) return std::nullopt;
        return Reg{u[0] == 'B' ? 1 : 0, n, false};
    }

    // Splits a line into label, mnemonic and operands; takes .equ and .set at once.
    void read(std::string_view source) {
        int number = 0, section = 0;
        std::string pending;
        while (!source.empty()) {
            const size_t eol = source.find('\n');
            std::string_view raw = source.substr(0, eol);
            source = eol == std::string_view::npos ? std::string_view{} : source.substr(eol + 1);
            ++number;
            if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
            Line line;
            line.number = number;
            line.text = std::string(raw);
            m_line = number;
            std::string_view code = raw;
            if (!code.empty() && code[0] == '*') code = {};  // a comment line
            if (const size_t semi = code.find(';'); semi != std::string_view::npos)
                code = code.substr(0, semi);
            if (!code.empty() && !std::isspace(static_cast<unsigned char>(code[0]))) {
                size_t end = 0;
                while (end < code.size() && !std::isspace(static_cast<unsigned char>(code[end])))
                    ++end;
                std::string label(code.substr(0, end));
                if (label.ends_with(":")) label.pop_back();
                if (label.empty()) fail("an empty label");
                line.label = label;
                code = code.substr(end);
            }
            code = trim(code);
            size_t end = 0;
            while (end < code.size() && !std::isspace(static_cast<unsigned char>(code[end])))
                ++end;
            line.mnemonic = upper(code.substr(0, end));
            std::string_view ops = trim(code.substr(end));
            while (!ops.empty()) {
                size_t comma = 0;  // the first comma outside an XY pair's brackets
                for (int depth = 0; comma < ops.size(); ++comma) {
                    if (ops[comma] == '[') ++depth;
                    if (ops[comma] == ']') --depth;
                    if (ops[comma] == ',' && depth == 0) break;
                }
                if (comma == ops.size()) comma = std::string_view::npos;
                line.operands.emplace_back(trim(ops.substr(0, comma)));
                if (line.operands.back().empty()) fail("an empty operand");
                ops = comma == std::string_view::npos ? std::string_view{} : ops.substr(comma + 1);
                if (comma != std::string_view::npos && trim(ops).empty())
                    fail("an operand missing after ','");
            }
            if (line.mnemonic == ".EQU" || line.mnemonic == ".SET") {
                if (line.label.empty()) fail(line.mnemonic + " needs a name in column 1");
                if (line.operands.size() != 1) fail(line.mnemonic + " takes one value");
                const std::string& name = line.label;
                if (line.mnemonic == ".EQU" &&
                    (m_symbols.count(name) || m_registers.count(upper(name))))
                    fail(line.label + " defined twice");
                if (const auto r = reg_named(line.operands[0])) {
                    m_registers[upper(name)] = *r;
                } else {
                    m_symbols[name] = evaluate(line.operands[0], false);
                }
                line.label.clear();
                line.mnemonic.clear();
                line.operands.clear();
            } else if (line.mnemonic == ".TEXT") {
                section = 0;
            } else if (line.mnemonic == ".DATA") {
                section = 1;
            }
            line.section = section;
            m_lines.push_back(std::move(line));
        }
        // labels name the line they are on (or, alone on a line, the next word)
        for (const Line& l : m_lines)
            if (!l.label.empty()) {
                if (m_labels.count(l.label) || m_symbols.count(l.label))
                    fail(l.number, l.label + " defined twice");
                m_labels[l.label] = 0;
            }
    }

    // Gives each line its address from the lengths.
    void place(const std::vector<size_t>& lengths) {
        uint32_t at[2] = {0, 0};
        m_address.assign(m_lines.size(), 0);
        for (size_t i = 0; i < m_lines.size(); ++i) {
            const int s = m_lines[i].section;
            m_address[i] = at[s];
            at[s] += static_cast<uint32_t>(16 * lengths[i]);
        }
        m_section_bits[0] = at[0];
        m_section_bits[1] = at[1];
        for (size_t i = 0; i < m_lines.size(); ++i) {
            if (m_lines[i].section == 1) m_address[i] += m_section_bits[0];
            if (!m_lines[i].label.empty()) m_labels[m_lines[i].label] = m_address[i];
        }
    }

    // A number: decimal, hexadecimal with a trailing h (or a leading 0x), binary with b.
    static std::optional<int64_t> number(std::string_view s) {
        if (s.empty() || !std::isdigit(static_cast<unsigned char>(s[0]))) return std::nullopt;
        int base = 10;
        if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
            base = 16;
            s.remove_prefix(2);
        } else if (s.back() == 'h' || s.back() == 'H') {
            base = 16;
            s.remove_suffix(1);
        } else if ((s.back() == 'b' || s.back() == 'B') &&
                   s.find_first_not_of("01bB") == std::string_view::npos) {
            base = 2;
            s.remove_suffix(1);
        }
        int64_t v = 0;
        for (char c : s) {
            int d = -1;
            if (std::isdigit(static_cast<unsigned char>(c)))
                d = c - '0';
            else if (std::isxdigit(static_cast<unsigned char>(c)))
                d = std::tolower(static_cast<unsigned char>(c)) - 'a' + 10;
            if (d < 0 || d >= base) return std::nullopt;
            v = v * base + d;
            if (v > 0xFFFFFFFFLL) return std::nullopt;
        }
        return v;
    }

    // Terms joined by + and -, each a number, a symbol, a label or a '-'d term.
    Value evaluate(std::string_view expr, bool labels_known) const {
        expr = trim(expr);
        if (expr.empty()) fail("a value is missing");
        if (expr.starts_with("[")) {  // an XY pair, [y,x]: y in the high half
            const size_t comma = expr.find(',');
            if (!expr.ends_with("]") || comma == std::string_view::npos)
                fail(fmt::format("'{}' is not an XY pair [y,x]", expr));
            const Value y = evaluate(expr.substr(1, comma - 1), labels_known);
            const Value x = evaluate(expr.substr(comma + 1, expr.size() - comma - 2), labels_known);
            return {((y.v & 0xFFFF) << 16) | (x.v & 0xFFFF), false};
        }
        Value total;
        int sign = 1;
        size_t i = 0;
        bool expect_term = true;
        while (i < expr.size()) {
            const char c = expr[i];
            if (std::isspace(static_cast<unsigned char>(c))) {
                ++i;
                continue;
            }
            if (expect_term && (c == '-' || c == '+')) {
                if (c == '-') sign = -sign;
                ++i;
                continue;
            }
            if (!expect_term) {
                if (c != '+' && c != '-') fail(fmt::format("'{}' is not a value", expr));
                sign = c == '-' ? -1 : 1;
                expect_term = true;
                ++i;
                continue;
            }
            size_t j = i;
            while (j < expr.size() && (std::isalnum(static_cast<unsigned char>(expr[j])) ||
                                       expr[j] == '_' || expr[j] == '.' || expr[j] == '$'))
                ++j;
            if (j == i) fail(fmt::format("'{}' is not a value", expr));
            const std::string_view term = expr.substr(i, j - i);
            Value v;
            if (const auto n = number(term)) {
                v.v = *n;
            } else if (const auto s = m_symbols.find(term); s != m_symbols.end()) {
                v = s->second;
            } else if (const auto l = m_labels.find(std::string(term)); l != m_labels.end()) {
                v.v = labels_known ? l->second : 0;
                v.relocatable = true;
            } else if (std::isdigit(static_cast<unsigned char>(term[0]))) {
                fail(fmt::format("'{}' is not a number", term));
            } else {
                fail(fmt::format("'{}' is not defined", term));
            }
            total.v += sign * v.v;
            total.relocatable = total.relocatable || v.relocatable;
            sign = 1;
            expect_term = false;
            i = j;
        }
        if (expect_term) fail(fmt::format("'{}' ends without a value", expr));
        return total;
    }

    Operand operand(std::string_view s) const {
        s = trim(s);
        Operand o;
        if (s.starts_with("@")) {
            o.mode = Mode::Absolute;
            o.expr = std::string(s.substr(1));
            return o;
        }
        if (s.starts_with("-*") || s.starts_with("*")) {
            // *-Rn (TI's way of writing a predecrement) or -*Rn
            const bool pre = s.starts_with("-*") || s.starts_with("*-");
            std::string_view r = s.substr(pre ? 2 : 1);
            o.mode = pre ? Mode::PreDec : Mode::Indirect;
            if (!pre && r.ends_with("+")) {
                o.mode = Mode::PostInc;
                r.remove_suffix(1);
            } else if (!pre && r.ends_with(")")) {
                const size_t open = r.find('(');
                if (open == std::string_view::npos) fail(fmt::format("'{}': no '('", s));
                o.mode = Mode::Displaced;
                o.expr = std::string(r.substr(open + 1, r.size() - open - 2));
                r = r.substr(0, open);
            } else if (!pre && upper(r).ends_with(".XY")) {
                o.mode = Mode::IndirectXY;
                r.remove_suffix(3);
            }
            const auto reg = reg_named(r);
            if (!reg) fail(fmt::format("'{}' is not a register", r));
            o.reg = *reg;
            return o;
        }
        if (const auto reg = reg_named(s)) {
            o.mode = Mode::Reg;
            o.reg = *reg;
            return o;
        }
        o.mode = Mode::Value;
        o.expr = std::string(s);
        return o;
    }

    // ------------------------------------------------------------------ encoding
    const Line* m_at = nullptr;  // the line being encoded
    uint32_t m_pc = 0;
    bool m_relaxing = false;  // a round before the last: labels may still move
    size_t m_min_words = 0;   // a jump made long in an earlier round stays long

    void want(size_t n) const {
        if (m_at->operands.size() != n)
            fail(fmt::format("{} takes {} operand{}, not {}", m_at->mnemonic, n, n == 1 ? "" : "s",
                             m_at->operands.size()));
    }
    Operand op(size_t i) const { return operand(m_at->operands[i]); }
    Reg reg(size_t i) const {
        const Operand o = op(i);
        if (o.mode != Mode::Reg)
            fail(fmt::format("{}: '{}' is not a register", m_at->mnemonic, m_at->operands[i]));
        return o.reg;
    }
    Value value(std::string_view expr) const { return evaluate(expr, true); }
    // Two registers of one file (SP belongs to either).
    int file_of(const Reg& a, const Reg& b) const {
        if (a.sp && b.sp) return 0;
        if (a.sp) return b.file;
        if (b.sp) return a.file;
        if (a.file != b.file) fail(fmt::format("{}: registers in opposite files", m_at->mnemonic));
        return a.file;
    }
    static uint16_t rr(uint16_t base, const Reg& s, const Reg& d, int file) {
        return static_cast<uint16_t>(base | (s.n << 5) | (file << 4) | d.n);
    }
    uint16_t two_regs(uint16_t base) const {
        want(2);
        const Reg s = reg(0), d = reg(1);
        return rr(base, s, d, file_of(s, d));
    }
    static uint16_t one(uint16_t base, const Reg& d) {
        return static_cast<uint16_t>(base | (d.file << 4) | d.n);
    }
    int field(size_t i) const {
        if (m_at->operands.size() <= i) return 0;
        const Value v = value(m_at->operands[i]);
        if (v.v != 0 && v.v != 1) fail(fmt::format("{}: the field is 0 or 1", m_at->mnemonic));
        return static_cast<int>(v.v);
    }
    static void push_long(std::vector<uint16_t>& w, int64_t v) {
        w.push_back(static_cast<uint16_t>(v & 0xFFFF));
        w.push_back(static_cast<uint16_t>((v >> 16) & 0xFFFF));
    }
    int64_t word_value(std::string_view expr) const {
        const Value v = value(expr);
        if (v.v < -32768 || v.v > 65535) fail(fmt::format("'{}' does not fit 16 bits", expr));
        return v.v;
    }
    // A constant 1-32 (ADDK, SUBK, MOVK: 32 is written 0).
    int constant_1_32(std::string_view expr) const {
        const Value v = value(expr);
        if (v.v < 1 || v.v > 32) fail(fmt::format("{}: '{}' is not 1-32", m_at->mnemonic, expr));
        return static_cast<int>(v.v & 31);
    }
    int constant_0_31(std::string_view expr) const {
        const Value v = value(expr);
        if (v.v < 0 || v.v > 31) fail(fmt::format("{}: '{}' is not 0-31", m_at->mnemonic, expr));
        return static_cast<int>(v.v);
    }
    // The words from the instruction after this one (PC + 16 bits) to `target`, and whether
    // the target is known (a round before the last may not know it yet).
    int64_t words_to(int64_t target, uint32_t from) const { return (target - from) / 16; }

    std::vector<uint16_t> immediate(uint16_t short_base, uint16_t long_base, bool complement,
                                    const Reg& d) const {
        const Value v = value(m_at->operands[0]);
        std::vector<uint16_t> w;
        const bool fits = !v.relocatable && v.v >= -32768 && v.v <= 32767;
        if (fits && short_base != 0) {
            w.push_back(one(short_base, d));
            w.push_back(static_cast<uint16_t>((complement ? ~v.v : v.v) & 0xFFFF));
        } else {
            if (v.v < -2147483648LL || v.v > 0xFFFFFFFFLL) fail("a value beyond 32 bits");
            w.push_back(one(long_base, d));
            push_long(w, complement ? ~v.v : v.v);
        }
        return w;
    }

    std::vector<uint16_t> jump_relative(int cc) const {
        want(1);
        const Value t = value(m_at->operands[0]);
        const int64_t short_disp = words_to(t.v, m_pc + 16);
        const uint16_t base = static_cast<uint16_t>(0xC000 | (cc << 8));
        // to the next instruction: GSPA writes a NOP, which goes there either way (the short
        // form has no displacement 0: its 0 means the long form)
        if (m_min_words < 2 && short_disp == 0) return {0x0300};
        if (m_min_words < 2 && short_disp >= -127 && short_disp <= 127 && short_disp != 0)
            return {static_cast<uint16_t>(base | (short_disp & 0xFF))};
        const int64_t disp = words_to(t.v, m_pc + 32);
        if (!m_relaxing && (disp < -32768 || disp > 32767))
            fail(fmt::format("{}: '{}' is out of a relative jump's reach", m_at->mnemonic,
                             m_at->operands[0]));
        return {base, static_cast<uint16_t>(disp & 0xFFFF)};
    }

    std::vector<uint16_t> move() const {
        const size_t n = m_at->operands.size();
        if (n < 2 || n > 3) fail("MOVE takes two operands and a field");
        const Operand s = op(0), d = op(1);
        if (s.mode == Mode::Reg && d.mode == Mode::Reg) {
            if (n != 2) fail("MOVE between registers takes no field");
            if (s.reg.sp || d.reg.sp || s.reg.file == d.reg.file)
                return {rr(0x4C00, s.reg, d.reg, file_of(s.reg, d.reg))};
            return {rr(0x4E00, s.reg, d.reg, s.reg.file)};
        }
        const int f = field(2);
        const uint16_t fb = static_cast<uint16_t>(f << 9);
        auto rr_f = [&](uint16_t base, const Reg& a, const Reg& b) {
            return static_cast<uint16_t>(rr(base, a, b, file_of(a, b)) | fb);
        };
        std::vector<uint16_t> w;
        if (s.mode == Mode::Reg) {
            switch (d.mode) {
                case Mode::Indirect:
                    return {rr_f(0x8000, s.reg, d.reg)};
                case Mode::PostInc:
                    return {rr_f(0x9000, s.reg, d.reg)};
                case Mode::PreDec:
                    return {rr_f(0xA000, s.reg, d.reg)};
                case Mode::Displaced:
                    w = {rr_f(0xB000, s.reg, d.reg)};
                    w.push_back(static_cast<uint16_t>(word_value(d.expr) & 0xFFFF));
                    return w;
                case Mode::Absolute:
                    w = {static_cast<uint16_t>(0x0580 | fb | (s.reg.file << 4) | s.reg.n)};
                    push_long(w, value(d.expr).v);
                    return w;
                default:
                    break;
            }
        } else if (d.mode == Mode::Reg) {
            switch (s.mode) {
                case Mode::Indirect:
                    return {rr_f(0x8400, s.reg, d.reg)};
                case Mode::PostInc:
                    return {rr_f(0x9400, s.reg, d.reg)};
                case Mode::PreDec:
                    return {rr_f(0xA400, s.reg, d.reg)};
                case Mode::Displaced:
                    w = {rr_f(0xB400, s.reg, d.reg)};
                    w.push_back(static_cast<uint16_t>(word_value(s.expr) & 0xFFFF));
                    return w;
                case Mode::Absolute:
                    w = {static_cast<uint16_t>(0x05A0 | fb | (d.reg.file << 4) | d.reg.n)};
                    push_long(w, value(s.expr).v);
                    return w;
                default:
                    break;
            }
        } else if (s.mode == Mode::Indirect && d.mode == Mode::Indirect) {
            return {rr_f(0x8800, s.reg, d.reg)};
        } else if (s.mode == Mode::PostInc && d.mode == Mode::PostInc) {
            return {rr_f(0x9800, s.reg, d.reg)};
        } else if (s.mode == Mode::PreDec && d.mode == Mode::PreDec) {
            return {rr_f(0xA800, s.reg, d.reg)};
        } else if (s.mode == Mode::Absolute && d.mode == Mode::Absolute) {
            w = {static_cast<uint16_t>(0x05C0 | fb)};
            push_long(w, value(s.expr).v);
            push_long(w, value(d.expr).v);
            return w;
        }
        fail(fmt::format("MOVE {},{}: not an operand pair of MOVE", m_at->operands[0],
                         m_at->operands[1]));
    }

    std::vector<uint16_t> register_list(uint16_t base, bool reversed) const {
        if (m_at->operands.size() < 2) fail(m_at->mnemonic + " takes a pointer and registers");
        const Reg p = reg(0);
        int file = p.sp ? -1 : p.file;
        uint16_t mask = 0;
        for (size_t i = 1; i < m_at->operands.size(); ++i) {
            const Reg r = reg(i);
            if (!r.sp) {
                if (file < 0) file = r.file;
                if (r.file != file) fail(m_at->mnemonic + ": registers in opposite files");
            }
            mask = static_cast<uint16_t>(mask | (reversed ? 0x8000 >> r.n : 1 << r.n));
        }
        return {one(base, Reg{std::max(file, 0), p.n, p.sp}), mask};
    }

    std::vector<uint16_t> pixt() const {
        want(2);
        const Operand s = op(0), d = op(1);
        auto pair = [&](uint16_t base) { return rr(base, s.reg, d.reg, file_of(s.reg, d.reg)); };
        if (s.mode == Mode::Reg && d.mode == Mode::Indirect) return {pair(0xF800)};
        if (s.mode == Mode::Indirect && d.mode == Mode::Reg) return {pair(0xFA00)};
        if (s.mode == Mode::Indirect && d.mode == Mode::Indirect) return {pair(0xFC00)};
        if (s.mode == Mode::Reg && d.mode == Mode::IndirectXY) return {pair(0xF000)};
        if (s.mode == Mode::IndirectXY && d.mode == Mode::Reg) return {pair(0xF200)};
        if (s.mode == Mode::IndirectXY && d.mode == Mode::IndirectXY) return {pair(0xF400)};
        fail(fmt::format("PIXT {},{}: not an operand pair of PIXT", m_at->operands[0],
                         m_at->operands[1]));
    }

    std::vector<uint16_t> data(bool longs) const {
        std::vector<uint16_t> w;
        for (const std::string& e : m_at->operands) {
            const Value v = value(e);
            if (longs)
                push_long(w, v.v);
            else
                w.push_back(static_cast<uint16_t>(word_value(e) & 0xFFFF));
        }
        return w;
    }

    // The words of line i (an instruction, data, or nothing); `relaxing`: a round of the
    // relaxation, where a label may still be placed later; `min_words`: the length an
    // earlier round gave it.
    std::vector<uint16_t> words_of(size_t i, bool relaxing, size_t min_words) {
        m_at = &m_lines[i];
        m_line = m_at->number;
        m_pc = m_address[i];
        m_relaxing = relaxing;
        m_min_words = min_words;
        const std::string& m = m_at->mnemonic;
        if (m.empty() || m == ".TEXT" || m == ".DATA" || m == ".END" || m == ".GLOBAL" ||
            m == ".GLOBL" || m == ".DEF" || m == ".REF" || m == ".TITLE" || m == ".WIDTH" ||
            m == ".LENGTH" || m == ".OPTION" || m == ".LIST" || m == ".NOLIST" || m == ".PAGE")
            return {};
        if (m == ".WORD") return data(false);
        if (m == ".LONG") return data(true);
        if (m == ".EVEN") return {};

        if (const Opcode* o = row_named<Opcode>(kRegisterPairOps, m)) return {two_regs(o->word)};
        if (const Opcode* o = row_named<Opcode>(kOneRegisterOps, m)) {
            want(1);
            return {one(o->word, reg(0))};
        }
        if (const Opcode* o = row_named<Opcode>(kPlainOps, m)) {
            want(0);
            return {o->word};
        }
        // constant and register
        if (m == "ADDK" || m == "SUBK" || m == "MOVK") {
            want(2);
            const uint16_t base = m == "ADDK" ? 0x1000 : m == "SUBK" ? 0x1400 : 0x1800;
            return {
                static_cast<uint16_t>(one(base, reg(1)) | (constant_1_32(m_at->operands[0]) << 5))};
        }
        if (m == "INC" || m == "DEC") {
            want(1);
            return {static_cast<uint16_t>(one(m == "INC" ? 0x1000 : 0x1400, reg(0)) | (1 << 5))};
        }
        if (m == "CLR") {
            want(1);
            const Reg d = reg(0);
            return {rr(0x5600, d, d, d.file)};
        }
        if (m == "SLA" || m == "SLL" || m == "SRA" || m == "SRL" || m == "RL") {
            want(2);
            const Operand s = op(0);
            if (s.mode == Mode::Reg) {
                const uint16_t base = m == "SLA"   ? 0x6000
                                      : m == "SLL" ? 0x6200
                                      : m == "SRA" ? 0x6400
                                      : m == "SRL" ? 0x6600
                                                   : 0x6800;
                return {two_regs(base)};
            }
            const uint16_t base = m == "SLA"   ? 0x2000
                                  : m == "SLL" ? 0x2400
                                  : m == "SRA" ? 0x2800
                                  : m == "SRL" ? 0x2C00
                                               : 0x3000;
            int k = constant_0_31(s.expr);
            if (m == "SRA" || m == "SRL") k = (32 - k) & 31;  // a right shift: -K
            return {static_cast<uint16_t>(one(base, reg(1)) | (k << 5))};
        }
        if (m == "BTST") {
            want(2);
            const Operand s = op(0);
            if (s.mode == Mode::Reg) return {two_regs(0x4A00)};
            return {
                static_cast<uint16_t>(one(0x1C00, reg(1)) | ((~constant_0_31(s.expr) & 31) << 5))};
        }
        if (m == "MOVE") return move();
        if (const ImmediateOpcode* o = row_named<ImmediateOpcode>(kImmediateOps, m)) {
            want(2);
            return immediate(o->short_form, o->long_form, o->complement, reg(1));
        }
        if (m.starts_with("JR")) {
            const int cc = condition_code(std::string_view(m).substr(2));
            if (cc < 0) fail(fmt::format("'{}' is not an instruction", m_at->mnemonic));
            return jump_relative(cc);
        }
        if (m.starts_with("JA")) {
            const int cc = condition_code(std::string_view(m).substr(2));
            if (cc < 0) fail(fmt::format("'{}' is not an instruction", m_at->mnemonic));
            want(1);
            std::vector<uint16_t> w = {static_cast<uint16_t>(0xC080 | (cc << 8))};
            push_long(w, value(m_at->operands[0]).v);
            return w;
        }
        if (m == "DSJ" || m == "DSJEQ" || m == "DSJNE" || m == "DSJS") {
            want(2);
            const Reg d = reg(0);
            const Value t = value(m_at->operands[1]);
            const int64_t short_disp = words_to(t.v, m_pc + 16);
            if ((m == "DSJS" || (m == "DSJ" && m_min_words < 2)) && short_disp >= -31 &&
                short_disp <= 31 && short_disp != 0) {
                const int back = short_disp < 0 ? 1 : 0;
                const int off = static_cast<int>(short_disp < 0 ? -short_disp : short_disp);
                return {static_cast<uint16_t>(one(0x3800, d) | (back << 10) | (off << 5))};
            }
            if (m == "DSJS" && !m_relaxing) fail("DSJS: the label is beyond 31 words");
            const uint16_t base = m == "DSJEQ" ? 0x0DA0 : m == "DSJNE" ? 0x0DC0 : 0x0D80;
            const int64_t disp = words_to(t.v, m_pc + 32);
            return {one(base, d), static_cast<uint16_t>(disp & 0xFFFF)};
        }
        if (m == "CALLA") {
            want(1);
            std::vector<uint16_t> w = {0x0D5F};
            push_long(w, value(m_at->operands[0]).v);
            return w;
        }
        if (m == "CALLR") {
            want(1);
            return {0x0D3F, static_cast<uint16_t>(words_to(value(m_at->operands[0]).v, m_pc + 32) &
                                                  0xFFFF)};
        }
        if (m == "RETS") {
            if (m_at->operands.size() > 1) fail("RETS takes at most one operand");
            const int n = m_at->operands.empty() ? 0 : constant_0_31(m_at->operands[0]);
            return {static_cast<uint16_t>(0x0960 | n)};
        }
        if (m == "TRAP") {
            want(1);
            return {static_cast<uint16_t>(0x0900 | constant_0_31(m_at->operands[0]))};
        }
        if (m == "MMTM") return register_list(0x0980, true);
        if (m == "MMFM") return register_list(0x09A0, false);
        if (m == "SETF") {
            if (m_at->operands.size() < 2 || m_at->operands.size() > 3)
                fail("SETF takes a size, an extension and a field");
            const int size = constant_1_32(m_at->operands[0]);
            const int ext = static_cast<int>(value(m_at->operands[1]).v & 1);
            const int f = field(2);
            return {static_cast<uint16_t>(0x0540 | (f << 9) | (ext << 5) | size)};
        }
        if (m == "SEXT" || m == "ZEXT") {
            if (m_at->operands.empty() || m_at->operands.size() > 2)
                fail(m + " takes a register and a field");
            return {static_cast<uint16_t>(one(m == "SEXT" ? 0x0500 : 0x0520, reg(0)) |
                                          (field(1) << 9))};
        }
        if (m == "FILL") {
            want(1);
            const std::string how = upper(m_at->operands[0]);
            if (how == "L") return {0x0FC0};
            if (how == "XY") return {0x0FE0};
            fail("FILL takes L or XY");
        }
        if (m == "LINE") {
            if (m_at->operands.size() > 1) fail("LINE takes 0 or 1");
            const int64_t z = m_at->operands.empty() ? 0 : value(m_at->operands[0]).v;
            if (z != 0 && z != 1) fail("LINE takes 0 or 1");
            return {static_cast<uint16_t>(z ? 0xDF9A : 0xDF1A)};
        }
        if (m == "PIXBLT") {
            want(2);
            const std::string from = upper(m_at->operands[0]), to = upper(m_at->operands[1]);
            static const std::map<std::string, uint16_t> forms = {
                {"L,L", 0x0F00},   {"L,XY", 0x0F20}, {"XY,L", 0x0F40},
                {"XY,XY", 0x0F60}, {"B,L", 0x0F80},  {"B,XY", 0x0FA0}};
            const auto it = forms.find(from + "," + to);
            if (it == forms.end()) fail("PIXBLT: not a form of PIXBLT");
            return {it->second};
        }
        if (m == "PIXT") return pixt();
        fail(fmt::format("'{}' is not an instruction", m_at->mnemonic));
    }
};

}  // namespace

std::vector<uint16_t> Program::image() const {
    std::vector<uint16_t> words((text_bits + data_bits) / 16, 0);
    for (const AssembledLine& l : lines)
        for (size_t i = 0; i < l.words.size(); ++i)
            words[l.address / 16 + i] = l.words[i];
    return words;
}

Program assemble(std::string_view file, std::string_view source) {
    return Assembler(file, source).run();
}

std::string hex_words(std::span<const uint16_t> words) {
    std::string out;
    for (uint16_t w : words)
        out += fmt::format("{:04X} ", w);
    return out;
}

std::string listing(const Program& program) {
    std::string out;
    for (const AssembledLine& l : program.lines) {
        if (l.words.empty()) {
            out += fmt::format("{:5}                    {}\n", l.line, l.text);
            continue;
        }
        const std::span<const uint16_t> words(l.words);
        for (size_t i = 0; i < words.size(); i += 3) {
            const std::string ws =
                hex_words(words.subspan(i, std::min<size_t>(3, words.size() - i)));
            if (i == 0)
                out += fmt::format("{:5} {:08X} {:15}{}\n", l.line, l.address, ws, l.text);
            else
                out += fmt::format("      {:08X} {}\n", l.address + 16 * i, ws);
        }
    }
    return out;
}

}  // namespace fb89::controller::gsp
