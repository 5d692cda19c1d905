#include "frontend/option_limits.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "frontend/common.h"
#include "frontend/names.h"
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

// A bound as CLI11 prints it ("0.125000", "8.000000") as it reads ("0.125", "8").
std::string bound_text(const std::string& printed) {
    char* stop = nullptr;
    const double v = std::strtod(printed.c_str(), &stop);
    return stop == printed.c_str() ? printed : number_text(v);
}

// "{a,b,c}" (CLI11's set) as its names.
std::vector<std::string> set_names(const std::string& inside) {
    std::vector<std::string> names;
    std::stringstream in(inside);
    for (std::string name; std::getline(in, name, ',');)
        names.push_back(name);
    return names;
}

// The words after "<option>: " for CLI11's own problem with a value, or "" when they are not
// CLI11's.
std::string value_words(const std::string& problem) {
    std::smatch m;
    static const std::regex range(R"(Value (.*) not in range (\S+) to (\S+))");
    static const std::regex member(R"((.*) not in \{(.*)\})");
    static const std::regex at_most(R"(At Most (\d+) required but received (\d+))");
    static const std::regex at_least(R"(At least (\d+) required but received (\d+))");
    static const std::regex missing(R"((\d+) required (.*) missing)");
    if (std::regex_match(problem, m, range)) {
        if (std::strtod(m[3].str().c_str(), nullptr) > 1e300)  // no upper bound
            return fmt::format("{} is not {} or more", m[1].str(), bound_text(m[2]));
        return fmt::format("{} is not in [{}, {}]", m[1].str(), bound_text(m[2]), bound_text(m[3]));
    }
    if (std::regex_match(problem, m, member)) {
        const std::vector<std::string> names = set_names(m[2]);
        return fmt::format("unknown choice '{}'{} ({})", m[1].str(), nearest_hint(m[1], names),
                           name_list(names));
    }
    if (std::regex_match(problem, m, at_most))
        return m[1] == "1"
                   ? fmt::format("given {} times; give it once", m[2].str())
                   : fmt::format("given {} values; give at most {}", m[2].str(), m[1].str());
    if (std::regex_match(problem, m, at_least))
        return fmt::format("given {} values; give at least {}", m[2].str(), m[1].str());
    if (std::regex_match(problem, m, missing)) {
        const std::string type = m[2];
        const size_t set = type.find(":{");
        const std::string what =
            set != std::string::npos && type.back() == '}'
                ? "one of " + name_list(set_names(type.substr(set + 2, type.size() - set - 3)))
            : m[1] == "1" ? "a value"
                          : m[1].str() + " values";
        return "needs " + what + " after it";
    }
    return "";
}

}  // namespace

std::string usage_words(const std::string& text) {
    std::smatch m;
    static const std::regex of_option(R"(([^ :]+): (.*))");
    if (std::regex_match(text, m, of_option)) {
        const std::string words = value_words(m[2]);
        if (!words.empty()) return m[1].str() + ": " + words;
    }
    if (const std::string words = value_words(text); !words.empty()) return words;
    static const std::regex excludes(R"((\S+) excludes (\S+))");
    static const std::regex at_most_of(R"(Requires at most 1 options be given from \[(.*)\])");
    static const std::regex extras(R"(The following arguments? (?:was|were) not expected: (.*))");
    if (std::regex_match(text, m, excludes))
        return fmt::format("{} and {} exclude each other: give one of them", m[1].str(),
                           m[2].str());
    if (std::regex_match(text, m, at_most_of)) return "give at most one of " + m[1].str();
    if (std::regex_match(text, m, extras))
        return "arguments the command does not take: " + m[1].str();
    return text;
}

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
