// CommandSink's calls: the dispatch of a decoded command, and the defaults that hand every
// command to take(). Kept apart from the sinks that override take() (memory_buffer.h), so that
// no compiler inlines one of them into these defaults on a guess.
#include "protocol/command_sink.h"

#include <stdexcept>

#include <fmt/format.h>

namespace fb89::protocol {

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

void CommandSink::take(const Command& c) {
    if (is_depth_opcode(opcode_of(c)))
        throw std::invalid_argument(fmt::format(
            "{}: this sink takes no depth commands (stream format version 3)", to_string(c)));
    throw std::invalid_argument(
        fmt::format("{}: this sink takes no {}", to_string(c), to_string(opcode_of(c))));
}

void CommandSink::frame_begin(const FrameBegin& c) {
    take(c);
}
void CommandSink::fill_rect(const FillRect& c) {
    take(c);
}
void CommandSink::draw_span(const DrawSpan& c) {
    take(c);
}
void CommandSink::marker(const Marker& c) {
    take(c);
}
void CommandSink::frame_end(const FrameEnd& c) {
    take(c);
}
void CommandSink::depth_clear(const DepthClear& c) {
    take(c);
}
void CommandSink::depth_span(const DepthSpan& c) {
    take(c);
}
void CommandSink::face(const Face& c) {
    take(c);
}

}  // namespace fb89::protocol
