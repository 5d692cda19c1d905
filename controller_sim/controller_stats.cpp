// Reporting the controller's counters: JSON for --stats and a table for humans.
//
// One set of counters feeds both. Only controller figures appear here; host times are
// reported elsewhere, apart. Modelled time = cycles / f_cyc; bus time = commands x
// (bytes / B_bus + t_handshake) for opcodes that are sent.
#include <algorithm>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"

namespace fb89::controller {

namespace {

using nlohmann::json;

const char* opcode_name(int i) {
    return protocol::to_string(protocol::kOpcodes[i]);
}

double modelled_us(const CostProfile& p, uint64_t cycles) {
    return cycles_to_seconds(p, cycles) * 1e6;
}

// The bus time of an opcode's commands: their bytes at the bus's rate and a handshake each
// (bus_seconds, summed; a FACE's bytes vary with its points).
double bus_us(const CostProfile& p, const OpcodeCounters& c) {
    if (c.bytes == 0) return 0;
    return (static_cast<double>(c.bytes) / p.bus_bytes_per_s() +
            static_cast<double>(c.commands) * p.t_handshake_s) *
           1e6;
}

json depth_json(const DepthCounters& d) {
    return json{{"tests", d.tests}, {"nearer", d.nearer}, {"equal", d.equal}};
}

json counters_json(const OpcodeCounters& c) {
    return json{{"commands", c.commands}, {"pixels", c.pixels},   {"bytes", c.bytes},
                {"cycles", c.cycles},     {"clipped", c.clipped}, {"outside", c.outside}};
}

// {"FRAME_BEGIN": {...}, ..., "all": {...}} with modelled and bus time per opcode.
json per_opcode_json(const CostProfile& p, const PerOpcode& ops) {
    json out = json::object();
    double all_bus_us = 0;
    for (int i = 0; i < protocol::kOpcodeCount; ++i) {
        json j = counters_json(ops[i]);
        j["modelled_us"] = modelled_us(p, ops[i].cycles);
        j["bus_us"] = bus_us(p, ops[i]);
        all_bus_us += bus_us(p, ops[i]);
        out[opcode_name(i)] = std::move(j);
    }
    const OpcodeCounters all = sum(ops);
    json j = counters_json(all);
    j["modelled_us"] = modelled_us(p, all.cycles);
    j["bus_us"] = all_bus_us;
    out["all"] = std::move(j);
    return out;
}

json frame_json(const CostProfile& p, const FrameResult& f) {
    return json{{"frame", f.frame},
                {"width", f.width},
                {"height", f.height},
                {"first_command", f.first_command},
                {"checksum", fmt::format("{:016x}", f.checksum)},
                {"complete", f.complete},
                {"opcodes", per_opcode_json(p, f.ops)},
                {"depth", depth_json(f.depth)},
                {"depth_bits", f.depth_bits},
                {"depth_buffer_bytes", f.depth_bits ? p.depth_buffer_bytes(f.width, f.height) : 0},
                {"bus_busy_us", f.bus_busy_us},
                {"controller_busy_us", f.controller_busy_us},
                {"end_us", f.end_us}};
}

void append_row(std::string& out, const char* name, const OpcodeCounters& c, double model_ms,
                double bus_ms) {
    out += fmt::format("{:<12} {:>12} {:>15} {:>13} {:>15} {:>13.3f} {:>11.3f} {:>9} {:>9}\n", name,
                       grouped(c.commands), grouped(c.pixels), grouped(c.bytes), grouped(c.cycles),
                       model_ms, bus_ms, grouped(c.clipped), grouped(c.outside));
}

}  // namespace

namespace {

// How the profile draws spans and clears a frame of width x height, by name:
// {"DRAW_SPAN": "FILL XY", "FRAME_BEGIN": "serial-register transfers", ...}.
json drawn_as_json(const CostProfile& p, uint32_t width, uint32_t height) {
    json j{{"DRAW_SPAN", p.span_as == SpanAs::Fill ? "FILL XY, one row" : "LINE"}};
    if (p.gsp.empty()) {
        j["FRAME_BEGIN"] = "FILL XY";
        return j;
    }
    const uint64_t rows = vram_rows(width, height, p.bpp);
    if (p.clear_as == ClearAs::SerialRegister && rows <= kVramRows && width > 0 && height > 0) {
        j["FRAME_BEGIN"] = "serial-register transfers";
        j["vram_rows"] = rows;
    } else {
        j["FRAME_BEGIN"] =
            p.clear_as == ClearAs::Fill ? "FILL XY" : "FILL XY (larger than the VRAM)";
    }
    return j;
}

}  // namespace

std::string drawn_as_text(const CostProfile& p, uint32_t width, uint32_t height) {
    const json j = drawn_as_json(p, width, height);
    std::string clear = j["FRAME_BEGIN"].get<std::string>();
    if (j.contains("vram_rows"))
        clear = fmt::format("through the VRAMs' serial registers ({} VRAM rows, TI's clear_page)",
                            j["vram_rows"].get<uint64_t>());
    else
        clear = "by " + clear + (p.gsp.empty() ? "" : " (TI's clear_screen)");
    return fmt::format(
        "drawn as: DRAW_SPAN by {}; FRAME_BEGIN clears {}",
        p.span_as == SpanAs::Fill ? "FILL XY of one row (TI's draw_line)" : "LINE (a vector draw)",
        clear);
}

namespace {

// The largest frame the stats saw (the clear's rows follow from it).
std::pair<uint32_t, uint32_t> largest_frame(const std::vector<FrameResult>& frames) {
    uint32_t width = 0, height = 0;
    for (const FrameResult& f : frames) {
        width = std::max(width, f.width);
        height = std::max(height, f.height);
    }
    return {width, height};
}

}  // namespace

std::string grouped(uint64_t v) {
    const std::string digits = std::to_string(v);
    std::string out;
    const std::size_t n = digits.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && (n - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

nlohmann::json ControllerStats::to_json() const {
    json frames_json = json::array();
    for (const FrameResult& f : frames)
        frames_json.push_back(frame_json(profile, f));
    const auto [w, h] = largest_frame(frames);
    return json{{"profile", profile.to_json()},
                {"drawn_as", drawn_as_json(profile, w, h)},
                {"frames_closed", frames_closed},
                {"frames_incomplete", frames_incomplete},
                {"frame_open", frame_open},
                {"totals", per_opcode_json(profile, totals)},
                {"unframed", per_opcode_json(profile, unframed)},
                {"depth", depth_json(depth)},
                {"bus_busy_us", bus_busy_us},
                {"controller_busy_us", controller_busy_us},
                {"frames_end_us", frames_end_us},
                {"frames", std::move(frames_json)}};
}

std::string ControllerStats::summary() const {
    std::string out = fmt::format("controller: {}\n", profile.to_string());
    {
        const auto [w, h] = largest_frame(frames);
        out += drawn_as_text(profile, w, h) + "\n";
    }
    out += fmt::format("{:<12} {:>12} {:>15} {:>13} {:>15} {:>13} {:>11} {:>9} {:>9}\n", "opcode",
                       "commands", "pixels", "bytes", "cycles", "modelled ms", "bus ms", "clipped",
                       "outside");
    double all_bus_ms = 0;
    for (int i = 0; i < protocol::kOpcodeCount; ++i) {
        // the depth commands' rows only where a stream has them
        if (protocol::is_depth_opcode(protocol::kOpcodes[i]) && totals[i].commands == 0) continue;
        const double bus_ms = bus_us(profile, totals[i]) / 1e3;
        all_bus_ms += bus_ms;
        append_row(out, opcode_name(i), totals[i], modelled_us(profile, totals[i].cycles) / 1e3,
                   bus_ms);
    }
    const OpcodeCounters all = sum(totals);
    append_row(out, "total", all, modelled_us(profile, all.cycles) / 1e3, all_bus_ms);

    out += fmt::format(
        "frames: {} closed ({} incomplete){}; frame time {:.3f} ms (sum of closed frames' end "
        "times), controller busy {:.3f} ms, bus busy {:.3f} ms\n",
        frames_closed, frames_incomplete,
        frame_open ? ", 1 still open (begun, never ended: its commands are counted above)" : "",
        frames_end_us / 1e3, controller_busy_us / 1e3, bus_busy_us / 1e3);
    if (depth.tests > 0) {
        uint32_t width = 0, height = 0;
        for (const FrameResult& f : frames)
            if (f.depth_bits) {
                width = std::max(width, f.width);
                height = std::max(height, f.height);
            }
        out += fmt::format(
            "depth: {} tests, {} nearer (drawn), {} as near as the word they met (kept: ties of "
            "the {}-bit word); the buffer takes {:.2f} MB of the board's DRAM at {}x{}\n",
            grouped(depth.tests), grouped(depth.nearer), grouped(depth.equal), profile.depth_bits,
            static_cast<double>(profile.depth_buffer_bytes(width, height)) / 1e6, width, height);
    }
    const OpcodeCounters loose = sum(unframed);
    if (loose.commands > 0)
        out +=
            fmt::format("commands outside any frame: {} (drew nothing)\n", grouped(loose.commands));
    return out;
}

}  // namespace fb89::controller
