// The growth benchmark's results: every run as CSV, the fitted log-log slope of each time and
// of memory against faces per method (bench/growth/loglog_fit.h) as CSV, and both as
// markdown with the verdict on memory: does any method's peak grow faster than its input?
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bench/growth/growth_run.h"

namespace fb89::growth {

// One quantity's slope against faces for one method and source: over every rung, and over
// the top rungs only (the largest three, where fixed costs no longer hide the growth).
struct Slope {
    std::string source, method, quantity;
    double all = 0, top = 0;
    int points_all = 0, points_top = 0;
};

// Quantities: setup_ms, hidden_surface_ms, total_ms (CPU), peak_rss, peak_above_baseline
// (peak less `baseline_rss`, what a child starts with) and scene_bytes (the input).
std::vector<Slope> fit_slopes(const std::vector<Measurement>& runs, uint64_t baseline_rss);

// A method's memory grows faster than its input when, over the top rungs, the slope of its
// peak above the baseline exceeds the input's by more than this (timing-free, but the
// allocator's rounding and the frame's fixed buffers make small rungs noisy).
inline constexpr double kMemorySlopeMargin = 0.1;
struct MemoryVerdict {
    std::string method;
    double memory_slope = 0, input_slope = 0;
    bool faster_than_input = false;
};
std::vector<MemoryVerdict> memory_verdicts(const std::vector<Slope>& slopes);

std::string runs_csv(const std::vector<Measurement>& runs, uint64_t baseline_rss);
std::string slopes_csv(const std::vector<Slope>& slopes);
// The tables for docs: runs (faces, times, memory, input) and slopes, and the verdicts.
std::string markdown(const std::vector<Measurement>& runs, const std::vector<Slope>& slopes,
                     uint64_t baseline_rss);

}  // namespace fb89::growth
