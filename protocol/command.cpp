#include "protocol/command.h"

#include <stdexcept>

#include <fmt/format.h>

#include "protocol/command_sink.h"
#include "protocol/memory_buffer.h"

namespace fb89::protocol {

const char* to_string(Opcode op) {
    const CommandRow* row = command_row(static_cast<uint8_t>(op));
    return row ? row->name : "UNKNOWN";
}

std::string to_string(Rgb c) {
    return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

Opcode opcode_of(const Command& c) {
    return kOpcodes[c.index()];  // variant order follows the opcodes
}

namespace {

std::string value_text(int32_t v) {
    return std::to_string(v);
}
std::string value_text(uint32_t v) {
    return std::to_string(v);
}
std::string value_text(Rgb c) {
    return to_string(c);
}

}  // namespace

// NAME, each field as name=value, then the tail: a MARKER's text in quotes, a FACE's point
// count and points.
std::string to_string(const Command& c) {
    return std::visit(
        [](const auto& command) {
            using C = std::decay_t<decltype(command)>;
            std::string out = CommandInfo<C>::name;
            for_each_field(command, [&](const auto& value, const auto& field) {
                out += fmt::format(" {}={}", field.name, value_text(value));
            });
            if constexpr (CommandInfo<C>::tail == Tail::Text) {
                out += fmt::format(" \"{}\"", command.text);
            } else if constexpr (CommandInfo<C>::tail == Tail::Points) {
                out += fmt::format(" points={}", command.points.size());
                for (const SnappedPoint& p : command.points)
                    out += fmt::format(" ({},{})", p.x, p.y);
            }
            return out;
        },
        c);
}

std::optional<std::string> CommandInfo<FrameBegin>::check(const FrameBegin& c) {
    for (const auto& [name, v] : {std::pair{"width", c.width}, std::pair{"height", c.height}})
        if (v == 0 || v > kMaxFrameDimension)
            return fmt::format("{} {} is outside 1..{}", name, v, kMaxFrameDimension);
    return std::nullopt;
}

std::optional<std::string> CommandInfo<DrawSpan>::check(const DrawSpan& c) {
    if (c.x1 < c.x0) return fmt::format("x1 {} < x0 {}", c.x1, c.x0);
    return std::nullopt;
}

std::optional<std::string> CommandInfo<Marker>::check(const Marker& c) {
    if (c.text.size() > kMaxMarkerLength)
        return fmt::format("text of {} bytes is longer than {}", c.text.size(), kMaxMarkerLength);
    return std::nullopt;
}

std::optional<std::string> CommandInfo<DepthSpan>::check(const DepthSpan& c) {
    if (c.x1 < c.x0) return fmt::format("x1 {} < x0 {}", c.x1, c.x0);
    return std::nullopt;
}

std::optional<std::string> CommandInfo<Face>::check(const Face& c) {
    if (c.points.size() < 3 || c.points.size() > kMaxFacePoints)
        return fmt::format("{} points, outside 3..{}", c.points.size(), kMaxFacePoints);
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        const SnappedPoint& p = c.points[i];
        if (p.x < -kMaxFaceCoordinate || p.x > kMaxFaceCoordinate || p.y < -kMaxFaceCoordinate ||
            p.y > kMaxFaceCoordinate)
            return fmt::format("point {} ({}, {}) is outside +-{} grid units", i, p.x, p.y,
                               kMaxFaceCoordinate);
    }
    return std::nullopt;
}

std::optional<std::string> check_command(const Command& c) {
    return std::visit(
        [](const auto& command) -> std::optional<std::string> {
            using I = CommandInfo<std::decay_t<decltype(command)>>;
            if constexpr (requires { I::check(command); })
                return I::check(command);
            else
                return std::nullopt;
        },
        c);
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
