// Call sets (protocol/call_set.cpp): the grammar of docs/PROTOCOL.md "Call sets", matching,
// bounds for seeking, and errors that name the text and position.
#include "protocol/call_set.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/scratch.h"

namespace {

using fb89::protocol::CallSet;
using fb89::protocol::CallSetError;
using fb89::protocol::kNoLastCall;
using fb89::protocol::Opcode;

constexpr Opcode kFill = Opcode::FillRect;
constexpr Opcode kSpan = Opcode::DrawSpan;

// The message of the CallSetError parsing `text` throws ("" if it parses).
std::string call_set_error_of(const std::string& text) {
    try {
        CallSet::parse(text);
    } catch (const CallSetError& e) {
        return e.what();
    }
    return "";
}

TEST(CallSet, SingleNumberMatchesOnlyItself) {
    const CallSet s = CallSet::parse("4");
    EXPECT_TRUE(s.contains(4, kFill));
    EXPECT_FALSE(s.contains(3, kFill));
    EXPECT_FALSE(s.contains(5, kFill));
    EXPECT_EQ(s.first(), 4u);
    EXPECT_EQ(s.last(), 4u);
}

TEST(CallSet, ListMatchesEachItem) {
    const CallSet s = CallSet::parse("0, 2,4");
    for (uint64_t n : {0, 2, 4})
        EXPECT_TRUE(s.contains(n, kSpan)) << n;
    for (uint64_t n : {1, 3, 5})
        EXPECT_FALSE(s.contains(n, kSpan)) << n;
    EXPECT_EQ(s.to_string(), "0,2,4");
}

TEST(CallSet, RangeWithStepCountsFromItsStart) {
    const CallSet s = CallSet::parse("0-100/2");
    EXPECT_TRUE(s.contains(0, kFill));
    EXPECT_TRUE(s.contains(100, kFill));
    EXPECT_FALSE(s.contains(99, kFill));
    EXPECT_FALSE(s.contains(102, kFill));
    const CallSet odd = CallSet::parse("3-9/3");
    EXPECT_TRUE(odd.contains(3, kFill));
    EXPECT_TRUE(odd.contains(6, kFill));
    EXPECT_TRUE(odd.contains(9, kFill));
    EXPECT_FALSE(odd.contains(4, kFill));
}

TEST(CallSet, OpenRangeHasNoLastCall) {
    const CallSet s = CallSet::parse("100-");
    EXPECT_FALSE(s.contains(99, kFill));
    EXPECT_TRUE(s.contains(100, kFill));
    EXPECT_TRUE(s.contains(1'000'000'000'000, kFill));
    EXPECT_EQ(s.first(), 100u);
    EXPECT_EQ(s.last(), kNoLastCall);
    EXPECT_EQ(s.to_string(), "100-");
}

TEST(CallSet, FrameMeansTheCallsThatEndFrames) {
    const CallSet s = CallSet::parse("frame");
    EXPECT_TRUE(s.contains(7, Opcode::FrameEnd));
    EXPECT_FALSE(s.contains(7, Opcode::FrameBegin));
    EXPECT_FALSE(s.contains(7, kFill));
    EXPECT_EQ(s.to_string(), "frame");
}

TEST(CallSet, OpcodeFiltersRestrictAndCombine) {
    const CallSet spans = CallSet::parse("/span");
    EXPECT_TRUE(spans.contains(12345, kSpan));
    EXPECT_FALSE(spans.contains(12345, kFill));
    const CallSet both = CallSet::parse("10-20/fill/span");
    EXPECT_TRUE(both.contains(10, kFill));
    EXPECT_TRUE(both.contains(20, kSpan));
    EXPECT_FALSE(both.contains(15, Opcode::Marker));
    EXPECT_FALSE(both.contains(21, kSpan));
    const CallSet draw = CallSet::parse("*/draw");
    EXPECT_TRUE(draw.contains(1, kFill) && draw.contains(1, kSpan));
    EXPECT_EQ(draw.to_string(), "*/fill/span/zspan/face");
    const CallSet depth = CallSet::parse("/depth");
    EXPECT_TRUE(depth.contains(3, Opcode::DepthClear) && depth.contains(3, Opcode::Face));
    EXPECT_FALSE(depth.contains(3, kSpan));
    EXPECT_EQ(depth.to_string(), "*/zspan/face/zclear");
    const CallSet framing = CallSet::parse("/frame,/marker");
    EXPECT_TRUE(framing.contains(0, Opcode::FrameBegin));
    EXPECT_TRUE(framing.contains(0, Opcode::FrameEnd));
    EXPECT_TRUE(framing.contains(0, Opcode::Marker));
    EXPECT_FALSE(framing.contains(0, kSpan));
}

TEST(CallSet, StepAndFilterTogetherMatchEveryOtherNumberThatIsASpan) {
    const CallSet s = CallSet::parse("0-1000/2/span");
    EXPECT_TRUE(s.contains(500, kSpan));
    EXPECT_FALSE(s.contains(501, kSpan));
    EXPECT_FALSE(s.contains(500, kFill));
    EXPECT_EQ(CallSet::parse("0-1000/span/2").to_string(), "0-1000/2/span");
}

TEST(CallSet, ContainsNumberIgnoresFilters) {
    const CallSet s = CallSet::parse("3-5/fill");
    EXPECT_TRUE(s.contains_number(4));
    EXPECT_TRUE(s.has_opcode_filter());
    EXPECT_FALSE(CallSet::parse("3-5").has_opcode_filter());
}

TEST(CallSet, AllMatchesEverything) {
    EXPECT_TRUE(CallSet::all().contains(0, kFill));
    EXPECT_TRUE(CallSet::parse("*").contains(99, Opcode::Marker));
    EXPECT_EQ(CallSet::parse("*").last(), kNoLastCall);
    EXPECT_TRUE(CallSet().empty());
}

TEST(CallSet, FileItemReadsLinesAndSkipsComments) {
    const auto path = fb89::testing::scratch_path("call_set_test.txt");
    std::ofstream(path) << "# calls to look at\n1\n\n5-7  # the span run\n/marker\n";
    const CallSet s = CallSet::parse("@" + path.string() + ",100");
    EXPECT_TRUE(s.contains(1, kFill));
    EXPECT_TRUE(s.contains(6, kFill));
    EXPECT_TRUE(s.contains(50, Opcode::Marker));
    EXPECT_TRUE(s.contains(100, kFill));
    EXPECT_FALSE(s.contains(2, kFill));
    std::filesystem::remove(path);
}

TEST(CallSet, FileErrorsNameTheFileLineAndColumn) {
    const auto path = fb89::testing::scratch_path("call_set_bad.txt");
    std::ofstream(path) << "1\n2-x\n";
    const std::string e = call_set_error_of("@" + path.string());
    EXPECT_NE(e.find(path.string() + ":2:3:"), std::string::npos) << e;
    std::filesystem::remove(path);
    const std::string missing = call_set_error_of("@/nonexistent/calls.txt");
    EXPECT_NE(missing.find("cannot read call-set file '/nonexistent/calls.txt'"), std::string::npos)
        << missing;
}

TEST(CallSet, ErrorsNameTheTextAndPosition) {
    EXPECT_EQ(call_set_error_of("0-1x"),
              "call set '0-1x': at character 4: expected ',' or '/', found 'x'");
    EXPECT_NE(call_set_error_of("10-5").find("at character 4: range 10-5 ends before it starts"),
              std::string::npos)
        << call_set_error_of("10-5");
    EXPECT_NE(call_set_error_of("0-9/0").find("at character 5: step 0"), std::string::npos);
    EXPECT_NE(call_set_error_of("0-9/2/3").find("a second step"), std::string::npos);
    EXPECT_NE(call_set_error_of("/spans").find("unknown filter '/spans'"), std::string::npos)
        << call_set_error_of("/spans");
    EXPECT_NE(call_set_error_of("frame/span").find("'frame' takes no '/' suffix"),
              std::string::npos);
    EXPECT_NE(call_set_error_of("").find("empty call set"), std::string::npos);
    EXPECT_NE(call_set_error_of("1,,2").find("at character 3: empty item"), std::string::npos);
    EXPECT_NE(call_set_error_of("1,").find("empty item"), std::string::npos);
    EXPECT_NE(call_set_error_of("-5").find("at character 1: expected a number"), std::string::npos);
    EXPECT_NE(call_set_error_of("99999999999999999999").find("number too large"),
              std::string::npos);
}

TEST(CallSet, ErrorPositionIsOneBased) {
    try {
        CallSet::parse("1,2,x");
        FAIL() << "parsed";
    } catch (const CallSetError& e) {
        EXPECT_EQ(e.position(), 5u);
    }
}

}  // namespace
