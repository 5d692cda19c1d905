// The host's phases as the guest marks them and the counting plugin numbers them.
#pragma once

#include <string_view>

namespace fb89::period {

enum class Phase : long { Startup = 0, Load = 1, Setup = 2, HiddenSurface = 3, Output = 4 };
inline constexpr int kPhases = 5;

// "startup" (C library start, options), "load", "setup", "hidden_surface", "output"
// (encoding the stream: never part of a host time, as natively).
inline std::string_view phase_name(int phase) {
    constexpr std::string_view names[kPhases] = {"startup", "load", "setup", "hidden_surface",
                                                 "output"};
    return phase >= 0 && phase < kPhases ? names[phase] : "unknown";
}

}  // namespace fb89::period
