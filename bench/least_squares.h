// The least-squares slope of a line through points (x, y), which the benchmarks fit in
// several places: the growth ladder's log-log exponents (bench/growth/loglog_fit.h) and the
// soak's memory trend (bench/soak/rss_slope.h). NaN with fewer than two points or no
// spread in x.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace fb89::bench {

inline double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
        n += 1;
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    const double spread = n * sxx - sx * sx;
    if (n < 2 || spread <= 0) return NAN;
    return (n * sxy - sx * sy) / spread;
}

}  // namespace fb89::bench
