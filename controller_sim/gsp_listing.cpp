// Counting the GSP's command executive (see gsp_listing.h and docs/COST_MODEL.md).
//
// The listing's text is read by gsp_listing_text.cpp. Each instruction is priced here by the
// form of its operands from the data sheet's tables; a form the tables do not give is an
// error, so nothing is priced by a default. Each path is then walked with the write queue.
#include "controller_sim/gsp_listing.h"

#include "controller_sim/gsp_assembler.h"
#include "controller_sim/gsp_listing_text.h"
#include "controller_sim/gsp_states.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace fb89::controller {

namespace {

using listing_text::Instruction;
using listing_text::is_register;
using listing_text::kBFileNames;
using listing_text::kConditions;
using listing_text::parse;
using listing_text::parse_number;
using listing_text::Parsed;
using listing_text::PathSpec;
using listing_text::trim;
using listing_text::upper;

// The two fields' sizes the executive sets at start-up (SETF 16,0,0 and SETF 32,0,1).
constexpr uint32_t kFieldBits[2] = {16, 32};
// On-chip I/O registers: 0C0000000h to 0C00001FFh (SPVS002C p. 10, figure 6).
constexpr uint64_t kIoFirst = 0xC0000000, kIoLast = 0xC00001FF;
// A path longer than this has a loop in it.
constexpr int kMaxPathSteps = 1000;

enum class Kind { Register, MemoryRead, MemoryWrite, Branch, Jump, Dispatch, Graphics };

// What one instruction costs, before the write queue is applied.
struct Price {
    Kind kind = Kind::Register;
    uint32_t words = 1;
    uint32_t cycles = 0;            // taken, for a branch
    uint32_t cycles_not_taken = 0;  // a branch only
    uint32_t queued = 0;            // a write's memory states, which overlap what follows
    uint32_t beside = 0;            // a memory access's first states that overlap a queued write
    std::string source;
    std::string target;  // a jump's label
    std::string graphics;
};

class Pricer {
  public:
    Pricer(const Listing& listing, const Parsed& parsed, const MemoryTiming& memory, TimingEnd end)
        : m_listing(listing), m_parsed(parsed), m_memory(memory), m_end(end) {
        // each instruction's words as the assembler makes them: a jump's form (short, long, or
        // a NOP to the next instruction) and DSJ's (DSJS within 31 words) are priced by them.
        // A listing the assembler refuses is priced from its text alone (JRcc short, DSJ
        // long), so that the pricer's own checks name what they find.
        try {
            for (const gsp::AssembledLine& l :
                 gsp::assemble(fmt::format("{}.asm", listing.name), listing.text).lines)
                if (l.code) m_words[l.line] = l.words;
        } catch (const gsp::AssemblyError&) {
            m_words.clear();
        }
        if (m_memory.chip != Chip::Tms34020) return;
        // each instruction's address in words, the listing loaded at a long word (its words
        // do not depend on the chip): the 34020 prices a long immediate by its alignment
        const Pricer words(listing, parsed, MemoryTiming{}, TimingEnd::Estimate);
        uint32_t at = 0;
        for (const Instruction& in : parsed.code) {
            m_word_at[in.line] = at;
            at += words.price(in).words;
        }
    }

    [[noreturn]] void fail(const Instruction& in, std::string_view what) const {
        throw std::runtime_error(
            fmt::format("listing {}.asm line {}: {}: {}", m_listing.name, in.line, in.text, what));
    }

