// The growth benchmark's slopes: a least-squares line through (log x, log y), whose slope is
// the exponent b of y ~ x^b (1: linear growth, 2: quadratic). Points with x or y <= 0 are
// left out; fewer than two points give no slope (NaN).
#pragma once

#include <cmath>
#include <vector>

namespace fb89::growth {

inline double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < x.size() && i < y.size(); ++i) {
        if (!(x[i] > 0 && y[i] > 0)) continue;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        n += 1;
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    const double spread = n * sxx - sx * sx;
    if (n < 2 || spread <= 0) return NAN;
    return (n * sxy - sx * sy) / spread;
}

}  // namespace fb89::growth
