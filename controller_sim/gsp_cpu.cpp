// The emulated TMS34010's instructions (see gsp_cpu.h). Decoding follows the encodings the
// assembler writes (gsp_opcodes.h, gsp_assembler.cpp; TI's GSPA held to them word for word):
// Rs in bits 8-5, the file in bit 4, Rd in bits 3-0, the field in bit 9. Semantics are the
// User's Guide's instruction pages (SPVU001A ch. 12) as the data sheet summarises them:
// status bits N (bit 31), C (30), Z (29), V (28); a subtraction's C is its borrow; a right
// shift's count is kept as its two's complement. States: gsp_states.h.
#include "controller_sim/gsp_cpu.h"

#include "controller_sim/gsp_states.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace fb89::controller::gsp {

GspFault::GspFault(uint32_t pc, const std::string& what)
    : std::runtime_error(fmt::format("GSP at {:08X}h: {}", pc, what)), m_pc(pc) {}

Tms34010::Tms34010(const GspTiming& timing)
    : m_timing(timing),
      m_handlers(handlers().data()),
      m_dram(kDramBits / 8 + 8),  // (field_bytes)
      m_vram_storage(kVramBits / 8 + 4096),
      m_shift_register(kVramRowBitsOnBoard / 8) {
    m_io[(kPsize - kIoStart) >> 4] = 8;
    m_vram = m_vram_storage.data() + 2112;
}

void Tms34010::fault(const std::string& what) const {
    throw GspFault(m_instruction_pc, what);
}

uint32_t Tms34010::status() const {
    return (uint32_t{m_n} << 31) | (uint32_t{m_c} << 30) | (uint32_t{m_z} << 29) |
           (uint32_t{m_v} << 28) | (uint32_t{m_ie} << 21) | (uint32_t{m_fe[1]} << 11) |
           ((m_fs[1] & 31) << 6) | (uint32_t{m_fe[0]} << 5) | (m_fs[0] & 31);
}

void Tms34010::set_status(uint32_t st) {
    m_n = (st >> 31) & 1;
    m_c = (st >> 30) & 1;
    m_z = (st >> 29) & 1;
    m_v = (st >> 28) & 1;
    m_ie = (st >> 21) & 1;
    m_fe[1] = (st >> 11) & 1;
    m_fs[1] = (st >> 6) & 31 ? (st >> 6) & 31 : 32;
    m_fe[0] = (st >> 5) & 1;
    m_fs[0] = st & 31 ? st & 31 : 32;
}

void Tms34010::set_field(int field, uint32_t size, bool sign_extend) {
    m_fs[field] = size;
    m_fe[field] = sign_extend;
}

// --- memory ------------------------------------------------------------------------------

const uint8_t* Tms34010::bytes_at(uint32_t address, uint32_t bits) const {
    const uint64_t end = uint64_t{address} + bits;
    if (end <= kDramBits) return m_dram.data() + address / 8;
    if (address >= kVramStart && end <= uint64_t{kVramStart} + kVramBits)
        return m_vram + (address - kVramStart) / 8;
    return nullptr;
}

uint8_t* Tms34010::bytes_at(uint32_t address, uint32_t bits) {
    return const_cast<uint8_t*>(std::as_const(*this).bytes_at(address, bits));
}

// Fields outside the DRAM and the VRAM: the I/O registers, and the faults.
uint32_t Tms34010::read_field_slow(uint32_t address, uint32_t bits) const {
    if (address >= kIoStart && address < kIoStart + kIoBits) {
        if (address % 16 != 0 || (bits != 16 && bits != 32))
            throw GspFault(m_instruction_pc,
                           fmt::format("an I/O register at {:08X}h read as a {}-bit field "
                                       "(fb89's board reads them as words)",
                                       address, bits));
        uint32_t v = io(address);
        if (bits == 32 && address + 16 < kIoStart + kIoBits) v |= uint32_t{io(address + 16)} << 16;
        return v;
    }
    if (address % 16 == 0 && (bits == 16 || bits == 32)) {  // a word or two: the common case
        const uint8_t* w = bytes_at(address, bits);
        if (w) {
            uint32_t v = 0;
            if (bits == 16) {
                uint16_t h;
                std::memcpy(&h, w, 2);
                v = h;
            } else {
                std::memcpy(&v, w, 4);
            }
            return v;
        }
    }
    // a field of up to 32 bits at any bit offset lies within 5 bytes
    const uint32_t offset = address & 7;
    const uint8_t* p = bytes_at(address - offset, offset + bits);
    if (!p)
        throw GspFault(m_instruction_pc,
                       fmt::format("a read at {:08X}h: the board has no memory there", address));
    uint64_t v = 0;
    std::memcpy(&v, p, (offset + bits + 7) / 8);
    v >>= offset;
    return bits == 32 ? static_cast<uint32_t>(v) : static_cast<uint32_t>(v & ((1u << bits) - 1));
}