    Price price(const Instruction& in) const {
        const std::string& m = in.mnemonic;
        const auto& ops = in.operands;
        const auto n = ops.size();
        const auto reg = [&](std::size_t i) { return i < n && is_register(ops[i]); };
        // The TMS34020's figures (User's Guide SPVU019 as [UG20], the cycles of a cached
        // instruction with no wait states, p. 15-1) where its pages give them; its form's
        // 34010 figure otherwise, said in the source.
        const bool c20 = m_memory.chip == Chip::Tms34020;
        const auto by_chip = [&](uint32_t words, uint32_t c10, std::string s10, uint32_t c20_cycles,
                                 std::string s20) {
            return c20 ? simple(words, c20_cycles, std::move(s20))
                       : simple(words, c10, std::move(s10));
        };

        if (m == "NOP" && n == 0)
            return by_chip(1, gsp::states::kRegister, "[DS] p. 13, NOP", 1, "[UG20] ch. 13, NOP");
        if (m == "MOVE" && n == 2 && reg(0) && reg(1))
            return by_chip(1, 1, "[DS] p. 12, MOVE Rs,Rd", 1, "[UG20] p. 13-158, MOVE Rs,Rd");
        if (m == "MOVE" && (n == 2 || n == 3)) return c20 ? memory_move_34020(in) : memory_move(in);
        if (m == "MOVI" && n == 2 && reg(1)) {
            const bool is_short = fits_word(in, ops[0]);
            if (c20)
                return is_short ? simple(2, 2, "[UG20] pp. 13-167, 15-6, MOVI IW,Rd")
                                : long_immediate(in, "MOVI", "pp. 13-168, 15-6");
            return is_short ? simple(2, 2, "[DS] p. 13, MOVI IW,Rd")
                            : simple(3, 3, "[DS] p. 13, MOVI IL,Rd");
        }
        if ((m == "ADDI" || m == "SUBI" || m == "CMPI") && n == 2 && reg(1)) {
            const bool is_short = fits_word(in, ops[0]);
            if (c20)
                return is_short ? simple(2, 2, fmt::format("[UG20] pp. 15-3 to 15-9, {} IW,Rd", m))
                                : long_immediate(in, m, "pp. 15-3 to 15-9");
            return is_short ? simple(2, 2, fmt::format("[DS] pp. 13-14, {} IW,Rd", m))
                            : simple(3, 3, fmt::format("[DS] pp. 13-14, {} IL,Rd", m));
        }
        if ((m == "ANDI" || m == "ORI" || m == "XORI") && n == 2 && reg(1))
            return c20 ? long_immediate(in, m, "pp. 15-3 to 15-9")
                       : simple(3, 3, fmt::format("[DS] pp. 13-14, {} IL,Rd", m));
        if ((m == "MOVK" || m == "ADDK" || m == "SUBK") && n == 2 && reg(1) && constant(in, ops[0]))
            return by_chip(1, 1, fmt::format("[DS] pp. 13-14, {} K,Rd", m), 1,
                           fmt::format("[UG20] pp. 13-37, 13-169, 13-245, {} K,Rd", m));
        if ((m == "SLL" || m == "SRL" || m == "SRA" || m == "RL") && n == 2 && reg(1) &&
            (reg(0) || constant(in, ops[0])))
            return by_chip(1, 1, fmt::format("[DS] pp. 13-14, {}", m), 1,
                           fmt::format("[UG20] pp. 13-222 to 13-240, 15-8, {}", m));
        if ((m == "ADD" || m == "ADDC" || m == "SUB" || m == "SUBB" || m == "CMP" || m == "AND" ||
             m == "ANDN" || m == "OR" || m == "XOR" || m == "ADDXY" || m == "SUBXY") &&
            n == 2 && reg(0) && reg(1)) {
            same_file(in);
            return by_chip(1, 1, fmt::format("[DS] pp. 11, 13-14, {} Rs,Rd", m), 1,
                           fmt::format("[UG20] ch. 13, pp. 15-2 to 15-9, {} Rs,Rd", m));
        }
        if (m == "CMPXY" && n == 2 && reg(0) && reg(1))
            return by_chip(1, 3, "[DS] p. 11, CMPXY", 1, "[UG20] p. 13-84, CMPXY");
        if ((m == "NEG" || m == "NEGB" || m == "NOT" || m == "CLR" || m == "INC" || m == "DEC" ||
             m == "ABS") &&
            n == 1 && reg(0))
            return by_chip(1, 1, fmt::format("[DS] p. 13, {} Rd", m), 1,
                           fmt::format("[UG20] ch. 13, {} Rd", m));
        if (m.size() >= 3 && m.rfind("JR", 0) == 0 && n == 1) {
            const std::string code = m.substr(2);
            if (std::find(std::begin(kConditions), std::end(kConditions), code) ==
                std::end(kConditions))
                fail(in, "not a condition code");
            const std::vector<uint16_t>& w = words_of(in);
            Price p;
            if (w.size() == 1 && w[0] == 0x0300) {
                // to the very next instruction: the assembler writes a NOP, which goes there
                // either way
                p = simple(1, gsp::states::kRegister,
                           "[DS] p. 13, NOP (GSPA's word for a jump to the next instruction)");
                p.cycles_not_taken = gsp::states::kRegister;
            } else if (w.size() == 2) {
                p = by_chip(2, gsp::states::kJumpLongTaken, "[DS] p. 14, JRcc long: 3 taken, 2 not",
                            gsp::states::kJumpLongTaken,
                            "[UG20] p. 15-5, JRcc long: 3 taken, 2 not");
                p.cycles_not_taken = gsp::states::kJumpLongNot;
            } else {
                p = by_chip(1, gsp::states::kJumpShortTaken,
                            "[DS] p. 14, JRcc short: 2 taken, 1 not", gsp::states::kJumpShortTaken,
                            "[EMU] JRcc short: 2 taken, 1 not, as the 34010's (the User's "
                            "Guide pages read give the long form only, 3/2: [UG20] p. 15-5)");
                p.cycles_not_taken = gsp::states::kJumpShortNot;
            }
            p.kind = code == "UC" ? Kind::Jump : Kind::Branch;
            p.target = ops[0];
            return p;
        }
        if (m == "DSJ" && n == 2 && reg(0)) {
            const bool is_short = words_of(in).size() == 1;  // DSJS (unknown: long)
            Price p =
                is_short
                    ? by_chip(1, gsp::states::kDsjsTaken,
                              "[DS] p. 14, DSJS Rd,Address (GSPA's form within 31 words): "
                              "2 taken, 3 not",
                              gsp::states::kDsjsTaken,
                              "[EMU] DSJS Rd,Address: 2 taken, 3 not, as the 34010's")
                    : by_chip(2, gsp::states::kDsjTaken,
                              "[DS] p. 14, DSJ Rd,Address: 3 taken, 2 not", gsp::states::kDsjTaken,
                              "[UG20] pp. 13-103, 15-4, DSJ Rd,Address: 3 taken, 2 not");
            p.kind = Kind::Branch;
            p.cycles_not_taken = is_short ? gsp::states::kDsjsNot : gsp::states::kDsjNot;
            p.target = ops[1];
            return p;
        }
        if (m == "MPYS" && n == 2 && reg(0) && reg(1))
            return by_chip(1, 5 + kFieldBits[1] / 2, "[DS] p. 13, MPYS Rs,Rd: 5 + FS1/2, FS1 = 32",
                           5 + kFieldBits[1] / 2 + (m_end == TimingEnd::High ? 1 : 0),
                           m_end == TimingEnd::High
                               ? "[UG20] p. 15-6, MPYS Rs,Rd: 6 + FS1/2 for a positive Rs, FS1 "
                                 "= 32 (the band's dear end: p. 13-173 reads 5 + FS1/2)"
                               : "[UG20] p. 13-173, MPYS Rs,Rd: 5 + FS1/2, FS1 = 32 (band "
                                 "21-22: p. 15-6 reads 6 + FS1/2 for a positive Rs)");
        if (m == "DIVS" && n == 2 && reg(0) && reg(1))
            return by_chip(1, 40, "[DS] p. 13, DIVS Rs,Rd", 40,
                           "[UG20] pp. 13-96, 15-4, DIVS Rs,Rd: 40, the form with a remainder "
                           "(64 by 32 bits; 39 for the quotient alone)");
        if (m == "CVXYL" && n == 2 && reg(0) && reg(1))
            return by_chip(1, 3, "[DS] p. 11, CVXYL", 3,
                           "[UG20] pp. 13-92, 15-4, CVXYL at a power-of-two pitch");
        if ((m == "MOVX" || m == "MOVY") && n == 2 && reg(0) && reg(1))
            return by_chip(1, 1, fmt::format("[DS] p. 11, {} Rs,Rd", m), 1,
                           fmt::format("[UG20] pp. 13-170, 15-6, {} Rs,Rd", m));
        if (c20 && m == "PIXT" && n == 2 && reg(0) && ops[1].starts_with("*") &&
            is_register(std::string_view(ops[1]).substr(1))) {
            const uint32_t issue = m_end == TimingEnd::Low ? 1 : 2;
            Price p = simple(
                1, issue,
                fmt::format("[EMU] PIXT Rs,*Rd: {} state{} to issue (MAME's 2, band 1-2; the "
                            "User's Guide pages read do not give it) + the pixel's hidden write, "
                            "{} state{} ([UG20] Table 15-2, p. 15-10: case 1 with byte strobes)",
                            issue, issue == 1 ? "" : "s", m_memory.pixel_write_states,
                            m_memory.pixel_write_states == 1 ? "" : "s"));
            p.kind = Kind::MemoryWrite;
            p.queued = m_memory.pixel_write_states;
            return p;
        }
        if (m == "PIXT" && n == 2 && reg(0) && ops[1].starts_with("*") &&
            is_register(std::string_view(ops[1]).substr(1))) {
            // PIXT Rs,*Rd: the data sheet defers it to the User's Guide (p. 11, "T"); GSPSIM's
            // states around the pixel's write, queued like a MOVE's [SIM]; the band's cheap end
            // a state to issue, the write whole
            const bool low = m_end == TimingEnd::Low;
            const gsp::states::Access a =
                low ? gsp::states::kDataSheetMinimum : gsp::states::kPixtWrite;
            const uint32_t own = a.lead + a.tail;
            const std::string write = fmt::format(
                "the pixel's write, {} states (DS p. 19; a read and a write for a pixel narrower "
                "than the word, no byte strobes)",
                m_memory.pixel_write_states);
            Price p = simple(1, own,
                             low ? fmt::format("[EST] PIXT Rs,*Rd: 1 state to issue (the band's "
                                               "cheap end; DS p. 11 defers it to the User's "
                                               "Guide) + {}",
                                               write)
                                 : fmt::format("[SIM] PIXT Rs,*Rd: {} states (GSPSIM 1.04) + {}, "
                                               "{} of them beside its last state",
                                               own, write, a.tail));
            p.kind = Kind::MemoryWrite;
            p.beside = a.beside;
            p.queued = m_memory.pixel_write_states - std::min(m_memory.pixel_write_states, a.tail);
            return p;
        }
        if (m == "PIXT" && n == 2 && reg(1) && ops[0].starts_with("*") &&
            is_register(std::string_view(ops[0]).substr(1))) {
            // PIXT *Rs,Rd: a pixel read, 4 states with its read cycle (SPVS002C p. 11; GSPSIM
            // the same, a state of it beside a queued write); with DPYCTL's SRT set the read is
            // the VRAMs' memory-to-register cycle (the clear)
            one_file(in, std::string_view(ops[0]).substr(1), ops[1]);
            const gsp::states::Access a = gsp::states::kPixtRead;
            Price p = simple(1, a.lead + m_memory.cycle_states + a.tail,
                             fmt::format("[DS] p. 11, PIXT *Rs,Rd: 4 ({} + its read cycle, {} "
                                         "states here)",
                                         a.lead + a.tail, m_memory.cycle_states));
            p.kind = Kind::MemoryRead;
            p.beside = m_end == TimingEnd::Low ? 0 : a.beside;
            return p;
        }
        if ((m == "MMTM" || m == "MMFM") && n >= 2 && reg(0) && upper(ops[0]) == "SP") {
            // n registers of 32 bits, two memory cycles each: 2 + 4n and 3 + 4n states at
            // two states a cycle (User's Guide via TMS34010_sv, "Turn 6 leads")
            const uint32_t regs = static_cast<uint32_t>(n - 1);
            for (std::size_t i = 1; i < n; ++i)
                if (!reg(i)) fail(in, "MMTM and MMFM take SP and registers of one file");
            for (std::size_t i = 2; i < n; ++i)
                one_file(in, ops[1], ops[i]);
            const uint32_t fixed = m == "MMTM" ? 2 : 3;
            Price p = simple(2, fixed + regs * 2 * m_memory.cycle_states,
                             fmt::format("[UG] {} SP,{} registers: {} + 4n at 2 states a cycle "
                                         "(two memory cycles a register, {} states each here{})",
                                         m, regs, fixed, m_memory.cycle_states,
                                         c20 ? "; the 34010's count" : ""));
            p.kind = Kind::MemoryRead;  // its memory cycles are in its count
            return p;
        }
        if (m == "CALLA" && n == 1) {
            Price p = simple(3, 6,
                             fmt::format("[DS] p. 14, CALLA Address: 6 (the return address "
                                         "pushed){}",
                                         c20 ? "; the 34010's count" : ""));
            p.kind = Kind::Jump;
            p.target = ops[0];
            return p;
        }
        if (m == "RETS" && n <= 1) {
            Price p = simple(
                1, 7, fmt::format("[DS] p. 14, RETS: 7{}", c20 ? "; the 34010's count" : ""));
            p.kind = Kind::Dispatch;  // back to the caller: the path's end
            return p;
        }
        if (m == "JUMP" && n == 1 && reg(0)) {
            Price p = by_chip(1, 2, "[DS] p. 14, JUMP Rs", 2, "[UG20] p. 13-141, JUMP Rs");
            p.kind = Kind::Dispatch;
            return p;
        }
        if (m == "FILL" && n == 1 && upper(ops[0]) == "XY") {
            Price p = simple(1, 8,
                             c20 ? "[EMU] FILL XY's own set-up, MAME's fill(): 4 + 2 (XY) + 2 "
                                   "(the 34020's User's Guide calls FILL a complex instruction "
                                   "and gives no count, p. 15-5); its pixels are the memory "
                                   "model's"
                                 : "[EMU] FILL XY's own set-up, MAME's fill(): 4 + 2 (XY) + 2; "
                                   "its pixels are the memory model's");
            p.kind = Kind::Graphics;
            p.graphics = "FILL";
            return p;
        }
        if (m == "FILL" && n == 1 && upper(ops[0]) == "L") {
            Price p = simple(1, 6,
                             "[EMU] FILL L's own set-up, MAME's fill(): 4 + 2 (no XY "
                             "conversion); its pixels are the memory model's");
            p.kind = Kind::Graphics;
            p.graphics = "FILL";
            return p;
        }
        if (m == "LINE" && n == 1 && (ops[0] == "0" || ops[0] == "1")) {
            const uint32_t c = m_end == TimingEnd::Low ? 2 : m_end == TimingEnd::High ? 8 : 4;
            Price p = simple(1, c,
                             "[EST] LINE's own set-up, 4 (band 2-8): the data sheet defers to the "
                             "User's Guide, MAME charges none; its pixels are the memory model's");
            p.kind = Kind::Graphics;
            p.graphics = "LINE";
            return p;
        }
        fail(in, "no timing for this instruction form in the data sheet's tables");
    }

