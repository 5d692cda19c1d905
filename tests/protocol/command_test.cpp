// Tests of protocol/command.h: opcode names, to_string of every command (used in test
// messages and `fb89 dump`), and CommandSink::submit dispatch.
#include "protocol/command.h"

#include <gtest/gtest.h>

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
