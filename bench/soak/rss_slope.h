// The soak's memory trend: the least-squares slope of the resident set against the cycle,
// in KiB per cycle, over the samples taken in the second half of the cycles (the first
// half warms up the allocator and the caches). NaN with fewer than two samples there.
//
// For the soak's own process the fit is over the resident set after malloc_trim(0): the
// free heap glibc keeps swings by up to 20 MiB from one round of scenes to the next (where
// the frames and grids of the last large scene happened to land), which would hide a leak
// of a few KiB a cycle; leaked memory stays resident after the trim. The bytes the heap
// holds (mallinfo2) are fitted too, in bytes per cycle: the finest leak measure there is.
// Header-only, so tests/bench checks it without the soak's sources.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "bench/least_squares.h"

namespace fb89::soak {

struct ResourceSample {
    int cycle = 0;             // cycles completed when sampled
    uint64_t rss_kib = 0;      // VmRSS as read
    int fds = 0;               // open descriptors
    uint64_t trimmed_kib = 0;  // this process: VmRSS after malloc_trim(0); 0: not taken
    uint64_t heap_bytes = 0;   // this process: bytes allocated and not freed (mallinfo2)
    uint64_t fitted_kib() const { return trimmed_kib ? trimmed_kib : rss_kib; }
};

// The least-squares slope of value(sample) against the cycle over the second half.
template <class Value>
double second_half_slope(const std::vector<ResourceSample>& samples, int cycles, Value value) {
    std::vector<double> x, y;
    for (const ResourceSample& s : samples) {
        if (2 * s.cycle < cycles) continue;  // warm-up
        x.push_back(s.cycle);
        y.push_back(static_cast<double>(value(s)));
    }
    return bench::least_squares_slope(x, y);
}

inline double rss_slope_kib_per_cycle(const std::vector<ResourceSample>& samples, int cycles) {
    return second_half_slope(samples, cycles,
                             [](const ResourceSample& s) { return s.fitted_kib(); });
}

inline double heap_slope_bytes_per_cycle(const std::vector<ResourceSample>& samples, int cycles) {
    return second_half_slope(samples, cycles, [](const ResourceSample& s) { return s.heap_bytes; });
}

}  // namespace fb89::soak
