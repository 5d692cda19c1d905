// Counts to time: the counting plugin's per-phase instruction classes (period/plugin),
// priced by a host profile (host_profile.h). Counts are exact and deterministic, so the
// modelled times are too.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "period/host_profile.h"
#include "period/phases.h"

namespace fb89::period {

struct PhaseCounts {
    int phase = 0;
    uint64_t entered = 0, instructions = 0;
    std::map<std::string, uint64_t> classes;  // class key -> executions
};

// What the guest ran from its last send mark (or the phase's start) to this one, when it
// had sent `commands` commands of its frame (period/guest: a mark a packet and at FRAME_END).
struct SendCounts {
    int phase = 0;
    uint64_t commands = 0, instructions = 0;
    std::map<std::string, uint64_t> classes;
};

struct GuestCounts {
    uint64_t instructions = 0;
    std::vector<PhaseCounts> phases;
    std::vector<SendCounts> sends;  // in order; none from a plugin or guest without them
    const PhaseCounts* phase(int p) const;
};

// The plugin's JSON. Throws std::runtime_error naming `origin` when it is not one.
GuestCounts parse_guest_counts(std::string_view json, const std::string& origin);

struct KeyPrice {
    double cpu = 0, fpu = 0;         // clocks of one execution
    const CostRule* rule = nullptr;  // null: the profile's default
};
// One class key, e.g. "movel disp,dreg", priced by the first rule it matches.
KeyPrice price_key(const HostProfile& profile, std::string_view key);

struct PhaseCost {
    uint64_t instructions = 0;
    uint64_t unpriced = 0;  // executions no rule matched (priced by the default)
    double cpu_cycles = 0, fpu_cycles = 0;
    double ms = 0;  // cpu_cycles / cpu clock + fpu_cycles / fpu clock
    // what of `ms` came from instructions the machine does not have, priced as the
    // sequences that would stand in for them (CostRule::stand_in), and how many there were
    double stand_in_ms = 0;
    uint64_t stand_ins = 0;
    // the pseudo-classes' counts that the profile prices: events that cost this machine time
    // but are no instruction of the guest's ("@window_overflow", "@dcache_128k_16b_wb_read_miss",
    // ...: period/plugin/README.md); another machine's cache or window count, which the plugin
    // follows beside it, is left out
    std::map<std::string, uint64_t> events;
    // each class key's executions and modelled time (for the classes that take most)
    std::map<std::string, std::pair<uint64_t, double>> classes;
};

// A send mark priced: `commands` sent by `ms` into the phase (its time from the phase's
// start, as the phase's own `ms` is priced).
struct SendTime {
    int phase = 0;
    uint64_t commands = 0;
    double ms = 0;
};

struct HostCost {
    std::string profile;
    PhaseCost phases[kPhases];
    std::vector<SendTime> sends;
    std::map<std::string, uint64_t> unpriced_keys;  // key -> executions
    // load + set-up + hidden-surface, as native end-to-end times are
    double end_to_end_ms() const;
};

HostCost price(const GuestCounts& counts, const HostProfile& profile);

}  // namespace fb89::period