void Tms34010::write_field_slow(uint32_t address, uint32_t bits, uint32_t value) {
    if (address >= kIoStart && address < kIoStart + kIoBits) {
        if (address % 16 != 0 || (bits != 16 && bits != 32))
            fault(
                fmt::format("an I/O register at {:08X}h written as a {}-bit field", address, bits));
        write_io(address, static_cast<uint16_t>(value));
        if (bits == 32 && address + 16 < kIoStart + kIoBits)
            write_io(address + 16, static_cast<uint16_t>(value >> 16));
        return;
    }
    if (address % 16 == 0 && (bits == 16 || bits == 32)) {  // a word or two
        if (uint8_t* w = bytes_at(address, bits)) {
            if (bits == 16) {
                const auto h = static_cast<uint16_t>(value);
                std::memcpy(w, &h, 2);
            } else {
                std::memcpy(w, &value, 4);
            }
            return;
        }
    }
    const uint32_t offset = address & 7;
    uint8_t* p = bytes_at(address - offset, offset + bits);
    if (!p) fault(fmt::format("a write at {:08X}h: the board has no memory there", address));
    const uint32_t n = (offset + bits + 7) / 8;
    uint64_t v = 0;
    std::memcpy(&v, p, n);
    const uint64_t mask = ((bits == 32 ? 0xFFFFFFFFull : (1ull << bits) - 1)) << offset;
    v = (v & ~mask) | ((uint64_t{value} << offset) & mask);
    std::memcpy(p, &v, n);
}

void Tms34010::load_words(uint32_t address, std::span<const uint16_t> words) {
    uint8_t* p = bytes_at(address, static_cast<uint32_t>(words.size() * 16));
    if (!p || address % 16 != 0)
        throw GspFault(address, fmt::format("the host wrote {} words at {:08X}h: no memory there",
                                            words.size(), address));
    std::memcpy(p, words.data(), words.size() * 2);
}

void Tms34010::write_io(uint32_t address, uint16_t v) {
    const uint32_t index = (address - kIoStart) >> 4;
    if (address == kPsize && v != 1 && v != 2 && v != 4 && v != 8 && v != 16)
        fault(fmt::format("PSIZE set to {}: a pixel is 1, 2, 4, 8 or 16 bits", v));
    if (address == kHstctll) m_message = v;
    m_io[index] = v;
}

// --- fetch and the instruction cache ------------------------------------------------------

void Tms34010::cache_fetch(uint32_t address) {
    const uint32_t tag = address >> 9;                        // 32 words a segment
    const uint8_t bit = uint8_t(1u << ((address >> 6) & 7));  // 4 words a sub-segment
    // a segment's tag is in no other, so that the one last looked at, if its tag is this,
    // is the one the search would find
    Segment* hit = &m_cache[m_last_segment];
    if (hit->tag != tag) {
        hit = nullptr;
        for (Segment& s : m_cache)
            if (s.tag == tag) hit = &s;
        if (!hit) {
            hit = &m_cache[0];
            for (Segment& s : m_cache)
                if (s.used < hit->used) hit = &s;
            hit->tag = tag;
            hit->present = 0;
        }
        m_last_segment = static_cast<uint32_t>(hit - m_cache.data());
    }
    hit->used = ++m_use;
    if (hit->present & bit) return;
    hit->present |= bit;
    // a miss fetches the sub-segment's four words, after the write queue (finish())
    m_events += kMiss;
}

void Tms34010::fetch_fault() const {
    // (the instruction's address is m_instruction_pc, the fetch's m_pc)
    fault(fmt::format("an instruction fetched from {:08X}h, outside the code", m_pc));
}

// --- execution ----------------------------------------------------------------------------

// (always inlined: step() and the loops share it, and a call per instruction costs)
// An instruction of `own` states that touches no memory runs beside the queued write, on
// both clocks: what it overlaps is taken off the queue.
[[gnu::always_inline]] inline void Tms34010::run_beside_queue(uint32_t own) {
    const uint32_t overlap = std::min(m_warm_queued, own);
    m_warm_queued -= overlap;
    m_count.queue_overlap_states += overlap;
    m_queued -= std::min(m_queued, own);
}

