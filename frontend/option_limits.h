// The ranges of the numeric options the front ends share, in one table. The command line's
// CLI11 checks (cli_check) and the Python module's keyword checks (check_limit, through
// python/options.h) read the same entries, so `fb89 render --repeat 0` and
// `fb89.render(..., repeat=0)` are refused by the same rule with the same words, the option
// named as each front end spells it ("--repeat: 0 is not in [1, 10000]", "repeat: ...").
// The requests of frontend/runs.h check their numbers against it again, whoever calls them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

namespace fb89::frontend {

// How an error names an option: as the command line spells it ("--reference-rays") or as
// the Python module's keyword ("reference_rays").
enum class Spelling { Option, Keyword };

struct OptionLimit {
    std::string_view option;   // the command line's name: "--repeat"
    std::string_view keyword;  // the Python module's: "repeat"
    double lo = 0, hi = 0;     // inclusive
    bool integer = true;       // a whole number; else any real number in [lo, hi]

    std::string_view name(Spelling s) const { return s == Spelling::Option ? option : keyword; }
};

namespace limits {
// render: frames rendered (the hidden-surface time is their median)
inline constexpr OptionLimit kRenderRepeat{"--repeat", "repeat", 1, 10000};
// experiment, sweep, calibrate, compare: interleaved timing rounds
inline constexpr OptionLimit kRepeat{"--repeat", "repeat", 1, 1000};
inline constexpr OptionLimit kJobs{"--jobs", "jobs", 1, 256};
inline constexpr OptionLimit kSteps{"--steps", "steps", 1, 200};
inline constexpr OptionLimit kTolerance{"--tolerance", "tolerance", 0, 100, false};
inline constexpr OptionLimit kPatches{"--patches", "patches", 0, 100000};
inline constexpr OptionLimit kReferenceRays{"--reference-rays", "reference_rays", 2, 16};
// raytrace and beam: mirror bounces (0 to host::kMaxReflections; beam with the grid: cells per
// face piece, host::kMinGridDensity to kMaxGridDensity; option_limits.cpp holds them equal)
inline constexpr OptionLimit kReflections{"--reflections", "reflections", 0, 16};
inline constexpr OptionLimit kGridDensity{"--grid-density", "grid_density", 0.01, 1000, false};
inline constexpr OptionLimit kApproxMin{"--approx-min", "approx_min", 0, 16384};
inline constexpr OptionLimit kApproxEps{"--approx-eps", "approx_eps", 0, 0.999, false};
inline constexpr OptionLimit kClasses{"--classes", "classes", 1, 1000};
// --size WxH: each side, in pixels
inline constexpr OptionLimit kImageSide{"--size", "size", 1, 16384};
// --buffer BYTES (or unbounded)
inline constexpr OptionLimit kBufferBytes{"--buffer", "buffer", 1, 1099511627776.0};  // 2^40
}  // namespace limits

// Why `value` is not a value of the option ("0 is not in [1, 10000]", "1.5 is not an
// integer"), or none when it is. `shown` is the value as given, for the message ("" : the
// number as it reads).
std::optional<std::string> limit_problem(const OptionLimit& limit, double value,
                                         std::string_view shown = "");

// Throws UsageError "<name>: <problem>" when limit_problem finds one.
void check_limit(const OptionLimit& limit, double value, Spelling spelling = Spelling::Option,
                 std::string_view shown = "");

// CLI11's words for a usage error said as fb89 says them, the option first: "--scale: Value 9
// not in range 0.125000 to 8.000000" -> "--scale: 9 is not in [0.125, 8]"; "--ff: hirarchical
// not in {flux,hierarchical}" -> "--ff: unknown choice 'hirarchical'; did you mean
// 'hierarchical'? (flux or hierarchical)"; "--method: At Most 1 required but received 2" ->
// "--method: given 2 times; give it once"; "--csv excludes --json" -> "--csv and --json
// exclude each other: give one of them"; and the like. Other text is returned as it is.
std::string usage_words(const std::string& cli11_text);

// The CLI11 check of an option with this limit: the text must read as a number of the kind
// ("1.5 is not an integer") and lie within it; CLI11 puts the option's name before the
// problem ("--repeat: 0 is not in [1, 10000]").
CLI::Validator cli_check(const OptionLimit& limit);

}  // namespace fb89::frontend
