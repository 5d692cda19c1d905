#include "frontend/pipelines.h"

#include <fmt/format.h>

#include "experiments/timeline.h"
#include "frontend/data_dir.h"
#include "frontend/period_host.h"

namespace fb89::frontend {

std::string render_timeline(const experiments::MethodRun& run, const std::string& scene_file,
                            const std::string& method, const std::string& host,
                            const controller::CostProfile& profile, const std::string& option) {
    if (run.send_us.empty())
        throw std::runtime_error(
            option +
            ": the frame has no send times (a 1989 host's counts from before send marks were "
            "counted, or a frame rendered untimed)");
    experiments::TimelineFrame frame;
    frame.title = fmt::format("scene {}, {} on {}, controller {}", scene_display_name(scene_file),
                              method, host, profile.name);
    frame.setup_end_us = run.setup_end_us;
    frame.send_times = send_times_source(run.period.has_value());
    frame.host_end_us = run.host_frame_ms * 1e3;
    return experiments::timeline_json(run.commands, run.send_us, frame, profile, run.buffer_bytes);
}

FramePipelines::FramePipelines(uint64_t buffer_bytes, bool keep_last_frame)
    : m_buffer(buffer_bytes), m_keep(keep_last_frame) {}

void FramePipelines::follow(const protocol::Command& c, int64_t send_ns,
                            const controller::Controller::CommandCost& cost, int64_t host_end_ns) {
    const double send_us = controller::from_ns(send_ns);
    if (std::holds_alternative<protocol::FrameBegin>(c)) {
        m_pipe.emplace(m_buffer);
        m_frame.clear();
        m_frame_send_us.clear();
    }
    if (!m_pipe) return;  // commands before the first frame
    m_pipe->push({send_us, cost.bytes, cost.bus_us, cost.exec_us});
    if (m_keep) {
        m_frame.submit(c);
        m_frame_send_us.push_back(send_us);
    }
    if (!std::holds_alternative<protocol::FrameEnd>(c)) return;
    const double host_end_us = controller::from_ns(host_end_ns);
    m_frames.push_back(m_pipe->finish(host_end_us));
    m_pipe.reset();
    std::swap(m_last_frame, m_frame);
    std::swap(m_last_send_us, m_frame_send_us);
    m_last_host_end_us = host_end_us;
}

std::string FramePipelines::last_frame_timeline(const std::string& stream,
                                                const std::string& output,
                                                const std::string& send_times,
                                                const controller::CostProfile& profile) const {
    if (m_frames.empty())
        throw std::runtime_error(stream + ": no complete frame; " + output + " not written");
    experiments::TimelineFrame frame;
    frame.title =
        fmt::format("{}, frame {}, controller {}", stream, m_frames.size() - 1, profile.name);
    frame.send_times = send_times;
    frame.host_end_us = m_last_host_end_us;
    return experiments::timeline_json(m_last_frame, m_last_send_us, frame, profile, m_buffer);
}

}  // namespace fb89::frontend
