// A stream replayed through the emulated GSP (controller_sim/gsp_board.h) beside the C++
// controller: every frame compared pixel for pixel at its FRAME_END, and each opcode's
// executed cycles set beside the model's, with what execution knows and the model leaves
// out named and counted (docs/COST_MODEL.md, "The GSP as code"). `fb89 replay --gsp` and
// the tests run it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "controller_sim/controller.h"
#include "controller_sim/gsp_board.h"
#include "protocol/stream_reader.h"

namespace fb89::frontend {

struct GspReplayOptions {
    // The executive's source: "" for the profile's built-in listing, else a file's text,
    // named `listing_file` in errors.
    std::string listing_file, listing_text;
    controller::gsp::GspBoardOptions board;
};

struct GspReplayResult {
    std::array<controller::gsp::ExecutedCounters, protocol::kOpcodeCount> executed{};
    std::array<uint64_t, protocol::kOpcodeCount> model_cycles{};  // the C++ controller's
    controller::gsp::ExecutedCounters polls;
    uint64_t frames = 0;  // frames compared at their FRAME_END
    uint64_t frames_differing = 0;
    std::string first_difference;                       // "" when every frame is equal
    std::optional<controller::Framebuffer> last_frame;  // the GSP's, at the last FRAME_END
    std::vector<controller::gsp::TracedInstruction> trace;
    uint64_t instructions = 0;
    double wall_s = 0;  // the GSP's execution alone

    uint64_t executed_cycles() const;
    // An opcode's executed cycles less the model's, less what the model leaves out (the
    // cache's misses, the queue run beside the next command): 0 when the two agree.
    int64_t unexplained(int opcode_index) const;
    uint64_t modelled_cycles() const;
    // A table for humans: per opcode, commands, executed cycles, the model's, the
    // difference and what execution knows that the model leaves out.
    std::string summary(const controller::CostProfile& profile) const;
};

// Replays `reader` through the emulated GSP and the C++ controller under `profile` (which
// names a listing). A StreamError, GspFault or AssemblyError propagates; so does
// std::invalid_argument for a command the board cannot take.
GspReplayResult gsp_replay(protocol::StreamReader& reader, const controller::CostProfile& profile,
                           const GspReplayOptions& options);

// The traced command's instructions as a period debugger shows them: address, states, the
// listing's line.
std::string trace_text(const std::vector<controller::gsp::TracedInstruction>& trace);

}  // namespace fb89::frontend
