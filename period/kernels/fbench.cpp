// fb89_kernel_fbench [ITERATIONS]: the work of John Walker's FBENCH (fourmilab.ch, 1980/1989),
// the floating-point benchmark whose published table times the Sun-4/260, the Sun-3/260 and the
// SPARCstation 2 on one program (docs/HOST_COST_MODEL.md, "Validation"). It traces rays through
// a four-surface achromatic telescope objective (Wyld's example in Amateur Telescope Making,
// vol. 3), in the D line (a marginal and a paraxial ray) and the C and F lines (marginal), and
// works out the aberrations; FBENCH times 1000 such iterations.
//
// This is the benchmark built with INTRIG, the column fb89 validates against: sine, cosine,
// tangent, arctangent, arcsine and square root are the program's own (polynomial and rational
// approximations after range reduction, and a Newton-Raphson square root), so the time is the
// machine's arithmetic and not its maths library, and no fsqrt is executed. The code is fb89's
// own, organised as FBENCH's is -- the same approximations of the same degrees, the same calls
// per surface and per iteration -- since that decides how many operations an iteration costs.
//
// Phase 3 holds ITERATIONS iterations (default 100); the result of the last is checked against
// FBENCH's reference values (its 11 printed decimals) after it, exit 1 on a mismatch.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "period/guest/phase_marker.h"

