// The controller's cost model: cycles per command and the bus/controller pipeline.
//
// Pure functions of a CostProfile and of the clipped geometry. A command costs the GSP's
// command loop and its set-up (counted from the listing, gsp_listing.h), the memory cycles
// of the host's words, and its pixels as memory cycles: per row of FILL the bus words
// touched, a whole word one write cycle, a partial word a read and a write; per pixel of
// LINE a read and a write unless a pixel is a whole word. docs/COST_MODEL.md gives every
// parameter, its source and the check values the tests verify.
#pragma once

#include <cstdint>

#include "controller_sim/framebuffer.h"
#include "controller_sim/profile.h"

namespace fb89::controller {

// Words of the local bus touched by pixels x .. x+w-1 at P pixels per word (w >= 1):
// floor((x+w-1)/P) - floor(x/P) + 1.
uint64_t words(uint64_t x, uint64_t w, uint32_t pixels_per_word);
// Of those, the partial ones (some of their pixels outside the run): 0, 1 or 2.
uint64_t partial_words(uint64_t x, uint64_t w, uint32_t pixels_per_word);

// FILL_RECT of the clipped rectangle r: C_cmd + C_setup + the host's words +
// h * (C_row + C_op * full words + C_op_partial * partial words).
uint64_t fill_rect_cycles(const CostProfile& p, const PixelRect& r);
// DRAW_SPAN of n pixels starting at x (clipped, n >= 1): as a line,
// C_cmd + C_line_setup + the host's words + C_line_pix * n; as a fill, one row of FILL after
// the span's own set-up.
uint64_t draw_span_cycles(const CostProfile& p, uint32_t x, uint32_t n);
// FRAME_BEGIN: its set-up and the clear; no pixels for a 0-pixel frame. The clear is the
// profile's clear_as: through the VRAMs' serial registers (srt_clear_cycles) where the frame
// lies in the board's VRAM, else (and with "fill") one FILL over the frame.
uint64_t frame_begin_cycles(const CostProfile& p, uint32_t width, uint32_t height);
// The serial-register clear's memory cycles for `rows` VRAM rows (rows >= 1): the first row
// filled as 16-bit pixels (kVramRowBits / bus_bits whole words, one FILL row), then one
// register-to-memory cycle for each other row (a FILL row of one word). Its set-up, with
// the memory-to-register cycle's PIXT, is the listing's FRAME_BEGIN path.
uint64_t srt_clear_cycles(const CostProfile& p, uint64_t rows);
// FRAME_END: C_cmd, its set-up and its host word.
uint64_t frame_end_cycles(const CostProfile& p);
// A drawing command with nothing inside the framebuffer: C_cmd, the host's words and (with
// a listing) the set-up that loads and runs FILL or LINE, which then draw nothing.
uint64_t outside_cycles(const CostProfile& p, protocol::Opcode op);
// The host's words of a command as the controller's bus pays for them.
inline uint64_t host_word_cycles(const CostProfile& p, protocol::Opcode op) {
    return uint64_t{p.host_words_of(op)} * p.c_host_word;
}

// --- the depth commands (docs/COST_MODEL.md, "Depth commands") --------------------------
// DEPTH_CLEAR: C_cmd, its set-up, its host word and the clear, a FILL of the depth buffer's
// words (the frame's width times depth_bits / 16 a row, whole words).
uint64_t depth_clear_cycles(const CostProfile& p, uint32_t width, uint32_t height);
// A DEPTH_SPAN that reaches its pixel loop: C_cmd, its set-up and host words, the left cut's
// steps when it was cut there, each pixel nearer or not, and the loop's return.
uint64_t depth_span_cycles(const CostProfile& p, bool cut_left, uint64_t nearer, uint64_t farther);
// One with nothing in the frame: C_cmd, its host words and its set-up to where it finds so.
// Where the listing finds it so: a row above the frame, below it, or no column of the span
// left in the frame (after a cut on the left or not).
enum class ZOutside { Above, Below, Empty, EmptyCut };
uint64_t depth_span_outside_cycles(const CostProfile& p, ZOutside where = ZOutside::Above);
// What a FACE did: its points, the rows of the frame it walked, the rows whose run was not
// empty, and its pixels' tests.
struct FaceWork {
    uint32_t points = 0;
    uint32_t level_points = 0;  // points whose edge to the next is level (nx = 0)
    uint64_t rows = 0, runs = 0;
    uint64_t nearer = 0, farther = 0;
    // of the rows' edges (rows x points), as the listing's edge loop meets them: level ones
    // (N >= 0, and N < 0: the row emptied), ones whose quotient is beyond 32 bits (likewise),
    // and the divided ones that gave a nearer bound
    uint64_t level = 0, level_none = 0, far = 0, far_none = 0, bounds = 0;
};
// FACE: C_cmd, its host words, its set-up and each point's edge, each row's step of every
// edge, each run's span set-up and return or an empty row's, each pixel, and the end.
uint64_t face_cycles(const CostProfile& p, const FaceWork& w);
// A FACE's bytes on the bus: its fixed words and two words a coordinate of each point.
inline uint32_t face_bytes(std::size_t points) {
    return kFaceFixedBytes + kFacePointBytes * static_cast<uint32_t>(points);
}

// The formulas above, for the controller's per-command path: the profile's figures widened
// to 64 bits once, each command's constant part summed, and the division by P a shift (P is
// a power of two). Same results as fill_rect_cycles / draw_span_cycles / outside_cycles /
// frame_end_cycles / depth_span_cycles / depth_span_outside_cycles for every input.
class CycleCosts {
  public:
    // Throws std::invalid_argument unless bpp is 1, 2, 4, 8 or 16 (as load_profile checks).
    explicit CycleCosts(const CostProfile& p);

