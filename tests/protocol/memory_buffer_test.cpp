// Tests of protocol/memory_buffer.h, the default transport: commands kept in order and
// replayed in that order into any sink.
#include "protocol/memory_buffer.h"

#include <gtest/gtest.h>

#include "sample_streams.h"

namespace fb89::protocol {
namespace {

TEST(MemoryBuffer, KeepsCommandsInSubmissionOrder) {
    MemoryBuffer buffer;
    const std::vector<Command> commands = testing::two_frames();
    for (const Command& c : commands)
        buffer.submit(c);
    EXPECT_EQ(buffer.size(), commands.size());
    EXPECT_EQ(buffer.commands(), commands);
}

TEST(MemoryBuffer, ReplayDeliversEveryCommandInOrder) {
    MemoryBuffer source;
    for (const Command& c : testing::every_opcode())
        source.submit(c);
    MemoryBuffer target;
    source.replay_into(target);
    EXPECT_EQ(target.commands(), testing::every_opcode());
    source.replay_into(target);  // replay appends; the source is unchanged
    EXPECT_EQ(target.size(), 2 * source.size());
    EXPECT_EQ(source.commands(), testing::every_opcode());
}

TEST(MemoryBuffer, ClearEmptiesIt) {
    MemoryBuffer buffer;
    buffer.reserve(16);
    buffer.frame_begin(FrameBegin{0, 4, 4, Rgb{}});
    buffer.frame_end(FrameEnd{});
    buffer.clear();
    EXPECT_EQ(buffer.size(), 0u);
    EXPECT_TRUE(buffer.commands().empty());
}

TEST(MemoryBuffer, CommandsAreSentWithTheirPacket) {
    MemoryBuffer buffer;
    EXPECT_TRUE(buffer.send_times_us().empty());  // not timed
    buffer.time_packets(3);
    buffer.frame_begin(FrameBegin{0, 4, 4, Rgb{}});
    for (int i = 0; i < 6; ++i)
        buffer.draw_span(DrawSpan{i, 0, 1, Rgb{}});
    buffer.frame_end(FrameEnd{});  // the frame's end sends the last packet, however full
    buffer.fill_rect(FillRect{0, 0, 1, 1, Rgb{}});  // after the last packet: sent when asked
    const std::vector<double> t = buffer.send_times_us();
    ASSERT_EQ(t.size(), 9u);
    // packets: commands 0-2, 3-5, 6-7 (the FRAME_END), 8
    EXPECT_EQ(t[0], t[1]);
    EXPECT_EQ(t[1], t[2]);
    EXPECT_EQ(t[3], t[5]);
    EXPECT_EQ(t[6], t[7]);
    for (std::size_t i = 1; i < t.size(); ++i)
        EXPECT_LE(t[i - 1], t[i]) << i;
    EXPECT_GE(t[0], 0);
    buffer.clear();  // a new frame, timed from the old origin until time_packets() again
    EXPECT_TRUE(buffer.timed());
    buffer.frame_begin(FrameBegin{1, 4, 4, Rgb{}});
    EXPECT_EQ(buffer.send_times_us().size(), 1u);
}

}  // namespace
}  // namespace fb89::protocol
