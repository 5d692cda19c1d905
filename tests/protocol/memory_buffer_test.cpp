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

}  // namespace
}  // namespace fb89::protocol
