// The split as a pipeline in time: a frame's commands as the host sends them, each crossing
// the bus into the controller's command buffer, executed in order -- with the buffer of a
// stated size, so that a full buffer stalls the host (issue 30's model; docs/COST_MODEL.md,
// "The pipeline in time").
//
// Time is in microseconds from the start of the host's set-up. A command is ready when the
// host sends it, moved by every stall before it. It starts across the bus when it is ready,
// the bus is free (one command crosses at a time) and the buffer has room for its bytes; the
// host waits until then (a stall). It takes the buffer's room from the moment it starts to
// cross until the controller has executed it. The controller executes a command once it has
// arrived and the one before is done. The frame ends when the last command is done or the
// host's own work ends, whichever is later. An unbounded buffer never stalls the host on
// room, only on the bus.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "controller_sim/profile.h"

namespace fb89::controller {

// Times in microseconds and the whole nanoseconds streams keep them in (docs/PROTOCOL.md,
// "Version 2"): to the nearest nanosecond, and back. The pipeline takes every time at that
// grain (whole_ns), so that a frame replayed from its stream goes through it exactly as it
// did when rendered.
inline int64_t to_ns(double us) {
    return static_cast<int64_t>(std::llround(us * 1e3));
}
inline double from_ns(int64_t ns) {
    return static_cast<double>(ns) / 1e3;
}
inline double whole_ns(double us) {
    return from_ns(to_ns(us));
}

// One command as the pipeline sees it.
struct TimedCommand {
    double send_us = 0;  // when the host sends it, without stalls; never before the last
    uint32_t bytes = 0;  // on the bus and in the buffer; 0: not sent (a MARKER)
    double bus_us = 0;   // crossing the bus
    double exec_us = 0;  // executing
};

// Where one command went, in the frame's time (with the stalls before it): for a timeline.
struct CommandTiming {
    double sent_us = 0;        // the host sent it (its send time moved by earlier stalls)
    double bus_start_us = 0;   // it started across the bus; past sent_us, the host stalled
    double arrived_us = 0;     // it was in the command buffer
    double exec_start_us = 0;  // the controller started it
    double done_us = 0;        // the controller was done with it; its bytes left the buffer
    uint32_t bytes = 0;        // 0: not sent (a MARKER); the other times are then sent_us
};

// One frame's figures.
struct PipelineFigures {
    double frame_us = 0;         // set-up start to the last command done (or the host's end)
    double host_us = 0;          // the host's own work: its end less its stalls
    double host_stalled_us = 0;  // waiting for the bus or for room in the buffer
    uint64_t stalls = 0;         // commands the host waited on
    double bus_busy_us = 0;
    double controller_busy_us = 0;
    double controller_idle_us = 0;  // within the frame, waiting for commands
    uint64_t high_water_bytes = 0;  // the most the buffer held
    uint64_t buffer_bytes = 0;      // its size (kUnboundedBuffer: none)
    double host_utilization() const { return frame_us > 0 ? host_us / frame_us : 0; }
    double controller_utilization() const {
        return frame_us > 0 ? controller_busy_us / frame_us : 0;
    }
};

class TimedPipeline {
  public:
    // Throws std::invalid_argument for a buffer of 0 bytes.
    explicit TimedPipeline(uint64_t buffer_bytes = kUnboundedBuffer);

    // The next command of the frame. Throws std::invalid_argument when its send time goes
    // back or is not finite, or when it cannot fit the buffer at all. Returns when it is done;
    // where it went, in `timing` when given.
    // (Inline: replay runs every command of a stream through here.)
    double push(const TimedCommand& c, CommandTiming* timing = nullptr) {
        // (the same as "finite and not before the last", NaN and infinities refused)
        if (!(c.send_us >= m_last_send_us && c.send_us <= kLatest) || c.bytes > m_capacity)
            reject(c);
        m_last_send_us = c.send_us;
        const double ready = c.send_us + m_shift_us;
        if (c.bytes == 0) {  // not sent
            if (timing) *timing = {ready, ready, ready, ready, ready, 0};
            return m_controller_free_us;
        }
        double start = std::max(ready, m_bus_free_us);
        free_until(start);
        while (m_occupied + c.bytes > m_capacity) {  // wait for the oldest to be executed
            start = std::max(start, m_held[m_head].done_us);
            free_until(start);
        }
        if (start > ready) {
            m_shift_us += start - ready;
            m_figures.host_stalled_us += start - ready;
            ++m_figures.stalls;
        }
        const double arrive = start + c.bus_us;
        m_bus_free_us = arrive;
        const double exec_start = std::max(arrive, m_controller_free_us);
        const double done = exec_start + c.exec_us;
        if (timing) *timing = {ready, start, arrive, exec_start, done, c.bytes};
        m_controller_free_us = done;
        m_held.push_back({done, c.bytes});
        m_occupied += c.bytes;
        m_figures.high_water_bytes = std::max(m_figures.high_water_bytes, m_occupied);
        m_figures.bus_busy_us += c.bus_us;
        m_figures.controller_busy_us += c.exec_us;
        return done;
    }
    // The frame's figures, the host's own work ending at `host_end_us` (not before the last
    // send). The pipeline is then ready for the next frame, from 0.
    PipelineFigures finish(double host_end_us);
    // The frame's figures so far (the sums; frame_us and host_us wait for finish()).
    const PipelineFigures& so_far() const { return m_figures; }

  private:
    static constexpr double kLatest = std::numeric_limits<double>::max();
    struct Held {
        double done_us;
        uint32_t bytes;
    };
    // What the controller has executed by t leaves the buffer.
    // (Head and occupancy in locals while popping: stored through each step, the loop runs at
    // the speed of a store and its reload.)
    void free_until(double t) {
        std::size_t head = m_head;
        uint64_t occupied = m_occupied;
        const Held* held = m_held.data();
        const std::size_t size = m_held.size();
        while (head < size && held[head].done_us <= t)
            occupied -= held[head++].bytes;
        m_head = head;
        m_occupied = occupied;
        if (m_head == size) {
            m_held.clear();
            m_head = 0;
        } else if (m_head >= 4096 && m_head * 2 >= m_held.size()) {
            compact();
        }
    }
    // Drops the queue's spent front (grown large, and half the queue).
    void compact();
    // Why push() refuses c (std::invalid_argument).
    [[noreturn]] void reject(const TimedCommand& c) const;

    uint64_t m_capacity;
    // In the buffer, oldest first: m_held from m_head on (a queue kept in one vector, its
    // front moved up and the spent part dropped now and then; replay runs every command
    // through here).
    std::vector<Held> m_held;
    std::size_t m_head = 0;
    uint64_t m_occupied = 0;
    double m_last_send_us = 0;
    double m_shift_us = 0;  // the stalls so far: every later send moves by them
    double m_bus_free_us = 0;
    double m_controller_free_us = 0;
    PipelineFigures m_figures;
};

}  // namespace fb89::controller
