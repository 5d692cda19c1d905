// Tests of protocol/stream_format.h: byte-exact little-endian fields, the record and header
// layouts of docs/PROTOCOL.md (including its hex example), and the field checks.
#include "protocol/stream_format.h"

#include <gtest/gtest.h>

#include "protocol/stream_writer.h"
#include "sample_streams.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

TEST(StreamFormat, IntegersAreLittleEndian) {
    Bytes out;
    put_u8(out, 0xab);
    put_u16(out, 0x1234);
    put_u32(out, 0x89abcdef);
    put_u64(out, 0x0102030405060708);
    EXPECT_EQ(out, (Bytes{0xab, 0x34, 0x12, 0xef, 0xcd, 0xab, 0x89, 0x08, 0x07, 0x06, 0x05, 0x04,
                          0x03, 0x02, 0x01}));
    EXPECT_EQ(get_u16(&out[1]), 0x1234);
    EXPECT_EQ(get_u32(&out[3]), 0x89abcdefu);
    EXPECT_EQ(get_u64(&out[7]), 0x0102030405060708u);
}

TEST(StreamFormat, SignedFieldsAreTwosComplement) {
    Bytes out;
    put_i32(out, -2);
    put_i32(out, std::numeric_limits<int32_t>::min());
    EXPECT_EQ(out, (Bytes{0xfe, 0xff, 0xff, 0xff, 0x00, 0x00, 0x00, 0x80}));
    EXPECT_EQ(get_i32(&out[0]), -2);
    EXPECT_EQ(get_i32(&out[4]), std::numeric_limits<int32_t>::min());
}

TEST(StreamFormat, RecordSizesAreFixedPerOpcode) {
    const auto size_of = [](const Command& c) {
        Bytes out;
        encode_command(out, c);
        return out.size();
    };
    EXPECT_EQ(size_of(FrameBegin{0, 1, 1, Rgb{}}), 16u);
    EXPECT_EQ(size_of(FrameBegin{0, 1, 1, Rgb{}}), kFrameBeginRecordSize);
    EXPECT_EQ(size_of(FillRect{}), 20u);
    EXPECT_EQ(size_of(DrawSpan{}), 16u);
    EXPECT_EQ(size_of(Marker{"abc"}), 6u);
    EXPECT_EQ(size_of(FrameEnd{}), 1u);
    EXPECT_EQ(payload_size(0x00), std::nullopt);
    EXPECT_EQ(payload_size(kIndexOpcode), std::nullopt);
}

TEST(StreamFormat, FillRectFieldsSitAtTheirSpecOffsets) {
    Bytes out;
    encode_command(out, FillRect{-1, 2, 3, 0x01000000, Rgb{0xaa, 0xbb, 0xcc}});
    EXPECT_EQ(out, (Bytes{0x02, 0xff, 0xff, 0xff, 0xff, 0x02, 0x00, 0x00, 0x00, 0x03,
                          0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0xaa, 0xbb, 0xcc}));
}

// The example of docs/PROTOCOL.md, byte for byte: the spec and the writer must agree.
TEST(StreamFormat, SpecHexExampleIsWhatTheWriterProduces) {
    const Bytes expected = {
        0x46, 0x42, 0x38, 0x39,                                // 0: magic "FB89"
        0x01, 0x00, 0x00, 0x00,                                // 4: version 1, flags 0
        0x01, 0x00, 0x00, 0x00,                                // 8: 1 property
        0x05, 0x00, 0x73, 0x63, 0x65, 0x6e, 0x65,              // 12: key "scene"
        0x05, 0x00, 0x00, 0x00, 0x69, 0x64, 0x65, 0x61, 0x6c,  // 19: value "ideal"
        0x01,                                                  // 28: FRAME_BEGIN
        0x00, 0x00, 0x00, 0x00,                                //     frame 0
        0x04, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00,        //     4 x 3
        0x00, 0x00, 0x00,                                      //     background #000000
        0x02,                                                  // 44: FILL_RECT
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //     x 0, y 0
        0x02, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,        //     w 2, h 2
        0xff, 0x00, 0x00,                                      //     #ff0000
        0x03,                                                  // 64: DRAW_SPAN
        0x02, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff,        //     y 2, x0 -1
        0x03, 0x00, 0x00, 0x00, 0x00, 0xff, 0x00,              //     x1 3, #00ff00
        0x04, 0x02, 0x00, 0x68, 0x69,                          // 80: MARKER "hi"
        0x05,                                                  // 85: FRAME_END
        0xfe, 0x01, 0x00, 0x00, 0x00,                          // 86: frame index, 1 entry:
        0x00, 0x00, 0x00, 0x00,                                //     frame 0
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //     command 0
        0x1c, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //     byte 28
        0x56, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        // 111: footer: index at byte 86
        0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //      5 commands
        0x46, 0x42, 0x49, 0x58};                               //      magic "FBIX"
    const std::vector<Command> commands = {
        FrameBegin{0, 4, 3, Rgb{}}, FillRect{0, 0, 2, 2, Rgb{0xff, 0, 0}},
        DrawSpan{2, -1, 3, Rgb{0, 0xff, 0}}, Marker{"hi"}, FrameEnd{}};
    EXPECT_EQ(encode_stream(commands, {{"scene", "ideal"}}, true, Checksums::Off), expected);
    EXPECT_EQ(expected.size(), 131u);
    // the cuts the spec describes below its example
    const testing::ReadResult cut86 =
        testing::read_all(Bytes(expected.begin(), expected.begin() + 86));
    EXPECT_FALSE(cut86.error);
    EXPECT_EQ(cut86.commands, commands);
    const testing::ReadResult cut70 =
        testing::read_all(Bytes(expected.begin(), expected.begin() + 70));
    ASSERT_TRUE(cut70.error);
    EXPECT_STREQ(cut70.error->what(),
                 "stream.fb89: truncated DRAW_SPAN at byte 64 (command 2): the "
                 "stream ends at byte 70");
    EXPECT_EQ(cut70.commands.size(), 2u);
}

