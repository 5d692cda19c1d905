// fb89 diff A B: compares the frames two streams produce (apitrace's `apitrace diff-images`
// as a regression test). Both streams are replayed side by side, a frame at a time, into
// controllers that draw as --profile's does (pixels depend on the profile only through its
// depth word, which decides the depth commands' ties; default the default profile's); after
// each frame's FRAME_END the two framebuffers are compared pixel by pixel. Only one frame of
// each stream is in memory at a time.
//
// It prints, per frame, both sizes and the number of differing pixels (a pixel outside one
// of two differently sized frames differs); a frame only one stream has is a difference.
// --image F writes, for the first differing frame, the diff image: differing pixels red,
// the rest A's pixels dimmed to a third; when no frame both streams have differs, the first
// frame they both have, all dimmed (an output asked for is always written, or the command
// fails). Exit 0 when every frame is identical, 1 when any
// differs, 2 on usage or a truncated or corrupt stream (after the frames compared so far).
// A frame that ends without FRAME_END (the next FRAME_BEGIN, or the end of a cut stream)
// is compared as it stands then, as the controller closes it. When either stream carries send
// times (version 2), each frame's host end in both is shown beside it (times do not count as
// a difference: the frames do).
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.h"
#include "frontend/stream_edit.h"
#include "frontend/stream_tools.h"

namespace fb89::cli {

namespace {

struct DiffArgs {
    std::string a, b, image;
    std::string profile = std::string(controller::kDefaultProfile);
    bool quiet = false;
};

int run_diff(const DiffArgs& args_in) {
    DiffArgs args = args_in;
    if (claims_stdout({{"--image", args.image}})) args.quiet = true;  // stdout carries the PNG
    const DiffOutcome out = diff_streams(args.a, args.b, args.image, args.profile);
    if (!args.quiet) {
        fmt::print("A: {}\nB: {}\n", out.header_a, out.header_b);
        // with send times in either stream, when the host's work on each frame ended
        const auto host_ends = [&](const FrameDiff& f) -> std::string {
            if (!out.timed) return "";
            const auto ms = [](const std::optional<double>& v) {
                return v ? fmt::format("{:.3f}", *v) : std::string("-");
            };
            return fmt::format(" {:>14} {:>14}", ms(f.host_end_ms_a), ms(f.host_end_ms_b));
        };
        fmt::print(
            "{:>6} {:>11} {:>11} {:>17}{}\n", "frame", "size A", "size B", "differing px",
            out.timed ? fmt::format(" {:>14} {:>14}", "host end A ms", "host end B ms") : "");
        for (const FrameDiff& f : out.frames) {
            const auto size = [](const std::string& s) { return s.empty() ? "-" : s; };
            if (f.size_a.empty() || f.size_b.empty())
                fmt::print("{:>6} {:>11} {:>11} {:>17}{}\n", f.frame, size(f.size_a),
                           size(f.size_b), fmt::format("only in {}", f.size_b.empty() ? "A" : "B"),
                           host_ends(f));
            else
                fmt::print("{:>6} {:>11} {:>11} {:>17}{}{}\n", f.frame, f.size_a, f.size_b,
                           grouped(f.differing), host_ends(f),
                           f.differing ? fmt::format("  ({:.3f}%)",
                                                     100.0 * static_cast<double>(f.differing) /
                                                         static_cast<double>(f.compared))
                                       : "");
        }
    }
    if (out.error) {
        std::cout << std::flush;
        report_stream_error(*out.error);
        std::cerr << fmt::format("fb89: diff: compared {} frame(s) before the error\n",
                                 out.frames.size());
        return kBadInput;
    }
    if (!args.quiet) {
        if (out.differing_frames == 0)
            fmt::print("identical: {} frame(s){}\n", out.frames.size(),
                       out.image_frame ? fmt::format("; image of frame {} (nothing differs): {}",
                                                     *out.image_frame, args.image)
                                       : "");
        else
            fmt::print(
                "A and B differ in {} of {} frame(s){}\n", out.differing_frames, out.frames.size(),
                out.image_frame ? fmt::format("; diff image of frame {}{}: {}", *out.image_frame,
                                              out.differing_frames && out.frames.size() > 0 &&
                                                      !out.frames[*out.image_frame].differs()
                                                  ? " (no frame of both differs)"
                                                  : "",
                                              args.image)
                                : "");
    }
    return out.differing_frames == 0 ? kSuccess : kCheckFailed;
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
    sub->add_option("--profile", args->profile,
                    profile_option_help() +
                        "; the frames are drawn as its controller draws them (its depth word "
                        "decides the depth commands' ties)")
        ->check(profile_validator())
        ->capture_default_str();
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing; only the exit code tells");
    sub->callback([args, &exit_code] { exit_code = run_diff(*args); });
}

}  // namespace fb89::cli