[[gnu::always_inline]] inline uint32_t Tms34010::execute_one() {
    m_instruction_pc = m_pc;
    m_states = 0;
    m_events = 0;
    const uint16_t w = fetch();
    m_handlers[w](*this, w);
    if (m_events != 0) return finish();
    // most instructions: the same on both clocks, and beside the queued write, if any (as
    // finish() would settle them)
    const uint32_t own = m_states;
    if ((m_warm_queued | m_queued) != 0) run_beside_queue(own);
    ++m_count.instructions;
    m_count.states += own;
    m_count.warm_states += own;
    return own;
}

uint32_t Tms34010::step() {
    return execute_one();
}

uint32_t Tms34010::finish() {
    const uint32_t own = m_states;
    const bool touched = (m_events & kTouched) != 0, wrote = (m_events & kWrote) != 0;
    const uint32_t misses = m_events / kMiss;
    // the warm clock: every fetch a hit
    // (its first access's lead runs `beside` states beside the queued write, then waits)
    uint32_t warm = own;
    if (touched) {
        const uint32_t overlap = std::min(m_warm_queued, m_beside);
        m_count.queue_overlap_states += overlap;
        warm += m_warm_queued - overlap;
        m_warm_queued = 0;
    }
    // the cache's: a miss fills its sub-segment after the queued write, four memory cycles
    // and a state (TI's GSPSIM 1.04: 9 states a miss at 2 a cycle)
    uint32_t cold = own;
    if (misses) {
        const uint32_t fill = misses * (4 * m_timing.cycle_states + 1);
        cold += m_queued + fill;
        m_queued = 0;
        m_count.cache_misses += misses;
        m_count.cache_miss_states += fill;
    }
    if (touched) {
        cold += m_queued - std::min(m_queued, m_beside);
        m_queued = 0;
        m_beside = 0;
    }
    if (wrote) {
        m_queued = m_new_queue;
        m_warm_queued = m_new_queue;
    } else if (!touched) {
        run_beside_queue(own);
    }
    ++m_count.instructions;
    m_count.states += cold;
    m_count.warm_states += warm;
    return cold;
}

uint64_t Tms34010::run_until(uint32_t stop, uint64_t most) {
    uint64_t n = 0;
    do {
        execute_one();
    } while (++n < most && m_pc != stop);
    return n;
}

void Tms34010::exec_d(uint16_t w) {
    if (w == 0xDF1A || w == 0xDF9A) {
        line(w == 0xDF9A);
        return;
    }
    fault(fmt::format("word {:04X}h: not an instruction fb89's GSP executes", w));
}

void Tms34010::exec_undefined(uint16_t w) {
    fault(fmt::format("word {:04X}h: not a TMS34010 instruction", w));
}

const std::array<Tms34010::Handler, 65536>& Tms34010::handlers() {
    static const std::array<Handler, 65536> table = [] {
        std::array<Handler, 65536> t;
        t.fill(&call<&Tms34010::exec_undefined>);
        install_instructions(t);
        install_moves(t);
        install_graphics(t);
        return t;
    }();
    return table;
}

void Tms34010::run(const std::function<bool()>& stop, uint64_t budget) {
    for (uint64_t i = 0; i < budget; ++i) {
        execute_one();
        if (stop()) return;
    }
    throw GspFault(m_pc, fmt::format("{} instructions without finishing: a loop that does not "
                                     "end?",
                                     budget));
}

bool Tms34010::condition(int cc) const {
    switch (cc) {
        case 0x0:
            return true;
        case 0x1:
            return !m_n && !m_z;  // P
        case 0x2:
            return m_c || m_z;  // LS
        case 0x3:
            return !m_c && !m_z;  // HI
        case 0x4:
            return m_n != m_v;  // LT
        case 0x5:
            return m_n == m_v;  // GE
        case 0x6:
            return m_n != m_v || m_z;  // LE
        case 0x7:
            return m_n == m_v && !m_z;  // GT
        case 0x8:
            return m_c;  // C, LO
        case 0x9:
            return !m_c;  // NC, HS
        case 0xA:
            return m_z;  // EQ
        case 0xB:
            return !m_z;  // NE
        case 0xC:
            return m_v;  // V
        case 0xD:
            return !m_v;  // NV
        case 0xE:
            return m_n;  // N
        default:
            return !m_n;  // NN
    }
}