  private:
    const std::vector<uint16_t>& words_of(const Instruction& in) const {
        static const std::vector<uint16_t> unknown;
        const auto it = m_words.find(in.line);
        return it == m_words.end() ? unknown : it->second;
    }
    static Price simple(uint32_t words, uint32_t cycles, std::string source) {
        Price p;
        p.words = words;
        p.cycles = cycles;
        p.source = std::move(source);
        return p;
    }

    uint64_t value(const Instruction& in, std::string_view s) const {
        if (auto v = parse_number(s)) return *v;
        // a code label: an address in the GSP's memory, a 32-bit immediate
        if (m_parsed.labels.count(std::string(trim(s)))) return 0xFFFFFFFFu;
        auto it = m_parsed.symbols.find(std::string(trim(s)));
        if (it == m_parsed.symbols.end()) fail(in, fmt::format("{}: not a number or a symbol", s));
        return it->second;
    }
    bool fits_word(const Instruction& in, std::string_view s) const {
        return value(in, s) < 0x8000;
    }
    bool constant(const Instruction& in, std::string_view s) const {
        const uint64_t v = value(in, s);
        if (v < 1 || v > 32) fail(in, "a constant K is 1 to 32");
        return true;
    }
    void same_file(const Instruction& in) const {
        const char a = file_of(in.operands[0]), b = file_of(in.operands[1]);
        if (a != b && a != 'S' && b != 'S') fail(in, "only MOVE crosses between the A and B files");
    }

