// What every fb89 front end shares (the command line, the Python module): exit codes,
// errors, output helpers.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json_fwd.hpp>

#include "experiments/settings.h"
#include "protocol/output_file.h"

namespace fb89::frontend {

// DESIGN.md "Command line": 0 success, 1 a check failed, 2 usage, I/O or corrupt input.
enum ExitCode : int { kSuccess = 0, kCheckFailed = 1, kBadInput = 2 };

// A usage mistake found after parsing (e.g. an unknown method); exits with 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

using experiments::ImageSize;
// "WxH", e.g. "1024x780"; throws UsageError.
ImageSize parse_size(const std::string& text);

// --buffer BYTES|unbounded for the controller profile `profile`: none when "" (the profile's
// own). Throws UsageError for anything else, and for a buffer smaller than the profile's
// largest command.
std::optional<uint64_t> parse_buffer_option(const std::string& text, const std::string& profile);

// Writes JSON (indented) to an output: "-" is stdout, a regular file is written whole or not
// at all, a device or pipe in place (protocol/output_file.h). Throws std::runtime_error
// naming the path on failure.
void write_json(const std::string& path, const nlohmann::json& value,
                protocol::Publish publish = protocol::Publish::WithCommand);
// Writes text to an output, as write_json. Throws std::runtime_error naming the path.
void write_text(const std::string& path, const std::string& text,
                protocol::Publish publish = protocol::Publish::WithCommand);

// Creates the parent folder of an output path if needed (not for "-", a device or a pipe).
void make_parent_dirs(const std::string& path);

// True when one of the (option, value) outputs is "-" (standard output), so the command
// must print nothing else there; a UsageError when two of them are.
bool claims_stdout(std::initializer_list<std::pair<std::string_view, std::string_view>> outputs);

// "; did you mean 'render'?" when a known name is near `word` (edit distance), else "".
std::string nearest_hint(const std::string& word, const std::vector<std::string>& known);

// --isa baseline|v3|v4: the instruction set the tracing kernels run with, for comparison
// (host/trace/kernel_level.h; default the best this CPU runs, or $FB89_ISA).
void add_isa_option(CLI::App* sub);

// Messages for humans go to stderr; --quiet silences them.
struct Console {
    bool quiet = false;
    void note(const std::string& text) const;
};

}  // namespace fb89::frontend
