// Tests of controller_sim/cost_model: the check values of docs/COST_MODEL.md, the word
// count against MAME's left/full/right decomposition, CycleCosts against the formulas, and
// the bus/controller pipeline.
#include "controller_sim/cost_model.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace fb89::controller {
namespace {

CostProfile tms34010() {
    return load_profile("tms34010-50mhz");
}

TEST(CostModel, FullScreenFillIs798753Cycles) {
    const CostProfile p = tms34010();
    const uint64_t cycles = fill_rect_cycles(p, PixelRect{0, 0, 1024, 780});
    EXPECT_EQ(cycles, 33u + 780u * 512u * 2u);
    EXPECT_EQ(cycles, 798'753u);
    EXPECT_NEAR(cycles_to_seconds(p, cycles) * 1e3, 127.8, 0.05);  // 127.80048 ms
}

TEST(CostModel, OnePixelFillIs35CyclesOf5Point6Microseconds) {
    const CostProfile p = tms34010();
    const uint64_t cycles = fill_rect_cycles(p, PixelRect{17, 3, 1, 1});
    EXPECT_EQ(cycles, 35u);
    EXPECT_DOUBLE_EQ(cycles_to_seconds(p, cycles) * 1e6, 5.6);
}

TEST(CostModel, HundredPixelSpanAsLineIs237Cycles) {
    const CostProfile p = tms34010();
    ASSERT_EQ(p.span_as, SpanAs::Line);
    EXPECT_EQ(draw_span_cycles(p, 0, 100), 25u + 12u + 200u);
    EXPECT_EQ(draw_span_cycles(p, 1, 100), 237u);  // a line does not care about alignment
}

TEST(CostModel, SpanAsFillIsAOneRowFill) {
    CostProfile p = tms34010();
    p.span_as = SpanAs::Fill;
    EXPECT_EQ(draw_span_cycles(p, 0, 100), 25u + 8u + 2u * 50u);  // 50 aligned words
    EXPECT_EQ(draw_span_cycles(p, 1, 100), 25u + 8u + 2u * 51u);  // partial words at both ends
    EXPECT_EQ(draw_span_cycles(p, 5, 7), fill_rect_cycles(p, PixelRect{5, 9, 7, 1}));
}

TEST(CostModel, WordsCountsPartialWordsAtUnalignedX) {
    EXPECT_EQ(words(0, 1, 2), 1u);
    EXPECT_EQ(words(1, 1, 2), 1u);
    EXPECT_EQ(words(0, 2, 2), 1u);
    EXPECT_EQ(words(1, 2, 2), 2u);  // straddles a word boundary
    EXPECT_EQ(words(3, 4, 2), 3u);  // pixels 3..6 touch words 1, 2, 3
    EXPECT_EQ(words(3, 2, 4), 2u);
    EXPECT_EQ(words(4, 4, 4), 1u);
    EXPECT_EQ(words(7, 5, 1), 5u);  // 16 bpp: one pixel per word
    EXPECT_EQ(words(0, 1024, 2), 512u);
}

// MAME's fill(): left partial pixels up to the first word boundary, full words, right
// partial pixels; a run inside one word is all left partials.
uint64_t mame_words(uint64_t x, uint64_t w, uint64_t ppw) {
    const uint64_t left = (ppw - x % ppw) % ppw;
    const uint64_t right = (x + w) % ppw;
    if (left + right > w) return 1;
    const uint64_t full = (w - left - right) / ppw;
    return full + (left ? 1 : 0) + (right ? 1 : 0);
}

TEST(CostModel, WordsMatchesMameLeftFullRightDecomposition) {
    for (uint32_t ppw : {1u, 2u, 4u, 8u, 16u})
        for (uint64_t x = 0; x < 40; ++x)
            for (uint64_t w = 1; w < 40; ++w)
                ASSERT_EQ(words(x, w, ppw), mame_words(x, w, ppw))
                    << "x=" << x << " w=" << w << " P=" << ppw;
}

TEST(CostModel, FrameBeginIsChargedAsOneFullScreenFill) {
    const CostProfile p = tms34010();
    EXPECT_EQ(frame_begin_cycles(p, 1024, 780), 798'753u);
    EXPECT_EQ(frame_begin_cycles(p, 640, 480), fill_rect_cycles(p, PixelRect{0, 0, 640, 480}));
    EXPECT_EQ(frame_begin_cycles(p, 0, 780), 25u);  // nothing to clear
}

TEST(CostModel, CommandWithNothingToDrawCostsCmdOnly) {
    EXPECT_EQ(command_only_cycles(tms34010()), 25u);
}

TEST(CostModel, BusTimeIsBytesOverBandwidthPlusHandshake) {
    const CostProfile p = tms34010();
    EXPECT_DOUBLE_EQ(bus_seconds(p, 12) * 1e6, 2.5);   // FILL_RECT: 1.5 + 1 us
    EXPECT_DOUBLE_EQ(bus_seconds(p, 10) * 1e6, 2.25);  // DRAW_SPAN, FRAME_BEGIN
    EXPECT_DOUBLE_EQ(bus_seconds(p, 2) * 1e6, 1.25);   // FRAME_END
    EXPECT_EQ(bus_seconds(p, 0), 0.0);                 // MARKER is not sent
}

TEST(CostModel, Tms34020FullScreenFillTakes79Point9Milliseconds) {
    const CostProfile p = load_profile("tms34020-40mhz");
    const uint64_t cycles = fill_rect_cycles(p, PixelRect{0, 0, 1024, 780});
    EXPECT_EQ(cycles, 798'753u);  // the same fill() in MAME, a faster clock
    EXPECT_NEAR(cycles_to_seconds(p, cycles) * 1e3, 79.8753, 1e-9);
    EXPECT_NEAR(bus_seconds(p, 12) * 1e6, 1.1, 1e-12);  // 0.6 + 0.5 us
}

TEST(CostModel, IdealProfileCostsNothing) {
    const CostProfile p = load_profile("ideal");
    EXPECT_EQ(fill_rect_cycles(p, PixelRect{0, 0, 1024, 780}), 0u);
    EXPECT_EQ(draw_span_cycles(p, 3, 100), 0u);
    EXPECT_EQ(frame_begin_cycles(p, 1024, 780), 0u);
    for (uint32_t b : p.bytes)
        EXPECT_EQ(bus_seconds(p, b), 0.0);
}

// Every built-in profile, and the TMS34010's at every bpp with spans both ways and non-zero
// set-up and row charges, so that each term of each formula counts.
std::vector<CostProfile> profiles_to_compare() {
    std::vector<CostProfile> out;
    for (const std::string& name : list_profiles())
        out.push_back(load_profile(name));
    for (uint32_t bpp : {1u, 2u, 4u, 8u, 16u})
        for (SpanAs span_as : {SpanAs::Line, SpanAs::Fill}) {
            CostProfile p = tms34010();
            p.bpp = bpp;
            p.span_as = span_as;
            p.c_row = 3;
            p.c_line_setup = 17;
            out.push_back(p);
        }
    return out;
}

TEST(CycleCosts, EqualTheCostFormulasForEveryProfileAndPlacement) {
    for (const CostProfile& p : profiles_to_compare()) {
        const CycleCosts costs(p);
        EXPECT_EQ(costs.command_only(), command_only_cycles(p)) << p.to_string();
        for (uint32_t x : {0u, 1u, 3u, 7u, 8u, 15u, 16u, 17u, 1023u, 16383u})
            for (uint32_t w : {1u, 2u, 5u, 15u, 16u, 17u, 33u, 1024u, 16384u}) {
                ASSERT_EQ(costs.draw_span(x, w), draw_span_cycles(p, x, w))
                    << p.to_string() << " x=" << x << " w=" << w;
                for (uint32_t h : {1u, 2u, 780u, 16384u})
                    ASSERT_EQ(costs.fill_rect(PixelRect{x, 5, w, h}),
                              fill_rect_cycles(p, PixelRect{x, 5, w, h}))
                        << p.to_string() << " x=" << x << " w=" << w << " h=" << h;
            }
    }
}

TEST(CycleCosts, RefuseABppThatIsNotAPowerOfTwoUpTo16) {
    for (uint32_t bpp : {0u, 3u, 32u}) {
        CostProfile p = tms34010();
        p.bpp = bpp;
        EXPECT_THROW(CycleCosts{p}, std::invalid_argument) << "bpp " << bpp;
    }
}

// Bus 2 us, execution 1 us: each command waits for the bus; the controller idles between.
TEST(Pipeline, BusBoundFrameEndsOneExecutionAfterTheLastArrival) {
    Pipeline pipe;
    EXPECT_DOUBLE_EQ(pipe.push(2, 1), 3);
    EXPECT_DOUBLE_EQ(pipe.push(2, 1), 5);
    EXPECT_DOUBLE_EQ(pipe.push(2, 1), 7);
    EXPECT_DOUBLE_EQ(pipe.bus_busy_us(), 6);
    EXPECT_DOUBLE_EQ(pipe.controller_busy_us(), 3);
    EXPECT_DOUBLE_EQ(pipe.end_us(), 7);
}

// Bus 1 us, execution 5 us: commands queue; the frame ends first arrival + all executions.
TEST(Pipeline, ControllerBoundFrameEndsAfterAllExecutions) {
    Pipeline pipe;
    EXPECT_DOUBLE_EQ(pipe.push(1, 5), 6);
    EXPECT_DOUBLE_EQ(pipe.push(1, 5), 11);
    EXPECT_DOUBLE_EQ(pipe.push(1, 5), 16);
    EXPECT_DOUBLE_EQ(pipe.bus_busy_us(), 3);
    EXPECT_DOUBLE_EQ(pipe.controller_busy_us(), 15);
    EXPECT_DOUBLE_EQ(pipe.end_us(), 16);
}

// A long command followed by short ones: the queue absorbs them, then drains.
TEST(Pipeline, QueueIsUnboundedAndDrainsInOrder) {
    Pipeline pipe;
    EXPECT_DOUBLE_EQ(pipe.push(1, 10), 11);
    EXPECT_DOUBLE_EQ(pipe.push(1, 1), 12);   // arrived at 2, waited until 11
    EXPECT_DOUBLE_EQ(pipe.push(20, 1), 23);  // arrived at 22, controller idle since 12
    pipe.reset();
    EXPECT_EQ(pipe.end_us(), 0.0);
    EXPECT_EQ(pipe.bus_busy_us(), 0.0);
}

}  // namespace
}  // namespace fb89::controller
