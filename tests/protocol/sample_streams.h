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
#include "protocol/stream_writer.h"

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

// A stream of every kind of record, as a renderer with send times and depth commands writes
// it: frame 0 with markers, a fill, a span, a depth buffer, a DEPTH_SPAN and a FACE between send
// times and its HOST_END; frame 1 of `spans` spans sent in packets of 64 (300: two batches and
// more in version 4); frame 2 a fill; then (closed) the frame index. The commands beside the
// bytes.
struct WrittenStream {
    std::vector<uint8_t> bytes;
    std::vector<Command> commands;
};

inline WrittenStream mixed_stream(Checksums checksums = Checksums::On, int spans = 300,
                                  bool close = true) {
    StreamWriter w(sample_properties(), Timing::Timed, Commands::Depth, checksums);
    WrittenStream out;
    const auto send = [&](Command c) {
        out.commands.push_back(c);
        w.submit(c);
    };
    send(FrameBegin{0, 8, 6, Rgb{0, 0, 0}});
    send(Marker{"zbuffer"});
    w.send_time(100);
    send(FillRect{0, 0, 4, 4, Rgb{255, 0, 0}});
    send(DrawSpan{5, 1, 6, Rgb{0, 255, 0}});
    send(DepthClear{});
    send(DepthSpan{2, 0, 7, 1u << 27, -4096, Rgb{0, 0, 255}});
    w.send_time(250);
    send(Face{Rgb{255, 255, 0},
              2,
              2,
              1u << 26,
              512,
              -256,
              {{256, 256}, {6 * 256, 512}, {3 * 256, 5 * 256}}});
    send(Marker{"done"});
    w.host_end(300);
    send(FrameEnd{});
    send(FrameBegin{1, 16, 12, Rgb{0, 0, 64}});
    for (int i = 0; i < spans; ++i) {
        if (i % 64 == 0) w.send_time(1000 + i);
        send(DrawSpan{i % 12, i % 16, 15, Rgb{static_cast<uint8_t>(i), 9, 9}});
    }
    send(FrameEnd{});
    send(FrameBegin{2, 8, 6, Rgb{9, 9, 9}});
    send(FillRect{1, 1, 2, 2, Rgb{1, 2, 3}});
    send(FrameEnd{});
    if (close) w.close();
    out.bytes = w.take_bytes();
    return out;
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
