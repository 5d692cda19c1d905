// The simulated frame-buffer controller, in the shape of a MAME device: an opcode table
// (name, parameter count, modelled bytes, exec function) and one exec_* per opcode.
// The cost of each command comes from cost_model.h and the loaded CostProfile.
//
// NOT MODELLED (see docs/COST_MODEL.md):
//  - The palette. Colours travel and are stored as RGB888; cost is modelled at the
//    profile's bpp (P = 16/bpp pixels per 16-bit word), as if the colour were an index.
//  - Back-pressure. The queue between bus and controller is unbounded: the host never
//    waits for the controller (protocol version 1 has no flow control).
//  - The host port register protocol (HSTADRL/H, HSTDATA auto-increment, HSTCTL) and the
//    command ring buffer in GSP memory: a command costs its modelled bytes / B_bus plus one
//    t_handshake, and C_cmd cycles to fetch and decode.
//  - Window-checking cycles (MAME's apply_window adds 3-11 when clipping): clipping is free,
//    a clipped command costs its set-up plus the pixels left.
//  - Screen refresh, VRAM shift-register transfers, DRAM refresh, host interrupts, the
//    instruction cache: none of them steal cycles here.
//  - Pixel processing other than replace (boolean, arithmetic, transparency, plane masks).
//  - Time between frames: each frame's clock starts at 0 with its FRAME_BEGIN, bus and
//    controller idle.
//
// Commands outside a frame (before the first FRAME_BEGIN, or after a FRAME_END and before
// the next FRAME_BEGIN) find no framebuffer to draw in: they write nothing, are counted
// as outside in ControllerStats::unframed and cost C_cmd plus their bus time. A
// FRAME_BEGIN arriving inside an open frame first closes that frame as incomplete.
#include "controller_sim/controller.h"

#include <stdexcept>
#include <variant>

#include <fmt/format.h>

namespace fb89::controller {

using protocol::Command;
using protocol::Opcode;
using protocol::opcode_index;

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
    std::array<OpcodeEntry, protocol::kOpcodeCount> t = {{
        {"FRAME_BEGIN", 4, 0, 0, &Controller::exec_frame_begin},
        {"FILL_RECT", 5, 0, 0, &Controller::exec_fill_rect},
        {"DRAW_SPAN", 4, 0, 0, &Controller::exec_draw_span},
        {"MARKER", 1, 0, 0, &Controller::exec_marker},
        {"FRAME_END", 0, 0, 0, &Controller::exec_frame_end},
    }};
    for (int i = 0; i < protocol::kOpcodeCount; ++i) {
        t[i].bytes = p.bytes[i];
        t[i].bus_us = bus_seconds(p, p.bytes[i]) * 1e6;
    }
    return t;
}

Controller::Controller(CostProfile profile)
    : m_opcodes(make_opcode_table(profile)), m_us_per_cycle(1e6 / profile.f_cyc_hz) {
    m_stats.profile = std::move(profile);
}

void Controller::frame_begin(const protocol::FrameBegin& c) {
    execute(Command{c});
}
void Controller::fill_rect(const protocol::FillRect& c) {
    execute(Command{c});
}
void Controller::draw_span(const protocol::DrawSpan& c) {
    execute(Command{c});
}
void Controller::marker(const protocol::Marker& c) {
    execute(Command{c});
}
void Controller::frame_end(const protocol::FrameEnd& c) {
    execute(Command{c});
}

void Controller::execute(const Command& c) {
    const int op = static_cast<int>(c.index());  // variant order follows the opcodes
    const OpcodeEntry& e = m_opcodes[op];
    const Executed x = (this->*e.exec)(c);
    account(op, e, x);
    if (op == opcode_index(Opcode::FrameEnd) && m_in_frame) close_frame(true);
    if (m_observer) m_observer(m_next_command - 1, c);
}

