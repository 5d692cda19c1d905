// The emulated TMS34010's instructions other than the MOVEs through a register, the jumps
// and the graphics instructions (see gsp_cpu.h): the 0xxxh group (the one-register and plain
// instructions, the absolute MOVEs, SETF, calls, DSJ, FILL), the immediates, the constant
// forms and shifts, and the register pairs with MPYS/MPYU and DIVS/DIVU/MODS/MODU. Decoding
// and semantics as gsp_cpu.cpp says; states from gsp_states.h.
#include "controller_sim/gsp_cpu.h"

#include "controller_sim/gsp_states.h"

#include <bit>
#include <cstdint>
#include <utility>

#include <fmt/format.h>

namespace fb89::controller::gsp {

template <uint16_t Form>
void Tms34010::exec_0(uint16_t w) {
    const int file = (w >> 4) & 1, rd = w & 15;
    uint32_t& d = r(file, rd);
    switch (Form) {
        case 0x0020:  // REV Rd: the chip's revision
            d = 0x0008;
            m_states += states::kRegister;
            return;
        case 0x0100:  // EMU
        case 0x0300:  // NOP
            m_states += states::kRegister;
            return;
        case 0x0120: {  // EXGPC Rd
            const uint32_t t = d;
            d = m_pc;
            m_pc = t & ~15u;
            m_states += states::kJump;
            return;
        }
        case 0x0140:  // GETPC Rd
            d = m_pc;
            m_states += states::kRegister;
            return;
        case 0x0160:  // JUMP Rs
            m_pc = d & ~15u;
            m_states += states::kJump;
            return;
        case 0x0180:  // GETST Rd
            d = status();
            m_states += states::kRegister;
            return;
        case 0x01A0:  // PUTST Rs
            set_status(d);
            m_states += states::kRegister;
            return;
        case 0x0320:  // CLRC
            m_c = false;
            m_states += states::kRegister;
            return;
        case 0x0360:  // DINT
            m_ie = false;
            m_states += states::kRegister;
            return;
        case 0x0380: {                               // ABS Rd
            const uint32_t v = d, negated = 0u - v;  // N and Z from -Rd
            m_n = negated >> 31;
            m_z = negated == 0;
            m_v = v == 0x80000000u;
            d = (v >> 31) ? negated : v;
            m_states += states::kRegister;
            return;
        }
        case 0x03A0: {  // NEG Rd
            const uint32_t v = d, res = 0u - v;
            m_c = v != 0;
            m_v = v == 0x80000000u;
            set_nz(res);
            d = res;
            m_states += states::kRegister;
            return;
        }
        case 0x03C0: {  // NEGB Rd
            const uint64_t sub = uint64_t{d} + (m_c ? 1 : 0);
            const uint32_t v = d, res = static_cast<uint32_t>(0 - sub);
            m_v = ((v & res) >> 31) != 0;
            m_c = sub != 0;
            set_nz(res);
            d = res;
            m_states += states::kRegister;
            return;
        }
        case 0x03E0:  // NOT Rd
            d = ~d;
            m_z = d == 0;
            m_states += states::kRegister;
            return;
        case 0x0920:  // CALL Rs
            sp() -= 32;
            pay_queue();
            write_field(sp(), 32, m_pc);
            m_pc = d & ~15u;
            m_states += states::kCall;
            return;
        case 0x0D60:  // EINT
            m_ie = true;
            m_states += states::kRegister;
            return;
        case 0x0DE0:  // SETC
            m_c = true;
            m_states += states::kRegister;
            return;
        default:
            break;
    }
    // SEXT, ZEXT, SETF and the absolute MOVEs carry the field in bit 9
    constexpr int field = (Form >> 9) & 1;
    switch (Form & 0xFDE0) {
        case 0x0500:    // SEXT Rd,F
        case 0x0520: {  // ZEXT Rd,F
            const uint32_t bits = m_fs[field];
            if (bits < 32) {
                const uint32_t mask = (1u << bits) - 1;
                d &= mask;
                if ((Form & 0xFDE0) == 0x0500) d = (d ^ (1u << (bits - 1))) - (1u << (bits - 1));
            }
            set_nz(d);
            m_states += states::kRegister;
            return;
        }
        case 0x0540:
        case 0x0560:  // SETF size,extension,F
            set_field(field, (w & 31) ? (w & 31) : 32, (w >> 5) & 1);
            m_states += states::kSetf;
            return;
        case 0x0580: {  // MOVE Rs,@address,F
            const uint32_t a = fetch_long();
            memory_write(a, field, d, states::kWriteAbsolute);
            return;
        }
        case 0x05A0: {  // MOVE @address,Rd,F
            const uint32_t a = fetch_long();
            d = memory_read(a, field, states::kReadAbsolute);
            set_nz(d);
            m_v = false;
            return;
        }
        case 0x05C0: {  // MOVE @address,@address,F
            const uint32_t from = fetch_long(), to = fetch_long();
            memory_write(to, field, memory_read(from, field, states::kReadAbsolute),
                         states::kWriteAbsolute);
            return;
        }
        default:
            break;
    }
    if (Form == 0x0960) {  // RETS N
        pay_queue();
        m_pc = read_field(sp(), 32) & ~15u;
        sp() += 32 + 16 * (w & 31);
        m_states += states::kRets + 2 * m_timing.cycle_states;
        return;
    }
    if ((Form & 0xFFC0) == 0x0980) {  // MMTM Rp,list / MMFM Rp,list
        constexpr bool to_memory = (Form & 0x0020) == 0;
        const uint16_t mask = fetch();
        uint32_t& p = r(file, rd);
        uint32_t n = 0;
        pay_queue();
        if (to_memory) {
            for (int i = 0; i < 16; ++i)
                if (mask & (0x8000 >> i)) {
                    p -= 32;
                    write_field(p, 32, reg(file, i));
                    ++n;
                }
        } else {
            for (int i = 15; i >= 0; --i)
                if (mask & (1 << i)) {
                    const uint32_t v = read_field(p, 32);
                    p += 32;
                    set_reg(file, i, v);
                    ++n;
                }
        }
        m_states +=
            (to_memory ? states::kMmFixedTm : states::kMmFixedFm) + n * 2 * m_timing.cycle_states;
        return;
    }
    if (w == 0x0D5F) {  // CALLA address
        const uint32_t to = fetch_long();
        sp() -= 32;
        pay_queue();
        write_field(sp(), 32, m_pc);
        m_pc = to;
        m_states += states::kCall;
        return;
    }
    if (w == 0x0D3F) {  // CALLR address
        const int32_t disp = sext16(fetch());
        sp() -= 32;
        pay_queue();
        write_field(sp(), 32, m_pc);
        m_pc = static_cast<uint32_t>(int64_t{m_pc} + int64_t{disp} * 16);
        m_states += states::kCallr;
        return;
    }
    if (w == 0x0FC0 || w == 0x0FE0) {
        fill(w == 0x0FE0);
        return;
    }
    fault(fmt::format("word {:04X}h: not an instruction fb89's GSP executes", w));
}

template <uint16_t Form>
void Tms34010::exec_dsj(uint16_t w) {
    uint32_t& d = rd_of(w);
    const int32_t disp = sext16(fetch());
    bool go = true;
    if constexpr (Form == 0x0DA0) go = m_z;
    if constexpr (Form == 0x0DC0) go = !m_z;
    bool taken = false;
    if (go) {
        d -= 1;
        taken = d != 0;
    }
    if (taken) m_pc = static_cast<uint32_t>(int64_t{m_pc} + int64_t{disp} * 16);
    m_states += taken ? states::kDsjTaken : states::kDsjNot;
}

template <uint16_t Form>
void Tms34010::exec_immediate(uint16_t w) {
    uint32_t& d = rd_of(w);
    constexpr uint16_t form = Form;
    constexpr bool is_long = form == 0x09E0 || form == 0x0B20 || form == 0x0B60 || form == 0x0B80 ||
                             form == 0x0BA0 || form == 0x0BC0 || form == 0x0D00;
    const uint32_t raw = is_long ? fetch_long() : static_cast<uint32_t>(sext16(fetch()));
    m_states += is_long ? states::kImmediateLong : states::kImmediateWord;
    const auto add = [&](uint32_t a, uint32_t b, bool store) {
        const uint64_t sum = uint64_t{a} + b;
        const uint32_t res = static_cast<uint32_t>(sum);
        m_c = (sum >> 32) != 0;
        m_v = (~(a ^ b) & (a ^ res)) >> 31;
        set_nz(res);
        if (store) d = res;
    };
    const auto sub = [&](uint32_t a, uint32_t b, bool store) {
        const uint32_t res = a - b;
        m_c = a < b;
        m_v = ((a ^ b) & (a ^ res)) >> 31;
        set_nz(res);
        if (store) d = res;
    };
    switch (form) {
        case 0x09C0:
        case 0x09E0:  // MOVI
            d = raw;
            set_nz(d);
            m_v = false;
            return;
        case 0x0B00:
        case 0x0B20:  // ADDI
            add(d, raw, true);
            return;
        case 0x0B40:
        case 0x0B60:  // CMPI: the value kept as its ones' complement
            sub(d, ~raw, false);
            return;
        case 0x0BE0:
        case 0x0D00:  // SUBI: likewise
            sub(d, ~raw, true);
            return;
        case 0x0B80:  // ANDI: likewise
            d &= ~raw;
            m_z = d == 0;
            return;
        case 0x0BA0:  // ORI
            d |= raw;
            m_z = d == 0;
            return;
        case 0x0BC0:  // XORI
            d ^= raw;
            m_z = d == 0;
            return;
        default:
            fault(fmt::format("word {:04X}h: not an immediate form", w));
    }
}

// ADDK, SUBK, MOVK, BTST K, the shifts by K, and DSJS
template <uint16_t Form>
void Tms34010::exec_k(uint16_t w) {
    uint32_t& d = rd_of(w);
    const uint32_t k5 = (w >> 5) & 31;
    const uint32_t k = k5 ? k5 : 32;
    m_states += states::kRegister;
    switch (Form) {
        case 0x1000: {  // ADDK
            const uint32_t a = d;
            const uint64_t sum = uint64_t{a} + k;
            d = static_cast<uint32_t>(sum);
            m_c = (sum >> 32) != 0;
            m_v = (~a & d) >> 31;
            set_nz(d);
            return;
        }
        case 0x1400: {  // SUBK
            const uint32_t a = d;
            d = a - k;
            m_c = a < k;
            m_v = (a & ~d) >> 31;
            set_nz(d);
            return;
        }
        case 0x1800:  // MOVK
            d = k;
            return;
        case 0x1C00:  // BTST K (kept as its ones' complement)
            m_z = ((d >> (~k5 & 31)) & 1) == 0;
            return;
        case 0x2000:
        case 0x2400: {  // SLA, SLL by K
            const uint32_t v = d;
            d = k5 ? v << k5 : v;
            m_c = k5 ? ((v >> (32 - k5)) & 1) : false;
            m_z = d == 0;
            if (Form == 0x2000) {
                m_n = d >> 31;
                // V: a bit unlike the sign shifted through it
                const uint32_t top = k5 ? (v >> (31 - k5)) : 0;
                const uint32_t all = k5 ? ((1u << (k5 + 1)) - 1) : 0;
                m_v = k5 && (top & all) != 0 && (top & all) != all;
            }
            return;
        }
        case 0x2800:
        case 0x2C00: {  // SRA, SRL by K: the count kept as 32 - K
            const uint32_t n = (32 - k5) & 31;
            const uint32_t v = d;
            if (n == 0) {
                m_c = false;
            } else {
                m_c = (v >> (n - 1)) & 1;
                d = Form == 0x2800 ? static_cast<uint32_t>(static_cast<int32_t>(v) >> n) : v >> n;
            }
            m_z = d == 0;
            if (Form == 0x2800) m_n = d >> 31;
            return;
        }
        case 0x3000: {  // RL by K
            const uint32_t v = d;
            d = k5 ? (v << k5) | (v >> (32 - k5)) : v;
            m_c = k5 ? ((v >> (32 - k5)) & 1) : false;
            m_z = d == 0;
            return;
        }
        case 0x3800:
        case 0x3C00: {  // DSJS Rd,address: bit 10 backwards, bits 9-5 the words
            m_states -= states::kRegister;
            d -= 1;
            if (d != 0) {
                const int64_t words = (Form & 0x0400) ? -int64_t{k5} : int64_t{k5};
                m_pc = static_cast<uint32_t>(int64_t{m_pc} + words * 16);
                m_states += states::kDsjsTaken;
            } else {
                m_states += states::kDsjsNot;
            }
            return;
        }
        default:
            fault(fmt::format("word {:04X}h: not an instruction fb89's GSP executes", w));
    }
}

template <uint16_t Form>
void Tms34010::exec_alu(uint16_t w) {
    const int file = (w >> 4) & 1, rd = w & 15;
    uint32_t& d = rd_of(w);
    const uint32_t s = rs_of(w);
    m_states += states::kRegister;
    switch (Form) {
        case 0x4000:
        case 0x4200: {  // ADD, ADDC
            const uint32_t carry = (Form & 0x0200) && m_c ? 1 : 0;
            const uint64_t sum = uint64_t{d} + s + carry;
            const uint32_t res = static_cast<uint32_t>(sum);
            m_c = (sum >> 32) != 0;
            m_v = (~(d ^ s) & (d ^ res)) >> 31;
            d = res;
            set_nz(res);
            return;
        }
        case 0x4400:
        case 0x4600:
        case 0x4800: {  // SUB, SUBB, CMP
            const uint32_t borrow = Form == 0x4600 && m_c ? 1 : 0;
            const uint64_t take = uint64_t{s} + borrow;
            const uint32_t res = static_cast<uint32_t>(uint64_t{d} - take);
            m_c = uint64_t{d} < take;
            m_v = ((d ^ s) & (d ^ res)) >> 31;
            set_nz(res);
            if (Form != 0x4800) d = res;
            return;
        }
        case 0x4A00:  // BTST Rs,Rd
            m_z = ((d >> (s & 31)) & 1) == 0;
            return;
        case 0x4C00:  // MOVE Rs,Rd
            d = s;
            set_nz(d);
            m_v = false;
            return;
        case 0x4E00: {  // MOVE Rs,Rd across the files: Rs in the R bit's file
            uint32_t& to = r(file ^ 1, rd);
            to = s;
            set_nz(to);
            m_v = false;
            return;
        }
        case 0x5000:
            d &= s;
            m_z = d == 0;
            return;
        case 0x5200:
            d &= ~s;
            m_z = d == 0;
            return;
        case 0x5400:
            d |= s;
            m_z = d == 0;
            return;
        case 0x5600:  // XOR (CLR is XOR Rd,Rd)
            d ^= s;
            m_z = d == 0;
            return;
        case 0x5800:
            divide(w, true, false);
            return;
        case 0x5A00:
            divide(w, false, false);
            return;
        case 0x5C00:
            multiply(w, true);
            return;
        case 0x5E00:
            multiply(w, false);
            return;
        case 0x6000:
        case 0x6200:
        case 0x6400:
        case 0x6600:
        case 0x6800: {  // SLA, SLL, SRA, SRL, RL by Rs: as by K, the count from Rs
            constexpr uint16_t base = 0x2000 + ((Form & 0x0E00) << 1);  // 0x2000 ... 0x3000
            const uint16_t as_k = static_cast<uint16_t>(base | ((s & 31) << 5) | (w & 0x1F));
            m_states -= states::kRegister;
            exec_k<base>(as_k);
            return;
        }
        case 0x6A00: {  // LMO Rs,Rd: the leftmost one's bit number, counted from the left
            m_z = s == 0;
            d = s == 0 ? 0 : static_cast<uint32_t>(std::countl_zero(s));
            return;
        }
        case 0x6C00:
            divide(w, true, true);
            return;
        case 0x6E00:
            divide(w, false, true);
            return;
        default:
            fault(fmt::format("word {:04X}h: not an instruction fb89's GSP executes", w));
    }
}

// MPYS and MPYU Rs,Rd: Rs's low FS1 bits times Rd; an even Rd takes the 64-bit product in
// Rd (high half) and Rd+1, an odd one the low half
void Tms34010::multiply(uint16_t w, bool is_signed) {
    const int file = (w >> 4) & 1, rd = w & 15, rs = (w >> 5) & 15;
    const uint32_t bits = m_fs[1];
    uint32_t s = reg(file, rs);
    if (bits < 32) {
        s &= (1u << bits) - 1;
        if (is_signed) s = (s ^ (1u << (bits - 1))) - (1u << (bits - 1));
    }
    const uint64_t product =
        is_signed ? static_cast<uint64_t>(int64_t{static_cast<int32_t>(reg(file, rd))} *
                                          int64_t{static_cast<int32_t>(s)})
                  : uint64_t{reg(file, rd)} * s;
    m_states += states::kMpyFixed + bits / 2 - states::kRegister;
    if (rd % 2 == 0 && rd < 14) {
        set_reg(file, rd, static_cast<uint32_t>(product >> 32));
        set_reg(file, rd + 1, static_cast<uint32_t>(product));
        m_n = product >> 63;
        m_z = product == 0;
    } else {
        set_reg(file, rd, static_cast<uint32_t>(product));
        set_nz(static_cast<uint32_t>(product));
    }
}

// DIVS/DIVU (quotient) and MODS/MODU (remainder) Rs,Rd: an even Rd of DIVS/DIVU divides the
// 64 bits Rd:Rd+1 and keeps the remainder in Rd+1; overflow (or a zero divisor) sets V and
// leaves the registers
void Tms34010::divide(uint16_t w, bool is_signed, bool modulo) {
    const int file = (w >> 4) & 1, rd = w & 15, rs = (w >> 5) & 15;
    const uint32_t s = reg(file, rs);
    m_states += (is_signed ? states::kDivs : states::kDivu) - states::kRegister;
    if (s == 0) {
        m_v = true;
        return;
    }
    const bool wide = !modulo && rd % 2 == 0 && rd < 14;
    if (is_signed) {
        const int64_t dividend =
            wide ? static_cast<int64_t>((uint64_t{reg(file, rd)} << 32) | reg(file, rd + 1))
                 : int64_t{static_cast<int32_t>(reg(file, rd))};
        const int64_t divisor = static_cast<int32_t>(s);
        if (dividend == INT64_MIN && divisor == -1) {
            m_v = true;
            return;
        }
        const int64_t q = dividend / divisor, rem = dividend % divisor;
        if (!modulo && (q > INT32_MAX || q < INT32_MIN)) {
            m_v = true;
            return;
        }
        m_v = false;
        const uint32_t result = static_cast<uint32_t>(modulo ? rem : q);
        set_reg(file, rd, result);
        if (wide) set_reg(file, rd + 1, static_cast<uint32_t>(rem));
        set_nz(result);
    } else {
        const uint64_t dividend =
            wide ? (uint64_t{reg(file, rd)} << 32) | reg(file, rd + 1) : uint64_t{reg(file, rd)};
        const uint64_t q = dividend / s, rem = dividend % s;
        if (!modulo && q > UINT32_MAX) {
            m_v = true;
            return;
        }
        m_v = false;
        const uint32_t result = static_cast<uint32_t>(modulo ? rem : q);
        set_reg(file, rd, result);
        if (wide) set_reg(file, rd + 1, static_cast<uint32_t>(rem));
        m_z = result == 0;
        if (is_signed) m_n = result >> 31;
    }
}

// The handlers of the 0xxxh words (the immediates and DSJ apart from the rest, as exec_0 once
// told them), the constant forms and the register pairs.
void Tms34010::install_instructions(std::array<Handler, 65536>& table) {
    using std::index_sequence, std::make_index_sequence;
    const auto k = []<std::size_t... I>(index_sequence<I...>) {
        return std::array{&call<&Tms34010::exec_k<static_cast<uint16_t>(0x1000 + 0x400 * I)>>...};
    }
    (make_index_sequence<12>());
    const auto alu = []<std::size_t... I>(index_sequence<I...>) {
        return std::array{&call<&Tms34010::exec_alu<static_cast<uint16_t>(0x4000 + 0x200 * I)>>...};
    }
    (make_index_sequence<24>());
    const auto movi = []<std::size_t... I>(index_sequence<I...>) {  // MOVI IW, IL
        return std::array{
            &call<&Tms34010::exec_immediate<static_cast<uint16_t>(0x09C0 + 0x20 * I)>>...};
    }
    (make_index_sequence<2>());
    const auto immediate = []<std::size_t... I>(index_sequence<I...>) {  // 0B00h-0BE0h
        return std::array{
            &call<&Tms34010::exec_immediate<static_cast<uint16_t>(0x0B00 + 0x20 * I)>>...};
    }
    (make_index_sequence<8>());
    const auto group_0 = []<std::size_t... I>(index_sequence<I...>) {
        return std::array{&call<&Tms34010::exec_0<static_cast<uint16_t>(0x20 * I)>>...};
    }
    (make_index_sequence<128>());
    const auto dsj = []<std::size_t... I>(index_sequence<I...>) {
        return std::array{&call<&Tms34010::exec_dsj<static_cast<uint16_t>(0x0D80 + 0x20 * I)>>...};
    }
    (make_index_sequence<3>());
    for (uint32_t w = 0; w < 0x1000; ++w) {
        const uint32_t form = w & 0xFFE0;
        if ((w & 0xFFC0) == 0x09C0)
            table[w] = movi[(form - 0x09C0) >> 5];
        else if ((w & 0xFF00) == 0x0B00)
            table[w] = immediate[(form - 0x0B00) >> 5];
        else if (form == 0x0D00)  // SUBI IL
            table[w] = &call<&Tms34010::exec_immediate<0x0D00>>;
        else if (form == 0x0D80 || form == 0x0DA0 || form == 0x0DC0)
            table[w] = dsj[(form - 0x0D80) >> 5];
        else
            table[w] = group_0[w >> 5];
    }
    for (uint32_t w = 0x1000; w < 0x4000; ++w)
        table[w] = k[(w - 0x1000) >> 10];
    for (uint32_t w = 0x4000; w < 0x7000; ++w)
        table[w] = alu[(w - 0x4000) >> 9];
}

}  // namespace fb89::controller::gsp
