// Fuzz target: the controller's cost-profile JSON (controller::parse_profile, what
// load_profile / load_profile_file use for `--profile FILE.json`; comments allowed). Bad
// input must throw std::runtime_error naming the file; nothing else may escape. A profile
// that loads must hold the ranges profile.cpp promises, survive a round trip through
// to_json(), and give the controller's fast cycle costs (CycleCosts) the same results as
// the plain formulas, without overflow, on a 16384 x 16384 frame; times may be infinite
// (a denormal clock or bus speed loads) but never NaN or negative.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "controller_sim/cost_model.h"
#include "controller_sim/profile.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using fb89::fuzz::finding;
namespace controller = fb89::controller;

constexpr uint32_t kMaxCycles = 1'000'000;

void check_ranges(const controller::CostProfile& p) {
    if (p.name.empty()) finding("empty name");
    if (p.bpp != 1 && p.bpp != 2 && p.bpp != 4 && p.bpp != 8 && p.bpp != 16)
        finding("bpp not 1, 2, 4, 8 or 16");
    for (uint32_t c :
         {p.c_cmd, p.c_setup, p.c_op, p.c_row, p.c_line_setup, p.c_line_pix, p.c_op_partial,
          p.c_host_word, p.c_frame_begin_setup, p.c_span_fill_setup, p.c_frame_end_setup})
        if (c > kMaxCycles) finding("a cycle figure above the limit");
    if (!std::isfinite(p.f_cyc_hz) || !(p.f_cyc_hz > 0)) finding("f_cyc_hz not finite and > 0");
    if (!(p.b_bus_bytes_per_s > 0)) finding("B_bus_bytes_per_s not > 0");
    if (!(p.stolen_share >= 0 && p.stolen_share < 0.5)) finding("refresh's share not in [0, 0.5)");
    if (!std::isfinite(p.t_handshake_s) || p.t_handshake_s < 0) finding("t_handshake_s bad");
    for (uint32_t b : p.bytes)
        if (b > 1'000'000) finding("a byte count above the limit");
}

void check_round_trip(const controller::CostProfile& p) {
    controller::CostProfile q;
    try {
        q = controller::parse_profile(p.to_json().dump(), "round trip");
    } catch (const std::runtime_error& e) {
        finding(std::string("to_json() of a loaded profile does not load: ") + e.what());
    }
    if (q.name != p.name || q.description != p.description || q.f_cyc_hz != p.f_cyc_hz ||
        q.bpp != p.bpp || q.c_cmd != p.c_cmd || q.c_setup != p.c_setup || q.c_op != p.c_op ||
        q.c_row != p.c_row || q.span_as != p.span_as || q.c_line_setup != p.c_line_setup ||
        q.c_line_pix != p.c_line_pix || q.b_bus_bytes_per_s != p.b_bus_bytes_per_s ||
        q.t_handshake_s != p.t_handshake_s || q.bytes != p.bytes || q.sources != p.sources ||
        q.gsp != p.gsp || q.c_op_partial != p.c_op_partial || q.c_host_word != p.c_host_word ||
        q.c_frame_begin_setup != p.c_frame_begin_setup ||
        q.c_span_fill_setup != p.c_span_fill_setup || q.stolen_share != p.stolen_share ||
        q.host_port_bytes_per_s != p.host_port_bytes_per_s)
        finding("the round trip through to_json() changed the profile");
}

void check_costs(const controller::CostProfile& p) {
    const controller::CycleCosts fast(p);
    constexpr uint32_t kSide = 16384;
    for (const controller::PixelRect r :
         {controller::PixelRect{0, 0, kSide, kSide}, controller::PixelRect{1, 2, 3, 1},
          controller::PixelRect{kSide - 1, kSide - 1, 1, 1}, controller::PixelRect{7, 0, 33, 5}}) {
        const uint64_t plain = controller::fill_rect_cycles(p, r);
        if (fast.fill_rect(r) != plain) finding("CycleCosts::fill_rect != fill_rect_cycles");
        if (plain < uint64_t{r.h} * p.c_row) finding("fill_rect_cycles wrapped around");
        if (fast.draw_span(r.x, r.w) != controller::draw_span_cycles(p, r.x, r.w))
            finding("CycleCosts::draw_span != draw_span_cycles");
    }
    const uint64_t clear = controller::frame_begin_cycles(p, kSide, kSide);
    if (clear < p.c_cmd) finding("frame_begin_cycles wrapped around");
    // A clock of 1e-300 Hz loads, and makes the time infinite: allowed here, NaN is not.
    const double s = controller::cycles_to_seconds(p, clear);
    if (std::isnan(s) || s < 0) finding("cycles_to_seconds NaN or negative");
    for (uint32_t b : p.bytes) {
        const double bus = controller::bus_seconds(p, b);
        if (std::isnan(bus) || bus < 0) finding("bus_seconds NaN or negative");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    constexpr std::string_view kOrigin = "fuzz.json";
    controller::CostProfile p;
    try {
        p = controller::parse_profile(text, kOrigin, "fuzz");
    } catch (const std::runtime_error& e) {
        if (std::string_view(e.what()).find(kOrigin) == std::string_view::npos)
            finding("an error that does not name the file");
        return 0;
    }
    check_ranges(p);
    check_round_trip(p);
    check_costs(p);
    (void)p.to_string();
    return 0;
}