    // Which register file a register is in: the B file's names and Bn; SP is in both.
    static char file_of(std::string_view r) {
        const std::string u = upper(r);
        if (u == "SP") return 'S';
        return u[0] == 'B' || std::find(std::begin(kBFileNames), std::end(kBFileNames), u) !=
                                  std::end(kBFileNames)
                   ? 'B'
                   : 'A';
    }
    // Two registers of one instruction word must be in one file (its R bit selects the file
    // for both): TI's assembler refuses, e.g., MOVE *A0+,DADDR,1 with "REGISTERS IN OPPOSITE
    // FILES". SP belongs to both.
    void one_file(const Instruction& in, std::string_view a, std::string_view b) const {
        const char fa = file_of(a), fb = file_of(b);
        if (fa != 'S' && fb != 'S' && fa != fb)
            fail(in,
                 "registers in opposite files: the chip has no such form (only MOVE Rs,Rd "
                 "crosses between the A and B files)");
    }
    // The register of an indirect operand: *Rn, *Rn+, *-Rn or *Rn(displacement).
    std::string_view indirect(const Instruction& in, std::string_view where) const {
        std::string_view r = where.substr(1);
        if (r.starts_with("-"))
            r.remove_prefix(1);
        else if (r.ends_with("+"))
            r.remove_suffix(1);
        else if (const std::size_t open = r.find('('); open != std::string_view::npos) {
            if (!r.ends_with(")") || !parse_number(r.substr(open + 1, r.size() - open - 2)))
                fail(in, "a displacement is *Rn(number)");
            r = r.substr(0, open);
        }
        if (!is_register(r)) fail(in, "an indirect operand is *Rn, *Rn+, *-Rn or *Rn(disp)");
        return r;
    }

