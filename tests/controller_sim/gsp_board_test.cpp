// The board running the executive (controller_sim/gsp_board.h) beside the C++ controller on
// commands made by hand: clipped and outside ones, both depth words, a ring that wraps, a
// FACE cut by every side of the frame. Each frame equal pixel for pixel, and each opcode's
// executed cycles with every fetch a hit (the model's assumption) equal to the model's.
#include "controller_sim/gsp_board.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "controller_sim/controller.h"
#include "controller_sim/gsp_assembler.h"
#include "controller_sim/gsp_listing.h"

namespace fb89::controller::gsp {
namespace {

using protocol::Command;
using protocol::Rgb;

GspBoard board_for(const CostProfile& p, const GspBoardOptions& o = {}) {
    return GspBoard(p, "tms34010.asm", builtin_listing("tms34010").text, o);
}

// Runs `commands` on both; expects equal frames and, warm, equal cycles opcode by opcode.
void expect_same(const CostProfile& p, const std::vector<Command>& commands,
                 GspBoardOptions o = {}) {
    o.cache = false;
    GspBoard board = board_for(p, o);
    Controller ctl(p);
    board.execute(commands);
    ctl.execute(commands);
    const Framebuffer gsp = board.frame();
    ASSERT_EQ(gsp.width(), ctl.framebuffer().width());
    ASSERT_EQ(gsp.height(), ctl.framebuffer().height());
    for (uint32_t y = 0; y < gsp.height(); ++y)
        for (uint32_t x = 0; x < gsp.width(); ++x)
            ASSERT_EQ(gsp.pixel(x, y), ctl.framebuffer().pixel(x, y)) << x << "," << y;
    for (int i = 0; i < protocol::kOpcodeCount; ++i) {
        const auto& e = board.executed()[static_cast<std::size_t>(i)];
        EXPECT_EQ(e.cycles() - e.cache_miss_states + e.queue_overlapped,
                  ctl.stats().totals[static_cast<std::size_t>(i)].cycles)
            << protocol::to_string(protocol::kOpcodes[i]);
        if (protocol::kOpcodes[i] != protocol::Opcode::Marker) {  // (not sent)
            EXPECT_EQ(e.commands, ctl.stats().totals[static_cast<std::size_t>(i)].commands);
        }
    }
}

protocol::Face square_face(int64_t x0, int64_t y0, int64_t x1, int64_t y1, uint32_t z, Rgb c) {
    protocol::Face f;
    f.color = c;
    f.x_ref = static_cast<int32_t>(x0 / 256);
    f.y_ref = static_cast<int32_t>(y0 / 256);
    f.z = z;
    f.dzdx = 1000;
    f.dzdy = -300;
    f.points = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};  // positive: clockwise on screen
    return f;
}

// The points in positive orientation (clockwise on the screen, y down), reversed if not.
std::vector<protocol::SnappedPoint> oriented(std::vector<protocol::SnappedPoint> p) {
    int64_t twice_area = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const auto& a = p[i];
        const auto& b = p[(i + 1) % p.size()];
        twice_area += a.x * b.y - b.x * a.y;
    }
    if (twice_area < 0) std::reverse(p.begin(), p.end());
    return p;
}

const Rgb kRed{200, 0, 0}, kGreen{0, 180, 0}, kBlue{0, 0, 220}, kGrey{90, 90, 90};

