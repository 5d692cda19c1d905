#include "frontend/option_limits.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "frontend/common.h"
#include "host/trace/ray_tracer.h"

namespace fb89::frontend {

static_assert(limits::kReflections.hi == host::kMaxReflections);
static_assert(limits::kGridDensity.lo == host::kMinGridDensity &&
              limits::kGridDensity.hi == host::kMaxGridDensity);

namespace {

// A bound or a value as it reads: whole numbers without a point, others shortest.
std::string number_text(double v) {
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15)
        return fmt::format("{}", static_cast<int64_t>(v));
    return fmt::format("{:g}", v);
}

}  // namespace

std::optional<std::string> limit_problem(const OptionLimit& limit, double value,
                                         std::string_view shown) {
    const std::string text = shown.empty() ? number_text(value) : std::string(shown);
    if (limit.integer && std::isfinite(value) && value != std::floor(value))
        return text + " is not an integer";
    if (!(value >= limit.lo && value <= limit.hi))  // NaN too
        return fmt::format("{} is not in [{}, {}]", text, number_text(limit.lo),
                           number_text(limit.hi));
    return std::nullopt;
}

void check_limit(const OptionLimit& limit, double value, Spelling spelling,
                 std::string_view shown) {
    if (const auto problem = limit_problem(limit, value, shown))
        throw UsageError(fmt::format("{}: {}", limit.name(spelling), *problem));
}

CLI::Validator cli_check(const OptionLimit& limit) {
    const std::string description = fmt::format("{} in [{}, {}]", limit.integer ? "INT" : "FLOAT",
                                                number_text(limit.lo), number_text(limit.hi));
    return CLI::Validator(
        [limit](std::string& input) -> std::string {
            const char* begin = input.data();
            const char* end = begin + input.size();
            double value = 0;
            if (limit.integer) {
                int64_t whole = 0;
                const auto [at, ec] = std::from_chars(begin, end, whole);
                if (ec == std::errc::result_out_of_range && at == end)
                    value = input[0] == '-' ? -HUGE_VAL : HUGE_VAL;  // digits beyond int64
                else if (ec != std::errc() || at != end)
                    return input + " is not an integer";
                else
                    value = static_cast<double>(whole);
            } else {
                char* stop = nullptr;
                value = std::strtod(input.c_str(), &stop);
                if (input.empty() || stop != input.c_str() + input.size())
                    return input + " is not a number";
            }
            return limit_problem(limit, value, input).value_or("");
        },
        description);
}

}  // namespace fb89::frontend
