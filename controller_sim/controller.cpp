// The simulated frame-buffer controller, in the shape of a MAME device: an opcode table
// (name, parameter count, modelled bytes, bus time) and one exec_* per opcode, reached
// through a switch on the opcode (execute) or straight from the CommandSink calls, so that
// each inlines into its step: no indirect call, no allocation, no copy of the command per
// command. The cost of each command comes from cost_model.h (CycleCosts) and the loaded
// CostProfile.
//
// NOT MODELLED (see docs/COST_MODEL.md):
//  - The palette. Colours travel and are stored as RGB888; cost is modelled at the
//    profile's bpp (P = 16/bpp pixels per 16-bit word), as if the colour were an index.
//  - Back-pressure. The queue between bus and controller is unbounded: the host never
//    waits for the controller (protocol version 1 has no flow control).
//  - The host port's register protocol step by step: a command costs its modelled bytes over
//    the slower of the host's bus and the chip's port plus one t_handshake, and each of its
//    16-bit words one memory cycle of the GSP's bus, charged to its own execution.
//  - Window-checking cycles (MAME's apply_window adds 3-11 when clipping): clipping is free,
//    a clipped command costs its set-up plus the pixels left.
//  - Refresh as events: DRAM refresh and the display's VRAM transfers take their share of
//    the bus as a stretch of every GSP state (CostProfile::stolen_share), not at the moments
//    they fall; host interrupts and instruction-cache misses (the listing fits the cache)
//    take nothing.
//  - Pixel processing other than replace (boolean, arithmetic, transparency, plane masks).
//  - Time between frames: each frame's clock starts at 0 with its FRAME_BEGIN, bus and
//    controller idle.
//  - The depth loops' wrap: Z is held to [0, kDepthOne] where the GSP's 32-bit ADD would
//    wrap a depth stepped past either end (a face's rounding at its very edge); the last
//    pixel of a run is charged DSJ's taken 3 states for its not-taken 2 (docs/COST_MODEL.md).
//
// Commands outside a frame (before the first FRAME_BEGIN, or after a FRAME_END and before
// the next FRAME_BEGIN) find no framebuffer to draw in: they write nothing, are counted
// as outside in ControllerStats::unframed and cost what a wholly clipped command costs
// (cost_model.h, outside_cycles) plus their bus time. A
// FRAME_BEGIN arriving inside an open frame first closes that frame as incomplete.
#include "controller_sim/controller.h"

#include <algorithm>
#include <stdexcept>
#include <variant>

#include "protocol/coverage.h"
#include "protocol/depth_fixed.h"

#include <fmt/format.h>

