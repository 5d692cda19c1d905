// The controller's cost model: cycles per command and the bus/controller pipeline.
//
// Pure functions of a CostProfile and of the clipped geometry. The formulas follow MAME's
// TMS34010 fill() (34010gfx.hxx): a set-up charge, then per row the 16-bit words touched
// (full words plus partial end words) times the cost of one word. docs/COST_MODEL.md gives
// every parameter, its source and the check values the tests verify.
#pragma once

#include <cstdint>

#include "controller_sim/framebuffer.h"
#include "controller_sim/profile.h"

namespace fb89::controller {

// 16-bit words touched by pixels x .. x+w-1 at P pixels per word (w >= 1):
// floor((x+w-1)/P) - floor(x/P) + 1.
uint64_t words(uint64_t x, uint64_t w, uint32_t pixels_per_word);

// FILL_RECT of the clipped rectangle r: C_cmd + C_setup + h * (C_row + C_op * words(x, w)).
uint64_t fill_rect_cycles(const CostProfile& p, const PixelRect& r);
// DRAW_SPAN of n pixels starting at x (clipped, n >= 1): as a line,
// C_cmd + C_line_setup + C_line_pix * n; as a fill, FILL_RECT with h = 1.
uint64_t draw_span_cycles(const CostProfile& p, uint32_t x, uint32_t n);
// FRAME_BEGIN: the clear, charged as one full-screen FILL_RECT; C_cmd alone for a 0-pixel frame.
uint64_t frame_begin_cycles(const CostProfile& p, uint32_t width, uint32_t height);
// A drawing command with nothing inside the framebuffer, and FRAME_END: fetch and decode only.
inline uint64_t command_only_cycles(const CostProfile& p) {
    return p.c_cmd;
}

// The formulas above, for the controller's per-command path: the profile's figures widened
// to 64 bits once, FILL_RECT's constant part summed, and the division by P a shift (bpp is
// a power of two, so P is). Same results as fill_rect_cycles / draw_span_cycles /
// command_only_cycles for every input.
class CycleCosts {
  public:
    // Throws std::invalid_argument unless bpp is 1, 2, 4, 8 or 16 (as load_profile checks).
    explicit CycleCosts(const CostProfile& p);

    uint64_t fill_rect(const PixelRect& r) const {
        return m_fill_base + uint64_t{r.h} * (m_row + m_op * words(r.x, r.w));
    }
    uint64_t draw_span(uint32_t x, uint32_t n) const {
        if (m_span_as_fill) return m_fill_base + m_row + m_op * words(x, n);
        return m_line_base + m_line_pix * n;
    }
    uint64_t command_only() const { return m_cmd; }

  private:
    uint64_t words(uint64_t x, uint64_t w) const {
        return ((x + w - 1) >> m_word_shift) - (x >> m_word_shift) + 1;
    }

    uint64_t m_cmd, m_fill_base, m_row, m_op, m_line_base, m_line_pix;
    uint32_t m_word_shift = 0;  // log2 P
    bool m_span_as_fill;
};

// Seconds a command of `bytes` modelled bytes occupies the bus: bytes / B_bus + t_handshake.
// A command of 0 modelled bytes (MARKER) is not sent: 0.
double bus_seconds(const CostProfile& p, uint32_t bytes);
double cycles_to_seconds(const CostProfile& p, uint64_t cycles);

// The two-stage pipeline of one frame, in microseconds from the moment its first command
// starts to cross the bus. The bus carries commands one after another; the controller
// executes a command once it has arrived and the previous one is done. The queue between
// them is unbounded (no back-pressure in protocol version 1).
class Pipeline {
  public:
    // Adds one command; returns the time its execution ends.
    double push(double bus_us, double exec_us) {
        m_bus_free_us += bus_us;  // arrival: the bus is sequential
        const double start =
            m_bus_free_us > m_controller_free_us ? m_bus_free_us : m_controller_free_us;
        m_controller_free_us = start + exec_us;
        m_bus_busy_us += bus_us;
        m_controller_busy_us += exec_us;
        return m_controller_free_us;
    }
    void reset() { *this = Pipeline{}; }

    double bus_busy_us() const { return m_bus_busy_us; }
    double controller_busy_us() const { return m_controller_busy_us; }
    // When the last command pushed has finished executing.
    double end_us() const { return m_controller_free_us; }

  private:
    double m_bus_free_us = 0;
    double m_controller_free_us = 0;
    double m_bus_busy_us = 0;
    double m_controller_busy_us = 0;
};

}  // namespace fb89::controller
