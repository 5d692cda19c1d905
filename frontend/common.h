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

#include "controller_sim/profile.h"
#include "experiments/settings.h"
#include "frontend/option_limits.h"
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
// "WxH", e.g. "1024x780", each side within limits::kImageSide; throws UsageError naming the
// option as `spelling` says (--size, or Python's size=).
ImageSize parse_size(const std::string& text, Spelling spelling = Spelling::Option);

// --buffer BYTES|unbounded for the controller profile `profile`: none when "" (the profile's
// own). Throws UsageError for anything else (BYTES within limits::kBufferBytes), and for a
// buffer smaller than the profile's largest command, naming the option as `spelling` says.
std::optional<uint64_t> parse_buffer_option(const std::string& text, const std::string& profile,
                                            Spelling spelling = Spelling::Option);

// The controller cost profile `name` (a built-in one or a .json file), for the option
// `option` ("--profile", or Python's "controller"): a UsageError naming it when there is none.
controller::CostProfile profile_option(const std::string& name, std::string_view option);

// Writes JSON (indented) to an output: "-" is stdout, a regular file is written whole or not
// at all, a device or pipe in place (protocol/output_file.h). Throws std::runtime_error
// naming the path on failure.
void write_json(const std::string& path, const nlohmann::json& value,
                protocol::Publish publish = protocol::Publish::WithCommand);
// Writes text to an output, as write_json. Throws std::runtime_error naming the path.
void write_text(const std::string& path, const std::string& text,
                protocol::Publish publish = protocol::Publish::WithCommand);

// A whole text file, e.g. a user's listing; throws std::runtime_error naming the path and
// what went wrong.
std::string read_text_file(const std::string& path);

// Creates the parent folder of an output path if needed (not for "-", a device or a pipe).
void make_parent_dirs(const std::string& path);

// True when one of the (option, value) outputs is "-" (standard output), so the command
// must print nothing else there; a UsageError when two of them are, or when two name the
// same file (the second would replace the first).
bool claims_stdout(std::initializer_list<std::pair<std::string_view, std::string_view>> outputs);

// A CSV field: as it is, or in double quotes (quotes doubled) when it holds a comma, a quote
// or a line break (RFC 4180).
std::string csv_field(const std::string& s);

// "; did you mean 'render'?" when a known name is near `word` (at most two edits), else the
// known names `word` opens when there are one to three ("; did you mean 'tms34020-40mhz'?"),
// else "".
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
