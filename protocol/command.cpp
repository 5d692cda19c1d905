#include "protocol/command.h"

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
    }
    return "UNKNOWN";
}

std::string to_string(Rgb c) {
    return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

Opcode opcode_of(const Command& c) {
    return static_cast<Opcode>(c.index() + 1);  // variant order follows the opcodes
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
    }
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