// The commands' rows (protocol/command.h) and the listing agree: its dispatch table holds each
// command's handler by opcode, as the board fills it; each command's words on the host port
// are its row's, and the profile's modelled bytes twice their count.
TEST(GspBoard, TheListingsTableAndTheHostsWordsAreTheCommandsRows) {
    const Program program = assemble("tms34010.asm", builtin_listing("tms34010").text);
    const std::vector<uint16_t> image = program.image();
    const uint32_t table = program.labels.at("table");
    for (const protocol::CommandRow& row : protocol::kCommandRows) {
        if (!row.handler) continue;
        const std::size_t at = (table + 32 * static_cast<uint32_t>(row.opcode)) / 16;
        ASSERT_LT(at + 1, image.size()) << row.name;
        const uint32_t entry = image[at] | (uint32_t{image[at + 1]} << 16);
        EXPECT_EQ(entry, program.labels.at(row.handler)) << row.name;
    }
    const CostProfile p = load_profile("tms34010-50mhz");
    GspBoard board = board_for(p);
    const std::vector<Command> commands = {
        protocol::FrameBegin{0, 64, 48, Rgb{1, 2, 3}},
        protocol::FillRect{-3, 2, 10, 5, Rgb{4, 5, 6}},
        protocol::DrawSpan{3, 1, 9, Rgb{7, 8, 9}},
        protocol::Marker{"m"},
        protocol::DepthClear{},
        protocol::DepthSpan{4, 0, 20, 1000, 3, Rgb{1, 1, 1}},
        protocol::Face{Rgb{2, 2, 2}, 1, 1, 500, 1, 1, {{0, 0}, {2560, 0}, {0, 2560}}},
        protocol::FrameEnd{}};
    for (const Command& c : commands) {
        const protocol::Opcode op = protocol::opcode_of(c);
        const protocol::CommandRow& row = protocol::kCommandRows[protocol::opcode_index(op)];
        const std::size_t points =
            op == protocol::Opcode::Face ? std::get<protocol::Face>(c).points.size() : 0;
        const std::vector<uint16_t> words = board.words_of(c);
        EXPECT_EQ(words.size(), row.port_words + 4 * points) << row.name;
        if (!words.empty()) {
            EXPECT_EQ(words[0], static_cast<uint16_t>(op));
        }
        EXPECT_EQ(p.bytes_of(op) + kFacePointBytes * points, 2 * words.size()) << row.name;
    }
}

TEST(GspBoard, ClippedAndOutsideTilingCommandsDrawWhatTheControllerDraws) {
    for (const char* span_as : {"fill", "line"}) {
        CostProfile p = load_profile("tms34010-50mhz");
        p.span_as = std::string(span_as) == "fill" ? SpanAs::Fill : SpanAs::Line;
        derive_figures(p);
        expect_same(p, {protocol::FrameBegin{0, 40, 30, kGrey},
                        protocol::FillRect{-5, -3, 12, 8, kRed},           // cut top-left
                        protocol::FillRect{35, 25, 100, 100, kGreen},      // cut bottom-right
                        protocol::FillRect{-100000, 2, 200000, 1, kBlue},  // beyond 16 bits
                        protocol::FillRect{50, 5, 4, 4, kRed},             // outside
                        protocol::DrawSpan{10, -7, 3, kBlue},              // cut left
                        protocol::DrawSpan{11, 38, 90, kGreen},            // cut right
                        protocol::DrawSpan{-1, 0, 39, kRed},               // above
                        protocol::DrawSpan{12, 7, 7, kRed},                // one pixel
                        protocol::Marker{"not sent"}, protocol::FrameEnd{}});
    }
}

TEST(GspBoard, DepthSpansAndFacesOfBothDepthWordsDrawWhatTheControllerDraws) {
    for (const uint32_t bits : {16u, 32u}) {
        CostProfile p = load_profile("tms34010-50mhz");
        p.depth_bits = bits;
        derive_figures(p);
        const uint32_t half = protocol::depth_fixed(0.5);
        expect_same(
            p, {protocol::FrameBegin{1, 48, 32, kGrey}, protocol::DepthClear{},
                protocol::DepthSpan{3, -6, 20, half, 1 << 12, kRed},  // cut left
                protocol::DepthSpan{3, 10, 60, half - (1 << 16), -4096, kGreen},
                protocol::DepthSpan{40, 0, 10, half, 0, kBlue},      // below
                protocol::DepthSpan{5, 30, 20, half, 0, kBlue},      // empty
                square_face(-3000, -2000, 6000, 4000, half, kBlue),  // cut top-left
                square_face(8000, 5000, 20000, 12000, half - 500000, kRed),
                square_face(1000, 1000, 3000, 3000, half + 900000, kGreen), protocol::FrameEnd{}});
    }
}

