#include "frontend/calibration.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "frontend/common.h"
#include "host/raster/hybrid.h"
#include "host/trace/beam_ray_hybrid.h"

namespace fb89::frontend {

std::string calibration_path() {
    if (const char* p = std::getenv("FB89_CALIBRATION"); p && *p) return p;
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x)
        return std::string(x) + "/fb89/calibration.json";
    const char* home = std::getenv("HOME");
    return std::string(home && *home ? home : ".") + "/.config/fb89/calibration.json";
}

namespace {

// The calibration file's contents, or null when there is none.
nlohmann::json read_calibration() {
    std::ifstream in(calibration_path());
    if (!in) return nullptr;
    std::stringstream ss;
    ss << in.rdbuf();
    try {
        nlohmann::json j = nlohmann::json::parse(ss.str());
        if (j.is_object()) return j;
    } catch (const std::exception&) {
    }
    throw std::runtime_error(
        fmt::format("{}: not a calibration file (expected a JSON object); run fb89 calibrate again",
                    calibration_path()));
}

std::string keyed(const char* key, const std::string& host) {
    return host == "native" ? std::string(key) : std::string(key) + "@" + host;
}

std::optional<double> read_threshold(const std::string& key) {
    const nlohmann::json j = read_calibration();
    if (j.is_null() || !j.contains(key)) return std::nullopt;
    const auto& v = j.at(key);
    if (v.is_number() && v.get<double>() >= 0) return v.get<double>();
    if (v == "inf") return std::numeric_limits<double>::infinity();  // JSON has no infinity
    throw std::runtime_error(
        fmt::format("{}: \"{}\" must be a number >= 0 or \"inf\"; run fb89 calibrate again",
                    calibration_path(), key));
}

// Writes `key` and its details, keeping what the file says of the other threshold.
void save_threshold(const std::string& key, const std::string& details_key, double threshold,
                    const std::string& details_json) {
    nlohmann::json j;
    try {
        j = read_calibration();
    } catch (const std::runtime_error&) {
        j = nullptr;  // a broken file is replaced
    }
    if (j.is_null()) j = nlohmann::json::object();
    if (std::isinf(threshold))
        j[key] = "inf";  // JSON has no infinity
    else
        j[key] = threshold;
    j[details_key] = nlohmann::json::parse(details_json);
    write_json(calibration_path(), j);
}

}  // namespace

std::optional<double> calibrated_threshold(const std::string& host) {
    return read_threshold(keyed("threshold", host));
}
std::optional<double> calibrated_beam_threshold(const std::string& host) {
    return read_threshold(keyed("beam_threshold", host));
}

void save_calibration(double threshold, const std::string& details_json, const std::string& host) {
    save_threshold(keyed("threshold", host), keyed("hybrid", host), threshold, details_json);
}

void save_beam_calibration(double threshold, const std::string& details_json,
                           const std::string& host) {
    save_threshold(keyed("beam_threshold", host), keyed("beam", host), threshold, details_json);
}

std::string calibrate_command(const std::string& method, const std::string& host) {
    std::string command = "fb89 calibrate";
    if (method != "hybrid") command += " --method " + method;
    if (host != "native") command += " --host " + host;
    return command;
}

std::string missing_calibration(const std::string& method, const std::string& host) {
    return fmt::format("not calibrated yet for method {} on host {}: `{}` makes it", method, host,
                       calibrate_command(method, host));
}

namespace {

// A threshold given on the command line: "inf", a number >= 0, or "calibrated" (the saved
// one, else `fallback`, described as `fallback_name`). Throws UsageError naming `option`.
double resolve(const std::string& option, const std::string& text, std::optional<double> saved,
               double fallback, const char* fallback_name, const char* forms, std::string* source,
               const std::string& missing) {
    auto said = [&](const std::string& s) {
        if (source) *source = s;
    };
    if (text == "calibrated") {
        if (saved) {
            said("calibrated here");
            return *saved;
        }
        said(std::string(fallback_name) + ": " + missing);
        return fallback;
    }
    if (text == "inf" || text == "infinity") {
        said("given");
        return std::numeric_limits<double>::infinity();
    }
    try {
        size_t used = 0;
        double t = std::stod(text, &used);
        if (used == text.size() && t >= 0) {
            said("given");
            return t;
        }
    } catch (const std::exception&) {
    }
    throw UsageError(fmt::format("{}: expected {}, got '{}'", option, forms, text));
}

}  // namespace

double resolve_threshold(const std::string& text, std::string* source, const std::string& host) {
    if (text == "paper") {
        if (source) *source = "the paper's";
        return host::kPaperThreshold;
    }
    const std::optional<double> saved =
        text == "calibrated" ? calibrated_threshold(host) : std::optional<double>{};
    return resolve("--threshold", text, saved, host::kPaperThreshold, "the paper's",
                   "a number >= 0, inf, paper or calibrated", source,
                   missing_calibration("hybrid", host));
}

double resolve_beam_threshold(const std::string& text, std::string* source,
                              const std::string& host) {
    const std::optional<double> saved =
        text == "calibrated" ? calibrated_beam_threshold(host) : std::optional<double>{};
    return resolve("--beam-threshold", text, saved, host::kDefaultBeamThreshold, "the built-in one",
                   "a number >= 0, inf or calibrated", source, missing_calibration("beam", host));
}

}  // namespace fb89::frontend
