#include "frontend/common.h"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <regex>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "controller_sim/profile.h"
#include "host/trace/kernel_level.h"
#include "protocol/output_file.h"

namespace fb89::frontend {

std::optional<uint64_t> parse_buffer_option(const std::string& text, const std::string& profile,
                                            Spelling spelling) {
    if (text.empty()) return std::nullopt;
    if (text == "unbounded") return controller::kUnboundedBuffer;
    const std::string_view name = limits::kBufferBytes.name(spelling);
    uint64_t bytes = 0;
    const char* end = text.data() + text.size();
    const auto [at, ec] = std::from_chars(text.data(), end, bytes);
    if (ec != std::errc() || at != end ||
        limit_problem(limits::kBufferBytes, static_cast<double>(bytes)))
        throw UsageError(
            fmt::format("{}: '{}': a whole number of bytes (1 to 2^40) or unbounded", name, text));
    const uint32_t largest = controller::load_profile(profile).largest_tiling_bytes();
    if (largest > bytes)
        throw UsageError(fmt::format("{}: {} bytes cannot hold a command of {} ({} bytes)", name,
                                     bytes, profile, largest));
    return bytes;
}

controller::CostProfile profile_option(const std::string& name, std::string_view option) {
    try {
        return controller::load_profile(name);
    } catch (const std::runtime_error& e) {
        throw UsageError(fmt::format("{}: {}", option, e.what()));
    }
}

ImageSize parse_size(const std::string& text, Spelling spelling) {
    static const std::regex pattern(R"((\d+)x(\d+))");
    const OptionLimit& side_limit = limits::kImageSide;
    const std::string_view name = side_limit.name(spelling);
    std::smatch m;
    if (!std::regex_match(text, m, pattern))
        throw UsageError(fmt::format(
            "{}: expected WxH such as 1024x780, width and height in [1, 16384], got '{}'", name,
            text));
    auto side = [](const std::string& digits) {  // more digits than an int holds: too large
        return digits.size() > 6 ? 1 << 30 : std::stoi(digits);
    };
    ImageSize s{side(m[1]), side(m[2])};
    if (limit_problem(side_limit, s.width) || limit_problem(side_limit, s.height))
        throw UsageError(
            fmt::format("{}: width and height must be in [1, 16384], got '{}'", name, text));
    return s;
}

void make_parent_dirs(const std::string& path) {
    if (path == "-" || protocol::output_kind(path) != protocol::OutputKind::Replace) return;
    std::filesystem::path parent = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) std::filesystem::create_directories(parent, ec);
}

void write_json(const std::string& path, const nlohmann::json& value, protocol::Publish publish) {
    write_text(path, value.dump(2) + "\n", publish);
}

std::string read_text_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(fmt::format("cannot read {}: {}", path, std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw std::runtime_error(fmt::format("cannot read {}", path));
    return text.str();
}

void write_text(const std::string& path, const std::string& text, protocol::Publish publish) {
    make_parent_dirs(path);
    protocol::write_output(path, text, publish);
}

bool claims_stdout(std::initializer_list<std::pair<std::string_view, std::string_view>> outputs) {
    // two outputs into one file: the second would silently replace the first
    std::vector<std::pair<std::string_view, std::filesystem::path>> files;
    for (const auto& [option, value] : outputs) {
        if (value.empty() || value == "-") continue;
        std::error_code ec;
        std::filesystem::path file = std::filesystem::weakly_canonical(std::string(value), ec);
        if (ec) file = std::filesystem::absolute(std::string(value)).lexically_normal();
        for (const auto& [other, seen] : files)
            if (seen == file)
                throw UsageError(
                    fmt::format("{} and {} both write to {}; give each a file of its own", other,
                                option, value));
        files.emplace_back(option, std::move(file));
    }
    std::string_view first;
    for (const auto& [option, value] : outputs) {
        if (value != "-") continue;
        if (!first.empty())
            throw UsageError(fmt::format(
                "{} and {} both write to standard output ('-'); give one of them a file", first,
                option));
        first = option;
    }
    return !first.empty();
}

void Console::note(const std::string& text) const {
    if (!quiet) std::cerr << text << '\n';
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string nearest_hint(const std::string& word, const std::vector<std::string>& known) {
    // Levenshtein distance, one row at a time
    auto distance = [](const std::string& a, const std::string& b) {
        std::vector<size_t> row(b.size() + 1);
        for (size_t j = 0; j <= b.size(); ++j)
            row[j] = j;
        for (size_t i = 1; i <= a.size(); ++i) {
            size_t diagonal = row[0];
            row[0] = i;
            for (size_t j = 1; j <= b.size(); ++j) {
                const size_t up = row[j];
                row[j] = std::min(
                    {row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
                diagonal = up;
            }
        }
        return row[b.size()];
    };
    std::string best;
    size_t best_distance = 3;  // at most 2 edits away
    for (const std::string& k : known) {
        const size_t d = distance(word, k);
        if (d < best_distance) best = k, best_distance = d;
    }
    if (!best.empty()) return "; did you mean '" + best + "'?";
    // else the names it opens ("tms34020" for "tms34020-40mhz"), up to three of them
    std::vector<std::string> opened;
    if (word.size() >= 2)
        for (const std::string& k : known)
            if (k.size() > word.size() && k.compare(0, word.size(), word) == 0) opened.push_back(k);
    if (opened.empty() || opened.size() > 3) return "";
    std::string list;
    for (size_t i = 0; i < opened.size(); ++i)
        list += (i == 0 ? "" : i + 1 == opened.size() ? " or " : ", ") + ("'" + opened[i] + "'");
    return "; did you mean " + list + "?";
}

void add_isa_option(CLI::App* sub) {
    std::string levels;
    for (host::KernelLevel l : host::supported_kernel_levels())
        levels += (levels.empty() ? "" : ", ") + std::string(host::kernel_level_name(l)) + " " +
                  std::string(host::kernel_level_description(l));
    sub->add_option_function<std::string>(
        "--isa",
        [](const std::string& name) {
            try {
                host::set_kernel_level(host::parse_kernel_level(name));
            } catch (const std::invalid_argument& e) {
                throw UsageError(std::string("--isa: ") + e.what());
            }
        },
        "Raytrace and beam: the instruction set their kernels run with, for comparison; every "
        "one gives the same frame and counts (this machine: " +
            levels + "; default the last, or $FB89_ISA)");
}

}  // namespace fb89::frontend
