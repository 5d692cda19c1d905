// Cycle counts per command (see cost_model.h and docs/COST_MODEL.md).
//
// Differences from MAME's fill(): window clipping is always on and free (MAME adds 3-11
// cycles in apply_window when clipping changes the rectangle; we charge only the set-up
// and the pixels left, as the design fixes), and the per-command fetch/decode C_cmd, which
// MAME leaves to the GSP program, is charged here.
#include "controller_sim/cost_model.h"

#include <bit>
#include <stdexcept>

#include <fmt/format.h>

namespace fb89::controller {

uint64_t words(uint64_t x, uint64_t w, uint32_t pixels_per_word) {
    return (x + w - 1) / pixels_per_word - x / pixels_per_word + 1;
}

uint64_t fill_rect_cycles(const CostProfile& p, const PixelRect& r) {
    const uint64_t per_row = p.c_row + uint64_t{p.c_op} * words(r.x, r.w, p.pixels_per_word());
    return uint64_t{p.c_cmd} + p.c_setup + uint64_t{r.h} * per_row;
}

uint64_t draw_span_cycles(const CostProfile& p, uint32_t x, uint32_t n) {
    if (p.span_as == SpanAs::Fill) return fill_rect_cycles(p, PixelRect{x, 0, n, 1});
    return uint64_t{p.c_cmd} + p.c_line_setup + uint64_t{p.c_line_pix} * n;
}

uint64_t frame_begin_cycles(const CostProfile& p, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) return command_only_cycles(p);
    return fill_rect_cycles(p, PixelRect{0, 0, width, height});
}

CycleCosts::CycleCosts(const CostProfile& p)
    : m_cmd(p.c_cmd),
      m_fill_base(uint64_t{p.c_cmd} + p.c_setup),
      m_row(p.c_row),
      m_op(p.c_op),
      m_line_base(uint64_t{p.c_cmd} + p.c_line_setup),
      m_line_pix(p.c_line_pix),
      m_span_as_fill(p.span_as == SpanAs::Fill) {
    if (p.bpp == 0 || 16 % p.bpp != 0 || !std::has_single_bit(p.bpp))
        throw std::invalid_argument(
            fmt::format("profile {}: bpp must be 1, 2, 4, 8 or 16, got {}", p.name, p.bpp));
    m_word_shift = static_cast<uint32_t>(std::countr_zero(p.pixels_per_word()));
}

double bus_seconds(const CostProfile& p, uint32_t bytes) {
    if (bytes == 0) return 0;
    return static_cast<double>(bytes) / p.b_bus_bytes_per_s + p.t_handshake_s;
}

double cycles_to_seconds(const CostProfile& p, uint64_t cycles) {
    return static_cast<double>(cycles) / p.f_cyc_hz;
}

}  // namespace fb89::controller