// FRAME_BEGIN: size the framebuffer and clear it; charged as one full-screen fill.
Controller::Executed Controller::exec_frame_begin(const Command& c) {
    const auto& f = std::get<protocol::FrameBegin>(c);
    if (f.width > kMaxFrameSide || f.height > kMaxFrameSide)
        throw std::invalid_argument(
            fmt::format("command {}: {}: frame size exceeds the maximum {}x{}", m_next_command,
                        protocol::to_string(c), kMaxFrameSide, kMaxFrameSide));
    if (m_in_frame) close_frame(false);

    m_fb.resize(f.width, f.height);
    m_fb.clear(f.background);
    m_in_frame = true;
    m_frame = FrameResult{};
    m_frame.frame = f.frame;
    m_frame.width = f.width;
    m_frame.height = f.height;
    m_frame.first_command = m_next_command;
    m_frame_pipe.reset();
    return Executed{frame_begin_cycles(profile(), f.width, f.height), uint64_t{f.width} * f.height,
                    false, false};
}

// FILL_RECT: clip to the framebuffer, fill what is left.
Controller::Executed Controller::exec_fill_rect(const Command& c) {
    const auto& f = std::get<protocol::FillRect>(c);
    const auto clip = m_in_frame ? clip_fill_rect(f, m_fb.width(), m_fb.height()) : std::nullopt;
    if (!clip) return Executed{command_only_cycles(profile()), 0, false, true};
    m_fb.fill_rect(clip->rect, f.color);
    return Executed{fill_rect_cycles(profile(), clip->rect), clip->rect.pixels(), clip->clipped,
                    false};
}

// DRAW_SPAN: clip to the framebuffer, draw what is left as a line or a one-row fill.
Controller::Executed Controller::exec_draw_span(const Command& c) {
    const auto& s = std::get<protocol::DrawSpan>(c);
    const auto clip = m_in_frame ? clip_span(s, m_fb.width(), m_fb.height()) : std::nullopt;
    if (!clip) return Executed{command_only_cycles(profile()), 0, false, true};
    const PixelRect& r = clip->rect;
    m_fb.draw_span(r.y, r.x, r.w, s.color);
    return Executed{draw_span_cycles(profile(), r.x, r.w), r.w, clip->clipped, false};
}

// MARKER: a label for the host's phases; never sent to the modelled hardware (0 bytes).
Controller::Executed Controller::exec_marker(const Command&) {
    return Executed{};
}

// FRAME_END: fetch and decode; execute() then closes the frame and takes its checksum.
Controller::Executed Controller::exec_frame_end(const Command&) {
    return Executed{command_only_cycles(profile()), 0, false, !m_in_frame};
}

void Controller::account(int op, const OpcodeEntry& e, const Executed& x) {
    // counters
    OpcodeCounters delta;
    delta.commands = 1;
    delta.pixels = x.pixels;
    delta.bytes = e.bytes;
    delta.cycles = x.cycles;
    delta.clipped = x.clipped ? 1 : 0;
    delta.outside = x.outside ? 1 : 0;
    (m_in_frame ? m_frame.ops : m_stats.unframed)[op] += delta;
    m_stats.totals[op] += delta;

    // time
    const double exec_us = static_cast<double>(x.cycles) * m_us_per_cycle;
    (m_in_frame ? m_frame_pipe : m_unframed_pipe).push(e.bus_us, exec_us);
    m_stats.bus_busy_us += e.bus_us;
    m_stats.controller_busy_us += exec_us;
    ++m_next_command;
}

void Controller::close_frame(bool complete) {
    m_frame.complete = complete;
    m_frame.checksum = m_fb.checksum();
    m_frame.bus_busy_us = m_frame_pipe.bus_busy_us();
    m_frame.controller_busy_us = m_frame_pipe.controller_busy_us();
    m_frame.end_us = m_frame_pipe.end_us();
    m_stats.frames_end_us += m_frame.end_us;
    m_stats.frames.push_back(m_frame);
    m_in_frame = false;
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
