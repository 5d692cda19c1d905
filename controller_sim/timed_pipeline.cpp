#include "controller_sim/timed_pipeline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fb89::controller {

TimedPipeline::TimedPipeline(uint64_t buffer_bytes) : m_capacity(buffer_bytes) {
    if (buffer_bytes == 0) throw std::invalid_argument("a command buffer of 0 bytes holds nothing");
}

double TimedPipeline::push(const TimedCommand& c, CommandTiming* timing) {
    if (!std::isfinite(c.send_us) || c.send_us < m_last_send_us)
        throw std::invalid_argument("a send time of " + std::to_string(c.send_us) +
                                    " us comes before the last one, " +
                                    std::to_string(m_last_send_us) + " us");
    if (c.bytes > m_capacity)
        throw std::invalid_argument("a command of " + std::to_string(c.bytes) +
                                    " bytes cannot fit a buffer of " + std::to_string(m_capacity) +
                                    " bytes");
    m_last_send_us = c.send_us;
    if (c.bytes == 0) {  // not sent
        if (timing) {
            const double t = c.send_us + m_shift_us;
            *timing = {t, t, t, t, t, 0};
        }
        return m_controller_free_us;
    }

    const double ready = c.send_us + m_shift_us;
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
    m_controller_free_us = done;
    if (timing) *timing = {ready, start, arrive, exec_start, done, c.bytes};
    m_held.push_back({done, c.bytes});
    m_occupied += c.bytes;
    m_figures.high_water_bytes = std::max(m_figures.high_water_bytes, m_occupied);
    m_figures.bus_busy_us += c.bus_us;
    m_figures.controller_busy_us += c.exec_us;
    return done;
}

void TimedPipeline::free_until(double t) {
    while (m_head < m_held.size() && m_held[m_head].done_us <= t)
        m_occupied -= m_held[m_head++].bytes;
    if (m_head == m_held.size()) {
        m_held.clear();
        m_head = 0;
    } else if (m_head >= 4096 && m_head * 2 >= m_held.size()) {
        m_held.erase(m_held.begin(), m_held.begin() + static_cast<std::ptrdiff_t>(m_head));
        m_head = 0;
    }
}

PipelineFigures TimedPipeline::finish(double host_end_us) {
    PipelineFigures f = m_figures;
    f.buffer_bytes = m_capacity;
    const double host_end = std::max(host_end_us, m_last_send_us) + m_shift_us;
    f.frame_us = std::max(host_end, m_controller_free_us);
    f.host_us = host_end - f.host_stalled_us;
    f.controller_idle_us = f.frame_us - f.controller_busy_us;
    // ready for the next frame, from 0, keeping the queue's room
    m_held.clear();
    m_head = 0;
    m_occupied = 0;
    m_last_send_us = m_shift_us = m_bus_free_us = m_controller_free_us = 0;
    m_figures = PipelineFigures{};
    return f;
}

}  // namespace fb89::controller
