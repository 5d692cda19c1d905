// What a stream holds, as `fb89 info` reports it (frontend/stream_info.h): the stream read
// once through the controller, each frame's commands, pixels, bus bytes, file bytes and
// checksum.
#include "frontend/stream_info.h"

#include <sys/stat.h>

#include <fmt/format.h>

#include "controller_sim/timed_pipeline.h"
#include "frontend/stream_tools.h"

namespace fb89::frontend {

namespace {

using nlohmann::json;

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
    // version 4: the batches found whole, and the first damaged one (none of it was read)
    j["checksums"] = nullptr;
    if (reader.checksummed()) {
        j["checksums"] = {{"batches_checked", reader.batches_checked()},
                          {"all_good", !info.error},
                          {"first_bad", nullptr}};
        if (info.error && info.error->damaged())
            j["checksums"]["first_bad"] = {
                {"batch", info.error->batch() ? json(*info.error->batch()) : json(nullptr)},
                {"offset", info.error->offset()},
                {"after_commands", info.error->command()}};
    }
    if (info.error) {
        j["error"] = {{"message", info.error->what()},
                      {"offset", info.error->offset()},
                      {"command", info.error->command()}};
    }
    return j;
}

}  // namespace

StreamInfoReport stream_info(const std::string& path, const controller::CostProfile& profile) {
    protocol::StreamReader reader(path);
    controller::Controller ctl(profile);
    const StreamInfo info = scan(reader, ctl);

    std::optional<uint64_t> file_size;
    struct stat st {};
    if (path != "-" && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode))
        file_size = static_cast<uint64_t>(st.st_size);
    return {info_json(reader, ctl, info, file_size), info.error};
}

}  // namespace fb89::frontend
