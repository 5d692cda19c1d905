#include "controller_sim/timed_pipeline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fb89::controller {

TimedPipeline::TimedPipeline(uint64_t buffer_bytes) : m_capacity(buffer_bytes) {
    if (buffer_bytes == 0) throw std::invalid_argument("a command buffer of 0 bytes holds nothing");
}

void TimedPipeline::reject(const TimedCommand& c) const {
    if (c.bytes > m_capacity)
        throw std::invalid_argument("a command of " + std::to_string(c.bytes) +
                                    " bytes cannot fit a buffer of " + std::to_string(m_capacity) +
                                    " bytes");
    throw std::invalid_argument("a send time of " + std::to_string(c.send_us) +
                                " us comes before the last one, " + std::to_string(m_last_send_us) +
                                " us");
}

void TimedPipeline::compact() {
    m_held.erase(m_held.begin(), m_held.begin() + static_cast<std::ptrdiff_t>(m_head));
    m_head = 0;
}

PipelineFigures TimedPipeline::finish(double host_end_us) {
    PipelineFigures f = m_figures;
    f.buffer_bytes = m_capacity;
    const double host_end = std::max(host_end_us, m_last_send_us) + m_shift_us;
    f.frame_us = std::max(host_end, m_controller_free_us);
    f.host_us = host_end - f.host_stalled_us;
    f.controller_idle_us = f.frame_us - f.controller_busy_us;
    // ready for the next frame, from 0, keeping the queue's room
    std::vector<Held> held = std::move(m_held);
    held.clear();
    *this = TimedPipeline(m_capacity);
    m_held = std::move(held);
    return f;
}

}  // namespace fb89::controller
