// The face-id buffer in false colour (experiments/id_view.h): black background, one colour
// per id, distinct ids distinct colours, neighbouring ids far apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>

#include "experiments/id_view.h"

namespace fb89::experiments {
namespace {

protocol::Rgb encoded(uint32_t id) {
    const uint32_t v = id + 1;
    return {static_cast<uint8_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
}

double distance(protocol::Rgb a, protocol::Rgb b) {
    const double dr = a.r - b.r, dg = a.g - b.g, db = a.b - b.b;
    return std::sqrt(dr * dr + dg * dg + db * db);
}

TEST(IdView, BackgroundStaysBlackAndEachIdGetsItsColour) {
    // a 4 x 3 buffer: background, ids 0, 1, 2, 255, 256 and 70000, some repeated
    controller::Framebuffer ids(4, 3);
    const uint32_t kIds[] = {0, 1, 2, 255, 256, 70000};
    for (uint32_t k = 0; k < 6; ++k)
        ids.set_pixel(k % 4, 1 + k / 4, encoded(kIds[k]));
    ids.set_pixel(3, 2, encoded(1));  // id 1 again
    const controller::Framebuffer view = id_view(ids);
    ASSERT_EQ(view.width(), 4u);
    ASSERT_EQ(view.height(), 3u);
    for (uint32_t x = 0; x < 4; ++x)
        EXPECT_EQ(view.pixel(x, 0), (protocol::Rgb{0, 0, 0})) << x;
    for (uint32_t k = 0; k < 6; ++k)
        EXPECT_EQ(view.pixel(k % 4, 1 + k / 4), id_view_colour(kIds[k])) << kIds[k];
    EXPECT_EQ(view.pixel(3, 2), view.pixel(1, 1));
    EXPECT_NE(view.pixel(0, 1), view.pixel(1, 1));
}

TEST(IdView, ColoursAreDistinctBrightAndNeighboursFarApart) {
    std::set<std::tuple<int, int, int>> seen;
    constexpr uint32_t kCount = 16384;
    for (uint32_t id = 0; id < kCount; ++id) {
        const protocol::Rgb c = id_view_colour(id);
        EXPECT_TRUE(seen.emplace(c.r, c.g, c.b).second) << "id " << id << " repeats a colour";
        // never near the black background
        EXPECT_GE(std::max({c.r, c.g, c.b}), 150) << id;
        // consecutive ids (neighbouring faces, often) are far apart
        if (id > 0) {
            EXPECT_GT(distance(c, id_view_colour(id - 1)), 150.0) << id;
        }
    }
    EXPECT_EQ(seen.size(), kCount);
}

}  // namespace
}  // namespace fb89::experiments