namespace {

constexpr double kPi = 3.1415926535897932;
constexpr double kTwoPi = kPi * 2.0, kHalfPi = kPi / 2.0, kQuarterPi = kPi / 4.0;
constexpr double kFourOverPi = 4.0 / kPi;

// ---- the program's own elementary functions (FBENCH's INTRIG set) ----------------------

// Truncation toward zero through a long, as the benchmark's aint().
double truncate(double x) {
    return static_cast<double>(static_cast<long>(x));
}

// Sine: reduced to [0, pi/2], then an odd polynomial of degree 15 in x * 4/pi below pi/4, or an
// even one of degree 14 in (pi/2 - x) * 4/pi above it.
double i_sin(double x) {
    bool negative = x < 0.0;
    if (negative) x = -x;
    if (x > kTwoPi) x -= truncate(x / kTwoPi) * kTwoPi;
    if (x > kPi) {
        x -= kPi;
        negative = !negative;
    }
    if (x > kHalfPi) x = kPi - x;
    double r;
    // the polynomials in Horner form, one coefficient a line
    // clang-format off
    if (x < kQuarterPi) {
        const double y = x * kFourOverPi, z = y * y;
        r = y * (((((((-0.202253129293E-13 * z
                       + 0.69481520350522E-11) * z
                      - 0.17572474176170806E-8) * z
                     + 0.313361688917325348E-6) * z
                    - 0.365762041821464001E-4) * z
                   + 0.249039457019271628E-2) * z
                  - 0.0807455121882807815) * z
                 + 0.785398163397448310);
    } else {
        const double y = (kHalfPi - x) * kFourOverPi, z = y * y;
        r = ((((((-0.38577620372E-12 * z
                  + 0.11500497024263E-9) * z
                 - 0.2461136382637005E-7) * z
                + 0.359086044588581953E-5) * z
               - 0.325991886926687550E-3) * z
              + 0.0158543442438154109) * z
             - 0.308425137534042452) * z
            + 1.0;
    }
    // clang-format on
    return negative ? -r : r;
}

double i_cos(double x) {
    if (x < 0.0) x = -x;
    if (x > kTwoPi) x -= truncate(x / kTwoPi) * kTwoPi;
    return i_sin(x + kHalfPi);
}

double i_tan(double x) {
    return i_sin(x) / i_cos(x);
}

// Square root: a rational first guess, then Newton-Raphson steps until the correction stops
// changing (at most 50).
double i_sqrt(double x) {
    if (x == 0.0) return 0.0;
    if (x < 0.0) {
        std::fprintf(stderr, "fbench: square root of %g\n", x);
        std::exit(1);
    }
    double y = (0.154116 + 1.893872 * x) / (1.0 + 1.047988 * x);
    double step = (y - x / y) / 2.0, previous = 0.0;
    for (int n = 50; step != previous && n--;) {
        y -= step;
        previous = step;
        step = (y - x / y) / 2.0;
    }
    return y;
}

// Arctangent: the argument brought below 1/4 by atan(1/x) = pi/2 - atan(x) and a table of
// atan(k/2), then a rational function of degree 10 over 8 in x.
double i_atan(double x) {
    static const double kAtanHalves[] = {0.0,
                                         0.4636476090008061165,
                                         0.7853981633974483094,
                                         0.98279372324732906714,
                                         1.1071487177940905022,
                                         1.1902899496825317322,
                                         1.2490457723982544262,
                                         1.2924966677897852673,
                                         1.3258176636680324644};
    const bool negative = x < 0.0;
    if (negative) x = -x;
    bool inverted = false;
    int k = 0;
    if (x >= 4.0) {
        inverted = true;
        x = 1.0 / x;
    } else if (x >= 0.25) {
        k = static_cast<int>(truncate(x / 0.5));
        const double z = k * 0.5;
        x = (x - z) / (x * z + 1);
    }
    const double z = x * x;
    const double den =
        ((((893025.0 * z + 49116375.0) * z + 425675250.0) * z + 1277025750.0) * z + 1550674125.0) *
            z +
        654729075.0;
    const double num =
        (((13852575.0 * z + 216602100.0) * z + 891080190.0) * z + 1332431100.0) * z + 654729075.0;
    double a = (num / den) * x + kAtanHalves[k];
    if (inverted) a = kHalfPi - a;
    return negative ? -a : a;
}

double i_atan2(double y, double x) {
    if (x == 0.0) return y == 0.0 ? 0.0 : y > 0 ? kHalfPi : -kHalfPi;
    double t = i_atan(y / x);
    if (x < 0.0) t += y >= 0.0 ? kPi : -kPi;
    return t;
}

double i_asin(double x) {
    if ((x < 0.0 ? -x : x) > 1.0) {
        std::fprintf(stderr, "fbench: arcsine of %g\n", x);
        std::exit(1);
    }
    return i_atan2(x, i_sqrt(1 - x * x));
}

// ---- the ray trace ---------------------------------------------------------------------

// One surface of the objective: radius of curvature (0: plane), refractive index and
// dispersion (Abbe number) of the glass behind it, and the distance to the next surface.
struct Surface {
    double radius, index, dispersion, thickness;
};

// Wyld's 4-inch achromat, as FBENCH's test case.
const Surface kObjective[4] = {
    {27.05, 1.5137, 63.6, 0.52},
    {-16.68, 1, 0, 0.138},
    {-16.68, 1.6164, 36.7, 0.38},
    {-78.1, 1, 0, 0},
};

// Fraunhofer lines, angstroms: C (red hydrogen), D (sodium), F (blue hydrogen).
constexpr double kLineC = 6562.816, kLineD = 5895.944, kLineF = 4861.344;

struct Ray {
    double object_distance, ray_height, slope;
};

// The sine of the angle of incidence at a curved surface: from the ray's height for a ray
// parallel to the axis, else from the object distance and the slope (its sine, or the slope
// itself in the paraxial approximation).
double incidence_sine(Ray& r, double radius, bool paraxial) {
    if (r.object_distance == 0.0) {
        r.slope = 0.0;
        return r.ray_height / radius;
    }
    return ((r.object_distance - radius) / radius) * (paraxial ? r.slope : i_sin(r.slope));
}

// Refraction at one surface between media of indices `from` and `to`, by the paraxial
// approximations or by the full trigonometric trace (FBENCH's transit_surface).
void transit(Ray& r, double radius, double from, double to, bool paraxial) {
    if (paraxial) {
        if (radius != 0.0) {
            const double incidence_sin = incidence_sine(r, radius, true);
            const double refraction_sin = (from / to) * incidence_sin;
            const double old_slope = r.slope;
            r.slope = r.slope + incidence_sin - refraction_sin;
            if (r.object_distance != 0.0) r.ray_height = r.object_distance * old_slope;
            r.object_distance = r.ray_height / r.slope;
            return;
        }
        r.object_distance = r.object_distance * (to / from);
        r.slope = r.slope * (from / to);
        return;
    }
    if (radius != 0.0) {
        const double incidence_sin = incidence_sine(r, radius, false);
        const double incidence = i_asin(incidence_sin);
        const double refraction_sin = (from / to) * incidence_sin;
        const double old_slope = r.slope;
        r.slope = r.slope + incidence - i_asin(refraction_sin);
        double sagitta = i_sin((old_slope + incidence) / 2.0);
        sagitta = 2.0 * radius * sagitta * sagitta;
        r.object_distance =
            ((radius * i_sin(old_slope + incidence)) * (1.0 / i_tan(r.slope))) + sagitta;
        return;
    }
    const double refraction = -i_asin((from / to) * i_sin(r.slope));
    r.object_distance = r.object_distance * ((to * i_cos(-refraction)) / (from * i_cos(r.slope)));
    r.slope = -refraction;
}

// A ray of height `height` parallel to the axis, traced through every surface in the light of
// wavelength `line` (FBENCH's trace_line).
Ray trace_line(const Surface* s, int surfaces, double line, double height, bool paraxial) {
    Ray r{0.0, height, 0.0};
    double from = 1.0;
    for (int i = 0; i < surfaces; i++) {
        double to = s[i].index;
        if (to > 1.0)
            to += ((kLineD - line) / (kLineC - kLineF)) * ((s[i].index - 1.0) / s[i].dispersion);
        transit(r, s[i].radius, from, to, paraxial);
        from = to;
        if (i < surfaces - 1) r.object_distance -= s[i].thickness;
    }
    return r;
}

struct Aberrations {
    Ray marginal, paraxial;
    double spherical, sine_condition, chromatic, max_spherical;
};

// One iteration of the benchmark.
Aberrations iterate(const Surface* s, int surfaces, double aperture) {
    Aberrations a;
    a.marginal = trace_line(s, surfaces, kLineD, aperture / 2.0, false);
    a.paraxial = trace_line(s, surfaces, kLineD, aperture / 2.0, true);
    const double c = trace_line(s, surfaces, kLineC, aperture / 2.0, false).object_distance;
    const double f = trace_line(s, surfaces, kLineF, aperture / 2.0, false).object_distance;
    a.spherical = a.paraxial.object_distance - a.marginal.object_distance;
    a.sine_condition = 1.0 - (a.paraxial.object_distance * a.paraxial.slope) /
                                 (i_sin(a.marginal.slope) * a.marginal.object_distance);
    a.chromatic = f - c;
    const double m = i_sin(a.marginal.slope);
    a.max_spherical = 0.0000926 / (m * m);
    return a;
}

}  // namespace