    // A memory MOVE's field select, direction and memory operand; fails for any other form.
    struct MoveOperands {
        std::size_t field;
        bool read;
        std::string_view where;
    };
    MoveOperands move_operands(const Instruction& in) const {
        const auto& ops = in.operands;
        const std::size_t field = ops.size() == 3 ? (ops[2] == "1" ? 1 : ops[2] == "0" ? 0 : 2) : 0;
        if (field > 1) fail(in, "the field select is 0 or 1");
        const auto memory = [](std::string_view s) {
            return s.starts_with("*") || s.starts_with("@");
        };
        const bool read = memory(ops[0]) && is_register(ops[1]);
        const bool write = is_register(ops[0]) && memory(ops[1]);
        if (!read && !write) fail(in, "a MOVE is register to memory or memory to register here");
        const std::string_view where = read ? std::string_view(ops[0]) : std::string_view(ops[1]);
        if (where.starts_with("*")) one_file(in, indirect(in, where), read ? ops[1] : ops[0]);
        return {field, read, where};
    }

    // MOVE with a memory operand: the data sheet's tables give no figure ("depends on field
    // size and alignment", p. 12); the price is its form's states around the memory cycles of
    // its field, word-aligned, as TI's simulator GSPSIM 1.04 gives them (gsp_states.h) [SIM]:
    // a read waits for its cycles, a write queues them (p. 10) to overlap the instructions
    // after it until the next memory access. The band's cheap end is the data sheet's reading
    // fb89 followed before GSPSIM was measured: a state to issue, the cycles waited for whole.
    Price memory_move(const Instruction& in) const {
        const auto [field, read, where] = move_operands(in);
        if (where.starts_with("*")) indirect(in, where);
        bool io = false;
        if (where.starts_with("@")) {
            const uint64_t address = value(in, where.substr(1));
            io = address >= kIoFirst && address <= kIoLast;
            if (address % 16 != 0) fail(in, "an absolute operand here is word-aligned");
        }
        const uint32_t field_words = kFieldBits[field] / 16;
        const uint32_t per_word = io ? m_memory.io_cycle_states : m_memory.cycle_states;
        namespace st = gsp::states;
        const bool absolute = where.starts_with("@"), displaced = where.ends_with(")");
        const bool pre = where.starts_with("-*") || where.starts_with("*-"),
                   post = where.ends_with("+");
        std::string_view form = absolute    ? "@a"
                                : displaced ? "*R(d)"
                                : pre       ? "-*R"
                                : post      ? "*R+"
                                            : "*R";
        st::Access a = read ? (absolute    ? st::kReadAbsolute
                               : displaced ? st::kReadDisplacement
                               : pre       ? st::kReadPreDecrement
                               : post      ? st::kReadPostIncrement
                                           : st::kReadIndirect)
                            : (absolute    ? st::kWriteAbsolute
                               : displaced ? st::kWriteDisplacement
                               : pre       ? st::kWritePreDecrement
                                           : st::kWriteIndirect);
        if (m_end == TimingEnd::Low) a = st::kDataSheetMinimum;
        Price p;
        p.words = absolute ? 3 : displaced ? 2 : 1;
        p.kind = read ? Kind::MemoryRead : Kind::MemoryWrite;
        p.source = fmt::format(
            "{} {}{} {}: {} + {} {}-bit {} cycle{} of {} states (DS p. 19{}){}",
            m_end == TimingEnd::Low ? "[EST]" : "[SIM]", read ? "MOVE " : "MOVE Rs,", form,
            read ? ",Rd" : "", a.lead + a.tail, field_words, 16, io ? "I/O" : "memory",
            field_words == 1 ? "" : "s", per_word, read ? "" : "; a write is queued, p. 10",
            m_end == TimingEnd::Low
                ? " (the band's cheap end: a state to issue)"
                : fmt::format(" (GSPSIM 1.04; {} beside a queued write)", a.beside));
        p.beside = a.beside;
        const uint32_t cycles = field_words * per_word;
        if (read) {
            p.cycles = a.lead + cycles + a.tail;
        } else {
            p.cycles = a.lead + a.tail;
            p.queued = cycles - std::min(cycles, a.tail);
        }
        return p;
    }

