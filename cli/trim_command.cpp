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
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "cli/common.h"
#include "cli/stream_tools.h"
#include "protocol/stream_writer.h"

namespace fb89::cli {

namespace {

struct TrimArgs {
    std::string stream, calls, frames, out;
    bool salvage = false;
    bool quiet = false;
};

// What to keep; parsed before the output is created.
struct Selection {
    bool has_calls = false, has_frames = false;
    protocol::CallSet calls, frames;

    explicit Selection(const TrimArgs& args)
        : has_calls(!args.calls.empty()), has_frames(!args.frames.empty()) {
        if (!has_calls && !has_frames)
            throw UsageError("trim: give --calls and/or --frames to say what to keep");
        if (has_calls) calls = parse_call_set_option("--calls", args.calls);
        if (has_frames) frames = parse_call_set_option("--frames", args.frames);
        if (has_frames && frames.has_opcode_filter())
            throw UsageError(fmt::format(
                "--frames: '{}': takes frame numbers and ranges (e.g. 0-3,7), no filters",
                args.frames));
    }
};

// The trimming state machine: frame framing around kept commands.
class Trimmer {
  public:
    Trimmer(const Selection& selection, protocol::StreamWriter& writer)
        : m_writer(writer),
          m_has_calls(selection.has_calls),
          m_has_frames(selection.has_frames),
          m_calls(selection.calls),
          m_frames(selection.frames) {}

    const protocol::CallSet& calls() const { return m_calls; }
    const protocol::CallSet& frames() const { return m_frames; }
    bool has_calls() const { return m_has_calls; }
    bool has_frames() const { return m_has_frames; }
    void set_next_frame_position(uint64_t p) { m_next_position = p; }
    uint64_t frames_kept() const { return m_frames_kept; }

    // Handles command n; false when nothing after it can be selected.
    bool take(uint64_t n, const protocol::Command& c) {
        if (m_has_calls && n > m_calls.last()) return false;
        if (const auto* begin = std::get_if<protocol::FrameBegin>(&c)) {
            close_frame();
            const uint64_t position = m_next_position++;
            if (m_has_frames && position > m_frames.last()) return false;
            m_pending = *begin;
            m_in_frame = true;
            m_frame_selected = !m_has_frames || m_frames.contains_number(position);
        }
        const bool selected = (!m_has_calls || m_calls.contains(n, c)) &&
                              (!m_has_frames || (m_in_frame && m_frame_selected));
        const bool is_framing = std::holds_alternative<protocol::FrameBegin>(c) ||
                                (m_in_frame && std::holds_alternative<protocol::FrameEnd>(c));
        if (selected && m_in_frame && !m_emitted) {
            m_writer.frame_begin(m_pending);
            m_emitted = true;
            ++m_frames_kept;
        }
        if (selected && !is_framing) m_writer.submit(c);
        if (std::holds_alternative<protocol::FrameEnd>(c)) close_frame();
        return true;
    }

    // Ends the output: an open kept frame gets its FRAME_END (after `note`, if any).
    void finish(const std::string& note) {
        if (m_in_frame && m_emitted && !note.empty())
            m_writer.marker(protocol::Marker{note.substr(0, protocol::kMaxMarkerLength)});
        close_frame();
        m_writer.close();
    }

  private:
    void close_frame() {
        if (m_in_frame && m_emitted) m_writer.frame_end(protocol::FrameEnd{});
        m_in_frame = m_emitted = false;
    }

    protocol::StreamWriter& m_writer;
    bool m_has_calls, m_has_frames;
    protocol::CallSet m_calls, m_frames;
    uint64_t m_next_position = 0;  // stream position of the next FRAME_BEGIN
    bool m_in_frame = false, m_frame_selected = false, m_emitted = false;
    protocol::FrameBegin m_pending;
    uint64_t m_frames_kept = 0;
};

std::string property_text(const std::string& text) {
    if (text.size() <= protocol::kMaxPropertyValueLength) return text;
    return text.substr(0, protocol::kMaxPropertyValueLength - 3) + "...";
}

void check_paths(const TrimArgs& args) {
    std::error_code ec;
    if (args.out != "-" && args.stream != "-" && std::filesystem::exists(args.out, ec) &&
        std::filesystem::equivalent(args.stream, args.out, ec))
        throw UsageError(fmt::format("trim: -o {} is the input stream itself", args.out));
}

int run_trim(const TrimArgs& args) {
    check_paths(args);
    const Selection selection(args);
    Console console{args.quiet};
    protocol::StreamReader reader(args.stream);
    protocol::Properties properties = reader.properties();
    properties["trimmed_from"] = property_text(args.stream);
    if (!args.calls.empty()) properties["trim_calls"] = property_text(args.calls);
    if (!args.frames.empty()) properties["trim_frames"] = property_text(args.frames);

    make_parent_dirs(args.out);
    protocol::StreamWriter writer(args.out, properties);
    Trimmer trimmer(selection, writer);

    // seek through the frame index to where the selection starts
    if (trimmer.has_frames()) {
        if (seek_to_frame(reader, trimmer.frames().first()))
            trimmer.set_next_frame_position(trimmer.frames().first());
    } else if (const auto position = seek_to_call(reader, trimmer.calls().first())) {
        trimmer.set_next_frame_position(*position);
    }

    std::optional<protocol::StreamError> error;
    protocol::Command c;
    try {
        while (reader.next(c) && trimmer.take(reader.command_number(), c)) {
        }
    } catch (const protocol::StreamError& e) {
        error = e;
    }
    if (writer.command_count() == 0) {
        writer.discard();
        std::cerr << fmt::format(
            "fb89: error: trim: the selection matched no command of {}; "
            "{} not written\n",
            args.stream, writer.path());
        if (error) report_stream_error(*error);
        return kBadInput;
    }
    if (error && !args.salvage) {
        writer.discard();
        report_stream_error(*error);
        std::cerr << fmt::format(
            "fb89: {}: not written (--salvage keeps what was read before the error)\n",
            writer.path());
        return kBadInput;
    }
    trimmer.finish(error ? fmt::format("fb89 trim: input ended here: {}", error->what()) : "");
    console.note(fmt::format("{}: kept {} command(s) in {} frame(s) of {}", writer.path(),
                             grouped(writer.command_count()), trimmer.frames_kept(), args.stream));
    if (error) {
        std::cerr << fmt::format(
            "fb89: warning: {}; --salvage: {} holds what was read before it, closed so that "
            "it replays\n",
            error->what(), writer.path());
    }
    return kSuccess;
}

}  // namespace

void register_trim(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<TrimArgs>();
    CLI::App* sub = app.add_subcommand(
        "trim", "Copy chosen commands or frames into a new stream that still replays");
    sub->add_option("stream", args->stream, "Input stream file ('-' for stdin)")->required();
    sub->add_option("--calls", args->calls,
                    "Call set to keep, e.g. '0-1000', '/span', '@calls.txt' (docs/PROTOCOL.md)");
    sub->add_option("--frames", args->frames,
                    "Frames to keep, by position in the stream from 0, e.g. '0-3,7'");
    sub->add_option("-o,--output", args->out, "Output stream file ('-' for stdout)")->required();
    sub->add_flag("--salvage", args->salvage,
                  "A truncated or corrupt input is a warning, not an error: keep what was read "
                  "before the damage, closed so that it replays, and exit 0");
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([args, &exit_code] { exit_code = run_trim(*args); });
}

}  // namespace fb89::cli
