// Host-side measurements: times of each stage (wall and CPU, kept apart) and counted
// operations. One registry feeds both the --stats JSON and the human summary.
//
// Counters are machine-independent (window samples, depth tests, spans...). Kernels keep
// their counts in locals inside hot loops and publish them here once per call.
#pragma once

#include <chrono>
#include <cstdint>
#include <ctime>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace fb89::host {

struct Timing {
    double wall_ms = 0;
    double cpu_ms = 0;
    Timing& operator+=(const Timing& o) {
        wall_ms += o.wall_ms;
        cpu_ms += o.cpu_ms;
        return *this;
    }
};

// Measures one interval of wall-clock and process CPU time. Its instructions do not depend on
// the times it reads, so that a counted run on a period host (period/) executes the same
// instructions however long it took (stats.cpp).
class Stopwatch {
  public:
    Stopwatch() { restart(); }
    void restart();
    Timing elapsed() const;

  private:
    timespec m_wall{}, m_cpu{};  // CLOCK_MONOTONIC, CLOCK_PROCESS_CPUTIME_ID
};

// Named counters in first-use order.
class Counters {
  public:
    void add(std::string_view name, uint64_t value);
    void set(std::string_view name, uint64_t value);
    uint64_t get(std::string_view name) const;  // 0 when never counted
    const std::vector<std::pair<std::string, uint64_t>>& items() const { return m_items; }
    // One "  name   value" line each, the names padded to the longest (24 at least) so the
    // values line up whatever the names.
    std::string lines() const;

  private:
    std::vector<std::pair<std::string, uint64_t>> m_items;
};

// DESIGN.md "Measuring": load, set-up, hidden-surface and end-to-end host times.
struct HostStats {
    Timing load;            // reading and building the scene
    Timing setup;           // projection, clipping, snapping
    Timing hidden_surface;  // the method's work, including handing commands to the buffer
    std::vector<Timing> hidden_surface_samples;  // every repeat; hidden_surface is their median
    Timing end_to_end;  // from reading the scene to the last command delivered
    Counters counters;

    nlohmann::json to_json() const;
    std::string summary() const;  // human-readable, several lines
};

// The median of repeated timings (wall and CPU each on their own).
Timing median(std::vector<Timing> samples);

}  // namespace fb89::host
