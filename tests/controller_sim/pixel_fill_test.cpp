// Tests of controller_sim/pixel_fill.h: every run length through every store path (byte
// stores, two 8-byte stores, 16-byte stores, 48-byte blocks with a flush end block) writes
// exactly the colour's bytes, in its own run and nowhere else.
#include "controller_sim/pixel_fill.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace fb89::controller {
namespace {

using protocol::Rgb;

TEST(PixelFill, PatternBlocksHoldTheColourPeriodFromPhaseZero) {
    const RgbPattern p = rgb_pattern(Rgb{0xa1, 0xb2, 0xc3});
    const uint8_t colour[3] = {0xa1, 0xb2, 0xc3};
    uint8_t bytes[48];
    for (int i = 0; i < 3; ++i)
        std::memcpy(bytes + 16 * i, &p.block[i], 16);
    for (int i = 0; i < 48; ++i)
        ASSERT_EQ(bytes[i], colour[i % 3]) << "byte " << i;
}

TEST(PixelFill, FillRunWritesExactlyItsPixelsForEveryLengthAndOffset) {
    for (const Rgb c : {Rgb{1, 2, 3}, Rgb{0xff, 0x00, 0xff}, Rgb{0, 0, 0}, Rgb{0x80, 0x7f, 0x01}}) {
        const RgbPattern pattern = rgb_pattern(c);
        const uint8_t colour[3] = {c.r, c.g, c.b};
        for (std::size_t n = 0; n <= 130; ++n)
            for (std::size_t at = 0; at < 3; ++at) {
                std::vector<uint8_t> buf(3 * n + 16, 0x5a);
                fill_run(buf.data() + 3 * at, n, pattern);
                for (std::size_t i = 0; i < buf.size(); ++i) {
                    const bool in = i >= 3 * at && i < 3 * (at + n);
                    const uint8_t want = in ? colour[(i - 3 * at) % 3] : uint8_t{0x5a};
                    ASSERT_EQ(buf[i], want) << "n=" << n << " at pixel " << at << " byte " << i;
                }
            }
    }
}

}  // namespace
}  // namespace fb89::controller
