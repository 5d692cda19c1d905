// fb89 diff A B: compares the frames two streams produce (apitrace's `apitrace diff-images`
// as a regression test). Both streams are replayed side by side, a frame at a time, into
// controllers under the `ideal` profile (pixels do not depend on the profile); after each
// frame's FRAME_END the two framebuffers are compared pixel by pixel. Only one frame of
// each stream is in memory at a time.
//
// It prints, per frame, both sizes and the number of differing pixels (a pixel outside one
// of two differently sized frames differs); a frame only one stream has is a difference.
// --image F writes, for the first differing frame, the diff image: differing pixels red,
// the rest A's pixels dimmed to a third. Exit 0 when every frame is identical, 1 when any
// differs, 2 on usage or a truncated or corrupt stream (after the frames compared so far).
// A frame that ends without FRAME_END (the next FRAME_BEGIN, or the end of a cut stream)
// is compared as it stands then, as the controller closes it.
#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "cli/common.h"
#include "cli/stream_tools.h"
#include "controller_sim/png_io.h"

namespace fb89::cli {

namespace {

struct DiffArgs {
    std::string a, b, image;
    bool quiet = false;
};

// One stream, replayed a frame at a time.
class FrameSource {
  public:
    explicit FrameSource(const std::string& path)
        : m_reader(path), m_ctl(controller::load_profile("ideal")) {}

    // Runs to the end of the next frame; false when the stream holds no more frames.
    // Throws StreamError for a truncated or corrupt stream.
    bool next_frame() {
        if (m_pending) m_ctl.execute(*m_pending);
        m_pending.reset();
        protocol::Command c;
        while (m_reader.next(c)) {
            if (std::holds_alternative<protocol::FrameBegin>(c) && m_ctl.in_frame()) {
                m_pending = c;  // closes the open frame: compare it before clearing
                return true;
            }
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

  private:
    protocol::StreamReader m_reader;
    controller::Controller m_ctl;
    std::optional<protocol::Command> m_pending;
    bool m_open_compared = false;
};

struct Comparison {
    uint64_t differing = 0;
    uint64_t compared = 0;  // pixels of the larger frame's extent
};

bool same_pixel(const controller::Framebuffer& fb, const controller::Framebuffer& other, uint32_t x,
                uint32_t y) {
    return x < fb.width() && y < fb.height() && x < other.width() && y < other.height() &&
           fb.pixel(x, y) == other.pixel(x, y);
}

Comparison compare(const controller::Framebuffer& a, const controller::Framebuffer& b) {
    Comparison out;
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

int run_diff(const DiffArgs& args_in) {
    DiffArgs args = args_in;
    if (claims_stdout({{"--image", args.image}})) args.quiet = true;  // stdout carries the PNG
    FrameSource a(args.a), b(args.b);
    if (!args.quiet) {
        fmt::print("A: {}\nB: {}\n", header_line(a.reader()), header_line(b.reader()));
        fmt::print("{:>6} {:>11} {:>11} {:>17}\n", "frame", "size A", "size B", "differing px");
    }
    uint64_t frames = 0, differing_frames = 0;
    std::optional<uint64_t> imaged;
    try {
        for (;;) {
            const bool has_a = a.next_frame(), has_b = b.next_frame();
            if (!has_a && !has_b) break;
            ++frames;
            if (has_a != has_b) {
                ++differing_frames;
                if (!args.quiet)
                    fmt::print("{:>6} {:>11} {:>11} {:>17}\n", frames - 1,
                               has_a ? size_of(a.framebuffer()) : "-",
                               has_b ? size_of(b.framebuffer()) : "-",
                               fmt::format("only in {}", has_a ? "A" : "B"));
                continue;
            }
            const Comparison cmp = compare(a.framebuffer(), b.framebuffer());
            if (!args.quiet)
                fmt::print("{:>6} {:>11} {:>11} {:>17}{}\n", frames - 1, size_of(a.framebuffer()),
                           size_of(b.framebuffer()), grouped(cmp.differing),
                           cmp.differing ? fmt::format("  ({:.3f}%)",
                                                       100.0 * static_cast<double>(cmp.differing) /
                                                           static_cast<double>(cmp.compared))
                                         : "");
            if (cmp.differing == 0) continue;
            ++differing_frames;
            if (!args.image.empty() && !imaged) {
                write_diff_image(args.image, a.framebuffer(), b.framebuffer());
                imaged = frames - 1;
            }
        }
    } catch (const protocol::StreamError& e) {
        report_stream_error(e);
        std::cerr << fmt::format("fb89: diff: compared {} frame(s) before the error\n", frames);
        return kBadInput;
    }
    if (!args.quiet) {
        if (differing_frames == 0)
            fmt::print("identical: {} frame(s)\n", frames);
        else
            fmt::print(
                "A and B differ in {} of {} frame(s){}\n", differing_frames, frames,
                imaged ? fmt::format("; diff image of frame {}: {}", *imaged, args.image) : "");
    }
    return differing_frames == 0 ? kSuccess : kCheckFailed;
}

}  // namespace

void register_diff(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<DiffArgs>();
    CLI::App* sub =
        app.add_subcommand("diff", "Compare the frames two streams produce; exit 1 if they differ");
    sub->add_option("a", args->a, "First stream file")->required();
    sub->add_option("b", args->b, "Second stream file")->required();
    sub->add_option("--image", args->image,
                    "Write the first differing frame's diff image (differences red over A dimmed)");
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing; only the exit code tells");
    sub->callback([args, &exit_code] { exit_code = run_diff(*args); });
}

}  // namespace fb89::cli
