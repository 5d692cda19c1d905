// Tests of controller_sim/controller: execution into the framebuffer, per-opcode counters,
// clipping, commands outside frames, per-frame results, pipeline timing, and the batch
// path and the sink calls against executing each command.
#include "controller_sim/controller.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "protocol/memory_buffer.h"

namespace fb89::controller {
namespace {

using protocol::DrawSpan;
using protocol::FillRect;
using protocol::FrameBegin;
using protocol::FrameEnd;
using protocol::Marker;
using protocol::Opcode;
using protocol::Rgb;

constexpr Rgb kGrey{50, 50, 50};
constexpr Rgb kRed{255, 0, 0};

// The first cost model (tms34010-mame): the hand computations below use its round figures
// (C_cmd 25, FILL's set-up 8, 2 cycles a word, LINE's set-up 12, 2 a pixel, 160 ns a cycle).
// The default profile's memory-cycle figures are cost_model_test.cpp's; here its own rule
// for commands outside the frame is checked, and the batch paths run under it too.
CostProfile mame_model() {
    return load_profile("tms34010-mame");
}

const OpcodeCounters& totals(const Controller& c, Opcode op) {
    return c.stats().totals[protocol::opcode_index(op)];
}

// Every pixel equals `inside` within r and `outside` elsewhere.
void expect_only_rect(const Framebuffer& fb, const PixelRect& r, Rgb inside, Rgb outside) {
    for (uint32_t y = 0; y < fb.height(); ++y)
        for (uint32_t x = 0; x < fb.width(); ++x) {
            const bool in = x >= r.x && x < r.x + r.w && y >= r.y && y < r.y + r.h;
            ASSERT_EQ(fb.pixel(x, y), in ? inside : outside) << "(" << x << ", " << y << ")";
        }
}

TEST(Controller, FrameBeginClearsAndIsChargedAsFullScreenFill) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 1024, 780, kGrey});
    expect_only_rect(c.framebuffer(), PixelRect{}, kRed, kGrey);
    const OpcodeCounters& fb = totals(c, Opcode::FrameBegin);
    EXPECT_EQ(fb.commands, 1u);
    EXPECT_EQ(fb.cycles, 798'753u);
    EXPECT_EQ(fb.pixels, 1024u * 780u);
    EXPECT_EQ(fb.bytes, 10u);
}

TEST(Controller, FillAndSpanCountCyclesPixelsAndBytes) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 64, 32, kGrey});
    c.fill_rect(FillRect{5, 6, 1, 1, kRed});
    c.draw_span(DrawSpan{10, 0, 59, kRed});  // 60 pixels, all inside
    const OpcodeCounters& fill = totals(c, Opcode::FillRect);
    EXPECT_EQ(fill.cycles, 35u);
    EXPECT_EQ(fill.pixels, 1u);
    EXPECT_EQ(fill.bytes, 12u);
    const OpcodeCounters& span = totals(c, Opcode::DrawSpan);
    EXPECT_EQ(span.cycles, 25u + 12u + 120u);
    EXPECT_EQ(span.pixels, 60u);
    EXPECT_EQ(span.bytes, 10u);
    EXPECT_EQ(c.framebuffer().pixel(5, 6), kRed);
    EXPECT_EQ(c.framebuffer().pixel(59, 10), kRed);
    EXPECT_EQ(c.framebuffer().pixel(60, 10), kGrey);
}

