// fb89 trim STREAM --calls CALLSET / --frames FRAMESET -o OUT: copies the selected commands
// into a new stream that always replays (apitrace's `apitrace trim`, without its
// complaint: trimmed traces that no longer replay).
//
// Selection: a command is kept when it is in --calls (if given) and lies in a frame listed
// by --frames (if given). --frames counts frames by position in the stream, from 0 (the
// frame index's entry number; fb89 render numbers its frames the same way), and takes
// numbers and ranges only. Framing: a kept command inside a frame brings its frame's
// FRAME_BEGIN (which carries the size and background) and FRAME_END, so every kept frame
// clears and closes as it did; a frame kept whole gives the same checksum on replay. If
// the selection stops inside a frame, or the input ends in it, trim writes its FRAME_END.
// The output copies the header properties, adds `trimmed_from`, `trim_calls` and
// `trim_frames`, and gets a fresh frame index. Commands are streamed, never held.
//
// A failed trim leaves nothing: when the selection matches no command, or the input is
// truncated or corrupt, the output is removed (a regular file; what went to stdout or a
// pipe cannot be taken back) and trim exits 2. With --salvage a damaged input is a
// warning instead: the output keeps what was read, closes an open frame after a MARKER
// saying where the input ended, is closed with its index (so it replays), and trim exits 0.
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.h"
#include "frontend/stream_edit.h"
#include "frontend/stream_tools.h"

namespace fb89::cli {

namespace {

struct TrimArgs {
    TrimRequest request;
    bool quiet = false;
};

int run_trim(const TrimArgs& args) {
    const TrimRequest& r = args.request;
    const TrimOutcome out = trim_stream(r);
    using Result = TrimOutcome::Result;
    if (out.result == Result::NothingMatched) {
        std::cerr << fmt::format(
            "fb89: error: trim: the selection matched no command of {}; "
            "{} not written\n",
            r.input, out.output);
        if (out.error) report_stream_error(*out.error);
        return kBadInput;
    }
    if (out.result == Result::Damaged) {
        report_stream_error(*out.error);
        std::cerr << fmt::format(
            "fb89: {}: not written (--salvage keeps what was read before the error)\n", out.output);
        return kBadInput;
    }
    Console console{args.quiet};
    console.note(fmt::format("{}: kept {} command(s) in {} frame(s) of {}", out.output,
                             grouped(out.commands_kept), out.frames_kept, r.input));
    if (out.error) {
        std::cerr << fmt::format(
            "fb89: warning: {}; --salvage: {} holds what was read before it, closed so that "
            "it replays\n",
            out.error->what(), out.output);
    }
    return kSuccess;
}

}  // namespace

void register_trim(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<TrimArgs>();
    CLI::App* sub = app.add_subcommand(
        "trim", "Copy chosen commands or frames into a new stream that still replays");
    sub->add_option("stream", args->request.input, "Input stream file ('-' for stdin)")->required();
    sub->add_option("--calls", args->request.calls,
                    "Call set to keep, e.g. '0-1000', '/span', '@calls.txt' (docs/PROTOCOL.md)");
    sub->add_option("--frames", args->request.frames,
                    "Frames to keep, by position in the stream from 0, e.g. '0-3,7'");
    sub->add_option("-o,--output", args->request.output, "Output stream file ('-' for stdout)")
        ->required();
    sub->add_flag("--salvage", args->request.salvage,
                  "A truncated or corrupt input is a warning, not an error: keep what was read "
                  "before the damage, closed so that it replays, and exit 0");
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([args, &exit_code] { exit_code = run_trim(*args); });
}

}  // namespace fb89::cli