    // The 34020's long immediate (IL): 2 states when its two words start on a long word, 3
    // when not ([UG20]); the listing's own layout says which.
    Price long_immediate(const Instruction& in, std::string_view m, std::string_view pages) const {
        const bool aligned = (m_word_at.at(in.line) + 1) % 2 == 0;
        return simple(3, aligned ? 2 : 3,
                      fmt::format("[UG20] {}, {} IL,Rd: {} (its long word {}aligned at word {} "
                                  "of the listing)",
                                  pages, m, aligned ? 2 : 3, aligned ? "" : "not ",
                                  m_word_at.at(in.line) + 1));
    }

    // The 34020's MOVE with a memory operand ([UG20] pp. 13-159 to 13-161, Table 15-2 p. 15-10
    // and p. 15-11), a field of 16 or 32 bits that its 32-bit bus moves in one cycle:
    //   *Rs,Rd and *Rs+,Rd   3         Rs,*Rd and Rs,*Rd+   1 (+1)
    //   @a,Rd                4 / 5     Rs,@a                2 (+1) / 3 (+1)
    // (+n: hidden write states, the write queue's), @a by its address's alignment in the
    // listing, FE = 0 (SETF 16,0,0 and 32,0,1). A 16-bit field on a 16-bit boundary and
    // @a's long-aligned symbols are case 1; a 32-bit field through a register is taken as
    // case 1 (long-aligned) and at the band's dear end as case 3, across a long word (+1
    // read state, +1 hidden write state: the ring's words are 16-bit aligned only). A wait
    // state adds a state to the cycle (the counts assume none, p. 15-1).
    Price memory_move_34020(const Instruction& in) const {
        const auto [field, read, where] = move_operands(in);
        bool io = false;
        const bool absolute = where.starts_with("@");
        bool across = false;  // a 32-bit field across a long word: case 3
        if (where.starts_with("*")) {
            indirect(in, where);
            across = kFieldBits[field] == 32 && m_end == TimingEnd::High;
        } else {
            const uint64_t address = value(in, where.substr(1));
            io = address >= kIoFirst && address <= kIoLast;
            if (address % 16 != 0) fail(in, "an absolute operand here is word-aligned");
            across = kFieldBits[field] == 32 && address % 32 != 0;
        }
        const uint32_t wait = io || m_memory.cycle_states <= 2 ? 0 : m_memory.cycle_states - 2;
        Price p;
        p.words = absolute ? 3 : where.ends_with(")") ? 2 : 1;
        p.kind = read ? Kind::MemoryRead : Kind::MemoryWrite;
        std::string form;
        uint32_t visible = 0, hidden = 0;
        if (absolute) {
            // the address's two words after the opcode: on a long word when the opcode is not
            const bool aligned = (m_word_at.at(in.line) + 1) % 2 == 0;
            visible = (read ? (aligned ? 4 : 5) : (aligned ? 2 : 3)) + (read && across ? 1 : 0);
            hidden = read ? 0 : 1 + (across ? 1 : 0);
            form = fmt::format("{}, its address {}aligned, {}-bit field, case {}",
                               read ? "MOVE @a,Rd" : "MOVE Rs,@a", aligned ? "" : "not ",
                               kFieldBits[field], across ? 3 : 1);
        } else {
            visible = read ? 3 + (across ? 1 : 0) : 1;
            hidden = read ? 0 : 1 + (across ? 1 : 0);
            form =
                fmt::format("{}, {}-bit field, case {}", read ? "MOVE *Rs(+),Rd" : "MOVE Rs,*Rd(+)",
                            kFieldBits[field], across ? 3 : 1);
        }
        if (read) {
            p.cycles = visible + wait;
        } else {
            p.cycles = visible;
            p.queued = hidden + wait;
        }
        p.source =
            fmt::format("[UG20] pp. 13-159 to 13-161, 15-10 to 15-11, {}: {}{}{}", form, visible,
                        hidden ? fmt::format(" (+{})", hidden) : "",
                        wait ? fmt::format(" + {} wait state{}", wait, wait == 1 ? "" : "s") : "");
        return p;
    }