TEST(Controller, ClippedFillIsCountedChargedForWhatIsLeftAndStaysInBounds) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 16, 8, kGrey});
    c.fill_rect(FillRect{-4, -2, 8, 4, kRed});   // 4x2 left inside
    c.fill_rect(FillRect{14, 7, 10, 10, kRed});  // 2x1 left, bottom-right corner
    const OpcodeCounters& fill = totals(c, Opcode::FillRect);
    EXPECT_EQ(fill.clipped, 2u);
    EXPECT_EQ(fill.outside, 0u);
    EXPECT_EQ(fill.pixels, 8u + 2u);
    EXPECT_EQ(fill.cycles, (25u + 8u + 2u * 2u * 2u) + (25u + 8u + 1u * 2u * 1u));
    const Framebuffer& fb = c.framebuffer();
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 16; ++x) {
            const bool in = (x < 4 && y < 2) || (x >= 14 && y == 7);
            ASSERT_EQ(fb.pixel(x, y), in ? kRed : kGrey) << "(" << x << ", " << y << ")";
        }
}

TEST(Controller, WhollyOutsideCommandsCostCmdAndBusAndWriteNothing) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 16, 8, kGrey});
    const uint64_t before = c.framebuffer().checksum();
    c.fill_rect(FillRect{16, 0, 4, 4, kRed});
    c.fill_rect(FillRect{0, -4, 4, 4, kRed});
    c.fill_rect(FillRect{3, 3, 0, 4, kRed});  // empty
    c.draw_span(DrawSpan{8, 0, 15, kRed});
    c.draw_span(DrawSpan{2, 9, 3, kRed});  // x1 < x0
    EXPECT_EQ(c.framebuffer().checksum(), before);
    const OpcodeCounters& fill = totals(c, Opcode::FillRect);
    EXPECT_EQ(fill.outside, 3u);
    EXPECT_EQ(fill.cycles, 3u * 25u);
    EXPECT_EQ(fill.pixels, 0u);
    EXPECT_EQ(fill.bytes, 3u * 12u);
    const OpcodeCounters& span = totals(c, Opcode::DrawSpan);
    EXPECT_EQ(span.outside, 2u);
    EXPECT_EQ(span.cycles, 2u * 25u);
    EXPECT_DOUBLE_EQ(c.stats().bus_busy_us, 2.25 + 3 * 2.5 + 2 * 2.25);
}

TEST(Controller, WithAListingAnOutsideCommandStillPaysItsSetUpAndHostWords) {
    const CostProfile p = default_profile();
    Controller c(p);
    c.frame_begin(FrameBegin{0, 16, 8, kGrey});
    c.fill_rect(FillRect{16, 0, 4, 4, kRed});
    c.draw_span(DrawSpan{8, 0, 15, kRed});
    c.frame_end(FrameEnd{});
    EXPECT_EQ(totals(c, Opcode::FillRect).cycles, outside_cycles(p, Opcode::FillRect));
    EXPECT_EQ(totals(c, Opcode::FillRect).cycles, 21u + 35u + 6u * 2u);
    EXPECT_EQ(totals(c, Opcode::DrawSpan).cycles, 21u + 40u + 5u * 2u);  // its FILL's set-up
    EXPECT_EQ(totals(c, Opcode::FrameEnd).cycles, 21u + 8u + 2u);
    EXPECT_EQ(totals(c, Opcode::FrameBegin).cycles, frame_begin_cycles(p, 16, 8));
    EXPECT_NEAR(c.stats().controller_busy_us,
                static_cast<double>(frame_begin_cycles(p, 16, 8) + 68 + 71 + 31) * us_per_cycle(p),
                1e-9);
}

TEST(Controller, ClippedSpanCostsSetUpPlusClippedPixels) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 16, 8, kGrey});
    c.draw_span(DrawSpan{3, -5, 3, kRed});
    const OpcodeCounters& span = totals(c, Opcode::DrawSpan);
    EXPECT_EQ(span.clipped, 1u);
    EXPECT_EQ(span.pixels, 4u);
    EXPECT_EQ(span.cycles, 25u + 12u + 2u * 4u);
    expect_only_rect(c.framebuffer(), PixelRect{0, 3, 4, 1}, kRed, kGrey);
}

