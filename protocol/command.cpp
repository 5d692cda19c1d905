#include "protocol/command.h"

#include <stdexcept>

#include <fmt/format.h>

#include "protocol/command_sink.h"
#include "protocol/memory_buffer.h"

namespace fb89::protocol {

const char* to_string(Opcode op) {
    switch (op) {
        case Opcode::FrameBegin:
            return "FRAME_BEGIN";
        case Opcode::FillRect:
            return "FILL_RECT";
        case Opcode::DrawSpan:
            return "DRAW_SPAN";
        case Opcode::Marker:
            return "MARKER";
        case Opcode::FrameEnd:
            return "FRAME_END";
        case Opcode::DepthClear:
            return "DEPTH_CLEAR";
        case Opcode::DepthSpan:
            return "DEPTH_SPAN";
        case Opcode::Face:
            return "FACE";
    }
    return "UNKNOWN";
}

std::string to_string(Rgb c) {
    return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

Opcode opcode_of(const Command& c) {
    return kOpcodes[c.index()];  // variant order follows the opcodes
}

namespace {
struct Describe {
    std::string operator()(const FrameBegin& c) const {
        return fmt::format("FRAME_BEGIN frame={} width={} height={} background={}", c.frame,
                           c.width, c.height, to_string(c.background));
    }
    std::string operator()(const FillRect& c) const {
        return fmt::format("FILL_RECT x={} y={} w={} h={} color={}", c.x, c.y, c.w, c.h,
                           to_string(c.color));
    }
    std::string operator()(const DrawSpan& c) const {
        return fmt::format("DRAW_SPAN y={} x0={} x1={} color={}", c.y, c.x0, c.x1,
                           to_string(c.color));
    }
    std::string operator()(const Marker& c) const { return fmt::format("MARKER \"{}\"", c.text); }
    std::string operator()(const FrameEnd&) const { return "FRAME_END"; }
    std::string operator()(const DepthClear&) const { return "DEPTH_CLEAR"; }
    std::string operator()(const DepthSpan& c) const {
        return fmt::format("DEPTH_SPAN y={} x0={} x1={} z={} dz={} color={}", c.y, c.x0, c.x1, c.z,
                           c.dz, to_string(c.color));
    }
    std::string operator()(const Face& c) const {
        std::string points;
        for (const SnappedPoint& p : c.points)
            points += fmt::format(" ({},{})", p.x, p.y);
        return fmt::format("FACE ref=({},{}) z={} dzdx={} dzdy={} color={} points={}{}", c.x_ref,
                           c.y_ref, c.z, c.dzdx, c.dzdy, to_string(c.color), c.points.size(),
                           points);
    }
};
}  // namespace

std::string to_string(const Command& c) {
    return std::visit(Describe{}, c);
}

void CommandSink::submit(const Command& c) {
    switch (c.index()) {
        case 0:
            frame_begin(std::get<FrameBegin>(c));
            break;
        case 1:
            fill_rect(std::get<FillRect>(c));
            break;
        case 2:
            draw_span(std::get<DrawSpan>(c));
            break;
        case 3:
            marker(std::get<Marker>(c));
            break;
        case 4:
            frame_end(std::get<FrameEnd>(c));
            break;
        case 5:
            depth_clear(std::get<DepthClear>(c));
            break;
        case 6:
            depth_span(std::get<DepthSpan>(c));
            break;
        case 7:
            face(std::get<Face>(c));
            break;
    }
}

namespace {
[[noreturn]] void refuse(const Command& c) {
    throw std::invalid_argument(fmt::format(
        "{}: this sink takes no depth commands (stream format version 3)", to_string(c)));
}
}  // namespace

void CommandSink::depth_clear(const DepthClear& c) {
    refuse(c);
}
void CommandSink::depth_span(const DepthSpan& c) {
    refuse(c);
}
void CommandSink::face(const Face& c) {
    refuse(c);
}

void MemoryBuffer::replay_into(CommandSink& sink) const {
    for (const Command& c : m_commands)
        sink.submit(c);
}

void MemoryBuffer::time_packets(uint32_t commands_per_packet) {
    m_packet = commands_per_packet;
    m_hook = nullptr;
    m_unstamped = 0;
    m_stamps.clear();
    m_origin = std::chrono::steady_clock::now();
}

std::vector<double> MemoryBuffer::send_times_us() {
    std::vector<double> out;
    if (!m_packet || m_hook) return out;
    if (m_stamps.empty() || m_stamps.back().end < m_commands.size()) stamp();
    out.reserve(m_commands.size());
    for (const Stamp& s : m_stamps) {
        const double us = std::chrono::duration<double, std::micro>(s.at - m_origin).count();
        out.resize(s.end, us);
    }
    return out;
}

}  // namespace fb89::protocol
