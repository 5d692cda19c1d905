// The controller's depth commands (stream format version 3): its depth buffer, its own
// scan conversion of FACE by the shared coverage rule, the counted ties, and their price from
// the listing (controller_sim/gsp/tms34010.asm).
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "controller_sim/controller.h"
#include "protocol/depth_fixed.h"

namespace fb89::controller {
namespace {

using protocol::DepthClear;
using protocol::DepthSpan;
using protocol::Face;
using protocol::FrameBegin;
using protocol::FrameEnd;
using protocol::Rgb;
using protocol::SnappedPoint;

constexpr int64_t kDepthPx = protocol::kSubpixel;

// A rectangle of pixels [x0, x1) x [y0, y1) as a face of four points, positively wound
// (protocol/coverage.h: right along the top, down the right side).
Face rect_face(int64_t x0, int64_t y0, int64_t x1, int64_t y1, uint32_t z, Rgb c) {
    return Face{
        c,
        0,
        0,
        z,
        0,
        0,
        {SnappedPoint{x0 * kDepthPx, y0 * kDepthPx}, SnappedPoint{x1 * kDepthPx, y0 * kDepthPx},
         SnappedPoint{x1 * kDepthPx, y1 * kDepthPx}, SnappedPoint{x0 * kDepthPx, y1 * kDepthPx}}};
}

CostProfile with_depth_bits(const char* name, uint32_t bits) {
    CostProfile p = load_profile(name);
    p.depth_bits = bits;
    derive_figures(p);
    return p;
}

TEST(ControllerDepth, ADepthCommandWithoutADepthBufferIsRefusedNamingIt) {
    Controller ctl(load_profile("ideal"));
    ctl.frame_begin({0, 8, 8, {}});
    try {
        ctl.depth_span({1, 0, 3, 0, 0, {}});
        FAIL() << "a DEPTH_SPAN without a DEPTH_CLEAR was drawn";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("command 1: DEPTH_SPAN: no depth buffer"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(ctl.face(rect_face(0, 0, 2, 2, 0, {})), std::invalid_argument);
    // a profile without a listing prices none
    Controller mame(load_profile("tms34010-mame"));
    mame.frame_begin({0, 8, 8, {}});
    EXPECT_THROW(mame.depth_clear({}), std::invalid_argument);
}

TEST(ControllerDepth, NearerWinsAndAsNearKeepsTheFirst) {
    Controller ctl(load_profile("ideal"));
    ctl.frame_begin({0, 8, 4, {}});
    ctl.depth_clear({});
    const uint32_t half = protocol::depth_fixed(0.5);
    ctl.depth_span({1, 0, 7, half, 0, Rgb{1, 0, 0}});
    ctl.depth_span({1, 2, 3, half, 0, Rgb{2, 0, 0}});         // as near: kept
    ctl.depth_span({1, 4, 5, half - 1, 0, Rgb{3, 0, 0}});     // nearer: drawn
    ctl.depth_span({1, 6, 7, half + 4096, 0, Rgb{4, 0, 0}});  // farther
    EXPECT_EQ(ctl.framebuffer().pixel(2, 1), (Rgb{1, 0, 0}));
    EXPECT_EQ(ctl.framebuffer().pixel(4, 1), (Rgb{3, 0, 0}));
    EXPECT_EQ(ctl.framebuffer().pixel(6, 1), (Rgb{1, 0, 0}));
    EXPECT_EQ(ctl.stats().depth.tests, 14u);
    EXPECT_EQ(ctl.stats().depth.nearer, 10u);
    EXPECT_EQ(ctl.stats().depth.equal, 2u);
}

TEST(ControllerDepth, SixteenLayersCostMoreAndKeepTheNearest) {
    // depth complexity 16: full-frame faces back to front (each drawn over the last) and
    // front to back (each tested and refused)
    for (const bool back_to_front : {true, false}) {
        Controller ctl(load_profile("tms34010-50mhz"));
        ctl.frame_begin({0, 32, 16, {}});
        ctl.depth_clear({});
        for (int i = 0; i < 16; ++i) {
            const int layer = back_to_front ? 15 - i : i;  // 0 nearest
            ctl.face(rect_face(0, 0, 32, 16, protocol::depth_fixed(0.05 + 0.05 * layer),
                               Rgb{static_cast<uint8_t>(layer), 0, 0}));
        }
        ctl.frame_end({});
        for (uint32_t y = 0; y < 16; ++y)
            for (uint32_t x = 0; x < 32; ++x)
                ASSERT_EQ(ctl.framebuffer().pixel(x, y), (Rgb{0, 0, 0})) << x << "," << y;
        const auto& d = ctl.stats().depth;
        EXPECT_EQ(d.tests, 16u * 32 * 16);
        EXPECT_EQ(d.nearer, back_to_front ? 16u * 32 * 16 : 32u * 16);
        // the price: every face's rows and pixels, nearer dearer than farther; a rectangle's
        // top and bottom edges are level (no division, and a level point's set-up), its sides
        // divided, and neither side bounds a row the frame's width further
        const CostProfile& p = ctl.profile();
        const uint64_t faces =
            ctl.stats().totals[protocol::opcode_index(protocol::Opcode::Face)].cycles;
        const uint64_t nearer = d.nearer, farther = d.tests - d.nearer;
        const uint64_t per_face = uint64_t{p.c_cmd} + (face_bytes(4) + 1) / 2 * p.c_host_word +
                                  p.c_face_setup + 3 * p.c_face_point + p.c_face_last +
                                  2 * p.c_face_level_point +
                                  16 * (p.c_face_row + 2 * p.c_face_edge + 2 * p.c_face_level) +
                                  16 * (p.c_face_span + p.c_zexit) + p.c_face_done;
        EXPECT_EQ(faces, 16 * per_face + nearer * p.c_zpass + farther * p.c_zfail);
    }
}

TEST(ControllerDepth, AFaceLargerThanTheFrameIsClippedToIt) {
    Controller ctl(load_profile("tms34010-50mhz"));
    ctl.frame_begin({0, 40, 30, {}});
    ctl.depth_clear({});
    // far past every edge, as the guard band allows
    ctl.face(rect_face(-30000, -30000, 30000, 30000, protocol::depth_fixed(0.5), Rgb{9, 9, 9}));
    const auto& f = ctl.stats().totals[protocol::opcode_index(protocol::Opcode::Face)];
    EXPECT_EQ(f.pixels, 40u * 30);
    EXPECT_EQ(f.clipped, 1u);
    EXPECT_EQ(ctl.framebuffer().pixel(39, 29), (Rgb{9, 9, 9}));
    // its rows: the frame's 30, not the face's 60,000
    const CostProfile& p = ctl.profile();
    EXPECT_LT(f.cycles, 31u * (p.c_face_row + 4 * p.c_face_edge + p.c_face_span + p.c_zexit) +
                            1200u * p.c_zpass + 2000u);
}

TEST(ControllerDepth, ADegenerateFaceDrawsNothing) {
    Controller ctl(load_profile("ideal"));
    ctl.frame_begin({0, 16, 16, {}});
    ctl.depth_clear({});
    // three points on a line, and a face wound the other way
    ctl.face(Face{Rgb{1, 1, 1},
                  0,
                  0,
                  0,
                  0,
                  0,
                  {{0, 0}, {4 * kDepthPx, 4 * kDepthPx}, {8 * kDepthPx, 8 * kDepthPx}}});
    Face reversed = rect_face(2, 2, 10, 10, 0, Rgb{2, 2, 2});
    std::reverse(reversed.points.begin(), reversed.points.end());
    ctl.face(reversed);
    EXPECT_EQ(ctl.stats().depth.tests, 0u);
    EXPECT_EQ(ctl.stats().totals[protocol::opcode_index(protocol::Opcode::Face)].outside, 2u);
    EXPECT_EQ(ctl.framebuffer().pixel(5, 5), (Rgb{0, 0, 0}));
}

TEST(ControllerDepth, SixteenBitWordsTieWhereThirtyTwoBitOnesDoNot) {
    // two faces 2^-20 apart in depth: one 16-bit step is 2^-16
    for (const uint32_t bits : {16u, 32u}) {
        Controller ctl(with_depth_bits("ideal", bits));
        ctl.frame_begin({0, 8, 8, {}});
        ctl.depth_clear({});
        ctl.face(
            rect_face(0, 0, 8, 8, protocol::depth_fixed(0.25 + 1.0 / (1 << 20)), Rgb{1, 0, 0}));
        ctl.face(rect_face(0, 0, 8, 8, protocol::depth_fixed(0.25), Rgb{2, 0, 0}));
        const auto& d = ctl.stats().depth;
        EXPECT_EQ(d.equal, bits == 16 ? 64u : 0u) << bits;
        EXPECT_EQ(ctl.framebuffer().pixel(3, 3),
                  (Rgb{static_cast<uint8_t>(bits == 16 ? 1 : 2), 0, 0}))
            << bits;
    }
}

TEST(ControllerDepth, ADepthSpanCostsItsListingsPaths) {
    const CostProfile p = load_profile("tms34010-50mhz");
    // the pixel loop by hand from the data sheet and GSPSIM (M = 2 states, a pixel at 8 bpp a
    // read and a write, 4): MOVE *A8,A5,0 1+2+1, MOVE 1, SRL 1, CMP 1, JRHS not taken 1, MOVE
    // A9,*A8,0 1 (its write queued), PIXT 2 after waiting 1 for it (its first state beside
    // the queue; its 4 queued less its last state), ADDK, ADD, ADD 1 each, DSJS taken 2 (the
    // PIXT's queue drained by then; GSPA writes DSJ within 31 words as DSJS): 17; farther:
    // 4+1+1+1+2+1+1+1+2 = 14
    EXPECT_EQ(p.c_zpass, 17u);
    EXPECT_EQ(p.c_zfail, 14u);
    Controller ctl(p);
    ctl.frame_begin({0, 64, 8, {}});
    ctl.depth_clear({});
    ctl.depth_span({3, 10, 29, protocol::depth_fixed(0.5), 0, {}});
    const auto& s = ctl.stats().totals[protocol::opcode_index(protocol::Opcode::DepthSpan)];
    EXPECT_EQ(s.bytes, kDepthSpanBytes);
    EXPECT_EQ(s.cycles,
              uint64_t{p.c_cmd} + p.c_zspan_setup + 9 * p.c_host_word + 20 * p.c_zpass + p.c_zexit);
    // cut on the left: Z stepped to column 0 (MPYS), the pixels left tested
    ctl.depth_span({4, -5, 2, protocol::depth_fixed(0.5), 1000, {}});
    EXPECT_EQ(s.clipped, 1u);
    EXPECT_EQ(ctl.stats().depth.tests, 23u);
}

}  // namespace
}  // namespace fb89::controller