TEST(Controller, CommandsBeforeAnyFrameAreUnframedOutsideAndDrawNothing) {
    Controller c(mame_model());
    const uint64_t before = c.framebuffer().checksum();
    c.fill_rect(FillRect{0, 0, 4, 4, kRed});
    c.draw_span(DrawSpan{0, 0, 3, kRed});
    c.frame_end(FrameEnd{});
    EXPECT_EQ(c.framebuffer().checksum(), before);
    EXPECT_TRUE(c.frames().empty());
    EXPECT_FALSE(c.in_frame());
    const OpcodeCounters loose = sum(c.stats().unframed);
    EXPECT_EQ(loose.commands, 3u);
    EXPECT_EQ(loose.outside, 3u);
    EXPECT_EQ(loose.cycles, 3u * 25u);
    EXPECT_EQ(sum(c.stats().totals), loose);
}

TEST(Controller, CommandsBetweenFramesDoNotChangeTheClosedFrame) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 8, 8, kGrey});
    c.frame_end(FrameEnd{});
    c.fill_rect(FillRect{0, 0, 8, 8, kRed});
    EXPECT_EQ(c.framebuffer().checksum(), c.frames().at(0).checksum);
    EXPECT_EQ(totals(c, Opcode::FillRect).outside, 1u);
}

TEST(Controller, FrameEndRecordsFrameResult) {
    Controller c(mame_model());
    c.marker(Marker{"before"});
    c.frame_begin(FrameBegin{7, 32, 16, kGrey});
    c.fill_rect(FillRect{1, 1, 2, 2, kRed});
    c.frame_end(FrameEnd{});
    ASSERT_EQ(c.frames().size(), 1u);
    const FrameResult& f = c.frames()[0];
    EXPECT_EQ(f.frame, 7u);
    EXPECT_EQ(f.width, 32u);
    EXPECT_EQ(f.height, 16u);
    EXPECT_EQ(f.first_command, 1u);
    EXPECT_TRUE(f.complete);
    EXPECT_EQ(f.checksum, c.framebuffer().checksum());
    EXPECT_EQ(f.total().commands, 3u);
    EXPECT_EQ(f.ops[protocol::opcode_index(Opcode::FillRect)].pixels, 4u);
    EXPECT_EQ(c.commands_executed(), 4u);
}

TEST(Controller, FrameBeginInsideOpenFrameClosesItAsIncomplete) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 8, 8, kGrey});
    c.fill_rect(FillRect{0, 0, 8, 8, kRed});
    c.frame_begin(FrameBegin{1, 8, 8, kGrey});
    ASSERT_EQ(c.frames().size(), 1u);
    EXPECT_FALSE(c.frames()[0].complete);
    Framebuffer red(8, 8);
    red.clear(kRed);
    EXPECT_EQ(c.frames()[0].checksum, red.checksum());
    EXPECT_TRUE(c.in_frame());
    EXPECT_EQ(c.open_frame().frame, 1u);
}

TEST(Controller, OversizedFrameBeginIsRefusedNamingTheCommand) {
    Controller c(mame_model());
    try {
        c.frame_begin(FrameBegin{0, 16385, 8, kGrey});
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("FRAME_BEGIN"), std::string::npos) << e.what();
    }
    EXPECT_EQ(c.framebuffer().width(), kDefaultWidth);
}

TEST(Controller, MarkerCostsNothingAndWritesNothing) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 8, 8, kGrey});
    c.marker(Marker{"phase"});
    const OpcodeCounters& m = totals(c, Opcode::Marker);
    EXPECT_EQ(m.commands, 1u);
    EXPECT_EQ(m.cycles, 0u);
    EXPECT_EQ(m.bytes, 0u);
    EXPECT_EQ(m.outside, 0u);
}

