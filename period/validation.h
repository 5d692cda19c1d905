// Validating the modelled 1989 hosts against published figures (docs/HOST_COST_MODEL.md,
// "Validation"). Small kernels of our own (period/kernels: a LINPACK 100x100 solve, the
// register-add loop of Appel & Li's vmpup.c, FFBENCH's 2-D FFT) run on each emulated
// instruction set like fb89's host code; a host profile prices their timed phase (3), and the
// modelled speed is set beside what the period measured on real machines. period/validation.json
// holds the figures, each with its source, and is embedded at build time.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "period/emulator.h"
#include "period/host_cost.h"
#include "period/host_profile.h"

namespace fb89::period {

// period/validation.json as written (defined in the file cmake/embed_text.cmake generates).
std::string_view validation_json();

struct ValidationKernel {
    std::string name;       // "linpack"
    std::string program;    // "fb89_kernel_linpack" (find_kernel)
    double operations = 0;  // what the published unit counts in the timed phase
    std::string operation;  // "flop", "add"
    std::string unit;       // the unit its own speed is quoted in ("Mflop/s", "us/add")
    std::string description;
};

// How a modelled value must stand to a published one (error = modelled / published - 1).
enum class FigureCheck {
    Within,   // |error| <= tolerance: the figure is of the profiled machine
    AtMost,   // error <= +tolerance: the figure's machine is at least as fast per clock
    AtLeast,  // error >= -tolerance: the figure's machine is at most as fast per clock
};

struct PublishedFigure {
    std::string id, machine, benchmark, kernel;
    double value = 0;
    std::string unit;  // "Mflop/s", "kflop/s", "us/add" (any "us/<op>") or "s/pass" ("s/<op>")
    FigureCheck check = FigureCheck::Within;
    std::vector<std::string> profiles;  // host profiles it is compared with; none: context only
    // > 0: the figure's machine runs at this clock, and the profiles' cycle counts are timed
    // at it instead of at the profile's own clocks (the cycle tables are compared).
    double clock_mhz = 0;
    // The error band of its check: kValidationTolerance unless the figure states its own (the
    // Sun-4s' are held to 15%).
    double tolerance = 0;
    std::string cite;  // short, for tables ("Appel & Li, vmpup.c (1990)")
    std::string source, note;
};

// The same program's figures on two machines: their ratio, published, against the ratio of the
// two profiles' modelled figures, within `tolerance` (two errors of opposite signs compound in a
// ratio, so one that each figure passes can still misstate how much faster one machine is).
struct RatioCheck {
    std::string id;
    std::string numerator, denominator;  // figure ids, of one kernel, each naming one profile
    double tolerance = 0;
    std::string note;
};

struct ValidationData {
    std::vector<ValidationKernel> kernels;
    std::vector<PublishedFigure> figures;
    std::vector<RatioCheck> ratios;
    // Throw std::runtime_error for an unknown kernel or figure.
    const ValidationKernel& kernel(const std::string& name) const;
    const PublishedFigure& figure(const std::string& id) const;
};

// Throws std::runtime_error naming `origin` and the field that is missing or wrong.
ValidationData parse_validation(std::string_view json, const std::string& origin);
ValidationData builtin_validation();  // the embedded period/validation.json

// The modelled value, in a figure's unit, of a kernel whose timed phase took `seconds`:
// operations per second (Mflop/s, kflop/s), or microseconds or seconds per operation
// (us/..., s/...).
// Throws std::runtime_error for a unit it does not know.
double modelled_value(const ValidationKernel& kernel, const std::string& unit, double seconds);

// modelled / published - 1: +0.25 means the model is 25% faster in a rate, or 25% slower in a
// time per operation.
inline double relative_error(double modelled, double published) {
    return modelled / published - 1.0;
}

// The error band of the validation (docs/HOST_COST_MODEL.md, "Validation") where a figure states
// none: beyond it, the table is wrong.
inline constexpr double kValidationTolerance = 0.30;

// Whether an error passes a check within `tolerance`.
bool passes(FigureCheck check, double error, double tolerance = kValidationTolerance);
inline bool passes(const PublishedFigure& f, double error) {
    return passes(f.check, error, f.tolerance);
}
std::string_view check_name(FigureCheck check);  // "within", "at_most", "at_least"

// A published figure as one host profile models it: a row of `fb89 host-validate`'s table.
struct ModelledFigure {
    const PublishedFigure* figure = nullptr;
    std::string profile;
    double modelled = 0;  // in the figure's unit
};

// The same program on two profiled machines where validation.json names no ratio check: the
// ratio of the two modelled figures beside the published ratios over every pair of the two
// machines' figures (a machine may have several: other compilers, other systems). Only
// figures of the profiled machine itself at its own clocks (a "within" check, no clock of
// their own) take part; two machines a RatioCheck already pairs are left out.
struct UncheckedRatio {
    std::string kernel, numerator, denominator;  // the profiles
    double modelled = 0;
    double published_low = 0, published_high = 0;  // over `pairs` pairs of figures
    int pairs = 0;
};
std::vector<UncheckedRatio> unchecked_ratios(const std::vector<ModelledFigure>& rows,
                                             const std::vector<RatioCheck>& checks);

// One profiled machine's several published figures of one program (the same rows as
// unchecked_ratios takes): how far apart they lie, beside the one modelled figure.
struct FigureSpread {
    std::string kernel, profile, unit;
    double modelled = 0, low = 0, high = 0;
    int figures = 0;
};
std::vector<FigureSpread> figure_spreads(const std::vector<ModelledFigure>& rows);

// One kernel run on the emulator: its counts (the same for every host profile) and what it
// printed (its own check).
struct KernelRun {
    GuestCounts counts;
    std::string output;
    double wall_s = 0;
};
// Throws EmulatorError (also when the kernel's own check fails).
KernelRun run_validation_kernel(const EmulatorParts& parts, const ValidationKernel& kernel);

// The timed phase (3) of a kernel's counts, priced by a profile, in seconds: at the profile's
// clocks, or with `clock_mhz` > 0 at that clock for both the MPU and the FPU.
double timed_seconds(const GuestCounts& counts, const HostProfile& profile, double clock_mhz = 0);

}  // namespace fb89::period
