// The emulated TMS34010's graphics instructions (see gsp_cpu.h): FILL, LINE, PIXT, the XY
// arithmetic and CVXYL, with the B file's graphics registers (SADDR = B0, DADDR = B2,
// DPTCH = B3, OFFSET = B4, WSTART = B5, WEND = B6, DYDX = B7, COLOR1 = B9, COUNT = B10,
// INC1 = B11, INC2 = B12), PSIZE, the window (CONTROL's W: 3 clips to WSTART..WEND) and
// DPYCTL's SRT, with which a pixel read is the VRAMs' memory-to-register cycle (a row into
// the serial registers) and a pixel write a register-to-memory cycle (the serial registers
// into the row). Pixel processing is replace, with no transparency (CONTROL's PPOP and T
// zero); any other is refused. The pixels' memory cycles are the cost model's (GspTiming).
#include "controller_sim/gsp_cpu.h"

#include "controller_sim/gsp_states.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include <fmt/format.h>

namespace fb89::controller::gsp {

namespace {
constexpr int kSaddr = 0, kDaddr = 2, kDptch = 3, kOffset = 4, kWstart = 5, kWend = 6, kDydx = 7,
              kColor1 = 9, kCount = 10, kInc1 = 11, kInc2 = 12;
constexpr int kB = 1;
int32_t x_of(uint32_t xy) {
    return static_cast<int16_t>(xy & 0xFFFF);
}
int32_t y_of(uint32_t xy) {
    return static_cast<int16_t>(xy >> 16);
}
uint32_t xy_of(int32_t x, int32_t y) {
    return (static_cast<uint32_t>(y) << 16) | (static_cast<uint32_t>(x) & 0xFFFF);
}
}  // namespace

uint32_t Tms34010::xy_address(uint32_t xy) const {
    return static_cast<uint32_t>(int64_t{y_of(xy)} * reg(kB, kDptch) +
                                 int64_t{x_of(xy)} * pixel_size() + reg(kB, kOffset));
}

bool Tms34010::in_window(int32_t x, int32_t y) const {
    const uint32_t ws = reg(kB, kWstart), we = reg(kB, kWend);
    return x >= x_of(ws) && x <= x_of(we) && y >= y_of(ws) && y <= y_of(we);
}

void Tms34010::write_pixel(uint32_t address, uint32_t pixel) {
    ++m_count.pixels;
    if (serial_transfer()) {  // register-to-memory: the serial registers into the row
        if (address < kVramStart || address >= kVramStart + kVramBits)
            fault(fmt::format("a serial-register transfer at {:08X}h, outside the VRAM", address));
        const uint32_t row = (address - kVramStart) / kVramRowBitsOnBoard;
        std::memcpy(m_vram + std::size_t{row} * (kVramRowBitsOnBoard / 8), m_shift_register.data(),
                    m_shift_register.size());
        return;
    }
    write_field(address, pixel_size(), pixel);
}

uint32_t Tms34010::read_pixel(uint32_t address) {
    if (serial_transfer()) {  // memory-to-register: the row into the serial registers
        if (address < kVramStart || address >= kVramStart + kVramBits)
            fault(fmt::format("a serial-register transfer at {:08X}h, outside the VRAM", address));
        const uint32_t row = (address - kVramStart) / kVramRowBitsOnBoard;
        std::memcpy(m_shift_register.data(), m_vram + std::size_t{row} * (kVramRowBitsOnBoard / 8),
                    m_shift_register.size());
        return 0;
    }
    return read_field(address, pixel_size());
}

// FILL L (linear: DADDR a bit address) or FILL XY (DADDR y:x, clipped to the window in mode
// 3): DYDX's rows of its width in COLOR1's pixels, DPTCH apart.
void Tms34010::fill(bool xy) {
    const uint16_t control = io(kControl);
    if ((control & 0x7C20) != 0)
        fault("FILL with a pixel processing other than replace, or transparency: not executed");
    pay_queue();
    m_states += xy ? states::kFillXy : states::kFillL;
    const uint32_t daddr = reg(kB, kDaddr), dydx = reg(kB, kDydx);
    int64_t x0 = 0, y0 = 0, w = dydx & 0xFFFF, h = dydx >> 16;
    uint32_t first = daddr;  // the first pixel's address
    const uint32_t psize = pixel_size(), pitch = reg(kB, kDptch);
    if (xy) {
        x0 = x_of(daddr);
        y0 = y_of(daddr);
        const uint32_t mode = window_mode();
        if (mode == 1 || mode == 2) fault("FILL XY in window mode 1 or 2: not executed");
        if (mode == 3) {
            const uint32_t ws = reg(kB, kWstart), we = reg(kB, kWend);
            const int64_t x1 = std::min<int64_t>(x0 + w, int64_t{x_of(we)} + 1);
            const int64_t y1 = std::min<int64_t>(y0 + h, int64_t{y_of(we)} + 1);
            x0 = std::max<int64_t>(x0, x_of(ws));
            y0 = std::max<int64_t>(y0, y_of(ws));
            w = std::max<int64_t>(0, x1 - x0);
            h = std::max<int64_t>(0, y1 - y0);
        }
        first = static_cast<uint32_t>(y0 * pitch + x0 * psize + reg(kB, kOffset));
        set_reg(kB, kDaddr, xy_of(x_of(daddr), y_of(daddr) + static_cast<int32_t>(dydx >> 16)));
    } else {
        set_reg(kB, kDaddr, daddr + (dydx >> 16) * pitch);
    }
    if (w == 0 || h == 0) return;
    const uint32_t colour = reg(kB, kColor1);
    const uint64_t row_bits = uint64_t(w) * psize;
    // the row's words: whole ones a write cycle, partial ones a read and a write
    const auto row_states = [&](uint32_t a) {
        const uint64_t begin = a, end = a + row_bits;
        const uint64_t n = ((end - 1) >> 4) - (begin >> 4) + 1;
        const bool left = begin % 16 != 0, right = end % 16 != 0;
        const uint64_t partial = n == 1 ? ((left || right) ? 1 : 0) : uint64_t{left} + right;
        return m_timing.fill_row + m_timing.fill_word * (n - partial) +
               m_timing.fill_partial_word * partial;
    };
    uint64_t pixel_states = 0;
    for (int64_t row = 0; row < h; ++row) {
        const uint32_t a = static_cast<uint32_t>(first + row * pitch);
        pixel_states += row_states(a);
        if (serial_transfer()) {
            for (int64_t i = 0; i < w; ++i)
                write_pixel(static_cast<uint32_t>(a + i * psize), 0);
            continue;
        }
        m_count.pixels += static_cast<uint64_t>(w);
        if ((psize == 8 || psize == 16) && a % 8 == 0) {
            uint8_t* p = bytes_at(a, static_cast<uint32_t>(row_bits));
            if (!p) fault(fmt::format("FILL at {:08X}h: the board has no memory there", a));
            if (psize == 8) {
                std::memset(p, static_cast<int>(colour & 0xFF), static_cast<std::size_t>(w));
            } else {
                const uint16_t v = static_cast<uint16_t>(colour);
                for (int64_t i = 0; i < w; ++i)
                    std::memcpy(p + 2 * i, &v, 2);
            }
            continue;
        }
        for (int64_t i = 0; i < w; ++i) {
            const uint32_t pa = static_cast<uint32_t>(a + i * psize);
            write_field(pa, psize, colour >> (pa % 16));
        }
    }
    m_states += static_cast<uint32_t>(pixel_states);
    m_count.graphics_states += pixel_states;
}

// LINE 0 or LINE 1: Bresenham's loop on the chip's registers -- COUNT pixels from DADDR (y:x)
// in COLOR1, each then a step of INC1 (diagonal) where the decision variable SADDR is >= 0
// (LINE 0; > 0 for LINE 1), adding 2b - 2a, else of INC2, adding 2b; DYDX is b:a. Clipped
// pixel by pixel to the window in mode 3.
void Tms34010::line(bool greater) {
    const uint16_t control = io(kControl);
    if ((control & 0x7C20) != 0)
        fault("LINE with a pixel processing other than replace, or transparency: not executed");
    pay_queue();
    m_states += states::kLine;
    int32_t d = static_cast<int32_t>(reg(kB, kSaddr));
    uint32_t at = reg(kB, kDaddr);
    const uint32_t dydx = reg(kB, kDydx);
    const int32_t a = static_cast<int32_t>(dydx & 0xFFFF), b = static_cast<int32_t>(dydx >> 16);
    const uint32_t inc1 = reg(kB, kInc1), inc2 = reg(kB, kInc2);
    const uint32_t colour = reg(kB, kColor1);
    const bool clip = window_mode() == 3;
    uint32_t count = reg(kB, kCount) & 0xFFFF;
    uint64_t pixel_states = 0;
    for (; count > 0; --count) {
        const int32_t x = x_of(at), y = y_of(at);
        if (!clip || in_window(x, y)) {
            const uint32_t pa = xy_address(at);
            write_pixel(pa, colour >> (pa % 16));
            pixel_states += m_timing.line_pixel;
        } else {
            pixel_states += m_timing.line_step;  // no memory cycle: the step alone
        }
        const bool diagonal = greater ? d > 0 : d >= 0;
        const uint32_t inc = diagonal ? inc1 : inc2;
        at = xy_of(x + x_of(inc), y + y_of(inc));
        d += diagonal ? 2 * b - 2 * a : 2 * b;
    }
    set_reg(kB, kSaddr, static_cast<uint32_t>(d));
    set_reg(kB, kDaddr, at);
    set_reg(kB, kCount, 0);
    m_states += static_cast<uint32_t>(pixel_states);
    m_count.graphics_states += pixel_states;
}

// ADDXY, SUBXY, CMPXY, CVXYL, MOVX, MOVY
template <uint16_t Form>
void Tms34010::exec_xy(uint16_t w) {
    const int file = (w >> 4) & 1, rd = w & 15, rs = (w >> 5) & 15;
    const uint32_t s = reg(file, rs), d = reg(file, rd);
    switch (Form) {
        case 0xE000: {  // ADDXY: N x = 0, C the sign of y, Z y = 0, V the sign of x
            const int32_t x = static_cast<int16_t>(x_of(d) + x_of(s));
            const int32_t y = static_cast<int16_t>(y_of(d) + y_of(s));
            set_reg(file, rd, xy_of(x, y));
            m_n = x == 0;
            m_c = y < 0;
            m_z = y == 0;
            m_v = x < 0;
            m_states += states::kRegister;
            return;
        }
        case 0xE200:
        case 0xE400: {  // SUBXY, CMPXY: N x = 0, C y borrow, Z y = 0, V x borrow
            const int32_t x = static_cast<int16_t>(x_of(d) - x_of(s));
            const int32_t y = static_cast<int16_t>(y_of(d) - y_of(s));
            m_n = x == 0;
            m_c = y_of(s) > y_of(d);
            m_z = y == 0;
            m_v = x_of(s) > x_of(d);
            if (Form == 0xE200) {
                set_reg(file, rd, xy_of(x, y));
                m_states += states::kRegister;
            } else {
                m_states += states::kCmpxy;
            }
            return;
        }
        case 0xE800:  // CVXYL Rs,Rd
            set_reg(file, rd, xy_address(s));
            m_states += states::kCvxyl;
            return;
        case 0xEC00:  // MOVX
            set_reg(file, rd, (d & 0xFFFF0000u) | (s & 0xFFFF));
            m_states += states::kRegister;
            return;
        case 0xEE00:  // MOVY
            set_reg(file, rd, (d & 0xFFFF) | (s & 0xFFFF0000u));
            m_states += states::kRegister;
            return;
        default:
            fault(fmt::format("word {:04X}h: not an instruction fb89's GSP executes", w));
    }
}

// PIXT: Rs,*Rd  *Rs,Rd  *Rs,*Rd, and the XY forms (with the window in mode 3)
template <uint16_t Form>
void Tms34010::exec_pixt(uint16_t w) {
    const int file = (w >> 4) & 1, rd = w & 15, rs = (w >> 5) & 15;
    const uint32_t s = reg(file, rs), d = reg(file, rd);
    const uint32_t mask = pixel_size() == 32 ? ~0u : (1u << pixel_size()) - 1;
    const auto write = [&](uint32_t address, uint32_t pixel) {
        write_access(states::kPixtWrite, m_timing.pixel_write_states);
        write_pixel(address, pixel & mask);
    };
    const auto read = [&](uint32_t address) {
        read_access(states::kPixtRead, m_timing.cycle_states);
        return read_pixel(address);
    };
    const auto xy_ok = [&](uint32_t xy) {
        return window_mode() != 3 || in_window(x_of(xy), y_of(xy));
    };
    switch (Form) {
        case 0xF800:
            write(d, s);
            return;  // PIXT Rs,*Rd
        case 0xFA00:
            set_reg(file, rd, read(s));
            return;  // PIXT *Rs,Rd
        case 0xFC00:
            write(d, read(s));
            return;   // PIXT *Rs,*Rd
        case 0xF000:  // PIXT Rs,*Rd.XY
            if (xy_ok(d))
                write(xy_address(d), s);
            else
                m_states += states::kPixtWrite.lead + states::kPixtWrite.tail;
            return;
        case 0xF200:
            set_reg(file, rd, read(xy_address(s)));
            return;     // PIXT *Rs.XY,Rd
        case 0xF400: {  // PIXT *Rs.XY,*Rd.XY
            const uint32_t v = read(xy_address(s));
            if (xy_ok(d)) write(xy_address(d), v);
            return;
        }
        case 0xF600:
            fault(fmt::format("word {:04X}h: DRAV is not executed by fb89's GSP", w));
        default:
            fault(fmt::format("word {:04X}h: not an instruction fb89's GSP executes", w));
    }
}

// The handlers of the XY instructions and PIXT.
void Tms34010::install_graphics(std::array<Handler, 65536>& table) {
    using std::index_sequence, std::make_index_sequence;
    const auto xy = []<std::size_t... I>(index_sequence<I...>) {
        return std::array{&call<&Tms34010::exec_xy<static_cast<uint16_t>(0xE000 + 0x200 * I)>>...};
    }
    (make_index_sequence<8>());
    const auto pixt = []<std::size_t... I>(index_sequence<I...>) {
        return std::array{
            &call<&Tms34010::exec_pixt<static_cast<uint16_t>(0xF000 + 0x200 * I)>>...};
    }
    (make_index_sequence<8>());
    for (uint32_t w = 0xE000; w < 0x10000; ++w)
        table[w] = w < 0xF000 ? xy[(w - 0xE000) >> 9] : pixt[(w - 0xF000) >> 9];
}

}  // namespace fb89::controller::gsp