int main(int argc, char** argv) {
    using fb89::period::mark;
    using fb89::period::Phase;
    const int iterations = argc > 1 ? std::atoi(argv[1]) : 100;
    if (iterations < 1 || iterations > 100000) return 2;

    mark(Phase::Load);
    // the lens through a volatile copy, so that no compiler folds the trace into constants
    static Surface lens[4];
    for (int i = 0; i < 4; i++) {
        const volatile double* from = &kObjective[i].radius;
        lens[i] = {from[0], from[1], from[2], from[3]};
    }
    volatile double aperture = 4.0;

    mark(Phase::HiddenSurface);
    Aberrations a{};
    for (int i = 0; i < iterations; i++)
        a = iterate(lens, 4, aperture);

    mark(Phase::Output);
    // FBENCH's reference results, as it prints them (11 decimals)
    const double expected[] = {47.09479120920, 0.04178472683, 47.08372160249, 0.04177864821,
                               -0.01106960671, 0.00008954761, 0.00448229032,  0.05306749907};
    const double got[] = {a.marginal.object_distance,
                          a.marginal.slope,
                          a.paraxial.object_distance,
                          a.paraxial.slope,
                          a.spherical,
                          a.sine_condition,
                          a.chromatic,
                          a.max_spherical};
    int wrong = 0;
    for (int i = 0; i < 8; i++)
        if (std::fabs(got[i] - expected[i]) > 0.6e-11) ++wrong;
    std::printf("fbench iterations=%d marginal=%.11f %.11f paraxial=%.11f %.11f wrong=%d\n",
                iterations, got[0], got[1], got[2], got[3], wrong);
    return wrong == 0 ? 0 : 1;
}
