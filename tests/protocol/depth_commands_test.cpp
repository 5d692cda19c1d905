// Stream format version 3 (docs/PROTOCOL.md, "Version 3: depth commands"): the depth
// commands' encoding, the spec's example, the version a writer picks without checksums, and
// what readers refuse (version 4 carries the depth commands as version 3 does).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "protocol/depth_fixed.h"
#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

std::vector<Command> read_commands(Bytes bytes) {
    StreamReader r(std::move(bytes));
    std::vector<Command> out;
    Command c;
    while (r.next(c))
        out.push_back(c);
    return out;
}

std::string read_error(Bytes bytes) {
    try {
        read_commands(std::move(bytes));
    } catch (const StreamError& e) {
        return e.what();
    }
    return "";
}

TEST(StreamFormat, Version3ExampleIsWhatTheWriterProduces) {
    StreamWriter w(Properties{}, Timing::Untimed, Commands::Depth, Checksums::Off);
    w.submit(FrameBegin{0, 4, 3, Rgb{0, 0, 0}});
    w.submit(DepthClear{});
    w.submit(DepthSpan{1, 0, 2, 0x08000000u, -1, Rgb{0, 255, 0}});
    w.submit(FrameEnd{});
    const Bytes expected = {0x46, 0x42, 0x38, 0x39, 0x03, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                            0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x03,
                            0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x08, 0x09, 0x01, 0x00, 0x00,
                            0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00,
                            0x00, 0x08, 0xff, 0xff, 0xff, 0xff, 0x00, 0xff, 0x00, 0x05};
    EXPECT_EQ(w.bytes(), expected);
}

TEST(DepthCommands, EveryFieldRoundTripsThroughAVersion3Stream) {
    const std::vector<Command> commands = {
        FrameBegin{7, 64, 48, Rgb{1, 2, 3}}, DepthClear{},
        DepthSpan{-5, -100, 2000, kDepthOne, std::numeric_limits<int32_t>::min(), Rgb{9, 8, 7}},
        Face{Rgb{4, 5, 6},
             -3,
             1 << 20,
             12345,
             -77,
             std::numeric_limits<int32_t>::max(),
             {{0, 0}, {kMaxFaceCoordinate, -kMaxFaceCoordinate}, {-kMaxFaceCoordinate, 256}}},
        FrameEnd{}};
    for (const Checksums checksums : {Checksums::Off, Checksums::On})
        for (const Timing timing : {Timing::Untimed, Timing::Timed}) {
            StreamWriter w(Properties{}, timing, Commands::Depth, checksums);
            for (const Command& c : commands)
                w.submit(c);
            w.close();
            StreamReader r(w.take_bytes());
            EXPECT_EQ(r.version(), checksums == Checksums::On ? kChecksumVersion : kDepthVersion);
            EXPECT_EQ(r.timed(), timing == Timing::Timed);
            Command c;
            std::vector<Command> got;
            while (r.next(c))
                got.push_back(c);
            EXPECT_EQ(got, commands);
        }
}