    const Listing& m_listing;
    const Parsed& m_parsed;
    MemoryTiming m_memory;
    TimingEnd m_end;
    std::map<int, uint32_t> m_word_at;             // the 34020's: each instruction's word, by line
    std::map<int, std::vector<uint16_t>> m_words;  // each instruction's words, by line
};

// The states the instructions from `pc` run beside a queued write: those that touch no
// memory, up to the first that jumps, and then the first memory access's `beside`.
uint32_t beside_at(const Parsed& parsed, const Pricer& pricer, std::size_t pc) {
    uint32_t states = 0;
    for (; pc < parsed.code.size(); ++pc) {
        const Price p = pricer.price(parsed.code[pc]);
        if (p.kind == Kind::MemoryRead || p.kind == Kind::MemoryWrite) return states + p.beside;
        if (p.kind != Kind::Register) return states;
        states += p.cycles;
    }
    return states;
}

// Walks one path from its label, pricing each instruction and applying the write queue:
// a queued write's states overlap the register instructions after it and are waited for
// by the next memory access, the graphics instruction, or the path's end.
CountedPath walk(const Listing& listing, const Parsed& parsed, const Pricer& pricer,
                 const PathSpec& spec, const std::string& loop) {
    CountedPath path;
    path.name = spec.name;
    const auto label = [&](const std::string& l) {
        auto it = parsed.labels.find(l);
        if (it == parsed.labels.end())
            throw std::runtime_error(
                fmt::format("listing {}.asm: @path {}: no label {}", listing.name, spec.name, l));
        return it->second;
    };
    std::size_t pc = label(spec.start);
    const std::size_t end = spec.end.empty() ? SIZE_MAX : label(spec.end);
    for (const std::string& t : spec.taken)
        (void)label(t);
    for (const std::string& t : spec.fallen)
        (void)label(t);
    uint32_t queued = 0;
    for (int step = 0;; ++step) {
        if (step > 0 && pc == end) {
            // reached its end: a queued write is paid by it, less what the next path's first
            // instructions run beside it (the next path is priced from an empty queue)
            const uint32_t paid = queued - std::min(queued, beside_at(parsed, pricer, pc));
            path.cycles += paid;
            if (!path.lines.empty()) path.lines.back().cycles += paid;
            break;
        }
        if (step > kMaxPathSteps || pc >= parsed.code.size())
            throw std::runtime_error(fmt::format(
                "listing {}.asm: @path {} does not end (a path ends at a dispatch, a jump to {}{})",
                listing.name, spec.name, loop, spec.end.empty() ? "" : " or at " + spec.end));
        const Instruction& in = parsed.code[pc];
        const Price p = pricer.price(in);
        uint32_t cycles = p.cycles;
        const bool touches_memory =
            p.kind == Kind::MemoryRead || p.kind == Kind::MemoryWrite || p.kind == Kind::Graphics;
        if (touches_memory) {
            cycles += queued - std::min(queued, p.beside);  // wait for the queued write
            queued = 0;
        }
        bool taken = p.kind == Kind::Jump;
        const bool forced =
            std::find(spec.taken.begin(), spec.taken.end(), p.target) != spec.taken.end();
        const bool falls =
            std::find(spec.fallen.begin(), spec.fallen.end(), p.target) != spec.fallen.end();
        if (p.kind == Kind::Branch) {
            if (forced)
                taken = true;
            else if (falls)
                taken = false;
            else if (in.comment.starts_with("not taken"))
                taken = false;
            else if (in.comment.starts_with("taken"))
                taken = true;
            else
                pricer.fail(in, "a conditional jump on a path says \"taken\" or \"not taken\"");
            if (!taken) cycles = p.cycles_not_taken;
        }
        if (!touches_memory) queued = cycles >= queued ? 0 : queued - cycles;
        if (p.kind == Kind::MemoryWrite) queued = p.queued;
        if (p.kind == Kind::Graphics) path.graphics = p.graphics;
        const bool ends = p.kind == Kind::Dispatch || (taken && p.target == loop);
        if (ends) cycles += queued;  // paid before the path's work is done
        path.lines.push_back({in.line, in.text, cycles, p.words, p.source});
        path.cycles += cycles;
        if (ends) break;
        if (taken) {
            auto target = parsed.labels.find(p.target);
            if (target == parsed.labels.end()) pricer.fail(in, "no such label");
            pc = target->second;
        } else {
            ++pc;
        }
    }
    return path;
}

}  // namespace

std::optional<Chip> chip_named(std::string_view name) {
    if (name == "tms34010") return Chip::Tms34010;
    if (name == "tms34020") return Chip::Tms34020;
    return std::nullopt;
}

std::string_view chip_name(Chip chip) {
    return chip == Chip::Tms34020 ? "tms34020" : "tms34010";
}

const Listing& builtin_listing(std::string_view name) {
    for (const Listing& l : builtin_listings())
        if (l.name == name) return l;
    std::vector<std::string> names;
    for (const Listing& l : builtin_listings())
        names.emplace_back(l.name);
    throw std::runtime_error(fmt::format("unknown GSP listing \"{}\": the built-in ones are {}",
                                         name, fmt::join(names, ", ")));
}

std::map<std::string, CountedPath> count_paths(const Listing& listing, const MemoryTiming& memory,
                                               TimingEnd end) {
    const Parsed parsed = parse(listing);
    const Pricer pricer(listing, parsed, memory, end);
    std::string loop;
    for (const PathSpec& spec : parsed.paths)
        if (spec.name == "COMMON") loop = spec.start;
    if (loop.empty())
        throw std::runtime_error(fmt::format("listing {}.asm: no @path COMMON", listing.name));
    std::map<std::string, CountedPath> out;
    for (const PathSpec& spec : parsed.paths)
        out[spec.name] = walk(listing, parsed, pricer, spec, loop);
    return out;
}