// FRAME_BEGIN 4x2: bus 2.25 us, 25+8+2*2*2 = 41 cycles = 6.56 us; FILL_RECT 1x1: bus
// 2.5 us, 5.6 us; FRAME_END: bus 1.25 us, 25 cycles = 4 us. Arrivals 2.25, 4.75, 6.0;
// executions 2.25-8.81, 8.81-14.41, 14.41-18.41.
TEST(Controller, ControllerBoundFrameTimingMatchesHandComputation) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{0, 4, 2, kGrey});
    c.fill_rect(FillRect{0, 0, 1, 1, kRed});
    c.frame_end(FrameEnd{});
    const FrameResult& f = c.frames().at(0);
    EXPECT_NEAR(f.bus_busy_us, 6.0, 1e-9);
    EXPECT_NEAR(f.controller_busy_us, 6.56 + 5.6 + 4.0, 1e-9);
    EXPECT_NEAR(f.end_us, 18.41, 1e-9);
}

// A 1 MB/s bus: FRAME_BEGIN 11 us, FILL_RECT 13 us, FRAME_END 3 us on the bus; execution
// 5.6, 5.6 x 3 and 4 us. Arrivals 11, 24, 37, 50, 53; the last ends at 55.6 + 4 = 59.6.
TEST(Controller, BusBoundFrameTimingMatchesHandComputation) {
    CostProfile p = mame_model();
    p.b_bus_bytes_per_s = 1e6;
    Controller c(p);
    c.frame_begin(FrameBegin{0, 2, 1, kGrey});  // 25 + 8 + 2 = 35 cycles
    for (int i = 0; i < 3; ++i)
        c.fill_rect(FillRect{0, 0, 1, 1, kRed});
    c.frame_end(FrameEnd{});
    const FrameResult& f = c.frames().at(0);
    EXPECT_NEAR(f.bus_busy_us, 53.0, 1e-9);
    EXPECT_NEAR(f.controller_busy_us, 4 * 5.6 + 4.0, 1e-9);
    EXPECT_NEAR(f.end_us, 59.6, 1e-9);
    EXPECT_NEAR(c.stats().frames_end_us, 59.6, 1e-9);
}

