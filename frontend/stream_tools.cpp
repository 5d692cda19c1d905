// Helpers shared by fb89 replay, dump, info, trim and diff (see stream_tools.h).
#include "frontend/stream_tools.h"

#include <iostream>

#include <fmt/format.h>

#include "controller_sim/cost_model.h"
#include "frontend/common.h"

namespace fb89::frontend {

protocol::CallSet parse_call_set_option(const std::string& option, const std::string& text) {
    try {
        return protocol::CallSet::parse(text);
    } catch (const protocol::CallSetError& e) {
        throw UsageError(option + ": " + e.what());
    }
}

std::optional<uint64_t> seek_to_call(protocol::StreamReader& reader, uint64_t first_call) {
    if (first_call == 0) return std::nullopt;
    const std::optional<protocol::FrameIndex> index = reader.read_trailing_index();
    if (!index) return std::nullopt;
    std::optional<uint64_t> best;
    for (uint64_t i = 0; i < index->size() && (*index)[i].command <= first_call; ++i)
        best = i;
    if (!best || (*index)[*best].command == 0) return std::nullopt;
    reader.seek((*index)[*best]);
    return best;
}

bool seek_to_frame(protocol::StreamReader& reader, uint64_t position) {
    const std::optional<protocol::FrameIndex> index = reader.read_trailing_index();
    if (!index || position >= index->size()) return false;
    if (position > 0 || (*index)[0].command > 0) reader.seek((*index)[position]);
    return true;
}

std::string printable(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '\n')
            out += "\\n";
        else if (c == '\t')
            out += "\\t";
        else if (c == '\\')
            out += "\\\\";
        else if (c < 0x20 || c >= 0x7f)
            out += fmt::format("\\x{:02x}", c);
        else
            out += ch;
    }
    return out;
}

std::string snapshot_path(const std::string& png, uint64_t call) {
    const std::size_t slash = png.find_last_of('/');
    const std::size_t dot = png.find_last_of('.');
    const bool has_ext =
        dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
    const std::string stem = has_ext ? png.substr(0, dot) : png;
    const std::string ext = has_ext ? png.substr(dot) : ".png";
    return fmt::format("{}-{:06}{}", stem, call, ext);
}

std::string grouped(uint64_t v) {
    return controller::grouped(v);
}

double modelled_ms(const controller::CostProfile& p, uint64_t cycles) {
    return controller::cycles_to_seconds(p, cycles) * 1e3;
}

void report_stream_error(const protocol::StreamError& e) {
    std::cerr << "fb89: error: " << e.what() << "\n";
}

std::string header_line(const protocol::StreamReader& reader) {
    std::string out = fmt::format("stream {}: format version {}", reader.name(), reader.version());
    for (const char* key :
         {protocol::kPropertyScene, protocol::kPropertyMethod, protocol::kPropertyResolution}) {
        const auto it = reader.properties().find(key);
        if (it != reader.properties().end())
            out += fmt::format(", {} {}", key, printable(it->second));
    }
    if (reader.timed()) out += ", send times " + printable(send_times_of(reader));
    return out;
}

std::string send_times_of(const protocol::StreamReader& reader) {
    return send_times_of(reader.properties(), reader.timed());
}

std::string send_times_of(const protocol::Properties& p, bool timed) {
    if (!timed) return "";
    const auto source = p.find(protocol::kPropertySendTimes);
    const auto host = p.find(protocol::kPropertyHost);
    return fmt::format("{} on {}", source == p.end() ? "of unstated source" : source->second,
                       host == p.end() ? "an unnamed host" : host->second);
}

namespace {

void append_frame_row(std::string& out, const controller::CostProfile& p,
                      const controller::FrameResult& f, const char* note) {
    const controller::OpcodeCounters t = f.total();
    out +=
        fmt::format("{:>6} {:>11} {:>9} {:>12} {:>15} {:>12.3f} {:>10.3f} {:>11.3f}  {:016x}{}\n",
                    f.frame, fmt::format("{}x{}", f.width, f.height), grouped(t.commands),
                    grouped(t.pixels), grouped(t.cycles), modelled_ms(p, t.cycles),
                    f.bus_busy_us / 1e3, f.end_us / 1e3, f.checksum, note);
}

}  // namespace

std::string frame_table(const controller::Controller& ctl) {
    std::string out = fmt::format("{:>6} {:>11} {:>9} {:>12} {:>15} {:>12} {:>10} {:>11}  {}\n",
                                  "frame", "size", "commands", "pixels", "cycles", "modelled ms",
                                  "bus ms", "frame ms", "checksum");
    for (const controller::FrameResult& f : ctl.frames())
        append_frame_row(out, ctl.profile(), f, f.complete ? "" : "  (no FRAME_END)");
    if (ctl.in_frame())
        append_frame_row(out, ctl.profile(), ctl.open_frame(), "  (open: stream ended in it)");
    return out;
}

}  // namespace fb89::frontend
