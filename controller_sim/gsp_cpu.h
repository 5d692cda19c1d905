// An emulated TMS34010 that executes the words the assembler (gsp_assembler.h) makes: the A
// and B register files, the status bits N C Z V and the two fields, the I/O registers the
// executive uses, memory as fb89's board maps it, and the graphics instructions FILL, LINE
// and PIXT with the window and the VRAMs' serial-register transfers. Each instruction costs
// its states from the data sheet's tables (SPVS002C pp. 11-14) as gsp_states.h gives them,
// the memory cycles of its fields, the write queue, and the instruction cache's misses; the
// graphics instructions' pixels cost the memory cycles the cost model gives them
// (docs/COST_MODEL.md, "The GSP as code").
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "controller_sim/gsp_listing.h"
#include "controller_sim/gsp_states.h"

namespace fb89::controller::gsp {

// The board's memory map, in bit addresses (TI's TIGA development board, TDB10/README.1ST
// and OEMPRIMS/CLEARFRM.ASM, with 4 MB of DRAM: tms34010.asm's header).
inline constexpr uint32_t kDramBits = 4u << 23;     // DRAM from address 0
inline constexpr uint32_t kVramStart = 0x10000000;  // VRAM_START
// The TDB's VRAM is 1 MB (the listing's serial-register clear reaches its 512 rows); the
// board maps 2 MB, so that a frame larger than the TDB's (1024 x 780 at 16 bits) has memory
// too, which the listing clears by FILL.
inline constexpr uint32_t kVramBits = 2u << 23;
inline constexpr uint32_t kIoStart = 0xC0000000;        // the I/O registers,
inline constexpr uint32_t kIoBits = 0x200;              // 0C0000000h to 0C00001FFh
inline constexpr uint32_t kVramRowBitsOnBoard = 16384;  // a VRAM row, the serial register

// The I/O registers fb89's executive and board touch (bit addresses; TI's GSPREG.INC).
inline constexpr uint32_t kDpyctl = 0xC0000080;   // display control: SRT is bit 11
inline constexpr uint32_t kControl = 0xC00000B0;  // W (window mode) bits 7-6, T bit 5
inline constexpr uint32_t kHstctll = 0xC00000F0;  // host control, low: the message out
inline constexpr uint32_t kConvdp = 0xC0000140;
inline constexpr uint32_t kPsize = 0xC0000150;

// A 16-bit word's value, sign-extended.
inline int32_t sext16(uint32_t v) {
    return static_cast<int16_t>(static_cast<uint16_t>(v));
}

// Something the program did that the chip or the board cannot: an illegal word, a jump
// out of the code, memory the board has not, an instruction budget spent. Names the address
// (and the caller names the listing's line).
class GspFault : public std::runtime_error {
  public:
    GspFault(uint32_t pc, const std::string& what);
    uint32_t pc() const { return m_pc; }

  private:
    uint32_t m_pc;
};

// What the memory costs and what a graphics instruction's pixels cost, from the profile.
struct GspTiming {
    uint32_t cycle_states = 2;        // a local-memory cycle, wait states included
    uint32_t io_cycle_states = 2;     // an I/O register's cycle
    uint32_t pixel_write_states = 4;  // PIXT's pixel write
    // FILL: each row, each whole word, each partial word (a read and a write)
    uint32_t fill_row = 0, fill_word = 0, fill_partial_word = 0;
    uint32_t line_pixel = 0;  // LINE: each pixel
    uint32_t line_step = 0;   // and each pixel the window refuses: its step, no memory cycle
    bool cache = true;        // model the instruction cache (off: every fetch hits)
};

// Counted as the program runs.
struct GspCounters {
    uint64_t instructions = 0;
    uint64_t states = 0;                // all of it: instructions, memory, pixels, misses
    uint64_t warm_states = 0;           // the same with every fetch a hit (the model's clock)
    uint64_t graphics_states = 0;       // of which the graphics instructions' pixels
    uint64_t cache_misses = 0;          // instruction-cache sub-segments fetched
    uint64_t cache_miss_states = 0;     // of which what they cost
    uint64_t pixels = 0;                // pixels written by FILL, LINE and PIXT
    uint64_t queue_overlap_states = 0;  // on the warm clock, a queued write run beside work
};

class Tms34010 {
  public:
    explicit Tms34010(const GspTiming& timing);
    Tms34010(const Tms34010&) = delete;  // (m_vram points into its own storage)
    Tms34010& operator=(const Tms34010&) = delete;

