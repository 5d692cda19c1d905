// Tests of controller_sim/board_memory.h: a buffer of 2 MiB or more starts on a 2 MiB
// boundary (where a huge page can back it), a smaller one is ordinary, and both hold what is
// written into them through growth, copies and reassignment.
#include "controller_sim/board_memory.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace fb89::controller {
namespace {

constexpr std::size_t kHugePageBytes = BoardMemoryAllocator<uint32_t>::kHugePage;

TEST(BoardMemory, AFrameSizedDepthBufferStartsOnAHugePageBoundary) {
    BoardVector<uint32_t> depth(std::size_t{1024} * 780, 0xffffffffu);  // 3.2 MB
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(depth.data()) % kHugePageBytes, 0u);
    depth.back() = 7;
    EXPECT_EQ(depth.front(), 0xffffffffu);
    EXPECT_EQ(depth.back(), 7u);
}

TEST(BoardMemory, BuffersBelowAHugePageAndAcrossItKeepTheirWords) {
    BoardVector<uint32_t> v;
    // grows from 4 bytes through the 2 MiB boundary, each allocation freed by its own kind
    for (uint32_t i = 0; i < kHugePageBytes / sizeof(uint32_t) + 1000; ++i)
        v.push_back(i * 2654435761u);
    for (uint32_t i = 0; i < v.size(); i += 997)
        ASSERT_EQ(v[i], i * 2654435761u) << "word " << i;
    BoardVector<uint32_t> copy = v;
    EXPECT_EQ(copy, v);
    copy.assign(16, 3u);  // reuses the large allocation
    EXPECT_EQ(copy.size(), 16u);
    BoardVector<uint32_t> small(16, 5u);
    EXPECT_EQ(small[15], 5u);
    small = v;  // a small buffer replaced by a large one
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % kHugePageBytes, 0u);
    EXPECT_EQ(small, v);
}

}  // namespace
}  // namespace fb89::controller
