// fb89 info STREAM [--json]: what a stream holds (apitrace's `apitrace info`): the header
// (format version, properties), whether it ends in a frame index, and per frame the
// commands by opcode, the pixels written (the FRAME_BEGIN clear included), the modelled
// bus bytes, the bytes the frame takes in the file, and the frame's checksum; in a stream with
// send times (version 2), each frame's last send time and the host's end; and, in a stream with
// checksums (version 4), their state: the batches checked, all good, or the first damaged one.
//
// Pixels, bus bytes and checksums come from replaying the stream through the controller
// (the default profile, tms34010-50mhz, unless --profile says otherwise: modelled bus bytes
// are the profile's per-opcode figures; `ideal` charges 0). The stream is read once, command
// by command. A truncated or corrupt stream: the complete frames are reported, then the
// error (also in the JSON's "error"), and exit 2.
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "frontend/stream_info.h"
#include "frontend/stream_tools.h"

namespace fb89::cli {

namespace {

using nlohmann::json;

struct InfoArgs {
    std::string stream;
    std::string profile = std::string(controller::kDefaultProfile);
    bool json = false;
};

// The checksums line: "37 batches, all good"; the first damaged batch; or none before version 4.
std::string checksums_text(const json& j) {
    const json& c = j["checksums"];
    if (c.is_null())
        return fmt::format("none (format version {}; version 4 has them)", j["version"].get<int>());
    const uint64_t good = c["batches_checked"].get<uint64_t>();
    if (c["all_good"].get<bool>()) return fmt::format("{} batches, all good", grouped(good));
    if (c["first_bad"].is_null())
        return fmt::format("{} batches good; the stream ends in an error before the rest (below)",
                           grouped(good));
    const json& bad = c["first_bad"];
    return fmt::format("{} at byte {} is damaged, after {} good ones (commands from {} not read)",
                       bad["batch"].is_null()
                           ? std::string("a batch")
                           : fmt::format("batch {}", bad["batch"].get<uint32_t>()),
                       grouped(bad["offset"].get<uint64_t>()), grouped(good),
                       grouped(bad["after_commands"].get<uint64_t>()));
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
    fmt::print("checksums      {}\n", checksums_text(j));
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
    const StreamInfoReport report =
        stream_info(args.stream, controller::load_profile(args.profile));
    if (args.json)
        fmt::print("{}\n", report.info.dump(2));
    else
        print_text(report.info);
    if (report.error) {
        report_stream_error(*report.error);
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
