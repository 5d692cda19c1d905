// fb89 dump STREAM: one numbered line per command (apitrace's `apitrace dump`):
//
//       12 @236       FILL_RECT x=0 y=0 w=64 h=64 color=#ff0000
//
// command number, '@' and the byte offset of its record, then the command's to_string()
// with marker text escaped; in a stream with send times (version 2) the line ends with the
// command's ("sent 1234.567 us", from the start of its frame's set-up) and FRAME_END's with
// the host's end. `--calls CALLSET` keeps the commands in the set; `--grep RE`
// (ECMAScript std::regex, searched anywhere in the command's text) keeps those matching.
// With a call set that starts late, dump seeks through the frame index to the frame
// holding its first call; with a bounded one it stops reading after its last call. So
// `fb89 dump big.fb89 --calls 5000000-5000010` reads a few frames, not the whole stream.
// `--header` first prints the header as `# key = value` lines.
#include <iostream>
#include <regex>

#include <fmt/format.h>

#include "cli/commands.h"
#include "frontend/stream_tools.h"

namespace fb89::cli {

namespace {

struct DumpArgs {
    std::string stream;
    std::string calls;
    std::string grep;
    bool header = false;
};

void print_header(const protocol::StreamReader& reader) {
    fmt::print("# fb89 stream {}, format version {}\n", reader.name(), reader.version());
    for (const auto& [key, value] : reader.properties())
        fmt::print("# {} = {}\n", printable(key), printable(value));
}

// A timed stream's line ends with the command's send time, and FRAME_END's with the host's
// end when the frame has one, in microseconds (nanoseconds exact).
void append_send_time(std::string& out, const protocol::StreamReader& reader,
                      const protocol::Command& c) {
    const auto us = [](int64_t ns) { return fmt::format("{}.{:03}", ns / 1000, ns % 1000); };
    out += "  sent " + us(reader.send_time_ns()) + " us";
    if (std::holds_alternative<protocol::FrameEnd>(c) && reader.host_end_ns())
        out += ", host end " + us(*reader.host_end_ns()) + " us";
}

int run_dump(const DumpArgs& args) {
    const protocol::CallSet calls = args.calls.empty()
                                        ? protocol::CallSet::all()
                                        : parse_call_set_option("--calls", args.calls);
    std::optional<std::regex> grep;
    if (!args.grep.empty()) {
        try {
            grep.emplace(args.grep, std::regex::ECMAScript | std::regex::optimize);
        } catch (const std::regex_error& e) {
            throw UsageError(
                fmt::format("--grep: bad regular expression '{}': {}", args.grep, e.what()));
        }
    }

    protocol::StreamReader reader(args.stream);
    if (args.header) print_header(reader);
    seek_to_call(reader, calls.first());
    const uint64_t last = calls.last();

    std::string out;  // lines are batched: a dump of millions of commands stays fast
    protocol::Command c;
    std::optional<protocol::StreamError> error;
    uint64_t commands = 0;  // command numbers seen, up to the set's last
    try {
        while (reader.next(c)) {
            const uint64_t n = reader.command_number();
            commands = n + 1;
            if (n > last) break;
            if (!calls.contains(n, c)) continue;
            const std::string text = printable(protocol::to_string(c));
            if (grep && !std::regex_search(text, *grep)) continue;
            out += fmt::format("{:>7} @{:<9} {}", n, reader.command_offset(), text);
            if (reader.timed()) append_send_time(out, reader, c);
            out += '\n';
            if (out.size() > (1u << 16)) {
                std::fwrite(out.data(), 1, out.size(), stdout);
                out.clear();
            }
        }
    } catch (const protocol::StreamError& e) {
        error = e;
    }
    std::fwrite(out.data(), 1, out.size(), stdout);
    std::fflush(stdout);
    if (error) {
        report_stream_error(*error);
        return kBadInput;
    }
    if (!args.calls.empty() && calls.first() >= commands)
        throw UsageError(
            fmt::format("--calls: the set starts at command {}, past the stream's "
                        "last (it has {} commands)",
                        calls.first(), commands));
    return kSuccess;
}

}  // namespace

void register_dump(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<DumpArgs>();
    CLI::App* sub = app.add_subcommand("dump", "Print a stream's commands, one numbered line each");
    sub->add_option("stream", args->stream, "Stream file ('-' for stdin)")->required();
    sub->add_option("--calls", args->calls,
                    "Call set to print, e.g. '0-100/2', 'frame', '/span', '@calls.txt' "
                    "(docs/PROTOCOL.md, \"Call sets\")");
    sub->add_option("--grep", args->grep,
                    "Print only commands whose text matches this regular expression");
    sub->add_flag("--header", args->header, "First print the header as '# key = value' lines");
    sub->callback([args, &exit_code] { exit_code = run_dump(*args); });
}

}  // namespace fb89::cli
