// Tests of controller_sim/cost_model: the check values of docs/COST_MODEL.md (the memory-cycle
// model of tms34010-50mhz and the first model's, tms34010-mame), the word count against
// MAME's left/full/right decomposition, CycleCosts against the formulas, and the
// bus/controller pipeline.
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
// The first cost model, MAME's figures (controller_sim/profiles/tms34010-mame.json).
CostProfile first_model() {
    return load_profile("tms34010-mame");
}

// tms34010-50mhz, counted from controller_sim/gsp/tms34010.asm at 2 states a memory cycle on
// TI's development board (INCLK 50.35 MHz: a 158.9 ns state): the loop (C_cmd) 18 states;
// the set-ups FRAME_BEGIN through the serial registers 94 (by FILL 35, a frame larger than
// the VRAM 48), FILL_RECT 29, DRAW_SPAN as a fill 34, as a line 33, FRAME_END 6 (GspListing.*
// hold these to the listing instruction by instruction). Each host word 2 states; a whole
// word 2, a partial one 4, a LINE pixel 4; a FILL row 1 more (TI's simulator).
constexpr double kState = 8 / 50.35e6;

// TI's clear_page (TDB10/OEMPRIMS/CLEARPAG.ASM): a VRAM row of 1,024 16-bit words, its
// memory-to-register cycle (in the set-up's PIXT), then one register-to-memory cycle for
// each of the frame's other 389 VRAM rows (780 lines of 8,192 bits, 16,384 bits a row).
TEST(CostModel, TheFramesClearThroughTheSerialRegistersIs3363StatesOfAboutHalfAMillisecond) {
    const CostProfile p = tms34010();
    ASSERT_EQ(p.clear_as, ClearAs::SerialRegister);
    EXPECT_EQ(vram_rows(1024, 780, 8), 390u);
    EXPECT_EQ(srt_clear_cycles(p, 390), (1u + 1024u * 2u) + 389u * (1u + 2u));
    const uint64_t cycles = frame_begin_cycles(p, 1024, 780);
    EXPECT_EQ(cycles, 21u + 116u + 5u * 2u + 2049u + 1167u);
    EXPECT_EQ(cycles, 3'363u);
    // refresh takes 2/64 of the states and the display 46,800 x 2 a second
    EXPECT_NEAR(p.stolen_share, 2.0 / 64 + 46'800.0 * 2 * kState, 1e-15);
    EXPECT_NEAR(cycles_to_seconds(p, cycles) * 1e3, 3'363 * kState / (1 - p.stolen_share) * 1e3,
                1e-9);
    EXPECT_NEAR(cycles_to_seconds(p, cycles) * 1e3, 0.560, 0.001);
    // the whole VRAM, as TI's clear_frame_buffer: 512 rows
    EXPECT_EQ(srt_clear_cycles(p, kVramRows), 2049u + 511u * 3u);
}

// TI's clear_screen (CLEARSCR.ASM), the profile's other choice: one FILL XY over the frame.
TEST(CostModel, TheFramesClearByFillIs799573StatesOf133Milliseconds) {
    CostProfile p = tms34010();
    p.clear_as = ClearAs::Fill;
    const uint64_t cycles = frame_begin_cycles(p, 1024, 780);
    EXPECT_EQ(cycles, 21u + 42u + 5u * 2u + 780u * (1u + 512u * 2u));
    EXPECT_EQ(cycles, 799'573u);
    EXPECT_NEAR(cycles_to_seconds(p, cycles) * 1e3, 133.2, 0.05);
}

// A frame whose rows the VRAM cannot hold (2048 x 1560 at 8 bpp: 1,560 VRAM rows of 512) is
// cleared by FILL after the serial clear's test.
TEST(CostModel, AFrameLargerThanTheVramIsClearedByFill) {
    const CostProfile p = tms34010();
    EXPECT_EQ(vram_rows(2048, 1560, 8), 1560u);
    EXPECT_EQ(frame_begin_cycles(p, 2048, 1560), 21u + 58u + 10u + 1560u * (1u + 1024u * 2u));
    EXPECT_EQ(vram_rows(1024, 1024, 8), 512u);  // the whole VRAM: still serial
    EXPECT_EQ(frame_begin_cycles(p, 1024, 1024), 21u + 116u + 10u + srt_clear_cycles(p, 512));
    // a narrow frame's rows at its own pitch: 256 wide, 2,048 bits a line, 8 lines a row
    EXPECT_EQ(vram_rows(256, 195, 8), 25u);
    EXPECT_EQ(vram_rows(200, 195, 8), 25u);  // the pitch a power of two
}

TEST(CostModel, OnePixelFillIsTheLoopItsSetUpItsHostWordsAndOnePartialWord) {
    const CostProfile p = tms34010();
    EXPECT_EQ(fill_rect_cycles(p, PixelRect{17, 3, 1, 1}), 21u + 35u + 6u * 2u + 1u + 4u);
    EXPECT_EQ(fill_rect_cycles(p, PixelRect{16, 3, 2, 1}), 21u + 35u + 12u + 1u + 2u);  // a word
    EXPECT_EQ(fill_rect_cycles(p, PixelRect{17, 3, 2, 1}), 21u + 35u + 12u + 1u + 2u * 4u);
}

TEST(CostModel, HundredPixelSpanAsLineIs470States) {
    CostProfile p = tms34010();
    p.span_as = SpanAs::Line;
    EXPECT_EQ(draw_span_cycles(p, 0, 100), 21u + 39u + 5u * 2u + 100u * 4u);
    EXPECT_EQ(draw_span_cycles(p, 1, 100), 470u);  // a line does not care about alignment
}

TEST(CostModel, ALinePixelAt16BppIsOneWriteCycle) {
    CostProfile p = tms34010();
    p.bpp = 16;
    p.span_as = SpanAs::Line;
    derive_figures(p);
    EXPECT_EQ(p.c_line_pix, 2u);
    EXPECT_EQ(draw_span_cycles(p, 0, 100), 21u + 39u + 10u + 100u * 2u);
    // and a fill has no partial words: every pixel is a word
    EXPECT_EQ(fill_rect_cycles(p, PixelRect{1, 0, 3, 1}), 21u + 35u + 12u + 1u + 3u * 2u);
}

TEST(CostModel, WaitStatesLengthenEveryMemoryCycleButNotAnIoRegistersCycle) {
    CostProfile p = tms34010();
    p.wait_states = 1;
    derive_figures(p);
    EXPECT_EQ(p.c_op, 3u);
    EXPECT_EQ(p.c_op_partial, 6u);
    EXPECT_EQ(p.c_line_pix, 6u);
    EXPECT_EQ(p.c_host_word, 3u);
    EXPECT_EQ(p.c_cmd, 21u + 3u);        // its two reads: one word and two
    EXPECT_EQ(p.c_frame_end_setup, 8u);  // its one write is to HSTCTL, an I/O register
    // and the host port waits for the longer cycle: 2 bytes per 3 states
    EXPECT_NEAR(p.host_port_bytes_per_s, 2 / (3 * kState), 1);
}

// TI's draw_line draws a horizontal line with FILL XY (EXTPRIMS/DRAWLINE.ASM): the default.
TEST(CostModel, ASpanIsAOneRowFillAfterItsOwnSetUp) {
    const CostProfile p = tms34010();
    ASSERT_EQ(p.span_as, SpanAs::Fill);
    EXPECT_EQ(draw_span_cycles(p, 0, 100), 21u + 40u + 10u + 1u + 2u * 50u);  // 50 aligned words
    EXPECT_EQ(draw_span_cycles(p, 1, 100), 21u + 40u + 10u + 1u + 2u * 49u + 4u * 2u);
    EXPECT_EQ(draw_span_cycles(p, 0, 100), 172u);  // against LINE's 470
}

TEST(CostModel, FirstModelKeepsMamesFigures) {
    const CostProfile p = first_model();
    EXPECT_EQ(fill_rect_cycles(p, PixelRect{0, 0, 1024, 780}), 33u + 780u * 512u * 2u);
    EXPECT_EQ(frame_begin_cycles(p, 1024, 780), 798'753u);
    EXPECT_EQ(fill_rect_cycles(p, PixelRect{17, 3, 1, 1}), 35u);
    EXPECT_DOUBLE_EQ(cycles_to_seconds(p, 35) * 1e6, 5.6);
    EXPECT_EQ(draw_span_cycles(p, 1, 100), 25u + 12u + 200u);
    EXPECT_EQ(outside_cycles(p, protocol::Opcode::FillRect), 25u);
    EXPECT_EQ(frame_end_cycles(p), 25u);
    EXPECT_EQ(frame_begin_cycles(p, 0, 780), 25u);
    EXPECT_DOUBLE_EQ(bus_seconds(p, 12) * 1e6, 2.5);  // 12 bytes at 8 MB/s + 1 us
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

// Its partial words: a left and a right one, or one when the run sits inside a word.
uint64_t mame_partial_words(uint64_t x, uint64_t w, uint64_t ppw) {
    const uint64_t left = (ppw - x % ppw) % ppw;
    const uint64_t right = (x + w) % ppw;
    if (left + right > w) return 1;
    return (left ? 1 : 0) + (right ? 1 : 0);
}

TEST(CostModel, WordsMatchesMameLeftFullRightDecomposition) {
    for (uint32_t ppw : {1u, 2u, 4u, 8u, 16u, 32u})
        for (uint64_t x = 0; x < 40; ++x)
            for (uint64_t w = 1; w < 40; ++w) {
                ASSERT_EQ(words(x, w, ppw), mame_words(x, w, ppw))
                    << "x=" << x << " w=" << w << " P=" << ppw;
                ASSERT_EQ(partial_words(x, w, ppw), mame_partial_words(x, w, ppw))
                    << "x=" << x << " w=" << w << " P=" << ppw;
            }
}

TEST(CostModel, FrameBeginIsItsSetUpAndAFullScreenClear) {
    CostProfile p = tms34010();
    // 640 x 480 at a pitch of 1,024 pixels: 240 VRAM rows
    EXPECT_EQ(frame_begin_cycles(p, 640, 480), 21u + 116u + 10u + srt_clear_cycles(p, 240));
    EXPECT_EQ(frame_begin_cycles(p, 0, 780), 21u + 116u + 10u);  // nothing to clear
    p.clear_as = ClearAs::Fill;
    EXPECT_EQ(frame_begin_cycles(p, 640, 480),
              fill_rect_cycles(p, PixelRect{0, 0, 640, 480}) - 35u - 12u + 42u + 10u);
    EXPECT_EQ(frame_begin_cycles(p, 0, 780), 21u + 42u + 10u);
}

TEST(CostModel, ACommandWithNothingToDrawStillLoadsAndRunsItsInstruction) {
    const CostProfile p = tms34010();
    EXPECT_EQ(outside_cycles(p, protocol::Opcode::FillRect), 21u + 35u + 12u);
    EXPECT_EQ(outside_cycles(p, protocol::Opcode::DrawSpan), 21u + 40u + 10u);
    EXPECT_EQ(frame_end_cycles(p), 21u + 8u + 2u);
}

TEST(CostModel, BusTimeIsBytesOverTheChipsPortPlusHandshake) {
    const CostProfile p = tms34010();
    // the host side's 8 MB/s is faster than the port: 2 bytes per 2 states of 158.9 ns
    EXPECT_DOUBLE_EQ(p.host_port_bytes_per_s, 2 / (2 * kState));
    EXPECT_DOUBLE_EQ(p.bus_bytes_per_s(), 6.29375e6);
    EXPECT_NEAR(bus_seconds(p, 12) * 1e6, 12 / 6.29375 + 1, 1e-12);  // FILL_RECT
    EXPECT_NEAR(bus_seconds(p, 2) * 1e6, 2 / 6.29375 + 1, 1e-12);    // FRAME_END
    EXPECT_EQ(bus_seconds(p, 0), 0.0);                               // MARKER is not sent
    // the ISA board's host is slower than the port
    EXPECT_DOUBLE_EQ(load_profile("tms34010-isa").bus_bytes_per_s(), 2.58e6);
}

TEST(CostModel, Tms34020WritesFourPixelsAWordInPageModeWithByteStrobes) {
    const CostProfile p = load_profile("tms34020-40mhz");
    EXPECT_EQ(p.pixels_per_word(), 4u);
    // a row: its first word a 2-state cycle, the other 255 page-mode cycles of 1 state
    EXPECT_EQ(p.c_op, 1u);
    EXPECT_EQ(p.c_row, 1u);
    // the loop 16 and FRAME_BEGIN's set-up 100 by the 34020's own timings ([UG20]); the
    // serial clear's VRAM row 512 32-bit words in page mode, then 389 register-to-memory
    // cycles of 2 states
    EXPECT_EQ(frame_begin_cycles(p, 1024, 780), 16u + 100u + 10u + (1u + 512u) + 389u * 2u);
    EXPECT_NEAR(cycles_to_seconds(p, frame_begin_cycles(p, 1024, 780)) * 1e3,
                1'417 / 10e6 / (1 - p.stolen_share) * 1e3, 1e-9);
    // by FILL, as before: a row a 2-state word and 255 page-mode words
    CostProfile by_fill = p;
    by_fill.clear_as = ClearAs::Fill;
    EXPECT_EQ(frame_begin_cycles(by_fill, 1024, 780), 16u + 33u + 10u + 780u * (1u + 256u * 1u));
    // a CAS per byte: an 8-bit pixel, or a partial word, is one write
    EXPECT_EQ(p.c_line_pix, 2u);
    EXPECT_EQ(p.c_op_partial, p.c_op);
    EXPECT_DOUBLE_EQ(p.bus_bytes_per_s(), 20e6);  // the port as its data sheet rates it
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
            derive_figures(p);
            out.push_back(p);
            for (uint32_t bus : {32u}) {  // and on a 32-bit bus, four or more pixels a word
                CostProfile wide = p;
                wide.bus_bits = bus;
                derive_figures(wide);
                out.push_back(wide);
            }
        }
    return out;
}

TEST(CycleCosts, EqualTheCostFormulasForEveryProfileAndPlacement) {
    for (const CostProfile& p : profiles_to_compare()) {
        const CycleCosts costs(p);
        EXPECT_EQ(costs.fill_outside(), outside_cycles(p, protocol::Opcode::FillRect))
            << p.to_string();
        EXPECT_EQ(costs.span_outside(), outside_cycles(p, protocol::Opcode::DrawSpan))
            << p.to_string();
        EXPECT_EQ(costs.frame_end(), frame_end_cycles(p)) << p.to_string();
        EXPECT_EQ(costs.depth_span_outside(), depth_span_outside_cycles(p)) << p.to_string();
        for (const bool cut : {false, true})
            for (uint64_t nearer : {0u, 1u, 1024u})
                for (uint64_t farther : {0u, 3u, 780u})
                    ASSERT_EQ(costs.depth_span(cut, nearer, farther),
                              depth_span_cycles(p, cut, nearer, farther))
                        << p.to_string();
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
    for (uint32_t bpp : {0u, 3u, 64u}) {
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