TEST(Controller, IdealProfileCountsWorkButChargesNoTime) {
    Controller c(load_profile("ideal"));
    c.frame_begin(FrameBegin{0, 1024, 780, kGrey});
    c.fill_rect(FillRect{0, 0, 100, 100, kRed});
    c.draw_span(DrawSpan{200, 0, 99, kRed});
    c.frame_end(FrameEnd{});
    const FrameResult& f = c.frames().at(0);
    EXPECT_EQ(f.total().cycles, 0u);
    EXPECT_EQ(f.total().pixels, 1024u * 780u + 10'000u + 100u);
    EXPECT_EQ(f.bus_busy_us, 0.0);
    EXPECT_EQ(f.controller_busy_us, 0.0);
    EXPECT_EQ(f.end_us, 0.0);
    // The bytes the commands take on the host port are counted as under the TMS34010:
    // FRAME_BEGIN 10 + FILL_RECT 12 + DRAW_SPAN 10 + FRAME_END 2. Only their time is free.
    EXPECT_EQ(f.total().bytes, 34u);
}

TEST(Controller, ExecuteAndSinkCallsAndMemoryReplayAgree) {
    protocol::MemoryBuffer buffer;
    buffer.frame_begin(FrameBegin{0, 40, 30, kGrey});
    buffer.fill_rect(FillRect{3, 4, 20, 10, kRed});
    buffer.draw_span(DrawSpan{20, -3, 50, Rgb{1, 2, 3}});
    buffer.marker(Marker{"x"});
    buffer.frame_end(FrameEnd{});
    Controller a, b;
    buffer.replay_into(a);
    for (const protocol::Command& cmd : buffer.commands())
        b.execute(cmd);
    EXPECT_EQ(a.frames().at(0).checksum, b.frames().at(0).checksum);
    EXPECT_EQ(a.stats().totals, b.stats().totals);
}

// A stream with every case the batch path must hand over or count: commands before any
// frame and between frames, FRAME_END outside a frame, frames of several sizes (one pixel,
// odd, full), fills and spans inside, clipped at every edge, wholly outside and empty,
// markers, and a frame closed by the next FRAME_BEGIN.
std::vector<protocol::Command> mixed_commands() {
    std::vector<protocol::Command> out;
    uint32_t seed = 12345;
    const auto next = [&seed](int64_t lo, int64_t hi) {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<int32_t>(lo + static_cast<int64_t>(seed >> 8) % (hi - lo + 1));
    };
    const auto drawing = [&](int32_t w, int32_t h, int n) {
        for (int i = 0; i < n; ++i) {
            const Rgb c{static_cast<uint8_t>(next(0, 255)), 9, static_cast<uint8_t>(i)};
            const int32_t x = next(-40, w + 40), y = next(-3, h + 3);
            if (i % 3 == 0) {
                out.push_back(FillRect{x, y, static_cast<uint32_t>(next(0, w + 8)),
                                       static_cast<uint32_t>(next(0, 6)), c});
            } else if (i % 50 == 7) {
                out.push_back(DrawSpan{y, x, x - 1, c});  // x1 < x0: empty
            } else {
                out.push_back(DrawSpan{y, x, x + next(0, i % 7 == 1 ? 3 * w : 20), c});
            }
            if (i % 97 == 0) out.push_back(Marker{"m"});
        }
    };
    drawing(50, 50, 20);
    out.push_back(FrameEnd{});
    const int32_t sizes[][2] = {{1, 1}, {37, 23}, {1024, 780}, {16, 1}, {3, 300}};
    for (uint32_t f = 0; f < 5; ++f) {
        const auto [w, h] = sizes[f];
        out.push_back(FrameBegin{f, static_cast<uint32_t>(w), static_cast<uint32_t>(h), kGrey});
        drawing(w, h, 400);
        if (f != 2) out.push_back(FrameEnd{});  // frame 2 is closed by frame 3's FRAME_BEGIN
        if (f == 3) drawing(w, h, 10);          // between frames
    }
    out.push_back(FrameBegin{9, 64, 48, kRed});
    drawing(64, 48, 50);  // left open
    return out;
}

// Everything a replay reports, exactly (doubles included), and the pixels.
void expect_same_run(const Controller& a, const Controller& b, const std::string& what) {
    EXPECT_EQ(a.stats().to_json(), b.stats().to_json()) << what;
    EXPECT_EQ(a.commands_executed(), b.commands_executed()) << what;
    EXPECT_EQ(a.elapsed_us(), b.elapsed_us()) << what;
    ASSERT_EQ(a.in_frame(), b.in_frame()) << what;
    EXPECT_EQ(a.open_frame().checksum, b.open_frame().checksum) << what;
    EXPECT_EQ(a.open_frame().ops, b.open_frame().ops) << what;
    EXPECT_TRUE(std::ranges::equal(a.framebuffer().pixels(), b.framebuffer().pixels())) << what;
}

std::vector<CostProfile> batch_profiles() {
    CostProfile slow_bus = default_profile();
    slow_bus.name = "slow bus, spans as lines, the clear by FILL, 4 bpp";
    slow_bus.b_bus_bytes_per_s = 1e6;
    slow_bus.span_as = SpanAs::Line;
    slow_bus.clear_as = ClearAs::Fill;
    slow_bus.bpp = 4;
    derive_figures(slow_bus);
    return {default_profile(), mame_model(), load_profile("ideal"), slow_bus};
}

TEST(Controller, BatchesGiveWhatExecutingEachCommandGives) {
    const std::vector<protocol::Command> commands = mixed_commands();
    for (const CostProfile& p : batch_profiles()) {
        Controller one(p);
        for (const protocol::Command& c : commands)
            one.execute(c);
        for (std::size_t batch :
             {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{64}, commands.size()}) {
            Controller batched(p);
            for (std::size_t i = 0; i < commands.size(); i += batch) {
                const std::size_t n = std::min(batch, commands.size() - i);
                batched.execute(std::span(commands).subspan(i, n));
            }
            expect_same_run(one, batched, fmt::format("{}, batches of {}", p.name, batch));
        }
    }
}

// A batch asked for its costs gives each command's, as last_cost() does command by command
// (the pipeline in time takes them), and runs the same.
TEST(Controller, BatchesGiveEachCommandsCostBesideIt) {
    const std::vector<protocol::Command> commands = mixed_commands();
    for (const CostProfile& p : batch_profiles()) {
        Controller one(p);
        std::vector<Controller::CommandCost> want;
        for (const protocol::Command& c : commands) {
            one.execute(c);
            want.push_back(one.last_cost());
        }
        Controller batched(p);
        std::vector<Controller::CommandCost> got(commands.size());
        for (std::size_t i = 0; i < commands.size(); i += 64) {
            const std::size_t n = std::min<std::size_t>(64, commands.size() - i);
            batched.execute(std::span(commands).subspan(i, n), std::span(got).subspan(i, n));
        }
        expect_same_run(one, batched, p.name + ", with costs");
        for (std::size_t i = 0; i < commands.size(); ++i) {
            ASSERT_EQ(got[i].bytes, want[i].bytes) << p.name << ", command " << i;
            ASSERT_EQ(got[i].bus_us, want[i].bus_us) << p.name << ", command " << i;
            ASSERT_EQ(got[i].exec_us, want[i].exec_us) << p.name << ", command " << i;
        }
    }
}

TEST(Controller, SinkCallsGiveWhatExecuteGivesWithAndWithoutAnObserver) {
    const std::vector<protocol::Command> commands = mixed_commands();
    Controller executed, sunk, observed;
    std::vector<uint64_t> seen;
    observed.set_observer(
        [&](uint64_t number, const protocol::Command&) { seen.push_back(number); });
    for (const protocol::Command& c : commands) {
        executed.execute(c);
        sunk.submit(c);
        observed.submit(c);
    }
    expect_same_run(executed, sunk, "sink calls");
    expect_same_run(executed, observed, "sink calls, observed");
    ASSERT_EQ(seen.size(), commands.size());
    for (std::size_t i = 0; i < seen.size(); ++i)
        ASSERT_EQ(seen[i], i);
}

TEST(Controller, BatchesShowAnObserverEveryCommandInOrder) {
    const std::vector<protocol::Command> commands = mixed_commands();
    Controller c(mame_model());
    std::vector<protocol::Command> seen;
    c.set_observer([&](uint64_t number, const protocol::Command& cmd) {
        EXPECT_EQ(number, seen.size());
        seen.push_back(cmd);
    });
    c.execute(commands);
    EXPECT_EQ(seen, commands);
}

TEST(Controller, StatsJsonAndSummaryReportEveryOpcode) {
    Controller c(mame_model());
    c.frame_begin(FrameBegin{3, 1024, 780, kGrey});
    c.fill_rect(FillRect{0, 0, 1, 1, kRed});
    c.frame_end(FrameEnd{});
    const nlohmann::json j = c.stats().to_json();
    EXPECT_EQ(j["profile"]["name"], "tms34010-mame");
    EXPECT_EQ(j["totals"]["FRAME_BEGIN"]["cycles"], 798'753u);
    EXPECT_EQ(j["totals"]["all"]["commands"], 3u);
    EXPECT_EQ(j["frames"][0]["frame"], 3u);
    EXPECT_EQ(j["frames"][0]["checksum"].get<std::string>().size(), 16u);
    const std::string s = c.stats().summary();
    for (const char* text : {"FRAME_BEGIN", "FILL_RECT", "DRAW_SPAN", "MARKER", "FRAME_END",
                             "798,753", "127.800", "modelled ms"})
        EXPECT_NE(s.find(text), std::string::npos) << text << " not in\n" << s;
}

}  // namespace
}  // namespace fb89::controller
