#include "frontend/stream_edit.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "controller_sim/png_io.h"
#include "controller_sim/timed_pipeline.h"
#include "frontend/common.h"
#include "frontend/stream_tools.h"
#include "protocol/stream_writer.h"

namespace fb89::frontend {

namespace {

// What to keep; parsed before the output is created.
struct Selection {
    bool has_calls = false, has_frames = false;
    protocol::CallSet calls, frames;

    explicit Selection(const TrimRequest& args)
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

    // Handles command n, read from `reader` (whose send times go with it into a timed
    // output); false when nothing after it can be selected.
    bool take(uint64_t n, const protocol::Command& c, const protocol::StreamReader& reader) {
        if (m_has_calls && n > m_calls.last()) return false;
        if (const auto* begin = std::get_if<protocol::FrameBegin>(&c)) {
            close_frame();
            const uint64_t position = m_next_position++;
            if (m_has_frames && position > m_frames.last()) return false;
            m_pending = *begin;
            m_depth_clear = false;
            m_in_frame = true;
            m_frame_selected = !m_has_frames || m_frames.contains_number(position);
        }
        const bool selected = (!m_has_calls || m_calls.contains(n, c)) &&
                              (!m_has_frames || (m_in_frame && m_frame_selected));
        // a kept frame keeps its DEPTH_CLEAR, as it keeps its FRAME_BEGIN: its depth
        // commands need the buffer it makes
        const bool depth_clear = m_in_frame && std::holds_alternative<protocol::DepthClear>(c);
        const bool is_framing = std::holds_alternative<protocol::FrameBegin>(c) ||
                                (m_in_frame && std::holds_alternative<protocol::FrameEnd>(c)) ||
                                depth_clear;
        if (depth_clear) {
            m_depth_clear = true;
            if (m_emitted) m_writer.depth_clear({});
        }
        if (selected && m_in_frame && !m_emitted) {
            m_writer.frame_begin(m_pending);
            if (m_depth_clear) m_writer.depth_clear({});
            m_emitted = true;
            ++m_frames_kept;
        }
        if (selected && !is_framing) {
            if (m_writer.timed()) m_writer.send_time(reader.send_time_ns());
            m_writer.submit(c);
        }
        if (std::holds_alternative<protocol::FrameEnd>(c)) {
            if (m_writer.timed() && m_emitted) {  // the kept frame ends as the input's did
                m_writer.send_time(reader.send_time_ns());
                if (const auto end = reader.host_end_ns()) m_writer.host_end(*end);
            }
            close_frame();
        }
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
    bool m_depth_clear = false;  // the open frame's DEPTH_CLEAR has been read
    uint64_t m_frames_kept = 0;
};

std::string property_text(const std::string& text) {
    if (text.size() <= protocol::kMaxPropertyValueLength) return text;
    return text.substr(0, protocol::kMaxPropertyValueLength - 3) + "...";
}

void check_paths(const TrimRequest& args) {
    std::error_code ec;
    if (args.output != "-" && args.input != "-" && std::filesystem::exists(args.output, ec) &&
        std::filesystem::equivalent(args.input, args.output, ec))
        throw UsageError(fmt::format("trim: -o {} is the input stream itself", args.output));
}

// One stream, replayed a frame at a time, its pixels as the profile's controller draws them
// (the ideal profile with its depth word: pixels depend on nothing else).
controller::CostProfile drawing_profile(const std::string& profile) {
    controller::CostProfile ideal = controller::load_profile("ideal");
    ideal.depth_bits = controller::load_profile(profile).depth_bits;
    return ideal;
}

class FrameSource {
  public:
    FrameSource(const std::string& path, const std::string& profile)
        : m_reader(path), m_ctl(drawing_profile(profile)) {}

    // Runs to the end of the next frame; false when the stream holds no more frames.
    // Throws StreamError for a truncated or corrupt stream.
    bool next_frame() {
        if (m_pending) m_ctl.execute(*m_pending);
        m_pending.reset();
        m_host_end_ns = 0;
        protocol::Command c;
        while (m_reader.next(c)) {
            if (std::holds_alternative<protocol::FrameBegin>(c) && m_ctl.in_frame()) {
                m_pending = c;  // closes the open frame: compare it before clearing
                return true;
            }
            m_host_end_ns = m_reader.frame_host_end_ns();
            const std::size_t closed = m_ctl.frames().size();
            m_ctl.execute(c);
            if (m_ctl.frames().size() > closed) return true;
        }
        if (m_ctl.in_frame() && !m_open_compared) {
            m_open_compared = true;  // a cut stream that ends inside a frame
            return true;
        }
        return false;
    }

    const controller::Framebuffer& framebuffer() const { return m_ctl.framebuffer(); }
    const protocol::StreamReader& reader() const { return m_reader; }
    // The frame's host end in a timed stream: its HOST_END, or without one its last send.
    std::optional<double> host_end_ms() const {
        if (!m_reader.timed()) return std::nullopt;
        return controller::from_ns(m_host_end_ns) / 1e3;
    }