// The MOVEs through a register: *Rd, *Rd+, -*Rd, *Rd(displacement), to, from and between
template <uint16_t Form>
void Tms34010::exec_move(uint16_t w) {
    const int file = (w >> 4) & 1, rd = w & 15, rs = (w >> 5) & 15;
    const int field = (w >> 9) & 1;
    const uint32_t bits = m_fs[field];
    constexpr uint32_t kind = (Form >> 10) & 3;  // 0: Rs to memory, 1: memory to Rd, 2: both
    constexpr uint32_t mode = Form >> 12;        // 8 *R, 9 *R+, A -*R, B *R(disp)
    if constexpr (kind == 3)
        fault(fmt::format("word {:04X}h: MOVB is not executed by fb89's GSP", w));
    constexpr states::Access read_form = mode == 0x8   ? states::kReadIndirect
                                         : mode == 0x9 ? states::kReadPostIncrement
                                         : mode == 0xA ? states::kReadPreDecrement
                                                       : states::kReadDisplacement;
    constexpr states::Access write_form = mode == 0x8 || mode == 0x9 ? states::kWriteIndirect
                                          : mode == 0xA              ? states::kWritePreDecrement
                                                                     : states::kWriteDisplacement;
    const auto address = [&](int n, int32_t disp) -> uint32_t {
        uint32_t& p = r(file, n);
        switch (mode) {
            case 0x8:
                return p;
            case 0x9: {
                const uint32_t a = p;
                p += bits;
                return a;
            }
            case 0xA:
                p -= bits;
                return p;
            default:
                return static_cast<uint32_t>(int64_t{p} + disp);
        }
    };
    if constexpr (kind == 0) {
        const int32_t disp = mode == 0xB ? sext16(fetch()) : 0;
        const uint32_t v = reg(file, rs);
        memory_write(address(rd, disp), field, v, write_form);
    } else if constexpr (kind == 1) {
        const int32_t disp = mode == 0xB ? sext16(fetch()) : 0;
        const uint32_t v = memory_read(address(rs, disp), field, read_form);
        r(file, rd) = v;
        set_nz(v);
        m_v = false;
    } else {
        const int32_t ds = mode == 0xB ? sext16(fetch()) : 0;
        const int32_t dd = mode == 0xB ? sext16(fetch()) : 0;
        const uint32_t v = memory_read(address(rs, ds), field, read_form);
        memory_write(address(rd, dd), field, v, write_form);
    }
}

template <int Cc, int Kind>
void Tms34010::exec_jump(uint16_t w) {
    constexpr int cc = Cc;
    const uint8_t disp = static_cast<uint8_t>(w & 0xFF);
    if constexpr (Kind == 2) {  // JAcc address
        const uint32_t to = fetch_long();
        const bool go = condition(cc);
        if (go) m_pc = to & ~15u;
        m_states += go ? states::kJumpAbsTaken : states::kJumpAbsNot;
        return;
    }
    if constexpr (Kind == 1) {  // JRcc long
        const int32_t words = sext16(fetch());
        const bool go = condition(cc);
        if (go) m_pc = static_cast<uint32_t>(int64_t{m_pc} + int64_t{words} * 16);
        m_states += go ? states::kJumpLongTaken : states::kJumpLongNot;
        return;
    }
    const bool go = condition(cc);
    if (go) m_pc = static_cast<uint32_t>(int64_t{m_pc} + int64_t{static_cast<int8_t>(disp)} * 16);
    m_states += go ? states::kJumpShortTaken : states::kJumpShortNot;
}

// The handlers of the MOVEs through a register, the jumps (a condition's test decided when
// the table is built) and the 7xxxh and Dxxxh words.
void Tms34010::install_moves(std::array<Handler, 65536>& table) {
    using std::index_sequence, std::make_index_sequence;
    const auto move = []<std::size_t... I>(index_sequence<I...>) {
        return std::array{
            &call<&Tms34010::exec_move<static_cast<uint16_t>(0x8000 + 0x400 * I)>>...};
    }
    (make_index_sequence<16>());
    const auto jump = []<int Kind, std::size_t... I>(index_sequence<I...>) {
        return std::array{&call<&Tms34010::exec_jump<static_cast<int>(I), Kind>>...};
    };
    const auto short_jump = jump.operator()<0>(make_index_sequence<16>());
    const auto long_jump = jump.operator()<1>(make_index_sequence<16>());
    const auto absolute = jump.operator()<2>(make_index_sequence<16>());
    for (uint32_t w = 0x8000; w < 0xC000; ++w)
        table[w] = move[(w - 0x8000) >> 10];
    for (uint32_t w = 0xC000; w < 0xD000; ++w) {
        const uint32_t cc = (w >> 8) & 15, disp = w & 0xFF;
        table[w] = disp == 0x80 ? absolute[cc] : disp == 0 ? long_jump[cc] : short_jump[cc];
    }
    for (uint32_t w = 0xD000; w < 0xE000; ++w)
        table[w] = &call<&Tms34010::exec_d>;
}

}  // namespace fb89::controller::gsp
