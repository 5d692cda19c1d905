// The growth benchmark's slopes: a least-squares line through (log x, log y), whose slope is
// the exponent b of y ~ x^b (1: linear growth, 2: quadratic). Points with x or y <= 0 are
// left out; fewer than two points give no slope (NaN).
#pragma once

#include <cmath>
#include <vector>

#include "bench/least_squares.h"

namespace fb89::growth {

inline double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
    std::vector<double> lx, ly;
    for (size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!(x[i] > 0 && y[i] > 0)) continue;
        lx.push_back(std::log(x[i]));
        ly.push_back(std::log(y[i]));
    }
    return bench::least_squares_slope(lx, ly);
}

}  // namespace fb89::growth
