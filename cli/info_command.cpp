// fb89 info STREAM [--json]: what a stream holds (apitrace's `apitrace info`): the header
// (format version, properties), whether it ends in a frame index, and per frame the
// commands by opcode, the pixels written (the FRAME_BEGIN clear included), the modelled
// bus bytes, the bytes the frame takes in the file, and the frame's checksum; in a stream with
// send times (version 2), each frame's last send time and the host's end.
//
// Pixels, bus bytes and checksums come from replaying the stream through the controller
// (the default profile, tms34010-50mhz, unless --profile says otherwise: modelled bus bytes
// are the profile's per-opcode figures; `ideal` charges 0). The stream is read once, command
// by command. A truncated or corrupt stream: the complete frames are reported, then the
// error (also in the JSON's "error"), and exit 2.
#include <sys/stat.h>

#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/timed_pipeline.h"
#include "frontend/stream_tools.h"

namespace fb89::cli {

namespace {

using nlohmann::json;

struct InfoArgs {
    std::string stream;
    std::string profile = std::string(controller::kDefaultProfile);
    bool json = false;
};

struct StreamInfo {
    std::vector<uint64_t> frame_bytes;  // bytes in the file, by closed frame
    uint64_t open_frame_bytes = 0;      // of the frame still open at the end
    // a timed stream's last send time and host end (its HOST_END, or without one its last
    // send time), by frame as frame_bytes, then the open one's
    std::vector<int64_t> last_send_ns, host_end_ns;
    std::optional<protocol::StreamError> error;
};

// Bytes of a command's version-1 record (docs/PROTOCOL.md, "Command records").
uint64_t record_size(const protocol::Command& c) {
    const auto op = static_cast<uint8_t>(protocol::opcode_of(c));
    const auto* marker = std::get_if<protocol::Marker>(&c);
    return 1 + protocol::payload_size(op).value_or(0) + (marker ? marker->text.size() : 0);
}

// Reads the stream into the controller, measuring each frame's encoded size: from its
// FRAME_BEGIN to after its FRAME_END (or to the FRAME_BEGIN that closed it).
StreamInfo scan(protocol::StreamReader& reader, controller::Controller& ctl) {
    StreamInfo info;
    uint64_t begin_offset = 0, end_offset = 0;
    int64_t last_send = 0, host_end = 0;  // of the frame so far
    const auto keep_times = [&] {
        info.last_send_ns.push_back(last_send);
        info.host_end_ns.push_back(host_end);
    };
    protocol::Command c;
    try {
        while (reader.next(c)) {
            const uint64_t at = reader.command_offset();
            ctl.execute(c);
            const bool is_begin = std::holds_alternative<protocol::FrameBegin>(c);
            end_offset = at + record_size(c);
            if (!is_begin) {  // (a FRAME_BEGIN that closes a frame starts the next's times)
                last_send = reader.send_time_ns();
                host_end = reader.frame_host_end_ns();
            }
            if (ctl.frames().size() > info.frame_bytes.size()) {  // this command closed a frame
                info.frame_bytes.push_back((is_begin ? at : end_offset) - begin_offset);
                keep_times();
            }
            if (is_begin) begin_offset = at, last_send = host_end = 0;
        }
    } catch (const protocol::StreamError& e) {
        info.error = e;
    }
    if (ctl.in_frame()) {
        info.open_frame_bytes = end_offset - begin_offset;
        keep_times();
    }
    return info;
}

json opcode_counts(const controller::PerOpcode& ops) {
    json j = json::object();
    for (int i = 0; i < protocol::kOpcodeCount; ++i)
        j[protocol::to_string(protocol::kOpcodes[i])] = ops[i].commands;
    return j;
}

json frame_json(const controller::FrameResult& f, uint64_t stream_bytes, bool open) {
    const controller::OpcodeCounters t = f.total();
    return {{"frame", f.frame},
            {"width", f.width},
            {"height", f.height},
            {"first_command", f.first_command},
            {"commands", t.commands},
            {"by_opcode", opcode_counts(f.ops)},
            {"pixels", t.pixels},
            {"bus_bytes", t.bytes},
            {"stream_bytes", stream_bytes},
            {"checksum", fmt::format("{:016x}", f.checksum)},
            {"complete", f.complete && !open},
            {"open", open}};
}

json info_json(const protocol::StreamReader& reader, const controller::Controller& ctl,
               const StreamInfo& info, std::optional<uint64_t> file_size) {
    json frames = json::array();
    for (std::size_t i = 0; i < ctl.frames().size(); ++i)
        frames.push_back(frame_json(ctl.frames()[i], info.frame_bytes[i], false));
    if (ctl.in_frame()) frames.push_back(frame_json(ctl.open_frame(), info.open_frame_bytes, true));
    if (reader.timed()) {
        for (std::size_t i = 0; i < frames.size(); ++i) {
            frames[i]["last_send_us"] = controller::from_ns(info.last_send_ns[i]);
            // a frame that never ended (open at the end, or no FRAME_END) has no host end
            frames[i]["host_end_us"] = frames[i]["complete"].get<bool>()
                                           ? json(controller::from_ns(info.host_end_ns[i]))
                                           : json(nullptr);
        }
    }
    json j{{"stream", reader.name()},
           {"version", reader.version()},
           {"properties", reader.properties()},
           {"header_bytes", reader.header_size()},
           {"frame_index", reader.frame_index().has_value()},
           {"commands", ctl.commands_executed()},
           {"by_opcode", opcode_counts(ctl.stats().totals)},
           {"unframed_commands", sum(ctl.stats().unframed).commands},
           {"bytes_profile", ctl.profile().name},
           {"frames", std::move(frames)}};
    if (reader.timed()) j["send_times"] = send_times_of(reader);
    if (file_size) j["file_bytes"] = *file_size;
    if (info.error) {
        j["error"] = {{"message", info.error->what()},
                      {"offset", info.error->offset()},
                      {"command", info.error->command()}};
    }
    return j;
}

void print_text(const json& j) {
    fmt::print("stream         {}\n", j["stream"].get<std::string>());
    if (j.contains("file_bytes"))
        fmt::print("size           {} bytes\n", grouped(j["file_bytes"].get<uint64_t>()));
    fmt::print("format version {}\n", j["version"].get<int>());
    for (const auto& [key, value] : j["properties"].items())
        fmt::print("  {:<12} {}\n", printable(key), printable(value.get<std::string>()));
    fmt::print("frame index    {}\n", j["frame_index"].get<bool>()
                                          ? "present"
                                          : "none (a cut stream, or it ends in an error)");
    fmt::print("commands       {} in {} frame(s), {} outside frames\n",
               grouped(j["commands"].get<uint64_t>()), j["frames"].size(),
               grouped(j["unframed_commands"].get<uint64_t>()));
    // the depth commands' columns only for a stream that has them (format version 3)
    bool depth = false;
    for (const json& f : j["frames"])
        for (const char* op : {"DEPTH_CLEAR", "DEPTH_SPAN", "FACE"})
            depth = depth || f["by_opcode"].value(op, uint64_t{0}) > 0;
    const auto depth_columns = [&](const json* ops) {
        if (!depth) return std::string();
        if (!ops) return fmt::format(" {:>11} {:>10} {:>8}", "DEPTH_CLEAR", "DEPTH_SPAN", "FACE");
        return fmt::format(" {:>11} {:>10} {:>8}", grouped((*ops)["DEPTH_CLEAR"]),
                           grouped((*ops)["DEPTH_SPAN"]), grouped((*ops)["FACE"]));
    };
    fmt::print("\n{:>6} {:>11} {:>11} {:>9} {:>9} {:>7} {:>9}{} {:>13} {:>11} {:>12}  {}\n",
               "frame", "size", "FRAME_BEGIN", "FILL_RECT", "DRAW_SPAN", "MARKER", "FRAME_END",
               depth_columns(nullptr), "pixels", "bus bytes", "file bytes", "checksum");
    for (const json& f : j["frames"]) {
        const json& ops = f["by_opcode"];
        fmt::print("{:>6} {:>11} {:>11} {:>9} {:>9} {:>7} {:>9}{} {:>13} {:>11} {:>12}  {}{}\n",
                   f["frame"].get<uint32_t>(),
                   fmt::format("{}x{}", f["width"].get<uint32_t>(), f["height"].get<uint32_t>()),
                   grouped(ops["FRAME_BEGIN"]), grouped(ops["FILL_RECT"]),
                   grouped(ops["DRAW_SPAN"]), grouped(ops["MARKER"]), grouped(ops["FRAME_END"]),
                   depth_columns(&ops), grouped(f["pixels"]), grouped(f["bus_bytes"]),
                   grouped(f["stream_bytes"]), f["checksum"].get<std::string>(),
                   f["open"].get<bool>()        ? "  (open at the end)"
                   : !f["complete"].get<bool>() ? "  (no FRAME_END)"
                                                : "");
    }
    fmt::print("bus bytes modelled under profile {}\n", j["bytes_profile"].get<std::string>());
    if (!j.contains("send_times")) return;
    fmt::print("\nsend times     {}, from the start of each frame's set-up\n",
               printable(j["send_times"].get<std::string>()));
    fmt::print("{:>6} {:>14} {:>14}\n", "frame", "last send ms", "host end ms");
    for (const json& f : j["frames"])
        fmt::print("{:>6} {:>14.6f} {:>14}\n", f["frame"].get<uint32_t>(),
                   f["last_send_us"].get<double>() / 1e3,
                   f["host_end_us"].is_null()
                       ? std::string("never ended")
                       : fmt::format("{:.6f}", f["host_end_us"].get<double>() / 1e3));
}

int run_info(const InfoArgs& args) {
    const controller::CostProfile profile = controller::load_profile(args.profile);
    protocol::StreamReader reader(args.stream);
    controller::Controller ctl(profile);
    const StreamInfo info = scan(reader, ctl);

    std::optional<uint64_t> file_size;
    struct stat st {};
    if (args.stream != "-" && ::stat(args.stream.c_str(), &st) == 0 && S_ISREG(st.st_mode))
        file_size = static_cast<uint64_t>(st.st_size);

    const json j = info_json(reader, ctl, info, file_size);
    if (args.json)
        fmt::print("{}\n", j.dump(2));
    else
        print_text(j);
    if (info.error) {
        report_stream_error(*info.error);
        return kBadInput;
    }
    return kSuccess;
}

}  // namespace

void register_info(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<InfoArgs>();
    CLI::App* sub = app.add_subcommand(
        "info", "Describe a stream: header, and per frame commands by opcode, pixels, bytes");
    sub->add_option("stream", args->stream, "Stream file ('-' for stdin)")->required();
    sub->add_flag("--json", args->json, "Print JSON instead of text");
    sub->add_option(
           "--profile", args->profile,
           profile_option_help("The controller profile whose modelled bus bytes are reported"))
        ->check(profile_validator())
        ->capture_default_str();
    sub->callback([args, &exit_code] { exit_code = run_info(*args); });
}

}  // namespace fb89::cli
