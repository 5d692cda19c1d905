// Where `fb89 calibrate` keeps the hybrid threshold it chose for this machine, so that
// later runs of `render --method hybrid` pick it up: $FB89_CALIBRATION if set, else
// $XDG_CONFIG_HOME/fb89/calibration.json, else ~/.config/fb89/calibration.json.
#pragma once

#include <optional>
#include <string>

namespace fb89::frontend {

// Both thresholds live in one file: "threshold" (the Warnock/Z-buffer hybrid's) and
// "beam_threshold" (the beam-ray hybrid's), each with the details of its calibration.
// A 1989 host's thresholds are kept apart, under "threshold@HOST" and "beam_threshold@HOST".
std::string calibration_path();
std::optional<double> calibrated_threshold(const std::string& host = "native");  // none: never
std::optional<double> calibrated_beam_threshold(const std::string& host = "native");
void save_calibration(double threshold, const std::string& details_json,
                      const std::string& host = "native");
void save_beam_calibration(double threshold, const std::string& details_json,
                           const std::string& host = "native");

// The command that saves the calibration of `method` (hybrid or beam) on `host`:
// "fb89 calibrate", "fb89 calibrate --method beam --host sun3-60".
std::string calibrate_command(const std::string& method, const std::string& host = "native");
// What a run without that calibration says: "not calibrated yet for method beam on host
// native: `fb89 calibrate --method beam` makes it".
std::string missing_calibration(const std::string& method, const std::string& host = "native");

// "--threshold" values: a number, "inf", "paper" (0.04) or "calibrated" (this machine's,
// else the paper's). Throws UsageError.
double resolve_threshold(const std::string& text, std::string* source = nullptr,
                         const std::string& host = "native");
// "--beam-threshold" values: a number, "inf" or "calibrated" (this machine's, else
// host::kDefaultBeamThreshold).
double resolve_beam_threshold(const std::string& text, std::string* source = nullptr,
                              const std::string& host = "native");

}  // namespace fb89::frontend