TEST(DepthCommands, WithoutChecksumsAWriterPicksTheOldestVersionThatCarriesItsCommands) {
    const Checksums off = Checksums::Off;
    EXPECT_EQ(StreamWriter(Properties{}, Timing::Untimed, Commands::Tiling, off).version(),
              kUntimedVersion);
    EXPECT_EQ(StreamWriter(Properties{}, Timing::Timed, Commands::Tiling, off).version(),
              kTimedVersion);
    EXPECT_EQ(StreamWriter(Properties{}, Timing::Untimed, Commands::Depth, off).version(),
              kDepthVersion);
    EXPECT_EQ(encode_stream({FrameBegin{0, 2, 2, {}}, FrameEnd{}}, {}, true, off)[4],
              kUntimedVersion);
    EXPECT_EQ(encode_stream({FrameBegin{0, 2, 2, {}}, DepthClear{}, FrameEnd{}}, {}, true, off)[4],
              kDepthVersion);
    // with checksums, version 4, which carries them all
    EXPECT_EQ(encode_stream({FrameBegin{0, 2, 2, {}}, DepthClear{}, FrameEnd{}})[4],
              kChecksumVersion);
    StreamWriter v4(Properties{});
    EXPECT_TRUE(v4.depth());
    v4.submit(FrameBegin{0, 2, 2, {}});
    EXPECT_NO_THROW(v4.submit(DepthClear{}));
    // a version-1 writer refuses a depth command before writing a byte of it
    StreamWriter w(Properties{}, Timing::Untimed, Commands::Tiling, off);
    w.submit(FrameBegin{0, 2, 2, {}});
    const std::size_t before = w.bytes().size();
    try {
        w.submit(DepthClear{});
        ADD_FAILURE() << "a version-1 writer took a DEPTH_CLEAR";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("needs format version 3"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(w.bytes().size(), before);
}

TEST(DepthCommands, OlderVersionsAndBadRecordsAreRefusedNamingTheByte) {
    const Bytes v3 = encode_stream({FrameBegin{0, 4, 3, {}}, DepthClear{}, FrameEnd{}}, {}, false,
                                   Checksums::Off);
    Bytes as_v2 = v3;
    as_v2[4] = 2;
    EXPECT_NE(read_error(as_v2).find("at byte 28"), std::string::npos) << read_error(as_v2);
    EXPECT_NE(read_error(as_v2).find("needs format version 3"), std::string::npos);
    Bytes flags = v3;
    flags[6] = 0x02;
    EXPECT_NE(read_error(flags).find("header flags"), std::string::npos) << read_error(flags);
    // a FACE of 2 points, and one of 65, and one cut inside its points
    Bytes face = encode_stream(
        {FrameBegin{0, 4, 3, {}}, Face{{}, 0, 0, 0, 0, 0, {{0, 0}, {256, 0}, {0, 256}}}}, {}, false,
        Checksums::Off);
    for (const uint8_t n : {uint8_t{2}, uint8_t{65}}) {
        Bytes bad = face;
        bad[29] = n;
        EXPECT_NE(read_error(bad).find("points, outside 3..64"), std::string::npos)
            << read_error(bad);
    }
    Bytes cut = face;
    cut.resize(cut.size() - 3);
    EXPECT_NE(read_error(cut).find("truncated FACE"), std::string::npos) << read_error(cut);
    // a DEPTH_SPAN with x1 < x0, through the fast path and the general one alike
    Bytes span = encode_stream({FrameBegin{0, 4, 3, {}}, DepthSpan{0, 1, 2, 0, 0, {}}}, {}, false,
                               Checksums::Off);
    span[29 + 8] = 0;  // x1 = 0 < x0 = 1
    EXPECT_NE(read_error(span).find("x1 0 < x0 1"), std::string::npos) << read_error(span);
}

TEST(DepthFixed, TheFarPlaneStaysNearerThanACleared16BitWord) {
    EXPECT_EQ(depth_fixed(0), 0u);
    EXPECT_EQ(depth_fixed(1), kDepthOne);
    EXPECT_EQ(depth_fixed(-0.5), 0u);
    EXPECT_EQ(depth_fixed(2), kDepthOne);
    EXPECT_LT(stored_depth(kDepthOne, 16), depth_clear_value(16));
    EXPECT_LT(stored_depth(kDepthOne, 32), depth_clear_value(32));
    EXPECT_EQ(stored_depth(-5, 16), 0u);
    EXPECT_EQ(stored_depth(int64_t{1} << 40, 32), kDepthOne);
    EXPECT_EQ(stored_depth(4096 * 3 + 4095, 16), 3u);
    EXPECT_FALSE(slope_fixed(8.01).has_value());
    EXPECT_TRUE(slope_fixed(-8.0).has_value());
    EXPECT_EQ(slope_fixed(-1.0 / kDepthOne).value(), -1);
    EXPECT_DOUBLE_EQ(depth_step(16), 4096.0 / kDepthOne);
}

}  // namespace
}  // namespace fb89::protocol
