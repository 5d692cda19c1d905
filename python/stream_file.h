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
    uint16_t version = protocol::kUntimedVersion;
    protocol::Properties header;
    CommandRows commands;
    // With a call set: each row's command number in the file; else none (row i is command i).
    std::optional<std::vector<uint64_t>> numbers;
};

// Writes the stream as a file (version 1). Throws FileProblem when it cannot be written.
void save_rows(const StreamFile& stream, const std::string& path);

}  // namespace fb89::python
