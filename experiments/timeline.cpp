#include "experiments/timeline.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "experiments/render_job.h"

namespace fb89::experiments {
namespace {

constexpr int kPid = 1;
enum Lane { kHost = 1, kBus = 2, kController = 3 };

// The events one by one, each dumped compactly on its own line: a frame of a million
// commands is never one JSON value in memory.
class TraceWriter {
  public:
    void add(const nlohmann::json& event) {
        m_text += m_first ? "\n" : ",\n";
        m_first = false;
        m_text += event.dump();
    }
    void slice(Lane lane, const char* name, double start_us, double end_us,
               nlohmann::json args = nullptr) {
        nlohmann::json e = {{"name", name}, {"ph", "X"},      {"pid", kPid},
                            {"tid", lane},  {"ts", start_us}, {"dur", end_us - start_us}};
        if (!args.is_null()) e["args"] = std::move(args);
        add(e);
    }
    std::string finish(const nlohmann::json& other) {
        return "{\"displayTimeUnit\": \"ms\",\n\"otherData\": " + other.dump() +
               ",\n\"traceEvents\": [" + m_text + "\n]}\n";
    }

  private:
    std::string m_text;
    bool m_first = true;
};

}  // namespace

std::string timeline_json(const protocol::MemoryBuffer& commands,
                          const std::vector<double>& send_us, const TimelineFrame& frame,
                          const controller::CostProfile& profile, uint64_t buffer_bytes,
                          controller::PipelineFigures* figures) {
    std::vector<controller::CommandTiming> timings;
    const controller::PipelineFigures f = pipeline_figures(
        commands, send_us, frame.host_end_us, profile, buffer_bytes, nullptr, &timings);
    if (figures) *figures = f;
    const auto& all = commands.commands();

    TraceWriter w;
    w.add(
        {{"name", "process_name"}, {"ph", "M"}, {"pid", kPid}, {"args", {{"name", frame.title}}}});
    for (const auto& [lane, name] :
         {std::pair{kHost, "host"}, std::pair{kBus, "bus"}, std::pair{kController, "controller"}}) {
        w.add({{"name", "thread_name"},
               {"ph", "M"},
               {"pid", kPid},
               {"tid", lane},
               {"args", {{"name", name}}}});
        w.add({{"name", "thread_sort_index"},
               {"ph", "M"},
               {"pid", kPid},
               {"tid", lane},
               {"args", {{"sort_index", static_cast<int>(lane)}}}});
    }

    // the host: its phases (hidden-surface moved by every stall), its stalls, its sends
    const double host_end = f.host_us + f.host_stalled_us;
    if (!frame.send_times.empty()) {
        const double setup_end = std::min(frame.setup_end_us, host_end);
        w.slice(kHost, "set-up", 0, setup_end);
        w.slice(kHost, "hidden-surface", setup_end, host_end);
    }
    for (std::size_t i = 0; i < all.size(); ++i) {
        const controller::CommandTiming& t = timings[i];
        if (t.bus_start_us > t.sent_us)
            w.slice(kHost, "stall", t.sent_us, t.bus_start_us, {{"command", i}});
        w.add({{"name", protocol::to_string(protocol::opcode_of(all[i]))},
               {"ph", "i"},
               {"s", "t"},
               {"pid", kPid},
               {"tid", kHost},
               {"ts", t.sent_us}});
    }
    // the bus and the controller, command by command
    for (std::size_t i = 0; i < all.size(); ++i) {
        const controller::CommandTiming& t = timings[i];
        if (t.bytes == 0) continue;  // not sent
        const char* name = protocol::to_string(protocol::opcode_of(all[i]));
        w.slice(kBus, name, t.bus_start_us, t.arrived_us);
        w.slice(kController, name, t.exec_start_us, t.done_us,
                {{"command", i}, {"bytes", t.bytes}});
    }
    // the buffer's fill: a command's bytes come in as it starts across the bus and leave
    // when it is done; both sequences are in time order, so merge them
    std::size_t in = 0, out = 0;
    uint64_t held = 0;
    const auto counter = [&](double ts) {
        w.add({{"name", "command buffer"},
               {"ph", "C"},
               {"pid", kPid},
               {"ts", ts},
               {"args", {{"bytes", held}}}});
    };
    counter(0);
    while (out < all.size()) {
        while (in < all.size() && timings[in].bytes == 0)
            ++in;
        while (out < all.size() && timings[out].bytes == 0)
            ++out;
        if (out == all.size()) break;
        const bool arrive = in < all.size() && timings[in].bus_start_us < timings[out].done_us;
        const double ts = arrive ? timings[in].bus_start_us : timings[out].done_us;
        // every change at this instant, then one sample
        while (in < all.size() && timings[in].bytes != 0 && timings[in].bus_start_us == ts)
            held += timings[in++].bytes;
        while (out < all.size() && timings[out].bytes != 0 && timings[out].done_us == ts)
            held -= timings[out++].bytes;
        counter(ts);
    }

    nlohmann::json other = pipeline_figures_json(f);
    other.update({{"title", frame.title},
                  {"send_times",
                   frame.send_times.empty() ? "none: every command ready at 0" : frame.send_times},
                  {"buffer_bytes", controller::command_buffer_json(buffer_bytes)},
                  {"commands", all.size()}});
    return w.finish(other);
}

nlohmann::json pipeline_figures_json(const controller::PipelineFigures& p) {
    return {{"frame_ms", p.frame_us / 1e3},
            {"host_ms", p.host_us / 1e3},
            {"host_stalled_ms", p.host_stalled_us / 1e3},
            {"host_stalls", p.stalls},
            {"bus_busy_ms", p.bus_busy_us / 1e3},
            {"controller_busy_ms", p.controller_busy_us / 1e3},
            {"controller_idle_ms", p.controller_idle_us / 1e3},
            {"buffer_high_water_bytes", p.high_water_bytes},
            {"buffer_bytes", controller::command_buffer_json(p.buffer_bytes)},
            {"host_utilization", p.host_utilization()},
            {"controller_utilization", p.controller_utilization()}};
}

}  // namespace fb89::experiments
