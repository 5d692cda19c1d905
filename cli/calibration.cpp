#include "cli/calibration.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/common.h"

namespace fb89::cli {

std::string calibration_path() {
    if (const char* p = std::getenv("FB89_CALIBRATION"); p && *p) return p;
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x)
        return std::string(x) + "/fb89/calibration.json";
    const char* home = std::getenv("HOME");
    return std::string(home && *home ? home : ".") + "/.config/fb89/calibration.json";
}

std::optional<double> calibrated_threshold() {
    std::ifstream in(calibration_path());
    if (!in) return std::nullopt;
    std::stringstream ss;
    ss << in.rdbuf();
    try {
        nlohmann::json j = nlohmann::json::parse(ss.str());
        double t = j.at("threshold").get<double>();
        if (t >= 0) return t;
    } catch (const std::exception&) {
    }
    throw std::runtime_error(
        fmt::format("{}: not a calibration file (expected {{\"threshold\": number >= 0}}); run "
                    "fb89 calibrate again",
                    calibration_path()));
}

void save_calibration(double threshold, const std::string& details_json) {
    nlohmann::json j = nlohmann::json::parse(details_json);
    j["threshold"] = threshold;
    write_json(calibration_path(), j);
}

double resolve_threshold(const std::string& text, std::string* source) {
    auto said = [&](const char* s) {
        if (source) *source = s;
    };
    if (text == "paper") {
        said("paper");
        return kPaperThreshold;
    }
    if (text == "calibrated") {
        if (auto t = calibrated_threshold()) {
            said("calibrated");
            return *t;
        }
        said("paper (not calibrated yet)");
        return kPaperThreshold;
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
    throw UsageError(fmt::format(
        "--threshold: expected a number >= 0, inf, paper or calibrated, got '{}'", text));
}

}  // namespace fb89::cli
