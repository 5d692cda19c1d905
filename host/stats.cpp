#include "host/stats.h"

#include <time.h>

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace fb89::host {

namespace {
timespec now(clockid_t clock) {
    timespec ts{};
    clock_gettime(clock, &ts);
    return ts;
}

// The milliseconds from `from` to `to`, converted to double from two 32-bit differences (whole
// seconds, under 68 years; nanoseconds). On the 32-bit period hosts a 64-bit integer's
// conversion is a library routine whose path depends on the value -- on the MC68020 one more
// `fadd` when bit 31 of the low word is set -- which made a counted run's instructions depend
// on how long the emulation took (by one, now and then).
double ms_between(const timespec& from, const timespec& to) {
    const auto seconds = static_cast<int32_t>(to.tv_sec - from.tv_sec);
    const auto nanoseconds = static_cast<int32_t>(to.tv_nsec - from.tv_nsec);
    return static_cast<double>(seconds) * 1e3 + static_cast<double>(nanoseconds) * 1e-6;
}

nlohmann::json timing_json(const Timing& t) {
    return {{"wall_ms", t.wall_ms}, {"cpu_ms", t.cpu_ms}};
}
}  // namespace

void Stopwatch::restart() {
    m_wall = now(CLOCK_MONOTONIC);
    m_cpu = now(CLOCK_PROCESS_CPUTIME_ID);
}

Timing Stopwatch::elapsed() const {
    const timespec wall = now(CLOCK_MONOTONIC), cpu = now(CLOCK_PROCESS_CPUTIME_ID);
    return {ms_between(m_wall, wall), ms_between(m_cpu, cpu)};
}

void Counters::add(std::string_view name, uint64_t value) {
    auto it = std::find_if(m_items.begin(), m_items.end(),
                           [&](const auto& item) { return item.first == name; });
    if (it == m_items.end())
        m_items.emplace_back(std::string(name), value);
    else
        it->second += value;
}

void Counters::set(std::string_view name, uint64_t value) {
    auto it = std::find_if(m_items.begin(), m_items.end(),
                           [&](const auto& item) { return item.first == name; });
    if (it == m_items.end())
        m_items.emplace_back(std::string(name), value);
    else
        it->second = value;
}

uint64_t Counters::get(std::string_view name) const {
    for (const auto& [key, value] : m_items)
        if (key == name) return value;
    return 0;
}

Timing median(std::vector<Timing> samples) {
    if (samples.empty()) return {};
    auto mid = [&](auto member) {
        std::vector<double> v;
        for (const auto& t : samples)
            v.push_back(t.*member);
        std::sort(v.begin(), v.end());
        size_t n = v.size();
        return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    };
    return {mid(&Timing::wall_ms), mid(&Timing::cpu_ms)};
}

nlohmann::json HostStats::to_json() const {
    nlohmann::json counts = nlohmann::json::object();
    for (const auto& [name, value] : counters.items())
        counts[name] = value;
    nlohmann::json samples = nlohmann::json::array();
    for (const auto& t : hidden_surface_samples)
        samples.push_back(timing_json(t));
    return {{"times",
             {{"load", timing_json(load)},
              {"setup", timing_json(setup)},
              {"hidden_surface", timing_json(hidden_surface)},
              {"hidden_surface_samples", samples},
              {"end_to_end", timing_json(end_to_end)}}},
            {"counters", counts}};
}

std::string HostStats::summary() const {
    std::string out = "host (wall / CPU):\n";
    auto line = [&](const char* name, const Timing& t) {
        out += fmt::format("  {:<16} {:>10.3f} ms {:>10.3f} ms\n", name, t.wall_ms, t.cpu_ms);
    };
    line("load", load);
    line("set-up", setup);
    line(hidden_surface_samples.size() > 1 ? "hidden-surface*" : "hidden-surface", hidden_surface);
    line("end to end", end_to_end);
    if (hidden_surface_samples.size() > 1)
        out += fmt::format("  * median of {} repeats; end to end uses it\n",
                           hidden_surface_samples.size());
    out += "host counted operations:\n";
    out += counters.lines();
    return out;
}

std::string Counters::lines() const {
    size_t width = 24;
    for (const auto& [name, value] : m_items)
        width = std::max(width, name.size());
    std::string out;
    for (const auto& [name, value] : m_items)
        out += fmt::format("  {:<{}} {:>14}\n", name, width, value);
    return out;
}

}  // namespace fb89::host
