// Small command sequences shared by the protocol tests -- one command of every opcode with
// extreme field values, and a two-frame stream like a renderer would emit -- and a helper
// that reads a stream to its end or its first error.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "protocol/command.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_format.h"
#include "protocol/stream_reader.h"

namespace fb89::protocol::testing {

// Every opcode, with field values at the edges of their widths and signedness.
inline std::vector<Command> every_opcode() {
    constexpr int32_t kMin = std::numeric_limits<int32_t>::min();
    constexpr int32_t kMax = std::numeric_limits<int32_t>::max();
    constexpr uint32_t kMaxU = std::numeric_limits<uint32_t>::max();
    return {
        FrameBegin{kMaxU, 1, kMaxFrameDimension, Rgb{0x01, 0x80, 0xff}},
        FillRect{kMin, kMax, kMaxU, 0, Rgb{0xff, 0x00, 0x7f}},
        FillRect{-3, 5, 7, 9, Rgb{1, 2, 3}},
        DrawSpan{kMin, kMin, kMax, Rgb{0x10, 0x20, 0x30}},
        DrawSpan{-1, -1, -1, Rgb{}},
        Marker{""},
        Marker{"phase: r\xc3\xa9solution \"quoted\"\n"},
        Marker{std::string(kMaxMarkerLength, 'm')},
        FrameEnd{},
    };
}

// Two frames as a renderer would send them: markers, fills and spans.
inline std::vector<Command> two_frames() {
    return {
        FrameBegin{0, 8, 6, Rgb{0, 0, 0}}, Marker{"warnock"}, FillRect{0, 0, 4, 4, Rgb{255, 0, 0}},
        DrawSpan{5, 1, 6, Rgb{0, 255, 0}}, FrameEnd{},        FrameBegin{1, 8, 6, Rgb{0, 0, 64}},
        DrawSpan{0, 0, 7, Rgb{0, 0, 255}}, Marker{"done"},    FrameEnd{},
    };
}

inline Properties sample_properties() {
    return {{"method", "warnock"},
            {"resolution", "8x6"},
            {"scene", "scenes/ideal.json"},
            {"threshold", "16"},
            {"tool", "fb89 0.1.0"}};
}

// What reading a stream to its end gives: the commands delivered, and the error, if any.
struct ReadResult {
    std::vector<Command> commands;
    std::optional<StreamError> error;
    std::optional<FrameIndex> index;
};

inline ReadResult read_all(std::vector<uint8_t> bytes, const std::string& name = "stream.fb89") {
    ReadResult result;
    MemoryBuffer buffer;
    try {
        StreamReader reader(std::move(bytes), name);
        reader.replay_into(buffer);
        result.index = reader.frame_index();
    } catch (const StreamError& e) {
        result.error = e;
    }
    result.commands = buffer.commands();
    return result;
}

}  // namespace fb89::protocol::testing