TEST(StreamFormat, HeaderWritesPropertiesInKeyOrder) {
    Bytes out;
    encode_header(out, {{"b", ""}, {"a", "x"}});
    EXPECT_EQ(out, (Bytes{'F', 'B', '8', '9', 1, 0, 0, 0,   2, 0, 0, 0,  //
                          1,   0,   'a', 1,   0, 0, 0, 'x',              //
                          1,   0,   'b', 0,   0, 0, 0}));
}

TEST(StreamFormat, CheckCommandRejectsFieldsOutOfRange) {
    EXPECT_EQ(check_command(FrameBegin{0, 1, kMaxFrameDimension, Rgb{}}), std::nullopt);
    EXPECT_EQ(check_command(FrameBegin{0, 0, 1, Rgb{}}), "width 0 is outside 1..16384");
    EXPECT_EQ(check_command(FrameBegin{0, 1, 16385, Rgb{}}), "height 16385 is outside 1..16384");
    EXPECT_EQ(check_command(DrawSpan{0, 5, 5, Rgb{}}), std::nullopt);
    EXPECT_EQ(check_command(DrawSpan{0, 0, -3, Rgb{}}), "x1 -3 < x0 0");
    EXPECT_EQ(check_command(Marker{std::string(kMaxMarkerLength, 'x')}), std::nullopt);
    EXPECT_EQ(check_command(Marker{std::string(kMaxMarkerLength + 1, 'x')}),
              "text of 1025 bytes is longer than 1024");
    for (const Command& c : testing::every_opcode())
        EXPECT_EQ(check_command(c), std::nullopt);
}

TEST(StreamFormat, EncodersRefuseWhatVersion1CannotCarry) {
    Bytes out;
    EXPECT_THROW(encode_command(out, DrawSpan{0, 1, 0, Rgb{}}), std::invalid_argument);
    EXPECT_THROW(encode_header(out, {{"", "empty key"}}), std::invalid_argument);
    EXPECT_THROW(encode_header(out, {{std::string(kMaxPropertyKeyLength + 1, 'k'), ""}}),
                 std::invalid_argument);
    EXPECT_THROW(encode_header(out, {{"k", std::string(kMaxPropertyValueLength + 1, 'v')}}),
                 std::invalid_argument);
    EXPECT_TRUE(out.empty());
}

TEST(StreamFormat, CheckIndexRequiresEntriesInStreamOrder) {
    const Footer footer{100, 10};
    EXPECT_EQ(check_index({{0, 0, 12}, {1, 4, 40}}, 12, footer), std::nullopt);
    EXPECT_NE(check_index({{0, 0, 11}}, 12, footer), std::nullopt);              // in the header
    EXPECT_NE(check_index({{0, 0, 100}}, 12, footer), std::nullopt);             // at the index
    EXPECT_NE(check_index({{0, 10, 12}}, 12, footer), std::nullopt);             // no such command
    EXPECT_NE(check_index({{0, 4, 40}, {1, 0, 12}}, 12, footer), std::nullopt);  // backwards
    EXPECT_NE(check_index({{0, 0, 12}, {1, 0, 40}}, 12, footer), std::nullopt);  // same command
}

TEST(StreamFormat, FooterNeedsItsMagic) {
    Bytes out;
    encode_index(out, {}, Footer{0x1122, 7});
    ASSERT_EQ(out.size(), kIndexPrefixSize + kFooterSize);
    const std::optional<Footer> footer = decode_footer(&out[kIndexPrefixSize]);
    ASSERT_TRUE(footer);
    EXPECT_EQ(footer->index_offset, 0x1122u);
    EXPECT_EQ(footer->command_count, 7u);
    out.back() = 'Y';
    EXPECT_EQ(decode_footer(&out[kIndexPrefixSize]), std::nullopt);
}

}  // namespace
}  // namespace fb89::protocol