uint32_t listing_words(const Listing& listing) {
    const Parsed parsed = parse(listing);
    const Pricer pricer(listing, parsed, MemoryTiming{}, TimingEnd::Estimate);
    uint32_t words = 0;
    for (const Instruction& in : parsed.code)
        words += pricer.price(in).words;
    return words;
}

uint32_t working_set_words(const std::map<std::string, CountedPath>& paths,
                           std::span<const std::string_view> names) {
    std::map<int, uint32_t> words;
    for (std::string_view name : names) {
        auto it = paths.find(std::string(name));
        if (it == paths.end()) throw std::runtime_error(fmt::format("no @path {}", name));
        for (const CountedLine& l : it->second.lines)
            words[l.line] = l.words;
    }
    uint32_t n = 0;
    for (const auto& [line, w] : words)
        n += w;
    return n;
}

uint32_t working_set_segments(const Listing& listing,
                              const std::map<std::string, CountedPath>& paths,
                              std::span<const std::string_view> names) {
    std::map<int, const gsp::AssembledLine*> at;
    const gsp::Program program = gsp::assemble(fmt::format("{}.asm", listing.name), listing.text);
    for (const gsp::AssembledLine& l : program.lines)
        if (l.code) at[l.line] = &l;
    constexpr uint32_t kSegmentBits = 32 * 16;
    std::map<uint32_t, bool> segments;
    for (std::string_view name : names) {
        auto it = paths.find(std::string(name));
        if (it == paths.end()) throw std::runtime_error(fmt::format("no @path {}", name));
        for (const CountedLine& l : it->second.lines) {
            auto a = at.find(l.line);
            if (a == at.end() || a->second->words.empty()) continue;
            const uint32_t first = a->second->address;
            const uint32_t last = first + 16 * static_cast<uint32_t>(a->second->words.size()) - 1;
            for (uint32_t s = first / kSegmentBits; s <= last / kSegmentBits; ++s)
                segments[s] = true;
        }
    }
    return static_cast<uint32_t>(segments.size());
}

std::span<const CachedWork> cached_work() {
    static const std::vector<CachedWork> work = {
        {"a FILL_RECT or a DRAW_SPAN", {"COMMON", "FILL_RECT", "DRAW_SPAN:fill"}},
        {"a DEPTH_SPAN and its pixel loop",
         {"COMMON", "DEPTH_SPAN", "ZPIXEL16:nearer", "ZPIXEL16:farther", "ZSPAN_EXIT"}},
        {"a FACE's row loop",
         {"FACE:row", "FACE:edge", "FACE:nearer", "FACE:level", "FACE:lastedge", "FACE:span",
          "FACE:step", "FACE:empty", "ZPIXEL16:nearer", "ZPIXEL16:farther", "ZSPAN_EXIT"}},
    };
    return work;
}

std::string annotated_listing(const Listing& listing, const MemoryTiming& memory) {
    const auto paths = count_paths(listing, memory);
    std::map<int, const CountedLine*> priced;
    for (const auto& [name, path] : paths)
        for (const CountedLine& l : path.lines)
            priced.emplace(l.line, &l);
    std::string out = fmt::format(
        "; {}.asm, each counted instruction with its cycles on the {} (memory cycle {} states, "
        "I/O {})\n",
        listing.name, memory.chip == Chip::Tms34020 ? "TMS34020" : "TMS34010", memory.cycle_states,
        memory.io_cycle_states);
    // each line with its address and words as TI's assembler writes them (gsp_assembler.h)
    const gsp::Program program = gsp::assemble(std::string(listing.name) + ".asm", listing.text);
    uint32_t code_words = 0, data_words = 0;
    for (const gsp::AssembledLine& l : program.lines) {
        (l.code ? code_words : data_words) += static_cast<uint32_t>(l.words.size());
        auto it = priced.find(l.line);
        const std::string cycles = it == priced.end() ? "" : std::to_string(it->second->cycles);
        const std::span<const uint16_t> all(l.words);
        const std::string words = gsp::hex_words(all.first(std::min<std::size_t>(all.size(), 3)));
        out += l.words.empty()
                   ? fmt::format("{:>4}  {:8} {:15} {}\n", cycles, "", "", l.text)
                   : fmt::format("{:>4}  {:08X} {:15} {}\n", cycles, l.address, words, l.text);
        for (std::size_t i = 3; i < all.size(); i += 3)
            out += fmt::format(
                "{:>4}  {:08X} {}\n", "", l.address + 16 * i,
                gsp::hex_words(all.subspan(i, std::min<std::size_t>(3, all.size() - i))));
    }
    for (const auto& [name, path] : paths)
        out += fmt::format(
            "; {:<15} {:>4} cycles{}\n", name, path.cycles,
            path.graphics.empty() ? "" : fmt::format(" with {}'s own set-up", path.graphics));
    out += fmt::format(
        "; {}.asm: {} bytes of instructions and {} of data, {} in all; the instruction cache "
        "holds {} bytes, so the executive {} it\n",
        listing.name, 2 * code_words, 2 * data_words, 2 * (code_words + data_words),
        kInstructionCacheBytes,
        2 * code_words <= kInstructionCacheBytes ? "fits in" : "does not fit");
    return out;
}

}  // namespace fb89::controller
