// Work done in a long loop, for progress reports: the loop calls the observer now and then
// with how much of its work is done, in its own units (rows, pairs), out of a total. The
// observer decides what to show and how often; an empty one costs one branch per call.
#pragma once

#include <cstdint>
#include <functional>

namespace fb89::host {

using WorkObserver = std::function<void(uint64_t done, uint64_t total)>;

// Of the n(n-1)/2 unordered pairs of n items, those whose first item is below `rows`: the
// work done once a loop over pairs (i, j > i) has finished row rows - 1.
constexpr uint64_t pairs_before(uint64_t n, uint64_t rows) {
    return rows * n - rows * (rows + 1) / 2;
}

}  // namespace fb89::host
