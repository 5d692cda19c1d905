// The controller's checks (see controller_validation.h). Every "stated" figure is what the
// source prints, computed here from the profile's own timing (its state, its memory cycle)
// where the source gives a rule rather than a number; every model figure is the cost model's
// (cost_model.h) or the listing's (gsp_listing.h), never typed in.
#include "experiments/controller_validation.h"

#include <limits>

#include <fmt/format.h>

#include "controller_sim/cost_model.h"
#include "controller_sim/gsp_listing.h"
#include "experiments/measure.h"

namespace fb89::experiments {

namespace {

using controller::CostProfile;
using controller::PixelRect;

// The same chip at 16 bpp, its figures derived again.
CostProfile at_16_bpp(CostProfile p) {
    p.bpp = 16;
    controller::derive_figures(p);
    return p;
}

double ms(const CostProfile& p, uint64_t cycles) {
    return controller::cycles_to_seconds(p, cycles) * 1e3;
}
double ms(const CostProfile& p, double cycles) {
    return cycles * controller::us_per_cycle(p) / 1e3;
}

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// Cycles of the pixels alone: a command's cost less the same command's with nothing drawn.
double fill_pixels(const CostProfile& p, const PixelRect& r) {
    return static_cast<double>(controller::fill_rect_cycles(p, r) -
                               controller::fill_rect_cycles(p, {r.x, r.y, 0, 0}));
}
double line_pixels(const CostProfile& p, uint32_t n) {
    CostProfile line = p;
    line.span_as = controller::SpanAs::Line;
    return static_cast<double>(controller::draw_span_cycles(line, 0, n) -
                               controller::draw_span_cycles(line, 0, 0));
}

}  // namespace

std::vector<ValidationRow> controller_validation(const CostProfile& after,
                                                 const CostProfile& before,
                                                 const CostProfile& tms34020,
                                                 const protocol::MemoryBuffer& frame) {
    std::vector<ValidationRow> rows;
    const auto add = [&](ValidationRow r) { rows.push_back(std::move(r)); };
    const auto at_least = [](double model, double floor) { return model >= floor; };
    const double m = after.memory_cycle_states;  // the data sheet's minimum, no wait states
    const double state_ns = 1e9 / after.f_cyc_hz;

    add({"a state (local clock)", "ns", "[DS] SPVS002C p. 1 (TMS34010-50: 160 ns) and p. 39",
         fmt::format("{:g}", 160.0), 1e9 / before.f_cyc_hz, state_ns, true, state_ns == 160,
         1e9 / before.f_cyc_hz == 160});
    add({"an aligned word written", "states",
         "[DS] SPVS002C p. 19: a memory cycle is at least 2 states", "at least 2",
         static_cast<double>(before.c_op), static_cast<double>(after.c_op), true,
         at_least(after.c_op, 2), at_least(before.c_op, 2)});
    add({"a partial word of a fill (read, modify, write)", "states",
         "[DS] SPVS002C p. 19 and the pin list (one CAS, one W, no byte strobes): two cycles",
         "at least 4", static_cast<double>(before.c_op_partial),
         static_cast<double>(after.c_op_partial), true, at_least(after.c_op_partial, 2 * m),
         at_least(before.c_op_partial, 2 * m)});
    add({"a pixel of LINE at 8 bpp", "states", "[DS] as a partial word: read and write its word",
         "at least 4", static_cast<double>(before.c_line_pix),
         static_cast<double>(after.c_line_pix), true, at_least(after.c_line_pix, 2 * m),
         at_least(before.c_line_pix, 2 * m)});
    const CostProfile after16 = at_16_bpp(after);
    add({"a pixel of LINE at 16 bpp", "states", "[DS] SPVS002C p. 19: a pixel is a word, one write",
         "at least 2", static_cast<double>(before.c_line_pix),
         static_cast<double>(after16.c_line_pix), true, at_least(after16.c_line_pix, m),
         at_least(before.c_line_pix, m)});

    const PixelRect screen{0, 0, 1024, 780};
    const double clear_floor = 780.0 * 512 * m;  // 512 words a row, one write cycle each
    add({"full-screen clear, 1024x780 at 8 bpp", "states",
         "[DS] p. 19: 780 rows x 512 words x one 2-state write",
         fmt::format("at least {:.0f}", clear_floor),
         static_cast<double>(controller::frame_begin_cycles(before, 1024, 780)),
         static_cast<double>(controller::frame_begin_cycles(after, 1024, 780)), true,
         at_least((fill_pixels(after, screen)), clear_floor),
         at_least((fill_pixels(before, screen)), clear_floor)});
    add({"full-screen clear, 1024x780 at 8 bpp", "ms",
         "the states at 160 ns, refresh's share of the bus included", "",
         ms(before, controller::frame_begin_cycles(before, 1024, 780)),
         ms(after, controller::frame_begin_cycles(after, 1024, 780)), false, true, true});
    add({"FILL of 64 aligned words (128 pixels from x = 0)", "states", "[DS] p. 19: 64 writes",
         fmt::format("{:.0f}", 64 * m), (fill_pixels(before, {0, 0, 128, 1})),
         (fill_pixels(after, {0, 0, 128, 1})), true, fill_pixels(after, {0, 0, 128, 1}) == 64 * m,
         fill_pixels(before, {0, 0, 128, 1}) == 64 * m});
    add({"FILL of 128 pixels from x = 1 (63 words and two partial)", "states",
         "[DS] p. 19: 63 writes and 2 read-modify-writes",
         fmt::format("{:.0f}", 63 * m + 2 * 2 * m), (fill_pixels(before, {1, 0, 128, 1})),
         (fill_pixels(after, {1, 0, 128, 1})), true,
         fill_pixels(after, {1, 0, 128, 1}) == 63 * m + 4 * m,
         fill_pixels(before, {1, 0, 128, 1}) == 63 * m + 4 * m});
    add({"LINE of 100 pixels at 8 bpp", "states", "[DS] p. 19: 100 read-modify-writes",
         fmt::format("at least {:.0f}", 100 * 2 * m), (line_pixels(before, 100)),
         (line_pixels(after, 100)), true, line_pixels(after, 100) >= 200 * m,
         line_pixels(before, 100) >= 200 * m});
    add({"LINE of 100 pixels at 16 bpp", "states", "[DS] p. 19: 100 writes",
         fmt::format("at least {:.0f}", 100 * m), (line_pixels(before, 100)),
         (line_pixels(after16, 100)), true, line_pixels(after16, 100) >= 100 * m,
         line_pixels(before, 100) >= 100 * m});

    // The host port: strobe to strobe at least 7 tQ + 10 ns (tQ a quarter state), p. 34.
    const double strobe_ns = 7 * state_ns / 4 + 10;
    const double port_cap = 2e3 / strobe_ns;  // MB/s
    add({"host port, 16-bit words", "MB/s",
         fmt::format(
             "[DS] SPVS002C p. 34, parameter 3: strobe to strobe at least 7tQ + 10 ns = {:.0f} ns",
             strobe_ns),
         fmt::format("at most {:.2f}", port_cap), before.bus_bytes_per_s() / 1e6,
         after.bus_bytes_per_s() / 1e6, true, after.bus_bytes_per_s() / 1e6 <= port_cap + 1e-9,
         before.bus_bytes_per_s() / 1e6 <= port_cap + 1e-9});
    add({"a host word's memory cycle, taken from the GSP", "states",
         "[UG] section 11.3 (host outranks the GSP), via TMS34010_sv", "at least 2",
         static_cast<double>(before.c_host_word), static_cast<double>(after.c_host_word), true,
         at_least(after.c_host_word, m), at_least(before.c_host_word, m)});
    add({"DRAM refresh and display transfers", "% of the bus",
         "[UG] p. 6-11: a refresh every 32 or 64 states; one VRAM load a line [EST]", "3.1 to 9.4",
         100 * before.stolen_share, 100 * after.stolen_share, true,
         after.stolen_share >= m / 64 && after.stolen_share > 0, before.stolen_share >= m / 64});

    // The listing: its paths' sums are the set-ups; what each command repeats must fit the
    // 256-byte cache.
    const auto& listing = controller::builtin_listing(after.gsp);
    const auto paths = controller::count_paths(listing, controller::MemoryTiming{});
    for (const controller::CachedWork& w : controller::cached_work()) {
        const auto words = controller::working_set_words(paths, w.paths);
        add({fmt::format("{}: its length", w.what), "16-bit words",
             "[DS] SPVS002C p. 2: a 256-byte instruction cache", "at most 128", kNone,
             static_cast<double>(words), true, words <= 128, true});
    }
    add({"C_cmd: the loop's fetch and dispatch", "states", "the listing, COMMON", "",
         static_cast<double>(before.c_cmd), static_cast<double>(after.c_cmd), false, true, true});
    add({"FILL_RECT's set-up", "states", "the listing, FILL_RECT", "",
         static_cast<double>(before.c_setup), static_cast<double>(after.c_setup), false, true,
         true});
    add({"DRAW_SPAN's set-up as a line", "states", "the listing, DRAW_SPAN:line", "",
         static_cast<double>(before.c_line_setup), static_cast<double>(after.c_line_setup), false,
         true, true});
    add({"a 1x1 FILL_RECT, all of it", "us", "the listing, the host's 6 words, one partial word",
         "", ms(before, controller::fill_rect_cycles(before, {17, 3, 1, 1})) * 1e3,
         ms(after, controller::fill_rect_cycles(after, {17, 3, 1, 1})) * 1e3, false, true, true});
    add({"a 100-pixel DRAW_SPAN as a line, all of it", "us",
         "the listing, the host's 5 words, 100 pixels", "",
         ms(before, controller::draw_span_cycles(before, 0, 100)) * 1e3,
         ms(after, controller::draw_span_cycles(after, 0, 100)) * 1e3, false, true, true});

    // The one published comparison of the two chips.
    const auto ratio = [&](auto&& cost) { return cost(after) / cost(tms34020); };
    const double fill_ratio = ratio(
        [&](const CostProfile& p) { return ms(p, controller::frame_begin_cycles(p, 1024, 780)); });
    const double span_ratio =
        ratio([&](const CostProfile& p) { return ms(p, controller::draw_span_cycles(p, 0, 100)); });
    const double frame_ratio =
        ratio([&](const CostProfile& p) { return controller_figures(frame, p).controller_ms; });
    const std::string byte =
        "BYTE, September 1988, \"Unwrapping the TMS34020\": 6 to 50 times faster";
    // The first model ran the 34020 on the 34010's figures at its faster clock: the clocks' ratio.
    const double clocks = tms34020.f_cyc_hz / before.f_cyc_hz;
    add({"TMS34020 : TMS34010, full-screen fill", "x", byte, "6 to 50", clocks, fill_ratio, false,
         true, true});
    add({"TMS34020 : TMS34010, 100-pixel span", "x", byte, "6 to 50", clocks, span_ratio, false,
         true, true});
    add({"TMS34020 : TMS34010, the demo's Z-buffer frame", "x", byte, "6 to 50", clocks,
         frame_ratio, false, true, true});
    const double fill_mbit = 32.0 * 1024 * 780 * 8 / 32 /
                             (ms(tms34020, fill_pixels(tms34020, screen)) * 1e3);  // bits per us
    add({"TMS34020 fill rate, 8 bpp", "Mbit/s", "BYTE, September 1988: PixBlt at 142 Mbit/s", "142",
         kNone, fill_mbit, false, true, true});
    return rows;
}

}  // namespace fb89::experiments
