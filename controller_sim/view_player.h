// ViewPlayer: the playback engine of `fb89 view`, with no window: it reads a stream
// incrementally, executes it into a Controller and a Recorder, and moves through it
// (play by a budget of modelled time, step, run to a frame's end, seek).
//
// A stream with send times (format version 2) plays at the pace of the pipeline in time
// (timed_pipeline.h): each command is done when the pipeline says, the host's sends, its
// stalls on a full buffer and the controller's waits for commands included; a stream
// without them at the controller's own pace, every command ready at once.
//
// It never holds the stream in memory: going back re-opens the file and, when the stream
// has a frame index, seeks straight to the frame's FRAME_BEGIN (StreamReader::seek), else
// re-reads from the start. A seek starts a fresh Controller and Recorder there, so modelled
// time counts from the frame sought. stdin ("-") plays forwards only.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "controller_sim/controller.h"
#include "controller_sim/recorder.h"
#include "controller_sim/timed_pipeline.h"
#include "protocol/stream_reader.h"

namespace fb89::controller {

// What the player is doing. Play is paced by the caller's budget; the others run unpaced
// until reached, then turn into what was asked after (Play or Pause).
enum class ViewGoal {
    Play,
    Pause,
    FrameEnd,    // until a FRAME_END of frame ordinal >= the target has executed
    Command,     // until the next command to execute is the target
    FrameBegin,  // until a FRAME_BEGIN carrying the target frame number has executed
    End,         // until the end of the stream
};

class ViewPlayer {
  public:
    using Clock = std::chrono::steady_clock;

    // Opens the stream (throws as StreamReader does) and reads its frame index if it can.
    // A timed stream's pipeline has a command buffer of `buffer_bytes` (none given: the
    // profile's); a command that cannot fit it stops the playback with an error().
    ViewPlayer(std::string path, CostProfile profile,
               std::optional<uint64_t> buffer_bytes = std::nullopt);

    // Executes the next command; false at the end of the stream or after an error.
    bool step();
    // Paced play: executes commands while the budget of modelled µs lasts (each spends its
    // modelled time) or until the deadline; returns what is left of the budget (may be < 0).
    double play(double budget_us, Clock::time_point deadline);
    // Unpaced goals: runs towards the goal until reached, the end, or the deadline. With
    // Play it runs to the end (a caller that does not pace).
    void run(Clock::time_point deadline);

    ViewGoal goal() const { return m_goal; }
    void set_goal(ViewGoal g) { m_goal = g; }

    // Moves: each ends paused, except the start positions, which then play.
    void restart();                          // back to command 0, paused
    void to_end();                           // to the end: the last frame via the index
    void next_frame();                       // to the end of this frame, or of the next
    void previous_frame();                   // to the end of the frame before this one
    void seek_frame_number(uint32_t frame);  // start at the FRAME_BEGIN carrying `frame`
    void seek_command(uint64_t number);      // start before command `number`

    bool at_end() const { return m_at_end; }
    const std::string& error() const { return m_error; }  // empty unless the stream failed

    const Controller& controller() const { return *m_controller; }
    const Recorder& recorder() const { return m_recorder; }
    const protocol::StreamReader& reader() const { return *m_reader; }
    uint64_t next_command() const { return m_reader->next_command_number(); }
    const protocol::Command* last_command() const { return m_last ? &*m_last : nullptr; }
    uint64_t last_number() const { return m_last_number; }
    int64_t frame_number() const { return m_frame_number; }  // of the last FRAME_BEGIN; -1
    int64_t frame_ordinal() const { return m_ordinal; }      // 0-based; -1 before a frame
    std::optional<std::size_t> frame_count() const;          // from the index, if any
    // Modelled time since the last seek: the pipeline's in a timed stream, the controller's
    // otherwise; and since the frame's FRAME_BEGIN.
    double elapsed_us() const;
    double frame_us() const { return m_in_frame_time ? elapsed_us() - m_frame_start_us : 0; }
    // The pipeline in time of a timed stream: its command buffer, and the frame so far (the
    // host's stalls, the controller's busy time; idle is frame_us() less busy).
    bool timed() const { return m_reader->timed(); }
    uint64_t buffer_bytes() const { return m_buffer; }
    const PipelineFigures& pipeline_so_far() const {
        return m_finished ? *m_finished : m_pipe.so_far();
    }

  private:
    void reopen();
    void reset_state(int64_t ordinal);
    void seek_entry(std::size_t i);  // needs the index
    void go_to_ordinal(int64_t ordinal);
    bool reached() const;

    std::string m_path;
    CostProfile m_profile;
    std::unique_ptr<protocol::StreamReader> m_reader;
    std::optional<protocol::FrameIndex> m_index;
    std::unique_ptr<Controller> m_controller;
    Recorder m_recorder;

    ViewGoal m_goal = ViewGoal::Play;
    ViewGoal m_after = ViewGoal::Pause;
    uint64_t m_target = 0;
    bool m_at_end = false;
    std::string m_error;

    std::optional<protocol::Command> m_last;
    uint64_t m_last_number = 0;
    int64_t m_frame_number = -1;
    int64_t m_ordinal = -1;
    bool m_frame_ended = false;  // the last command was a FRAME_END
    bool m_in_frame_time = false;
    double m_frame_start_us = 0;
    // the pipeline in time (a timed stream): frames before this one, and this one's clock
    uint64_t m_buffer;
    TimedPipeline m_pipe;
    std::optional<PipelineFigures> m_finished;  // the frame's, once its FRAME_END is done
    double m_pipe_frames_us = 0;
    double m_pipe_clock_us = 0;
};

}  // namespace fb89::controller
