// Tests of protocol/command.h: opcode names, to_string of every command (used in test
// messages and `fb89 dump`), and CommandSink::submit dispatch.
#include "protocol/command.h"

#include <gtest/gtest.h>

#include <iterator>
#include <string>
#include <vector>

#include "protocol/command_sink.h"
#include "protocol/memory_buffer.h"

namespace fb89::protocol {
namespace {

TEST(Command, OpcodeNamesAreTheSpecNames) {
    EXPECT_STREQ(to_string(Opcode::FrameBegin), "FRAME_BEGIN");
    EXPECT_STREQ(to_string(Opcode::FillRect), "FILL_RECT");
    EXPECT_STREQ(to_string(Opcode::DrawSpan), "DRAW_SPAN");
    EXPECT_STREQ(to_string(Opcode::Marker), "MARKER");
    EXPECT_STREQ(to_string(Opcode::FrameEnd), "FRAME_END");
    EXPECT_STREQ(to_string(static_cast<Opcode>(0x7f)), "UNKNOWN");
}

TEST(Command, OpcodeValuesAreFixedByVersion1) {
    EXPECT_EQ(static_cast<int>(Opcode::FrameBegin), 1);
    EXPECT_EQ(static_cast<int>(Opcode::FillRect), 2);
    EXPECT_EQ(static_cast<int>(Opcode::DrawSpan), 3);
    EXPECT_EQ(static_cast<int>(Opcode::Marker), 4);
    EXPECT_EQ(static_cast<int>(Opcode::FrameEnd), 5);
    EXPECT_EQ(opcode_index(Opcode::FrameBegin), 0);
    EXPECT_EQ(opcode_index(Opcode::FrameEnd), 4);
    // version 3's, after version 2's time records 0x06 and 0x07
    EXPECT_EQ(static_cast<int>(Opcode::DepthClear), 8);
    EXPECT_EQ(static_cast<int>(Opcode::DepthSpan), 9);
    EXPECT_EQ(static_cast<int>(Opcode::Face), 10);
    for (int i = 0; i < kOpcodeCount; ++i)
        EXPECT_EQ(opcode_index(kOpcodes[i]), i);
    EXPECT_EQ(opcode_index(Opcode::Face), kOpcodeCount - 1);
}

TEST(Command, OpcodeOfFollowsTheVariantAlternative) {
    EXPECT_EQ(opcode_of(FrameBegin{}), Opcode::FrameBegin);
    EXPECT_EQ(opcode_of(FillRect{}), Opcode::FillRect);
    EXPECT_EQ(opcode_of(DrawSpan{}), Opcode::DrawSpan);
    EXPECT_EQ(opcode_of(Marker{}), Opcode::Marker);
    EXPECT_EQ(opcode_of(FrameEnd{}), Opcode::FrameEnd);
}

TEST(Command, RgbToStringIsLowercaseHex) {
    EXPECT_EQ(to_string(Rgb{0xff, 0x0a, 0x00}), "#ff0a00");
    EXPECT_EQ(to_string(Rgb{}), "#000000");
}

TEST(Command, ToStringDescribesEveryFieldOnOneLine) {
    EXPECT_EQ(to_string(Command{FrameBegin{3, 1024, 780, Rgb{0, 0, 0x40}}}),
              "FRAME_BEGIN frame=3 width=1024 height=780 background=#000040");
    EXPECT_EQ(to_string(Command{FillRect{-2, 5, 4, 3, Rgb{0xff, 0, 0}}}),
              "FILL_RECT x=-2 y=5 w=4 h=3 color=#ff0000");
    EXPECT_EQ(to_string(Command{DrawSpan{7, 0, 99, Rgb{0, 0xff, 0}}}),
              "DRAW_SPAN y=7 x0=0 x1=99 color=#00ff00");
    EXPECT_EQ(to_string(Command{Marker{"scan-line"}}), "MARKER \"scan-line\"");
    EXPECT_EQ(to_string(Command{FrameEnd{}}), "FRAME_END");
    EXPECT_EQ(to_string(Command{DepthSpan{4, -1, 2, 268435456, -5, Rgb{1, 2, 3}}}),
              "DEPTH_SPAN y=4 x0=-1 x1=2 z=268435456 dz=-5 color=#010203");
    EXPECT_EQ(
        to_string(Command{Face{Rgb{9, 9, 9}, 1, 2, 300, -4, 5, {{0, 0}, {256, 0}, {0, 512}}}}),
        "FACE color=#090909 x_ref=1 y_ref=2 z=300 dzdx=-4 dzdy=5 points=3 (0,0) (256,0) "
        "(0,512)");
}

// The table: each command's row names it, its opcode, the format that first carries it and
// what its record and its host-port words hold, as docs/PROTOCOL.md and the listing's header
// give them.
TEST(Command, TheRowsGiveEachCommandsNameVersionAndWords) {
    struct Expect {
        Opcode op;
        const char* name;
        uint16_t since;
        uint32_t port_words;
    };
    const Expect expect[] = {
        {Opcode::FrameBegin, "FRAME_BEGIN", 1, 5}, {Opcode::FillRect, "FILL_RECT", 1, 6},
        {Opcode::DrawSpan, "DRAW_SPAN", 1, 5},     {Opcode::Marker, "MARKER", 1, 0},
        {Opcode::FrameEnd, "FRAME_END", 1, 1},     {Opcode::DepthClear, "DEPTH_CLEAR", 3, 1},
        {Opcode::DepthSpan, "DEPTH_SPAN", 3, 9},   {Opcode::Face, "FACE", 3, 11}};
    ASSERT_EQ(std::size(expect), static_cast<std::size_t>(kOpcodeCount));
    for (int i = 0; i < kOpcodeCount; ++i) {
        const CommandRow& row = kCommandRows[i];
        EXPECT_EQ(row.opcode, expect[i].op);
        EXPECT_STREQ(row.name, expect[i].name);
        EXPECT_EQ(row.since, expect[i].since) << row.name;
        EXPECT_EQ(row.port_words, expect[i].port_words) << row.name;
        EXPECT_EQ(is_depth_opcode(row.opcode), row.since >= kDepthVersion);
        EXPECT_EQ(command_row(static_cast<uint8_t>(row.opcode)), &row);
    }
    EXPECT_EQ(command_row(6), nullptr);  // version 2's time records are no commands
    EXPECT_EQ(command_row(0), nullptr);
    EXPECT_EQ(opcode_index(static_cast<Opcode>(0x7f)), -1);
    EXPECT_FALSE(is_depth_opcode(static_cast<Opcode>(0x7f)));
}

TEST(Command, EachRowsCheckIsCheckCommands) {
    EXPECT_EQ(check_command(FrameBegin{0, 0, 10, {}}), "width 0 is outside 1..16384");
    EXPECT_EQ(check_command(FrameBegin{0, 10, 16385, {}}), "height 16385 is outside 1..16384");
    EXPECT_EQ(check_command(DrawSpan{0, 5, 4, {}}), "x1 4 < x0 5");
    EXPECT_EQ(check_command(DepthSpan{0, 5, 4, 0, 0, {}}), "x1 4 < x0 5");
    EXPECT_EQ(check_command(Face{}), "0 points, outside 3..64");
    EXPECT_EQ(check_command(Marker{std::string(kMaxMarkerLength + 1, 'm')}),
              "text of 1025 bytes is longer than 1024");
    EXPECT_EQ(check_command(FillRect{-5, -5, 0, 0, {}}), std::nullopt);  // no check of its own
}

// Records which sink call each submitted command reached.
class CallRecorder final : public CommandSink {
  public:
    std::vector<std::string> calls;
    void frame_begin(const FrameBegin&) override { calls.push_back("frame_begin"); }
    void fill_rect(const FillRect&) override { calls.push_back("fill_rect"); }
    void draw_span(const DrawSpan&) override { calls.push_back("draw_span"); }
    void marker(const Marker&) override { calls.push_back("marker"); }
    void frame_end(const FrameEnd&) override { calls.push_back("frame_end"); }
};

TEST(CommandSink, SubmitCallsTheMatchingMethod) {
    CallRecorder sink;
    for (const Command& c :
         std::vector<Command>{FrameEnd{}, Marker{}, DrawSpan{}, FillRect{}, FrameBegin{}}) {
        sink.submit(c);
    }
    EXPECT_EQ(sink.calls, (std::vector<std::string>{"frame_end", "marker", "draw_span", "fill_rect",
                                                    "frame_begin"}));
}

}  // namespace
}  // namespace fb89::protocol
