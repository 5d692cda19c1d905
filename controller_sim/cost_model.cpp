// Cycle counts per command (see cost_model.h and docs/COST_MODEL.md).
//
// Window clipping is always on and free (MAME adds 3-11 cycles in apply_window when
// clipping changes the rectangle; we charge only the set-up and the pixels left, as the
// design fixes).
#include "controller_sim/cost_model.h"

#include <bit>
#include <stdexcept>

#include <fmt/format.h>

namespace fb89::controller {

uint64_t words(uint64_t x, uint64_t w, uint32_t pixels_per_word) {
    return (x + w - 1) / pixels_per_word - x / pixels_per_word + 1;
}

uint64_t partial_words(uint64_t x, uint64_t w, uint32_t pixels_per_word) {
    const bool left = x % pixels_per_word != 0, right = (x + w) % pixels_per_word != 0;
    if (words(x, w, pixels_per_word) == 1) return left || right ? 1 : 0;
    return uint64_t{left} + right;
}

namespace {

uint64_t row_cycles(const CostProfile& p, uint64_t x, uint64_t w) {
    const uint32_t ppw = p.pixels_per_word();
    const uint64_t partial = partial_words(x, w, ppw);
    return p.c_row + uint64_t{p.c_op} * (words(x, w, ppw) - partial) +
           uint64_t{p.c_op_partial} * partial;
}

uint32_t setup_of(const CostProfile& p, protocol::Opcode op) {
    switch (op) {
        case protocol::Opcode::FrameBegin:
            return p.clear_as == ClearAs::Fill ? p.c_frame_begin_setup : p.c_frame_begin_srt_setup;
        case protocol::Opcode::FillRect:
            return p.c_setup;
        case protocol::Opcode::DrawSpan:
            return p.span_as == SpanAs::Fill ? p.c_span_fill_setup : p.c_line_setup;
        case protocol::Opcode::FrameEnd:
            return p.c_frame_end_setup;
        case protocol::Opcode::Marker:
        // the depth commands: a clear outside a frame pays no set-up; spans and faces are
        // priced outside a frame by depth_span_outside_cycles and the controller's own rule
        case protocol::Opcode::DepthClear:
        case protocol::Opcode::DepthSpan:
        case protocol::Opcode::Face:
            return 0;
    }
    return 0;
}

}  // namespace

uint64_t fill_rect_cycles(const CostProfile& p, const PixelRect& r) {
    return uint64_t{p.c_cmd} + p.c_setup + host_word_cycles(p, protocol::Opcode::FillRect) +
           uint64_t{r.h} * row_cycles(p, r.x, r.w);
}

uint64_t draw_span_cycles(const CostProfile& p, uint32_t x, uint32_t n) {
    const uint64_t host = host_word_cycles(p, protocol::Opcode::DrawSpan);
    if (p.span_as == SpanAs::Fill)
        return uint64_t{p.c_cmd} + p.c_span_fill_setup + host + row_cycles(p, x, n);
    return uint64_t{p.c_cmd} + p.c_line_setup + host + uint64_t{p.c_line_pix} * n;
}

uint64_t frame_begin_cycles(const CostProfile& p, uint32_t width, uint32_t height) {
    if (width == 0 || height == 0) return outside_cycles(p, protocol::Opcode::FrameBegin);
    const uint64_t base = uint64_t{p.c_cmd} + host_word_cycles(p, protocol::Opcode::FrameBegin);
    const uint64_t by_fill = uint64_t{height} * row_cycles(p, 0, width);
    if (p.clear_as == ClearAs::Fill) return base + p.c_frame_begin_setup + by_fill;
    const uint64_t rows = vram_rows(width, height, p.bpp);
    if (rows > kVramRows) return base + p.c_frame_begin_large_setup + by_fill;
    return base + p.c_frame_begin_srt_setup + srt_clear_cycles(p, rows);
}

uint64_t srt_clear_cycles(const CostProfile& p, uint64_t rows) {
    // the first row at 16 bits a pixel: whole words of the bus, one FILL row
    const uint64_t row_fill = p.c_row + uint64_t{p.c_op} * (kVramRowBits / p.bus_bits);
    // one register-to-memory cycle a further row, each a FILL row of one word
    return row_fill + (rows - 1) * (p.c_row + uint64_t{p.c_op});
}

uint64_t frame_end_cycles(const CostProfile& p) {
    return uint64_t{p.c_cmd} + p.c_frame_end_setup +
           host_word_cycles(p, protocol::Opcode::FrameEnd);
}

uint64_t outside_cycles(const CostProfile& p, protocol::Opcode op) {
    return uint64_t{p.c_cmd} + (p.outside_pays_setup ? setup_of(p, op) : 0) +
           host_word_cycles(p, op);
}

CycleCosts::CycleCosts(const CostProfile& p)
    : m_fill_base(uint64_t{p.c_cmd} + p.c_setup + host_word_cycles(p, protocol::Opcode::FillRect)),
      m_span_fill_base(uint64_t{p.c_cmd} + p.c_span_fill_setup +
                       host_word_cycles(p, protocol::Opcode::DrawSpan)),
      m_line_base(uint64_t{p.c_cmd} + p.c_line_setup +
                  host_word_cycles(p, protocol::Opcode::DrawSpan)),
      m_fill_outside(outside_cycles(p, protocol::Opcode::FillRect)),
      m_span_outside(outside_cycles(p, protocol::Opcode::DrawSpan)),
      m_frame_end(frame_end_cycles(p)),
      m_row(p.c_row),
      m_op(p.c_op),
      m_op_partial(p.c_op_partial),
      m_line_pix(p.c_line_pix),
      m_zspan_base(depth_span_cycles(p, false, 0, 0)),
      m_zspan_outside{depth_span_outside_cycles(p, ZOutside::Above),
                      depth_span_outside_cycles(p, ZOutside::Below),
                      depth_span_outside_cycles(p, ZOutside::Empty),
                      depth_span_outside_cycles(p, ZOutside::EmptyCut)},
      m_zclip(p.c_zclip),
      m_zpass(p.c_zpass),
      m_zfail(p.c_zfail),
      m_span_as_fill(p.span_as == SpanAs::Fill) {
    if (p.bpp == 0 || p.bus_bits % p.bpp != 0 || !std::has_single_bit(p.bpp))
        throw std::invalid_argument(
            fmt::format("profile {}: bpp must be 1, 2, 4, 8 or 16, got {}", p.name, p.bpp));
    m_word_shift = static_cast<uint32_t>(std::countr_zero(p.pixels_per_word()));
    m_word_mask = p.pixels_per_word() - 1;
}

uint64_t depth_clear_cycles(const CostProfile& p, uint32_t width, uint32_t height) {
    const uint64_t host = host_word_cycles(p, protocol::Opcode::DepthClear);
    if (width == 0 || height == 0) return uint64_t{p.c_cmd} + p.c_zclear_setup + host;
    const uint64_t words = (uint64_t{width} * p.depth_bits + p.bus_bits - 1) / p.bus_bits;
    return uint64_t{p.c_cmd} + p.c_zclear_setup + host +
           uint64_t{height} * (p.c_row + uint64_t{p.c_op} * words);
}

uint64_t depth_span_cycles(const CostProfile& p, bool cut_left, uint64_t nearer, uint64_t farther) {
    return uint64_t{p.c_cmd} + p.c_zspan_setup + host_word_cycles(p, protocol::Opcode::DepthSpan) +
           (cut_left ? p.c_zclip : 0) + nearer * p.c_zpass + farther * p.c_zfail + p.c_zexit;
}

uint64_t depth_span_outside_cycles(const CostProfile& p, ZOutside where) {
    const uint32_t setup = where == ZOutside::Above   ? p.c_zspan_outside
                           : where == ZOutside::Below ? p.c_zspan_below
                           : where == ZOutside::Empty ? p.c_zspan_empty
                                                      : p.c_zspan_empty_cut;
    return uint64_t{p.c_cmd} + setup + host_word_cycles(p, protocol::Opcode::DepthSpan);
}

uint64_t face_cycles(const CostProfile& p, const FaceWork& w) {
    const uint64_t host = uint64_t{(face_bytes(w.points) + 1) / 2} * p.c_host_word;
    const uint64_t edges = w.rows * w.points;
    const uint64_t divided = edges - w.level - w.level_none - w.far - w.far_none;
    return uint64_t{p.c_cmd} + host + p.c_face_setup +
           (w.points > 0 ? uint64_t{w.points - 1} * p.c_face_point + p.c_face_last : 0) +
           uint64_t{w.level_points} * p.c_face_level_point + w.rows * p.c_face_row +
           divided * p.c_face_edge + w.level * p.c_face_level + w.level_none * p.c_face_level_none +
           w.far * p.c_face_far + w.far_none * p.c_face_far_none + w.bounds * p.c_face_bound +
           w.runs * (uint64_t{p.c_face_span} + p.c_zexit) + (w.rows - w.runs) * p.c_face_empty +
           w.nearer * p.c_zpass + w.farther * p.c_zfail + p.c_face_done;
}

double bus_seconds(const CostProfile& p, uint32_t bytes) {
    if (bytes == 0) return 0;
    return static_cast<double>(bytes) / p.bus_bytes_per_s() + p.t_handshake_s;
}

double cycles_to_seconds(const CostProfile& p, uint64_t cycles) {
    return static_cast<double>(cycles) / (p.f_cyc_hz * (1 - p.stolen_share));
}

}  // namespace fb89::controller
