// fb89_kernel_fft2d [PASSES]: the work of John Walker's FFBENCH (fourmilab.ch, 1989), a
// benchmark the period ran unchanged on Sun-3s and Sun-4s: a 256 x 256 array of complex
// doubles transformed forward and back by a two-dimensional FFT, 20 passes, the whole run
// timed. Its published times are therefore a ratio between machines of one program
// (docs/HOST_COST_MODEL.md, "Validation"). This kernel does the same work with its own
// code organised as FFBENCH's transform is (below), with the twiddle factors by the sine
// recurrence (one sin() a stage, not one a butterfly). Phase 3 holds PASSES forward + inverse pairs
// (default 1); the array is filled before it and checked after it. Prints the largest error and
// exits 1 if the round trip does not give the input back.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "period/guest/phase_marker.h"

namespace {

constexpr int kSide = 256;
constexpr double kPi = 3.14159265358979323846;

// The multidimensional in-place FFT as FFBENCH's transform organises it (the
// Danielson-Lanczos method over a flat array, one dimension after another, the bit
// reversal of each dimension by swapping whole strided lines, 1-based indices): the loop
// nest decides how much index arithmetic each butterfly costs, so it is kept. `v` holds
// complex values interleaved (re, im) from v[1]; dims[1..ndim] are the sizes; sign = +1
// forward, -1 inverse (unscaled).
void transform(double* v, const int* dims, int ndim, int sign) {
    int total = 1;
    for (int d = 1; d <= ndim; ++d)
        total *= dims[d];
    int inner = 1;  // values in the dimensions already done
    for (int d = ndim; d >= 1; --d) {
        const int n = dims[d];
        const int outer = total / (n * inner);
        const int step = inner << 1;    // one element of this dimension, in doubles
        const int line = step * n;      // one whole line of it
        const int span = line * outer;  // the whole array
        // bit reversal of this dimension
        int reversed = 1;
        for (int i = 1; i <= line; i += step) {
            if (i < reversed) {
                for (int j = i; j <= i + step - 2; j += 2)
                    for (int k = j; k <= span; k += line) {
                        const int kr = reversed + k - i;
                        double t = v[k];
                        v[k] = v[kr], v[kr] = t;
                        t = v[k + 1];
                        v[k + 1] = v[kr + 1], v[kr + 1] = t;
                    }
            }
            int bit = line >> 1;
            while (bit >= step && reversed > bit) {
                reversed -= bit;
                bit >>= 1;
            }
            reversed += bit;
        }
        // butterflies, twiddle factors by the sine recurrence
        for (int half = step; half < line; half <<= 1) {
            const int pair = half << 1;
            const double theta = sign * (2 * kPi) / (pair / step);
            const double s = std::sin(0.5 * theta);
            const double wpr = -2.0 * s * s, wpi = std::sin(theta);
            double wr = 1.0, wi = 0.0;
            for (int m = 1; m <= half; m += step) {
                for (int j = m; j <= m + step - 2; j += 2)
                    for (int k = j; k <= span; k += pair) {
                        const int q = k + half;
                        const double tr = wr * v[q] - wi * v[q + 1];
                        const double ti = wr * v[q + 1] + wi * v[q];
                        v[q] = v[k] - tr;
                        v[q + 1] = v[k + 1] - ti;
                        v[k] += tr;
                        v[k + 1] += ti;
                    }
                const double t = wr;
                wr = t * wpr - wi * wpi + wr;
                wi = wi * wpr + t * wpi + wi;
            }
        }
        inner *= n;
    }
}

void fft2d(double* a, int sign) {
    static const int dims[3] = {0, kSide, kSide};
    transform(a - 1, dims, 2, sign);
}

}  // namespace

int main(int argc, char** argv) {
    using fb89::period::mark;
    using fb89::period::Phase;
    const int passes = argc > 1 ? std::atoi(argv[1]) : 1;
    if (passes < 1 || passes > 100) return 2;

    mark(Phase::Load);
    // FFBENCH's test image: a raised square in the middle of a flat field
    std::vector<double> a(2 * kSide * kSide, 0.0);
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x)
            if (x >= kSide / 4 && x < 3 * kSide / 4 && y >= kSide / 4 && y < 3 * kSide / 4)
                a[2 * (y * kSide + x)] = 128.0;
    const std::vector<double> input = a;

    mark(Phase::HiddenSurface);
    for (int p = 0; p < passes; ++p) {
        fft2d(a.data(), 1);
        fft2d(a.data(), -1);
        const double scale = 1.0 / (kSide * kSide);
        for (double& v : a)
            v *= scale;
    }

    mark(Phase::Output);
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i)
        worst = std::fmax(worst, std::fabs(a[i] - input[i]));
    std::printf("fft2d %dx%d passes=%d max_error=%.3g\n", kSide, kSide, passes, worst);
    return worst < 1e-9 ? 0 : 1;
}
