// What a stream holds, as `fb89 info` reports it and fb89.info() returns it (apitrace's
// `apitrace info`): the header (format version, properties), whether it ends in a frame
// index, and per frame the commands by opcode, the pixels written (the FRAME_BEGIN clear
// included), the modelled bus bytes, the bytes the frame takes in the file, and the frame's
// checksum (16 hex digits, as every command prints one); in a stream with send times
// (version 2), each frame's last send time and the host's end; in a stream with checksums
// (version 4), their state: "checksums" {batches_checked, all_good, first_bad}, null before
// version 4. Pixels, bus bytes and frame checksums come from replaying the stream through a
// controller with the given profile.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "controller_sim/profile.h"
#include "protocol/stream_reader.h"

namespace fb89::frontend {

struct StreamInfoReport {
    nlohmann::json info;  // what `fb89 info --json` prints (an "error" in it when there is one)
    std::optional<protocol::StreamError> error;  // a truncated or corrupt stream's, after the
                                                 // complete frames
};

// Reads `path` ("-": stdin) once, command by command. Throws std::runtime_error for a file
// that cannot be opened.
StreamInfoReport stream_info(const std::string& path, const controller::CostProfile& profile);

}  // namespace fb89::frontend