    // Memory, by bit address; a field of 1 to 32 bits at any bit address. Throws GspFault
    // for an address the board does not decode.
    // (always inlined, as memory_read and memory_write are: the compiler would call them from
    // each MOVE, and a field's access is the emulator's commonest after a fetch)
    [[gnu::always_inline]] uint32_t read_field(uint32_t address, uint32_t bits) const {
        if (const uint8_t* p = field_bytes(address, bits)) [[likely]]
            return load_field(p, address & 7, bits);
        return read_field_slow(address, bits);
    }
    [[gnu::always_inline]] void write_field(uint32_t address, uint32_t bits, uint32_t value) {
        if (const uint8_t* p = field_bytes(address, bits)) [[likely]]
            return store_field(const_cast<uint8_t*>(p), address & 7, bits, value);
        write_field_slow(address, bits, value);
    }
    // Loads 16-bit words at `address` (a word boundary), as the host port writes them.
    void load_words(uint32_t address, std::span<const uint16_t> words);
    // The VRAM's bytes (a byte is 8 bits from a bit address that is a multiple of 8).
    std::span<const uint8_t> vram() const { return {m_vram, kVramBits / 8}; }
    std::span<const uint8_t> dram() const { return {m_dram.data(), kDramBits / 8}; }

    // Registers: file 0 is A, 1 is B; n 15 is SP in both.
    uint32_t reg(int file, int n) const { return m_regs[reg_index(file, n)]; }
    void set_reg(int file, int n, uint32_t v) { m_regs[reg_index(file, n)] = v; }
    uint32_t pc() const { return m_pc; }
    void set_pc(uint32_t pc) { m_pc = pc; }
    uint32_t status() const;
    void set_status(uint32_t st);
    // SETF size, extension, field
    void set_field(int field, uint32_t size, bool sign_extend);
    uint16_t io(uint32_t address) const { return m_io[(address - kIoStart) >> 4]; }
    void set_io(uint32_t address, uint16_t v) { write_io(address, v); }

    // Executes one instruction; returns its states.
    uint32_t step();
    // Executes one instruction, then more until the PC is `stop` or `most` have run; returns
    // how many ran. Counts and states as step() each; the board's loop between its checks.
    uint64_t run_until(uint32_t stop, uint64_t most);
    // Executes until `stop` says so after an instruction, or `budget` instructions have run
    // (then GspFault).
    void run(const std::function<bool()>& stop, uint64_t budget);

    const GspCounters& counters() const { return m_count; }
    void reset_counters() { m_count = {}; }
    // The states the write queue still holds (paid by the next memory access), on the
    // clock with the cache and on the warm one.
    uint32_t queued_states() const { return m_queued; }
    uint32_t warm_queued_states() const { return m_warm_queued; }
    // Whether the last instruction touched memory (and so waited for the queue).
    bool touched_memory() const { return (m_events & kTouched) != 0; }
    // A message the executive sent the host through HSTCTLL since the last take (0: none).
    uint16_t take_host_message() {
        const uint16_t m = m_message;
        m_message = 0;
        return m;
    }

  private:
    // The instruction groups' handlers, one for each 16-bit word (gsp_dispatch.cpp): a word
    // is decoded once, when the table is built, into the function for its form.
    using Handler = void (*)(Tms34010&, uint16_t);
    static const std::array<Handler, 65536>& handlers();
    template <auto Member>
    static void call(Tms34010& cpu, uint16_t w) {
        (cpu.*Member)(w);
    }
    static void install_instructions(std::array<Handler, 65536>& table);
    static void install_graphics(std::array<Handler, 65536>& table);
    static void install_moves(std::array<Handler, 65536>& table);

    // The registers lie in one array, A0-A14, SP, B0-B14 (and a slot unused), so that a
    // word's file bit and register number index it: bits 4-0 are file * 16 + Rd.
    static unsigned reg_index(int file, int n) {
        return n == 15 ? 15u : static_cast<unsigned>(file * 16 + n);
    }
    uint32_t& r(int file, int n) { return m_regs[reg_index(file, n)]; }
    uint32_t& sp() { return m_regs[15]; }
    uint32_t& rd_of(uint16_t w) {  // file bit 4, Rd bits 3-0
        const unsigned i = w & 0x1Fu;
        return m_regs[i == 31 ? 15 : i];
    }
    uint32_t rs_of(uint16_t w) const {  // file bit 4, Rs bits 8-5
        const unsigned i = (w & 0x10u) | ((w >> 5) & 15u);
        return m_regs[i == 31 ? 15 : i];
    }

