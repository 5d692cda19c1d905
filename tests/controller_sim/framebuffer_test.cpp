// Tests of controller_sim/framebuffer: clipping, exact pixel coverage of fills and spans,
// size limits and the checksum (XXH64, controller_sim/xxhash64.h).
#include "controller_sim/framebuffer.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "controller_sim/xxhash64.h"

namespace fb89::controller {
namespace {

using protocol::DrawSpan;
using protocol::FillRect;
using protocol::Rgb;

constexpr Rgb kFbRed{255, 0, 0};
constexpr Rgb kBlue{0, 0, 255};

// Every pixel of fb equals `inside` within r and `outside` elsewhere.
void expect_rect_in_fb(const Framebuffer& fb, const PixelRect& r, Rgb inside, Rgb outside) {
    for (uint32_t y = 0; y < fb.height(); ++y)
        for (uint32_t x = 0; x < fb.width(); ++x) {
            const bool in = x >= r.x && x < r.x + r.w && y >= r.y && y < r.y + r.h;
            ASSERT_EQ(fb.pixel(x, y), in ? inside : outside)
                << "pixel (" << x << ", " << y << ") is " << protocol::to_string(fb.pixel(x, y));
        }
}

TEST(Framebuffer, DefaultIs1024x780Black) {
    const Framebuffer fb;
    EXPECT_EQ(fb.width(), 1024u);
    EXPECT_EQ(fb.height(), 780u);
    EXPECT_EQ(fb.pixels().size(), 1024u * 780u * 3u);
    EXPECT_EQ(fb.pixel(1023, 779), Rgb{});
}

TEST(Framebuffer, RefusesSidesAbove16384) {
    EXPECT_THROW(Framebuffer(16385, 1), std::invalid_argument);
    EXPECT_THROW(Framebuffer(1, 16385), std::invalid_argument);
    Framebuffer fb(4, 4);
    EXPECT_THROW(fb.resize(kMaxFrameSide + 1, 4), std::invalid_argument);
    EXPECT_EQ(fb.width(), 4u);  // unchanged by the refusal
}

TEST(Framebuffer, FillRectWritesExactlyTheRectangle) {
    Framebuffer fb(8, 6);
    fb.clear(kBlue);
    fb.fill_rect(PixelRect{2, 1, 3, 2}, kFbRed);
    expect_rect_in_fb(fb, PixelRect{2, 1, 3, 2}, kFbRed, kBlue);
}

TEST(Framebuffer, SpanWritesExactlyItsPixels) {
    Framebuffer fb(40, 3);
    fb.draw_span(2, 39, 1, kFbRed);  // the very last pixel
    expect_rect_in_fb(fb, PixelRect{39, 2, 1, 1}, kFbRed, Rgb{});
    fb.clear(Rgb{});
    fb.draw_span(1, 3, 33, kFbRed);  // long enough for the doubling copy
    expect_rect_in_fb(fb, PixelRect{3, 1, 33, 1}, kFbRed, Rgb{});
}

TEST(Framebuffer, FillPixelsStopsAtTheLastPixelForEveryLength) {
    for (std::size_t n = 0; n < 200; ++n) {
        std::vector<uint8_t> buf(3 * n + 6, 0xAA);
        fill_pixels(buf.data() + 3, n, Rgb{1, 2, 3});
        for (std::size_t i = 0; i < buf.size(); ++i) {
            const bool in = i >= 3 && i < 3 + 3 * n;
            const uint8_t want = in ? static_cast<uint8_t>(1 + (i - 3) % 3) : uint8_t{0xAA};
            ASSERT_EQ(buf[i], want) << "n=" << n << " byte " << i;
        }
    }
}

TEST(Framebuffer, ClipFillRectCutsAtEveryEdge) {
    auto c = clip_fill_rect(FillRect{-3, -2, 5, 4, kFbRed}, 10, 8);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->rect, (PixelRect{0, 0, 2, 2}));
    EXPECT_TRUE(c->clipped);
    c = clip_fill_rect(FillRect{8, 6, 5, 5, kFbRed}, 10, 8);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->rect, (PixelRect{8, 6, 2, 2}));
    EXPECT_TRUE(c->clipped);
    c = clip_fill_rect(FillRect{0, 0, 10, 8, kFbRed}, 10, 8);
    ASSERT_TRUE(c);
    EXPECT_FALSE(c->clipped);
}