    uint64_t fill_rect(const PixelRect& r) const {
        return m_fill_base + uint64_t{r.h} * row(r.x, r.w);
    }
    uint64_t draw_span(uint32_t x, uint32_t n) const {
        if (m_span_as_fill) return m_span_fill_base + row(x, n);
        return m_line_base + m_line_pix * n;
    }
    uint64_t fill_outside() const { return m_fill_outside; }
    uint64_t span_outside() const { return m_span_outside; }
    // depth_span_cycles and depth_span_outside_cycles
    uint64_t depth_span(bool cut_left, uint64_t nearer, uint64_t farther) const {
        return m_zspan_base + (cut_left ? m_zclip : 0) + nearer * m_zpass + farther * m_zfail;
    }
    uint64_t depth_span_outside(ZOutside where = ZOutside::Above) const {
        return m_zspan_outside[static_cast<int>(where)];
    }
    uint64_t frame_end() const { return m_frame_end; }

  private:
    // One row of FILL: C_row, the whole words, the partial ones.
    uint64_t row(uint64_t x, uint64_t w) const {
        const uint64_t first = x >> m_word_shift, last = (x + w - 1) >> m_word_shift;
        const bool left = (x & m_word_mask) != 0, right = ((x + w) & m_word_mask) != 0;
        const uint64_t n = last - first + 1;
        const uint64_t partial = n == 1 ? ((left || right) ? 1 : 0) : uint64_t{left} + right;
        return m_row + m_op * (n - partial) + m_op_partial * partial;
    }

    uint64_t m_fill_base, m_span_fill_base, m_line_base, m_fill_outside, m_span_outside,
        m_frame_end, m_row, m_op, m_op_partial, m_line_pix;
    uint64_t m_zspan_base, m_zspan_outside[4], m_zclip, m_zpass, m_zfail;
    uint32_t m_word_shift = 0;  // log2 P
    uint64_t m_word_mask = 0;   // P - 1
    bool m_span_as_fill;
};

// Seconds a command of `bytes` modelled bytes occupies the bus: bytes / the bus's rate (the
// host's side or the chip's port, the slower) + t_handshake. A command of 0 modelled bytes
// (MARKER) is not sent: 0.
double bus_seconds(const CostProfile& p, uint32_t bytes);
// Seconds the GSP takes for `cycles` of its own states, with the share of the bus that
// refresh takes from it: cycles / (f_cyc * (1 - stolen_share)).
double cycles_to_seconds(const CostProfile& p, uint64_t cycles);
// Microseconds per GSP state, refresh's share included.
inline double us_per_cycle(const CostProfile& p) {
    return 1e6 / (p.f_cyc_hz * (1 - p.stolen_share));
}

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
