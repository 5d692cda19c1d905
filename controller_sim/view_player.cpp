// ViewPlayer: playback of a stream for `fb89 view` (see view_player.h).
//
// Frames are counted by ordinal (the n-th FRAME_BEGIN of the stream, as the frame index
// lists them), and shown to people by the frame number FRAME_BEGIN carries. Without an
// index, going back re-reads the stream from its start, fast: nothing is drawn meanwhile.
#include "controller_sim/view_player.h"

#include <algorithm>
#include <stdexcept>
#include <variant>

#include <fmt/format.h>

namespace fb89::controller {

ViewPlayer::ViewPlayer(std::string path, CostProfile profile, std::optional<uint64_t> buffer_bytes)
    : m_path(std::move(path)),
      m_profile(std::move(profile)),
      m_buffer(buffer_bytes.value_or(m_profile.command_buffer_bytes)),
      m_pipe(m_buffer) {
    reopen();
    if (m_path != "-") m_index = m_reader->read_trailing_index();
}

double ViewPlayer::elapsed_us() const {
    return timed() ? m_pipe_frames_us + m_pipe_clock_us : m_controller->elapsed_us();
}

void ViewPlayer::reopen() {
    m_reader = std::make_unique<protocol::StreamReader>(m_path);
    reset_state(-1);
}

void ViewPlayer::reset_state(int64_t ordinal) {
    m_controller = std::make_unique<Controller>(m_profile);
    m_controller->keep_depth_drawn(true);  // the recorder attributes depth-tested pixels
    m_recorder.reset();
    m_at_end = false;
    m_error.clear();
    m_last.reset();
    m_frame_number = -1;
    m_ordinal = ordinal;
    m_frame_ended = false;
    m_in_frame_time = false;
    m_pipe = TimedPipeline(m_buffer);
    m_finished.reset();
    m_pipe_frames_us = m_pipe_clock_us = 0;
}

bool ViewPlayer::step() {
    if (m_at_end) return false;
    protocol::Command c;
    try {
        if (!m_reader->next(c)) {
            m_at_end = true;
            if (!m_index && m_reader->frame_index()) m_index = m_reader->frame_index();
            return false;
        }
        const auto* begin = std::get_if<protocol::FrameBegin>(&c);
        if (begin && timed()) {  // the pipeline starts the frame at its set-up
            m_pipe_frames_us += m_pipe_clock_us;
            m_pipe_clock_us = 0;
            m_pipe = TimedPipeline(m_buffer);
            m_finished.reset();
        }
        const double before = elapsed_us();
        m_controller->execute(c);
        if (timed()) {
            const Controller::CommandCost& cost = m_controller->last_cost();
            const double send_us = from_ns(m_reader->send_time_ns());
            m_pipe_clock_us = std::max(
                m_pipe_clock_us, m_pipe.push({send_us, cost.bytes, cost.bus_us, cost.exec_us}));
            if (std::holds_alternative<protocol::FrameEnd>(c)) {  // the host's end may be later
                m_finished = m_pipe.finish(from_ns(m_reader->frame_host_end_ns()));
                m_pipe_clock_us = m_finished->frame_us;
            }
        }
        if (begin) {
            m_frame_start_us = before;
            m_in_frame_time = true;
            m_frame_number = begin->frame;
            ++m_ordinal;
        }
    } catch (const std::exception& e) {  // corrupt stream, or a frame the controller refuses
        m_error = e.what();
        m_at_end = true;
        return false;
    }
    m_last_number = m_reader->command_number();
    m_recorder.record(m_last_number, c, m_controller->depth_drawn());
    m_frame_ended = std::holds_alternative<protocol::FrameEnd>(c);
    m_last = std::move(c);
    return true;
}

double ViewPlayer::play(double budget_us, Clock::time_point deadline) {
    for (int n = 1; budget_us > 0 && !m_at_end; ++n) {
        if (n % 256 == 0 && Clock::now() >= deadline) break;
        const double before = elapsed_us();
        if (!step()) break;
        budget_us -= elapsed_us() - before;
    }
    return budget_us;
}

bool ViewPlayer::reached() const {
    switch (m_goal) {
        case ViewGoal::FrameEnd:
            return m_frame_ended && m_ordinal >= static_cast<int64_t>(m_target);
        case ViewGoal::Command:
            return next_command() >= m_target;
        case ViewGoal::FrameBegin:
            return m_last && std::holds_alternative<protocol::FrameBegin>(*m_last) &&
                   m_frame_number == static_cast<int64_t>(m_target);
        case ViewGoal::Play:
        case ViewGoal::End:
            return false;
        case ViewGoal::Pause:
            return true;
    }
    return true;
}

void ViewPlayer::run(Clock::time_point deadline) {
    if (m_goal == ViewGoal::Pause) return;
    for (int n = 1; !m_at_end && !reached(); ++n) {
        if (n % 256 == 0 && Clock::now() >= deadline) return;
        step();
    }
    if (m_goal == ViewGoal::FrameBegin && m_at_end && m_error.empty())
        m_error = fmt::format("no FRAME_BEGIN carries frame number {}", m_target);
    if (m_goal != ViewGoal::Play && m_goal != ViewGoal::End) m_goal = m_after;
}

std::optional<std::size_t> ViewPlayer::frame_count() const {
    if (!m_index) return std::nullopt;
    return m_index->size();
}

void ViewPlayer::seek_entry(std::size_t i) {
    m_reader->seek((*m_index)[i]);
    reset_state(static_cast<int64_t>(i) - 1);
}

void ViewPlayer::restart() {
    if (m_path == "-") return;  // stdin cannot be rewound
    reopen();
    m_goal = ViewGoal::Pause;
}

void ViewPlayer::to_end() {
    if (m_index && !m_index->empty() && m_index->back().command > next_command())
        seek_entry(m_index->size() - 1);
    m_goal = ViewGoal::End;
}

// shows frame `ordinal` complete: seek to it (index) or re-read up to it, run to its end
void ViewPlayer::go_to_ordinal(int64_t ordinal) {
    ordinal = std::max<int64_t>(ordinal, 0);
    if (m_index && static_cast<std::size_t>(ordinal) < m_index->size()) {
        seek_entry(static_cast<std::size_t>(ordinal));
    } else if (ordinal <= m_ordinal) {
        if (m_path == "-") return;
        reopen();
    }
    m_target = static_cast<uint64_t>(ordinal);
    m_goal = ViewGoal::FrameEnd;
    m_after = ViewGoal::Pause;
}

void ViewPlayer::next_frame() {
    const bool open = m_controller->in_frame();
    m_target = static_cast<uint64_t>(std::max<int64_t>(open ? m_ordinal : m_ordinal + 1, 0));
    m_goal = ViewGoal::FrameEnd;
    m_after = ViewGoal::Pause;
}

void ViewPlayer::previous_frame() {
    go_to_ordinal(m_ordinal - 1);
}

void ViewPlayer::seek_frame_number(uint32_t frame) {
    if (m_index) {
        const auto it = std::find_if(m_index->begin(), m_index->end(),
                                     [frame](const auto& e) { return e.frame == frame; });
        if (it == m_index->end())
            throw std::invalid_argument(
                fmt::format("{}: no frame numbered {} in the frame index", m_path, frame));
        seek_entry(static_cast<std::size_t>(it - m_index->begin()));
        m_goal = ViewGoal::Play;
        return;
    }
    m_target = frame;
    m_goal = ViewGoal::FrameBegin;
    m_after = ViewGoal::Play;
}

void ViewPlayer::seek_command(uint64_t number) {
    if (m_index) {
        // the last frame starting at or before `number`
        std::size_t best = m_index->size();
        for (std::size_t i = 0; i < m_index->size(); ++i)
            if ((*m_index)[i].command <= number) best = i;
        if (best < m_index->size() && (*m_index)[best].command > next_command()) seek_entry(best);
    }
    if (number < next_command() && m_path != "-") reopen();
    m_target = number;
    m_goal = ViewGoal::Command;
    m_after = ViewGoal::Play;
}

}  // namespace fb89::controller