    [[gnu::always_inline]] uint16_t fetch() {
        if ((m_pc & 15) != 0 || m_pc >= kDramBits) [[unlikely]]
            fetch_fault();
        // the cache is looked at once a sub-segment: a fetch from the one the last came
        // from hits
        if ((m_pc >> 6) != m_last_sub && m_timing.cache) {
            // a hit in the segment last found, as cache_fetch() would count it
            Segment& s = m_cache[m_last_segment];
            if (s.tag == m_pc >> 9 && (s.present & (1u << ((m_pc >> 6) & 7))) != 0)
                s.used = ++m_use;
            else
                cache_fetch(m_pc);
            m_last_sub = m_pc >> 6;
        }
        uint16_t w;
        std::memcpy(&w, m_dram.data() + m_pc / 8, 2);
        m_pc += 16;
        return w;
    }
    [[gnu::always_inline]] uint32_t fetch_long() {
        const uint32_t lo = fetch();
        return lo | (uint32_t{fetch()} << 16);
    }
    void cache_fetch(uint32_t address);
    [[noreturn]] void fetch_fault() const;
    [[noreturn]] void fault(const std::string& what) const;

    // memory
    uint8_t* bytes_at(uint32_t address, uint32_t bits);
    const uint8_t* bytes_at(uint32_t address, uint32_t bits) const;
    // The byte holding a field's first bit, in the DRAM or the VRAM (null in neither). Their
    // storage runs at least 8 bytes past its end, so that a field of up to 32 bits at any
    // offset is one 8-byte load (and store) from there.
    const uint8_t* field_bytes(uint32_t address, uint32_t bits) const {
        if (uint64_t{address} + bits <= kDramBits) [[likely]]
            return m_dram.data() + address / 8;
        if (address >= kVramStart && uint64_t{address} + bits <= uint64_t{kVramStart} + kVramBits)
            return m_vram + (address - kVramStart) / 8;
        return nullptr;
    }
    static uint32_t load_field(const uint8_t* p, uint32_t offset, uint32_t bits) {
        uint64_t v;
        std::memcpy(&v, p, 8);
        return static_cast<uint32_t>((v >> offset) & (~0ull >> (64 - bits)));
    }
    static void store_field(uint8_t* p, uint32_t offset, uint32_t bits, uint32_t value) {
        uint64_t v;
        std::memcpy(&v, p, 8);
        const uint64_t mask = (~0ull >> (64 - bits)) << offset;
        v = (v & ~mask) | ((uint64_t{value} << offset) & mask);
        std::memcpy(p, &v, 8);
    }
    uint32_t read_field_slow(uint32_t address, uint32_t bits) const;
    void write_field_slow(uint32_t address, uint32_t bits, uint32_t value);
    void write_io(uint32_t address, uint16_t v);
    // A MOVE's read and write, states counted by the form's access (gsp_states.h)
    [[gnu::always_inline]] uint32_t memory_read(uint32_t address, int field, states::Access form) {
        const uint32_t bits = m_fs[field];
        const uint32_t words = (address % 16 + bits + 15) / 16;
        read_access(form, words * cycle_states(address));
        return extend(read_field(address, bits), field);
    }
    [[gnu::always_inline]] void memory_write(uint32_t address, int field, uint32_t value,
                                             states::Access form) {
        const uint32_t bits = m_fs[field];
        const uint32_t words = (address % 16 + bits + 15) / 16;
        write_access(form, words * cycle_states(address));
        write_field(address, bits, value);
    }
    uint32_t extend(uint32_t v, int field) const {
        const uint32_t bits = m_fs[field];
        if (bits == 32 || !m_fe[field]) return v;
        const uint32_t sign = 1u << (bits - 1);
        return (v ^ sign) - sign;
    }
    // A memory access waits for the queued write; an instruction that touches no memory
    // runs beside it (SPVS002C p. 10), and GSPSIM shows the same ("write 16, NOP, read 16"
    // takes the read's 4 states and the write's 2 only). The wait is settled at the end of
    // the instruction (finish()), on two clocks: the cache's and a warm one.
    void pay_queue() { m_events |= kTouched; }
    // the same, for an access whose first `beside` states run beside the queued write (the
    // instruction's first access says)
    void access(states::Access form) {
        if (!(m_events & kTouched)) m_beside = form.beside;
        m_events |= kTouched;
    }
    // a read's states, its cycles in them; a write's, its cycles queued less its tail
    void read_access(states::Access form, uint32_t cycles) {
        access(form);
        m_states += form.lead + cycles + form.tail;
    }
    void write_access(states::Access form, uint32_t cycles) {
        access(form);
        m_states += form.lead + form.tail;
        queue_write(cycles - std::min(cycles, form.tail));
    }
    void queue_write(uint32_t states) {
        m_new_queue = states;
        m_events |= kWrote;
    }
    // This instruction's states on both clocks from its own (m_states), the queue and the
    // cache's misses; returns the states with the cache.
    uint32_t finish();
    void run_beside_queue(uint32_t own);
    uint32_t execute_one();  // step(), inlined in the loops
    uint32_t cycle_states(uint32_t address) const {
        return address >= kIoStart ? m_timing.io_cycle_states : m_timing.cycle_states;
    }

