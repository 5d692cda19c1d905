// fb89.Stream: a command stream held as rows (python/convert.h), read from a file, made from a
// render, or built in Python from a structured array.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "protocol/stream_format.h"
#include "python/convert.h"

namespace fb89::python {

struct StreamFile {
    std::string path;  // "" when it was not read from a file
    // read from a file: its format version; else the version save() writes
    uint16_t version = protocol::kFormatVersion;
    protocol::Properties header;
    CommandRows commands;
    // With a call set: each row's command number in the file; else none (row i is command i).
    std::optional<std::vector<uint64_t>> numbers;
    // A stream with send times (format version 2): each row's send time in nanoseconds from
    // its frame's set-up, and the HOST_ENDs as (row of the frame's FRAME_END, nanoseconds);
    // both empty without times.
    std::vector<int64_t> send_ns;
    std::vector<std::pair<std::size_t, int64_t>> host_ends;
};

// Writes the stream as a file: format version 4 (with checksums), with its send times when it
// has them. Throws FileProblem when it cannot be written, std::invalid_argument for times the
// format refuses (docs/PROTOCOL.md, "Version 2: send times").
void save_rows(const StreamFile& stream, const std::string& path);

}  // namespace fb89::python
