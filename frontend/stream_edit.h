// trim and diff as functions, for the commands and the Python module alike: what they take,
// what they found, and the stream error that ended them, if any; the commands print it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "controller_sim/profile.h"
#include "protocol/stream_format.h"

namespace fb89::frontend {

// trim (cli/trim_command.cpp says what is kept and how frames are closed).
struct TrimRequest {
    std::string input, output;  // "-": stdin, stdout
    std::string calls, frames;  // call sets; at least one
    bool salvage = false;
};
struct TrimOutcome {
    enum class Result { Written, NothingMatched, Damaged } result = Result::Written;
    std::string output;  // the writer's name for it
    uint64_t commands_kept = 0, frames_kept = 0;
    // What ended the reading early: with Written, salvaged (the output holds what was read
    // before it); with Damaged, the output was not written.
    std::optional<protocol::StreamError> error;
};
// Throws UsageError for a bad selection or an output that is the input, std::runtime_error
// when a file cannot be opened.
TrimOutcome trim_stream(const TrimRequest& request);

// diff (cli/diff_command.cpp): each frame of the two streams compared, pixel by pixel.
struct FrameDiff {
    uint64_t frame = 0;
    std::string size_a, size_b;  // "WxH"; "" when only the other stream has the frame
    uint64_t differing = 0;      // pixels (a frame only one stream has: 0, and it differs)
    uint64_t compared = 0;       // pixels of the larger frame's extent
    // in a stream with send times (version 2): when the host's work on the frame ended
    std::optional<double> host_end_ms_a, host_end_ms_b;
    bool differs() const { return size_a.empty() || size_b.empty() || differing > 0; }
};
struct DiffOutcome {
    std::string header_a, header_b;  // header_line() of each
    bool timed = false;              // either stream has send times
    std::vector<FrameDiff> frames;
    uint64_t differing_frames = 0;
    std::optional<uint64_t> image_frame;         // the frame whose diff image was written
    std::optional<protocol::StreamError> error;  // what ended the comparison early
};
// With `image` non-empty, writes the first differing frame's diff image there (differing
// pixels red, the rest A's dimmed to a third), or, when no frame both have differs, the
// first frame both have (all dimmed); throws std::runtime_error when they have none.
// The frames are drawn as `profile`'s controller draws them: the depth commands with its
// depth word.
DiffOutcome diff_streams(const std::string& a, const std::string& b, const std::string& image,
                         const std::string& profile = std::string(controller::kDefaultProfile));

}  // namespace fb89::frontend
