// Where `fb89 calibrate` keeps the hybrid threshold it chose for this machine, so that
// later runs of `render --method hybrid` pick it up: $FB89_CALIBRATION if set, else
// $XDG_CONFIG_HOME/fb89/calibration.json, else ~/.config/fb89/calibration.json.
#pragma once

#include <optional>
#include <string>

namespace fb89::cli {

inline constexpr double kPaperThreshold = 0.04;

std::string calibration_path();
std::optional<double> calibrated_threshold();  // none when never calibrated
void save_calibration(double threshold, const std::string& details_json);

// "--threshold" values: a number, "inf", "paper" (0.04) or "calibrated" (this machine's,
// else the paper's). Throws UsageError.
double resolve_threshold(const std::string& text, std::string* source = nullptr);

}  // namespace fb89::cli