  private:
    int64_t m_host_end_ns = 0;
    protocol::StreamReader m_reader;
    controller::Controller m_ctl;
    std::optional<protocol::Command> m_pending;
    bool m_open_compared = false;
};

struct FrameComparison {
    uint64_t differing = 0;
    uint64_t compared = 0;  // pixels of the larger frame's extent
};

bool same_pixel(const controller::Framebuffer& fb, const controller::Framebuffer& other, uint32_t x,
                uint32_t y) {
    return x < fb.width() && y < fb.height() && x < other.width() && y < other.height() &&
           fb.pixel(x, y) == other.pixel(x, y);
}

FrameComparison compare(const controller::Framebuffer& a, const controller::Framebuffer& b) {
    FrameComparison out;
    const uint32_t w = std::max(a.width(), b.width()), h = std::max(a.height(), b.height());
    out.compared = uint64_t{w} * h;
    if (a.width() == b.width() && a.height() == b.height()) {
        const auto pa = a.pixels(), pb = b.pixels();
        for (std::size_t i = 0; i < pa.size(); i += 3)
            out.differing += (pa[i] != pb[i] || pa[i + 1] != pb[i + 1] || pa[i + 2] != pb[i + 2]);
        return out;
    }
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            out.differing += !same_pixel(a, b, x, y);
    return out;
}

// Differing pixels red, the rest A dimmed to a third (black outside A).
void write_diff_image(const std::string& path, const controller::Framebuffer& a,
                      const controller::Framebuffer& b) {
    const uint32_t w = std::max(a.width(), b.width()), h = std::max(a.height(), b.height());
    std::vector<uint8_t> rgb(std::size_t{w} * h * 3, 0);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            uint8_t* p = &rgb[(std::size_t{y} * w + x) * 3];
            if (!same_pixel(a, b, x, y)) {
                p[0] = 255;
            } else {
                const protocol::Rgb c = a.pixel(x, y);
                p[0] = c.r / 3, p[1] = c.g / 3, p[2] = c.b / 3;
            }
        }
    }
    make_parent_dirs(path);
    controller::write_png(path, w, h, rgb);
}

std::string size_of(const controller::Framebuffer& fb) {
    return fmt::format("{}x{}", fb.width(), fb.height());
}

}  // namespace

TrimOutcome trim_stream(const TrimRequest& args) {
    check_paths(args);
    const Selection selection(args);
    protocol::StreamReader reader(args.input);
    protocol::Properties properties = reader.properties();
    properties["trimmed_from"] = property_text(args.input);
    if (!args.calls.empty()) properties["trim_calls"] = property_text(args.calls);
    if (!args.frames.empty()) properties["trim_frames"] = property_text(args.frames);

    make_parent_dirs(args.output);
    protocol::StreamWriter writer(
        args.output, properties,
        reader.timed() ? protocol::Timing::Timed : protocol::Timing::Untimed,
        reader.version() >= protocol::kDepthVersion ? protocol::Commands::Depth
                                                    : protocol::Commands::Tiling);
    Trimmer trimmer(selection, writer);

    // seek through the frame index to where the selection starts
    if (trimmer.has_frames()) {
        if (seek_to_frame(reader, trimmer.frames().first()))
            trimmer.set_next_frame_position(trimmer.frames().first());
    } else if (const auto position = seek_to_call(reader, trimmer.calls().first())) {
        trimmer.set_next_frame_position(*position);
    }

    TrimOutcome out;
    out.output = writer.path();
    protocol::Command c;
    try {
        while (reader.next(c) && trimmer.take(reader.command_number(), c, reader)) {
        }
    } catch (const protocol::StreamError& e) {
        out.error = e;
    }
    if (writer.command_count() == 0) {
        writer.discard();
        out.result = TrimOutcome::Result::NothingMatched;
        return out;
    }
    if (out.error && !args.salvage) {
        writer.discard();
        out.result = TrimOutcome::Result::Damaged;
        return out;
    }
    trimmer.finish(out.error ? fmt::format("fb89 trim: input ended here: {}", out.error->what())
                             : "");
    out.commands_kept = writer.command_count();
    out.frames_kept = trimmer.frames_kept();
    return out;
}

DiffOutcome diff_streams(const std::string& path_a, const std::string& path_b,
                         const std::string& image, const std::string& profile) {
    FrameSource a(path_a, profile), b(path_b, profile);
    DiffOutcome out;
    // the first frame both streams have, kept until a differing one replaces it: an image
    // asked for is written whatever the streams hold, the first difference if there is one
    std::optional<std::pair<controller::Framebuffer, controller::Framebuffer>> first_pair;
    std::optional<uint64_t> first_frame;
    out.header_a = header_line(a.reader());
    out.header_b = header_line(b.reader());
    out.timed = a.reader().timed() || b.reader().timed();
    try {
        for (uint64_t frame = 0;; ++frame) {
            const bool has_a = a.next_frame(), has_b = b.next_frame();
            if (!has_a && !has_b) break;
            FrameDiff f;
            f.frame = frame;
            if (has_a) f.size_a = size_of(a.framebuffer()), f.host_end_ms_a = a.host_end_ms();
            if (has_b) f.size_b = size_of(b.framebuffer()), f.host_end_ms_b = b.host_end_ms();
            if (has_a && has_b) {
                const FrameComparison cmp = compare(a.framebuffer(), b.framebuffer());
                f.differing = cmp.differing;
                f.compared = cmp.compared;
            }
            out.frames.push_back(f);
            if (has_a && has_b && !image.empty() && !first_frame) {
                first_pair.emplace(a.framebuffer(), b.framebuffer());
                first_frame = frame;
            }
            if (!f.differs()) continue;
            ++out.differing_frames;
            if (has_a && has_b && !image.empty() && !out.image_frame) {
                write_diff_image(image, a.framebuffer(), b.framebuffer());
                out.image_frame = frame;
            }
        }
    } catch (const protocol::StreamError& e) {
        out.error = e;
        return out;
    }
    if (!image.empty() && !out.image_frame) {
        // no frame of both differs: the image of the first one both have (nothing in red)
        if (!first_pair)
            throw std::runtime_error(fmt::format(
                "{} and {} have no frame in common; {} not written", path_a, path_b, image));
        write_diff_image(image, first_pair->first, first_pair->second);
        out.image_frame = first_frame;
    }
    return out;
}

}  // namespace fb89::frontend