TEST(Framebuffer, ClipFillRectRejectsWhollyOutsideAndEmpty) {
    EXPECT_FALSE(clip_fill_rect(FillRect{10, 0, 5, 5, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_fill_rect(FillRect{-5, 0, 5, 5, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_fill_rect(FillRect{0, 8, 1, 1, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_fill_rect(FillRect{0, 0, 0, 5, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_fill_rect(FillRect{0, 0, 5, 0, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_fill_rect(FillRect{0, 0, 5, 5, kFbRed}, 0, 0));
}

TEST(Framebuffer, ClipFillRectHandlesExtremeCoordinatesWithoutOverflow) {
    constexpr int32_t kMin = std::numeric_limits<int32_t>::min();
    constexpr int32_t kMax = std::numeric_limits<int32_t>::max();
    constexpr uint32_t kHuge = std::numeric_limits<uint32_t>::max();
    const auto c = clip_fill_rect(FillRect{kMin, kMin, kHuge, kHuge, kFbRed}, 10, 8);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->rect, (PixelRect{0, 0, 10, 8}));
    EXPECT_FALSE(clip_fill_rect(FillRect{kMax, kMax, kHuge, kHuge, kFbRed}, 10, 8));
}

TEST(Framebuffer, ClipSpanCutsEndsAndRejectsOutsideOrReversed) {
    auto c = clip_span(DrawSpan{3, -5, 3, kFbRed}, 10, 8);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->rect, (PixelRect{0, 3, 4, 1}));
    EXPECT_TRUE(c->clipped);
    c = clip_span(DrawSpan{7, 0, 9, kFbRed}, 10, 8);
    ASSERT_TRUE(c);
    EXPECT_FALSE(c->clipped);
    EXPECT_FALSE(clip_span(DrawSpan{-1, 0, 9, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_span(DrawSpan{8, 0, 9, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_span(DrawSpan{0, 10, 20, kFbRed}, 10, 8));
    EXPECT_FALSE(clip_span(DrawSpan{0, 5, 4, kFbRed}, 10, 8));  // x1 < x0
    c = clip_span(DrawSpan{0, std::numeric_limits<int32_t>::min(),
                           std::numeric_limits<int32_t>::max(), kFbRed},
                  10, 8);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->rect, (PixelRect{0, 0, 10, 1}));
}

TEST(Framebuffer, ChecksumIsXxh64OverSizeAndPixels) {
    // XXH64 (seed 0) of 01 00 00 00 01 00 00 00 00 00 00, computed independently (libxxhash)
    EXPECT_EQ(Framebuffer(1, 1).checksum(), 0x34f0036812ea8873ULL);
    // of 04 00 00 00 03 00 00 00 and twelve pixels 12 34 56: more than one 32-byte stripe
    Framebuffer fb(4, 3);
    fb.clear(Rgb{0x12, 0x34, 0x56});
    EXPECT_EQ(fb.checksum(), 0x9ef4ae36bd54dd6bULL);
}

TEST(Framebuffer, ChecksumIsXxh64OfTheSizeBytesThenThePixelBytes) {
    Framebuffer fb(37, 23);
    for (uint32_t y = 0; y < fb.height(); ++y)
        fb.draw_span(y, y % 5, 30, Rgb{static_cast<uint8_t>(y), 7, static_cast<uint8_t>(3 * y)});
    std::vector<uint8_t> bytes = {37, 0, 0, 0, 23, 0, 0, 0};
    bytes.insert(bytes.end(), fb.pixels().begin(), fb.pixels().end());
    EXPECT_EQ(fb.checksum(), xxh64(bytes.data(), bytes.size()));
}

TEST(Framebuffer, ChecksumChangesWhenOnePixelChanges) {
    Framebuffer fb(64, 48);
    fb.clear(kBlue);
    const uint64_t before = fb.checksum();
    fb.set_pixel(63, 47, Rgb{0, 0, 254});
    EXPECT_NE(fb.checksum(), before);
    fb.set_pixel(63, 47, kBlue);
    EXPECT_EQ(fb.checksum(), before);
}

TEST(Framebuffer, ChecksumDependsOnTheShape) {
    EXPECT_NE(Framebuffer(4, 2).checksum(), Framebuffer(2, 4).checksum());
}

}  // namespace
}  // namespace fb89::controller