    // the instruction groups
    // the instruction groups; a template's Form is the bits of the word that name its
    // instruction (the installers in each file give each word its form's handler)
    template <uint16_t Form>
    void exec_0(uint16_t w);  // the 0xxxh words but the immediates and DSJ; Form: w & FFE0h
    template <uint16_t Form>
    void exec_immediate(uint16_t w);  // Form: w & FFE0h
    template <uint16_t Form>
    void exec_dsj(uint16_t w);  // DSJ, DSJEQ, DSJNE; Form: w & FFE0h
    template <uint16_t Form>
    void exec_k(uint16_t w);  // Form: w & FC00h
    template <uint16_t Form>
    void exec_alu(uint16_t w);  // Form: w & FE00h
    template <uint16_t Form>
    void exec_move(uint16_t w);  // Form: w & FC00h
    template <int Cc, int Kind>
    void exec_jump(uint16_t w);  // Kind: 0 short, 1 long (JRcc), 2 absolute (JAcc)
    void exec_d(uint16_t w);     // LINE
    void exec_undefined(uint16_t w);
    template <uint16_t Form>
    void exec_xy(uint16_t w);  // Form: w & FE00h
    template <uint16_t Form>
    void exec_pixt(uint16_t w);  // Form: w & FE00h
    void multiply(uint16_t w, bool is_signed);
    void divide(uint16_t w, bool is_signed, bool modulo);
    bool condition(int cc) const;
    void set_nz(uint32_t v) {
        m_n = (v >> 31) != 0;
        m_z = v == 0;
    }

    // graphics (gsp_graphics.cpp)
    void fill(bool xy);
    void line(bool greater);
    void write_pixel(uint32_t address, uint32_t pixel);
    uint32_t read_pixel(uint32_t address);
    uint32_t xy_address(uint32_t xy) const;
    bool in_window(int32_t x, int32_t y) const;
    uint32_t pixel_size() const { return m_io[(kPsize - kIoStart) >> 4]; }
    bool serial_transfer() const { return (m_io[(kDpyctl - kIoStart) >> 4] & 0x0800) != 0; }
    uint32_t window_mode() const { return (m_io[(kControl - kIoStart) >> 4] >> 6) & 3; }

    GspTiming m_timing;
    std::array<uint32_t, 32> m_regs{};  // (reg_index)
    uint32_t m_pc = 0, m_instruction_pc = 0;
    const Handler* m_handlers;
    bool m_n = false, m_c = false, m_z = false, m_v = false, m_ie = false;
    uint32_t m_fs[2] = {32, 32};
    bool m_fe[2] = {false, false};
    uint32_t m_states = 0;       // this instruction's own, before the queue and the cache
    uint32_t m_beside = 0;       // of them, those before its first access, beside the queue
    uint32_t m_queued = 0;       // the write queue's states, not yet paid
    uint32_t m_warm_queued = 0;  // the same on the warm clock
    uint32_t m_new_queue = 0;    // this instruction's write
    // what this instruction did besides its own states, in one word so that the commonest
    // case, none of it, is one test: whether it touched memory (and so waited for the queue),
    // whether it wrote, and its cache misses (from bit 8)
    static constexpr uint32_t kTouched = 1, kWrote = 2, kMiss = 1u << 8;
    uint32_t m_events = 0;
    std::vector<uint8_t> m_dram;
    // the VRAM, placed a little past a page boundary in its storage: a depth word in DRAM and
    // its pixel in VRAM at the same offset from their pages would alias in the host's store
    // buffer (4K aliasing) and halve the emulator's speed
    std::vector<uint8_t> m_vram_storage;
    uint8_t* m_vram = nullptr;
    std::array<uint16_t, kIoBits / 16> m_io{};
    std::vector<uint8_t> m_shift_register;  // the VRAMs' serial registers, one row
    uint16_t m_message = 0;
    // the instruction cache: four segments of eight sub-segments of four words (SPVS002C
    // p. 2), least recently used replaced
    struct Segment {
        uint32_t tag = ~0u;
        uint8_t present = 0;  // one bit a sub-segment
        uint64_t used = 0;
    };
    std::array<Segment, 4> m_cache{};
    uint32_t m_last_sub = ~0u;    // the sub-segment the last fetch came from
    uint32_t m_last_segment = 0;  // and the segment it was found in
    uint64_t m_use = 0;
    GspCounters m_count;
};

}  // namespace fb89::controller::gsp