TEST(GspBoard, AFaceOfEveryShapeTakesTheEdgesPathsTheModelCounts) {
    // triangles and a hexagon at odd sub-pixel positions: left, right and level edges,
    // nearer bounds and none, a row emptied, points far outside the frame
    const CostProfile p = load_profile("tms34010-50mhz");
    std::vector<Command> c = {protocol::FrameBegin{2, 64, 48, kGrey}, protocol::DepthClear{}};
    const uint32_t z = protocol::depth_fixed(0.4);
    const std::vector<std::vector<protocol::SnappedPoint>> shapes = {
        {{300, 200}, {900, 9000}, {14000, 3100}},
        {{5000, 100}, {5000, 11000}, {15000, 11000}},
        {{-4000000, -3000000}, {20, 11900}, {16000, 12100}},
        {{2000, 2000}, {1000, 5000}, {2000, 8000}, {6000, 8000}, {7000, 5000}, {6000, 2000}},
        {{100, 100}, {100, 300}, {16300, 300}},  // a sliver: rows with no covered centre
    };
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        protocol::Face f;
        f.color = Rgb{static_cast<uint8_t>(40 * i), 100, 30};
        f.x_ref = 3;
        f.y_ref = 4;
        f.z = z;
        f.dzdx = 2000 - 700 * static_cast<int32_t>(i);
        f.dzdy = 1500;
        f.points = oriented(shapes[i]);
        c.push_back(f);
    }
    c.push_back(protocol::FrameEnd{});
    expect_same(p, c);
}

TEST(GspBoard, ARingThatWrapsCarriesEveryCommandWhole) {
    const CostProfile p = load_profile("tms34010-50mhz");
    std::vector<Command> c = {protocol::FrameBegin{0, 64, 64, kGrey}};
    for (int i = 0; i < 400; ++i)
        c.push_back(protocol::FillRect{i % 60, (i * 7) % 60, 5, 3,
                                       Rgb{static_cast<uint8_t>(i % 7 * 30), 10, 10}});
    c.push_back(protocol::FrameEnd{});
    GspBoardOptions o;
    o.ring_words = 600;  // a hundred FILL_RECTs a lap
    expect_same(p, c, o);
    GspBoard board = board_for(p, o);
    board.execute(c);
    EXPECT_GE(board.executed()[protocol::opcode_index(protocol::Opcode::FillRect)].wraps, 3u);
}

TEST(GspBoard, ACommandTheBoardCannotTakeIsRefusedNamingIt) {
    const CostProfile p = load_profile("tms34010-50mhz");
    GspBoard board = board_for(p);
    const std::vector<Command> wide = {protocol::FrameBegin{0, 2048, 16, kGrey}};
    try {
        board.execute(wide);
        FAIL() << "a frame wider than the board's";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("command 0: FRAME_BEGIN"), std::string::npos)
            << e.what();
    }
    std::vector<Command> colours = {protocol::FrameBegin{0, 16, 16, kGrey}};
    for (int i = 0; i < 300; ++i)
        colours.push_back(protocol::FillRect{
            0, 0, 1, 1, Rgb{static_cast<uint8_t>(i), static_cast<uint8_t>(i >> 8), 1}});
    GspBoard other = board_for(p);
    try {
        other.execute(colours);
        FAIL() << "more colours than 8 bits hold";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("16-bit"), std::string::npos) << e.what();
    }
}

TEST(GspBoard, AUsersListingThatGoesWrongIsAFaultNamingItsLine) {
    const CostProfile p = load_profile("tms34010-50mhz");
    std::string text(builtin_listing("tms34010").text);
    // FILL_RECT's handler made to loop for ever
    const std::string handler = "fill_rect:\n";
    text.insert(text.find(handler) + handler.size(), "spin:     JRUC   spin\n");
    GspBoardOptions o;
    o.budget = 100000;
    GspBoard board(p, "mine.asm", text, o);
    try {
        board.execute(std::vector<Command>{protocol::FrameBegin{0, 8, 8, kGrey},
                                           protocol::FillRect{0, 0, 2, 2, kRed}});
        FAIL() << "a loop that does not end";
    } catch (const GspFault& f) {
        const std::string what = f.what();
        EXPECT_NE(what.find("mine.asm line"), std::string::npos) << what;
        EXPECT_NE(what.find("JRUC   spin"), std::string::npos) << what;
        EXPECT_NE(what.find("command 1"), std::string::npos) << what;
    }
    EXPECT_THROW(GspBoard(p, "bad.asm", "next: FROB A1\n"), AssemblyError);
}

}  // namespace
}  // namespace fb89::controller::gsp