namespace fb89::controller {

// Unnamed, so that in a unity build no enumerator of the same name in a later header
// (ViewGoal::Command) shadows them (-Wshadow).
namespace {
using protocol::Command;
using protocol::DepthClear;
using protocol::DepthSpan;
using protocol::DrawSpan;
using protocol::Face;
using protocol::FillRect;
using protocol::FrameBegin;
using protocol::FrameEnd;
using protocol::Marker;
using protocol::Opcode;
using protocol::opcode_index;
}  // namespace

OpcodeCounters& OpcodeCounters::operator+=(const OpcodeCounters& o) {
    commands += o.commands;
    pixels += o.pixels;
    bytes += o.bytes;
    cycles += o.cycles;
    clipped += o.clipped;
    outside += o.outside;
    return *this;
}

OpcodeCounters sum(const PerOpcode& ops) {
    OpcodeCounters total;
    for (const OpcodeCounters& c : ops)
        total += c;
    return total;
}

std::array<Controller::OpcodeEntry, protocol::kOpcodeCount> Controller::make_opcode_table(
    const CostProfile& p) {
    // opcode table: in opcode order (protocol::opcode_index)
    std::array<OpcodeEntry, protocol::kOpcodeCount> t{};
    for (int i = 0; i < protocol::kOpcodeCount; ++i) {
        t[i].name = protocol::kCommandRows[i].name;
        t[i].bytes = p.bytes[i];
        t[i].bus_us = bus_seconds(p, p.bytes[i]) * 1e6;
    }
    return t;
}

Controller::Controller(CostProfile profile)
    : m_opcodes(make_opcode_table(profile)),
      m_costs(profile),
      m_us_per_cycle(us_per_cycle(profile)) {
    m_stats.profile = std::move(profile);
}

// --- dispatch ------------------------------------------------------------------------

void Controller::execute(const Command& c) {
    switch (c.index()) {  // variant order follows the opcodes
        case opcode_index(Opcode::FrameBegin):
            step(*std::get_if<FrameBegin>(&c));
            break;
        case opcode_index(Opcode::FillRect):
            step(*std::get_if<FillRect>(&c));
            break;
        case opcode_index(Opcode::DrawSpan):
            step(*std::get_if<DrawSpan>(&c));
            break;
        case opcode_index(Opcode::Marker):
            step(*std::get_if<Marker>(&c));
            break;
        case opcode_index(Opcode::FrameEnd):
            step(*std::get_if<FrameEnd>(&c));
            break;
        case opcode_index(Opcode::DepthClear):
            step(*std::get_if<DepthClear>(&c));
            break;
        case opcode_index(Opcode::DepthSpan):
            step(*std::get_if<DepthSpan>(&c));
            break;
        case opcode_index(Opcode::Face):
            step(*std::get_if<Face>(&c));
            break;
    }
    if (m_observer) m_observer(m_next_command - 1, c);
}

void Controller::execute(std::span<const Command> commands, std::span<CommandCost> costs) {
    if (!costs.empty() && costs.size() < commands.size())
        throw std::logic_error("Controller::execute: fewer costs than commands");
    CommandCost* const out = costs.empty() ? nullptr : costs.data();
    std::size_t i = 0;
    while (i < commands.size()) {
        if (m_in_frame && !m_observer && !m_keep_drawn) i = execute_drawing(commands, i, out);
        if (i < commands.size()) {
            execute(commands[i]);
            if (out) out[i] = m_last_cost;
            ++i;
        }
    }
}

template <class C>
void Controller::submit_one(const C& c) {
    if (m_observer) {
        execute(Command{c});
    } else {
        step(c);
    }
}

void Controller::frame_begin(const protocol::FrameBegin& c) {
    submit_one(c);
}
void Controller::fill_rect(const protocol::FillRect& c) {
    submit_one(c);
}
void Controller::draw_span(const protocol::DrawSpan& c) {
    submit_one(c);
}
void Controller::marker(const protocol::Marker& c) {
    submit_one(c);
}
void Controller::frame_end(const protocol::FrameEnd& c) {
    submit_one(c);
}
void Controller::depth_clear(const protocol::DepthClear& c) {
    submit_one(c);
}
void Controller::depth_span(const protocol::DepthSpan& c) {
    submit_one(c);
}
void Controller::face(const protocol::Face& c) {
    submit_one(c);
}

void Controller::step(const FrameBegin& c) {
    account(Opcode::FrameBegin, exec_frame_begin(c));
}
void Controller::step(const FillRect& c) {
    account(Opcode::FillRect, exec_fill_rect(c));
}
void Controller::step(const DrawSpan& c) {
    account(Opcode::DrawSpan, exec_draw_span(c));
}
void Controller::step(const Marker& c) {
    account(Opcode::Marker, exec_marker(c));
}
void Controller::step(const FrameEnd& c) {
    account(Opcode::FrameEnd, exec_frame_end(c));
    if (m_in_frame) close_frame(true);
}
void Controller::step(const DepthClear& c) {
    account(Opcode::DepthClear, exec_depth_clear(c));
}
void Controller::step(const DepthSpan& c) {
    check_depth(Opcode::DepthSpan, true);
    DepthCounters counts;
    const Executed x = exec_depth_span(c, counts);
    m_frame.depth += counts;
    m_stats.depth += counts;
    account(Opcode::DepthSpan, x);
}
void Controller::step(const Face& c) {
    account(Opcode::Face, exec_face(c));
}

// --- exec_* ----------------------------------------------------------------------------

// FRAME_BEGIN: size the framebuffer and clear it; charged as one full-screen fill.
Controller::Executed Controller::exec_frame_begin(const FrameBegin& f) {
    if (f.width > kMaxFrameSide || f.height > kMaxFrameSide)
        throw std::invalid_argument(
            fmt::format("command {}: {}: frame size exceeds the maximum {}x{}", m_next_command,
                        protocol::to_string(Command{f}), kMaxFrameSide, kMaxFrameSide));
    if (m_in_frame) close_frame(false);

    m_fb.resize(f.width, f.height);
    m_fb.clear(f.background);
    m_depth.clear();  // a frame's depth buffer is its DEPTH_CLEAR's
    m_in_frame = true;
    m_stats.frame_open = true;
    m_frame = FrameResult{};
    m_frame.frame = f.frame;
    m_frame.width = f.width;
    m_frame.height = f.height;
    m_frame.first_command = m_next_command;
    m_frame_pipe.reset();
    return Executed{frame_begin_cycles(profile(), f.width, f.height), uint64_t{f.width} * f.height,
                    false, false};
}

// FILL_RECT: clip to the framebuffer, fill what is left. (This and exec_draw_span are
// inlined into execute_drawing's loop, too, where the calls would cost a tenth of a span.)
[[gnu::always_inline]] inline Controller::Executed Controller::exec_fill_rect(const FillRect& f) {
    const auto clip = m_in_frame ? clip_fill_rect(f, m_fb.width(), m_fb.height()) : std::nullopt;
    if (!clip) return Executed{m_costs.fill_outside(), 0, false, true};
    m_fb.fill_rect(clip->rect, f.color);
    return Executed{m_costs.fill_rect(clip->rect), clip->rect.pixels(), clip->clipped, false};
}

// DRAW_SPAN: clip to the framebuffer, draw what is left as a line or a one-row fill.
[[gnu::always_inline]] inline Controller::Executed Controller::exec_draw_span(const DrawSpan& s) {
    const auto clip = m_in_frame ? clip_span(s, m_fb.width(), m_fb.height()) : std::nullopt;
    if (!clip) return Executed{m_costs.span_outside(), 0, false, true};
    const PixelRect& r = clip->rect;
    m_fb.draw_span(r.y, r.x, r.w, s.color);
    return Executed{m_costs.draw_span(r.x, r.w), r.w, clip->clipped, false};
}

// MARKER: a label for the host's phases; never sent to the modelled hardware (0 bytes).
Controller::Executed Controller::exec_marker(const Marker&) {
    return Executed{};
}

// FRAME_END: fetch, decode and tell the host; step() then closes the frame and takes its
// checksum.
Controller::Executed Controller::exec_frame_end(const FrameEnd&) {
    return Executed{m_costs.frame_end(), 0, false, !m_in_frame};
}

// --- the depth commands ------------------------------------------------------------------

void Controller::check_depth(Opcode op, bool needs_buffer) const {
    if (!profile().depth_priced)
        throw std::invalid_argument(fmt::format(
            "command {}: {}: profile {} prices no depth commands (it has no listing, \"gsp\"; "
            "docs/COST_MODEL.md, \"Depth commands\")",
            m_next_command, protocol::to_string(op), profile().name));
    if (needs_buffer && m_in_frame && m_depth.empty())
        throw std::invalid_argument(fmt::format(
            "command {}: {}: no depth buffer in this frame (a DEPTH_CLEAR after its FRAME_BEGIN "
            "makes one)",
            m_next_command, protocol::to_string(op)));
}

namespace {

// The depth test of n words against Z stepped from z by dz (uint32 wrap: every Z of the run
// lies in [0, kDepthOne], so the sum mod 2^32 is Z itself), stored as Z >> shift: a word
// nearer takes the new depth and its flag is 1, else its flag is 0. Branch-free, so that it
// vectorises. Returns the nearer count; adds the as-near ones to `equal`.
template <int Shift>
uint32_t depth_test_in_range(uint32_t* word, uint8_t* flags, uint32_t n, uint32_t z, uint32_t dz,
                             uint64_t& equal) {
    uint32_t nearer = 0, same = 0;
    for (uint32_t i = 0; i < n; ++i, z += dz) {
        const uint32_t s = z >> Shift;
        const uint32_t old = word[i];
        const uint32_t now = s < old ? s : old;
        word[i] = now;
        const uint32_t taken = now != old ? 1u : 0u;
        flags[i] = static_cast<uint8_t>(taken);
        nearer += taken;
        same += s == old ? 1u : 0u;
    }
    equal += same;
    return nearer;
}

}  // namespace

void Controller::depth_run(uint32_t y, uint32_t x, uint32_t n, int64_t z, int64_t dz,
                           protocol::Rgb color, DepthCounters& counts) {
    const uint32_t bits = profile().depth_bits;
    uint32_t* const word = m_depth.data() + std::size_t{y} * m_fb.width() + x;
    uint8_t* const flags = m_nearer.data();
    uint64_t nearer = 0, equal = 0;
    const int64_t last = z + dz * (int64_t{n} - 1);
    if (std::min(z, last) >= 0 && std::max(z, last) <= protocol::kDepthOne) {
        // the common case: every depth in range, tested without the hold
        const auto z32 = static_cast<uint32_t>(z), dz32 = static_cast<uint32_t>(dz);
        nearer = bits == 16 ? depth_test_in_range<protocol::kDepth16Shift>(word, flags, n, z32,
                                                                           dz32, equal)
                            : depth_test_in_range<0>(word, flags, n, z32, dz32, equal);
    } else {
        for (uint32_t i = 0; i < n; ++i, z += dz) {
            const uint32_t s = protocol::stored_depth(z, bits);
            const bool taken = s < word[i];
            equal += s == word[i] ? 1 : 0;
            word[i] = taken ? s : word[i];
            flags[i] = taken ? 1 : 0;
            nearer += taken ? 1 : 0;
        }
    }
    if (nearer == n)
        m_fb.draw_span(y, x, n, color);
    else if (nearer)
        m_fb.draw_flagged(y, x, n, flags, color);
    // the viewer's hook (keep_depth_drawn): what this run drew; off, an untaken branch
    if (m_keep_drawn && nearer) [[unlikely]]
        keep_drawn(y, x, n, nearer == n ? nullptr : flags);
    counts.tests += n;
    counts.nearer += nearer;
    counts.equal += equal;
}

// keep_depth_drawn's record of one run: the flagged pixels as runs, for the command being
// executed (the recording path only; depth_run calls it when asked to keep them).
void Controller::keep_drawn(uint32_t y, uint32_t x, uint32_t n, const uint8_t* flags) {
    if (m_drawn_after != m_next_command + 1) {  // the first run of this command
        m_drawn.clear();
        m_drawn_after = m_next_command + 1;
    }
    for (uint32_t i = 0; i < n;) {
        if (flags && !flags[i]) {
            ++i;
            continue;
        }
        uint32_t end = i + 1;
        while (end < n && (!flags || flags[end]))
            ++end;
        m_drawn.push_back(PixelRect{x + i, y, end - i, 1});
        i = end;
    }
}

// DEPTH_CLEAR: the frame's depth buffer, every word far; charged as the FILL that clears it.
Controller::Executed Controller::exec_depth_clear(const DepthClear&) {
    check_depth(Opcode::DepthClear, false);
    if (!m_in_frame) return Executed{outside_cycles(profile(), Opcode::DepthClear), 0, false, true};
    m_depth.assign(std::size_t{m_fb.width()} * m_fb.height(),
                   protocol::depth_clear_value(profile().depth_bits));
    m_nearer.resize(m_fb.width());
    m_frame.depth_bits = profile().depth_bits;
    return Executed{depth_clear_cycles(profile(), m_fb.width(), m_fb.height()), 0, false, false};
}

// DEPTH_SPAN: clipped to the frame (a cut on the left steps Z to the first column), then
// each pixel tested and drawn where nearer; its pixels' counts added to `counts`. The caller
// has checked it (check_depth). Inlined into execute_drawing's loop too.
[[gnu::always_inline]] inline Controller::Executed Controller::exec_depth_span(
    const DepthSpan& s, DepthCounters& counts) {
    const int64_t w = m_fb.width(), h = m_fb.height();
    if (!m_in_frame || s.y < 0 || s.y >= h || s.x1 < 0 || s.x0 >= w || s.x1 < s.x0) {
        // where the listing finds it so (dspan: the row, then the columns left after the cuts)
        const ZOutside where = !m_in_frame || s.y < 0 ? ZOutside::Above
                               : s.y >= h             ? ZOutside::Below
                               : s.x0 < 0             ? ZOutside::EmptyCut
                                                      : ZOutside::Empty;
        return Executed{m_costs.depth_span_outside(where), 0, false, true};
    }
    const int64_t x0 = std::max<int64_t>(s.x0, 0), x1 = std::min<int64_t>(s.x1, w - 1);
    const bool cut_left = x0 > s.x0;
    const int64_t z = int64_t{s.z} + int64_t{s.dz} * (x0 - s.x0);
    const uint64_t tests = counts.tests, nearer = counts.nearer;
    depth_run(static_cast<uint32_t>(s.y), static_cast<uint32_t>(x0),
              static_cast<uint32_t>(x1 - x0 + 1), z, s.dz, s.color, counts);
    const uint64_t drawn = counts.nearer - nearer, refused = counts.tests - tests - drawn;
    return Executed{m_costs.depth_span(cut_left, drawn, refused), drawn, cut_left || x1 < s.x1,
                    false};
}

namespace {

// What the listing's edge loop meets in row y (tms34010.asm, face_edge), counted for the
// cost model: each edge's N = floor((k0 - bias) / 256) + ny y; a level edge (none when
// N < 0), a quotient N / |nx| beyond 32 bits (none when N < 0), else a bound from the
// floored quotient that is nearer or not -- in the listing's 32-bit registers and order,
// every edge of the row whatever the ones before it found. The pixels are row_span's.
void count_edge_row(const protocol::EdgeFunction* edges, uint32_t n, int64_t y, int32_t last,
                    FaceWork& work) {
    int32_t lo = 0, hi = last;
    for (uint32_t i = 0; i < n; ++i) {
        const protocol::EdgeFunction& e = edges[i];
        const int64_t big_n = ((e.k0 - e.bias) >> 8) + e.ny * y;
        if (e.nx == 0 || big_n / (e.nx < 0 ? -e.nx : e.nx) > INT32_MAX ||
            big_n / (e.nx < 0 ? -e.nx : e.nx) < INT32_MIN) {
            const bool level = e.nx == 0;
            if (big_n < 0) {
                (level ? work.level_none : work.far_none) += 1;
                hi = -1;
            } else {
                (level ? work.level : work.far) += 1;
            }
            continue;
        }
        const int64_t d = e.nx < 0 ? -e.nx : e.nx;
        const int64_t q = big_n / d, r = big_n % d;
        const auto floored = static_cast<int32_t>(static_cast<uint32_t>(q) - (r < 0 ? 1u : 0u));
        if (e.nx > 0) {
            const auto x = static_cast<int32_t>(0u - static_cast<uint32_t>(floored));
            if (x > lo) {
                lo = x;
                ++work.bounds;
            }
        } else if (floored < hi) {
            hi = floored;
            ++work.bounds;
        }
    }
}

}  // namespace

// FACE: its edges by the coverage rule (protocol/coverage.h), its rows clipped to the frame,
// each row's covered run tested and drawn like a DEPTH_SPAN.
Controller::Executed Controller::exec_face(const Face& f) {
    check_depth(Opcode::Face, true);
    if (f.points.size() < 3 || f.points.size() > protocol::kMaxFacePoints)
        throw std::invalid_argument(fmt::format("command {}: FACE: {} points, outside 3..{}",
                                                m_next_command, f.points.size(),
                                                protocol::kMaxFacePoints));
    const uint32_t n = static_cast<uint32_t>(f.points.size());
    const int64_t bytes = face_bytes(n);
    FaceWork work;
    work.points = n;
    if (!m_in_frame) {
        Executed x{face_cycles(profile(), work), 0, false, true};
        x.bytes = bytes;
        return x;
    }
    std::array<protocol::EdgeFunction, protocol::kMaxFacePoints> edges;
    protocol::setup_edges(f.points.data(), n, edges.data());
    // the rows whose centres (y + 1/2) may be covered: between the points' lowest and highest
    int64_t lo = f.points[0].y, hi = f.points[0].y;
    for (const protocol::SnappedPoint& p : f.points) {
        lo = std::min(lo, p.y);
        hi = std::max(hi, p.y);
    }
    const int64_t half = protocol::kSubpixel / 2;
    const int64_t h = m_fb.height(), w = m_fb.width();
    const int64_t top = protocol::detail::ceil_div(lo - half, protocol::kSubpixel);
    const int64_t bottom = protocol::detail::floor_div(hi - half, protocol::kSubpixel);
    const int64_t first = std::max<int64_t>(0, top), last = std::min<int64_t>(h - 1, bottom);
    const bool clipped = first > top || last < bottom;
    DepthCounters counts;
    bool cut_sides = false;
    for (uint32_t i = 0; i < n; ++i)
        work.level_points += edges[i].nx == 0 ? 1 : 0;
    for (int64_t y = first; y <= last; ++y) {
        ++work.rows;
        count_edge_row(edges.data(), n, y, static_cast<int32_t>(w - 1), work);
        int xb = 0, xe = 0;
        if (!protocol::row_span(edges.data(), n, static_cast<int>(y), 0, static_cast<int>(w), xb,
                                xe))
            continue;
        ++work.runs;
        cut_sides = cut_sides || xb == 0 || xe == w;
        const int64_t z = int64_t{f.z} + int64_t{f.dzdx} * (xb - int64_t{f.x_ref}) +
                          int64_t{f.dzdy} * (y - int64_t{f.y_ref});
        depth_run(static_cast<uint32_t>(y), static_cast<uint32_t>(xb),
                  static_cast<uint32_t>(xe - xb), z, f.dzdx, f.color, counts);
    }
    work.nearer = counts.nearer;
    work.farther = counts.tests - counts.nearer;
    m_frame.depth += counts;
    m_stats.depth += counts;
    Executed x{face_cycles(profile(), work), counts.nearer, clipped || cut_sides, work.runs == 0};
    x.bytes = bytes;
    return x;
}

// --- accounting ------------------------------------------------------------------------

namespace {

// One command's figures added to its opcode's counters.
void count(OpcodeCounters& c, uint32_t bytes, uint64_t cycles, uint64_t pixels, bool clipped,
           bool outside) {
    ++c.commands;
    c.pixels += pixels;
    c.bytes += bytes;
    c.cycles += cycles;
    c.clipped += clipped ? 1 : 0;
    c.outside += outside ? 1 : 0;
}

}  // namespace

void Controller::account(Opcode opcode, const Executed& x) {
    const int op = opcode_index(opcode);
    const OpcodeEntry& e = m_opcodes[op];
    const uint32_t bytes = x.bytes < 0 ? e.bytes : static_cast<uint32_t>(x.bytes);
    const double bus_us = x.bytes < 0 ? e.bus_us : bus_seconds(profile(), bytes) * 1e6;
    // counters
    count((m_in_frame ? m_frame.ops : m_stats.unframed)[op], bytes, x.cycles, x.pixels, x.clipped,
          x.outside);
    count(m_stats.totals[op], bytes, x.cycles, x.pixels, x.clipped, x.outside);

    // time: summed command by command, in stream order (floating-point sums)
    const double exec_us = static_cast<double>(x.cycles) * m_us_per_cycle;
    (m_in_frame ? m_frame_pipe : m_unframed_pipe).push(bus_us, exec_us);
    m_last_cost = {bytes, bus_us, exec_us};
    m_stats.bus_busy_us += bus_us;
    m_stats.controller_busy_us += exec_us;
    ++m_next_command;
}

// The batch path's fast path: FILL_RECT, DRAW_SPAN and DEPTH_SPAN. Counter deltas of this run of
// drawing commands build up in locals and are added to the frame and the totals once at the end
// (integer sums: the order does not matter). The clocks are copied into locals and written back:
// the same floating-point additions as account(), in the same order, only kept in registers.
std::size_t Controller::execute_drawing(std::span<const Command> commands, std::size_t i,
                                        CommandCost* costs) {
    const int fill_op = opcode_index(Opcode::FillRect), span_op = opcode_index(Opcode::DrawSpan),
              zspan_op = opcode_index(Opcode::DepthSpan);
    const OpcodeEntry& fill_entry = m_opcodes[fill_op];
    const OpcodeEntry& span_entry = m_opcodes[span_op];
    const OpcodeEntry& zspan_entry = m_opcodes[zspan_op];
    OpcodeCounters fills, spans, zspans;
    DepthCounters depth;
    // DEPTH_SPANs too once the frame has its depth buffer (check_depth passes them then; before
    // it, the general path reports them with their number)
    const bool depth_ok = !m_depth.empty() && profile().depth_priced;
    Pipeline pipe = m_frame_pipe;
    double bus_busy_us = m_stats.bus_busy_us, controller_busy_us = m_stats.controller_busy_us;
    // account() for the open frame, on the locals
    const auto account_local = [&](const OpcodeEntry& e, OpcodeCounters& n, const Executed& x) {
        count(n, e.bytes, x.cycles, x.pixels, x.clipped, x.outside);
        const double exec_us = static_cast<double>(x.cycles) * m_us_per_cycle;
        pipe.push(e.bus_us, exec_us);
        bus_busy_us += e.bus_us;
        controller_busy_us += exec_us;
        if (costs) costs[i] = {e.bytes, e.bus_us, exec_us};
    };

    // execute: only drawing commands, which neither open nor close the frame
    for (; i < commands.size(); ++i) {
        const Command& c = commands[i];
        if (const auto* s = std::get_if<DrawSpan>(&c)) {
            account_local(span_entry, spans, exec_draw_span(*s));
        } else if (const auto* f = std::get_if<FillRect>(&c)) {
            account_local(fill_entry, fills, exec_fill_rect(*f));
        } else if (const auto* z = depth_ok ? std::get_if<DepthSpan>(&c) : nullptr) {
            account_local(zspan_entry, zspans, exec_depth_span(*z, depth));
        } else {
            break;
        }
    }

    // write back
    m_frame.ops[fill_op] += fills;
    m_frame.ops[span_op] += spans;
    m_frame.ops[zspan_op] += zspans;
    m_stats.totals[fill_op] += fills;
    m_stats.totals[span_op] += spans;
    m_stats.totals[zspan_op] += zspans;
    m_frame.depth += depth;
    m_stats.depth += depth;
    m_frame_pipe = pipe;
    m_stats.bus_busy_us = bus_busy_us;
    m_stats.controller_busy_us = controller_busy_us;
    m_next_command += fills.commands + spans.commands + zspans.commands;
    return i;
}

void Controller::close_frame(bool complete) {
    m_frame.complete = complete;
    m_frame.checksum = m_fb.checksum();
    m_frame.bus_busy_us = m_frame_pipe.bus_busy_us();
    m_frame.controller_busy_us = m_frame_pipe.controller_busy_us();
    m_frame.end_us = m_frame_pipe.end_us();
    m_stats.frames_end_us += m_frame.end_us;
    ++m_stats.frames_closed;
    m_stats.frames_incomplete += complete ? 0 : 1;
    m_stats.frames.push_back(m_frame);
    m_in_frame = false;
    m_stats.frame_open = false;
}

double Controller::elapsed_us() const {
    return m_stats.frames_end_us + m_unframed_pipe.end_us() +
           (m_in_frame ? m_frame_pipe.end_us() : 0.0);
}

FrameResult Controller::open_frame() const {
    FrameResult f = m_frame;
    f.complete = false;
    f.checksum = m_fb.checksum();
    f.bus_busy_us = m_frame_pipe.bus_busy_us();
    f.controller_busy_us = m_frame_pipe.controller_busy_us();
    f.end_us = m_frame_pipe.end_us();
    return f;
}

}  // namespace fb89::controller
