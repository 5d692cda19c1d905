#include "period/host_cost.h"

#include <algorithm>
#include <stdexcept>
#include <unordered_map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace fb89::period {

namespace {

// "fmoved disp,fpreg" -> mnemonic "fmoved", operands {"disp", "fpreg"}
void split_key(std::string_view key, std::string_view& mnemonic,
               std::vector<std::string_view>& operands) {
    operands.clear();
    const size_t space = key.find(' ');
    mnemonic = key.substr(0, space);
    if (space == std::string_view::npos) return;
    std::string_view rest = key.substr(space + 1);
    while (!rest.empty()) {
        const size_t comma = rest.find(',');
        operands.push_back(rest.substr(0, comma));
        if (comma == std::string_view::npos) break;
        rest = rest.substr(comma + 1);
    }
}

bool matches(const CostRule& rule, std::string_view mnemonic,
             const std::vector<std::string_view>& operands) {
    if (!std::regex_match(mnemonic.begin(), mnemonic.end(), rule.mnemonic)) return false;
    if (rule.any_operands) return true;
    if (rule.operands.size() != operands.size()) return false;
    for (size_t i = 0; i < operands.size(); ++i) {
        const auto& allowed = rule.operands[i];
        if (std::find(allowed.begin(), allowed.end(), "*") != allowed.end()) continue;
        if (std::find(allowed.begin(), allowed.end(), operands[i]) == allowed.end()) return false;
    }
    return true;
}

// The EA table's entry for an operand; immediates by the mnemonic's size letter.
double ea_cycles(const std::map<std::string, double>& table, std::string_view operand,
                 std::string_view mnemonic) {
    std::string cls(operand);
    if (cls == "imm" && !mnemonic.empty()) cls += std::string(".") + mnemonic.back();
    const auto it = table.find(cls);
    return it == table.end() ? 0 : it->second;
}

double rule_cpu(const HostProfile& p, const CostRule& rule, std::string_view mnemonic,
                const std::vector<std::string_view>& operands) {
    double cycles = rule.cpu;
    for (int i : rule.fetch)
        if (static_cast<size_t>(i) < operands.size())
            cycles += ea_cycles(p.ea_fetch, operands[static_cast<size_t>(i)], mnemonic);
    for (int i : rule.calc)
        if (static_cast<size_t>(i) < operands.size())
            cycles += ea_cycles(p.ea_calc, operands[static_cast<size_t>(i)], mnemonic);
    int accesses = rule.accesses;
    if (accesses < 0)
        accesses = static_cast<int>(
            std::count_if(operands.begin(), operands.end(), [&](std::string_view c) {
                return std::find(p.memory_classes.begin(), p.memory_classes.end(), c) !=
                       p.memory_classes.end();
            }));
    return cycles + p.memory_wait_states * accesses;
}

}  // namespace

const PhaseCounts* GuestCounts::phase(int p) const {
    for (const PhaseCounts& c : phases)
        if (c.phase == p) return &c;
    return nullptr;
}

GuestCounts parse_guest_counts(std::string_view text, const std::string& origin) {
    GuestCounts out;
    // a count is a non-negative integer as the plugin writes it; anything else (a negative,
    // fractional or huge number) is refused, never converted
    const auto count = [](const nlohmann::json& v, const std::string& what) {
        if (!v.is_number_unsigned())
            throw std::runtime_error(fmt::format("{} must be a count, got {}", what, v.dump()));
        return v.get<uint64_t>();
    };
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        if (!j.is_object() || j.value("tool", "") != "fb89_count" || !j.contains("version") ||
            !j["version"].is_number_unsigned() || j["version"].get<uint64_t>() != 1)
            throw std::runtime_error("not the output of the fb89_count plugin, version 1");
        out.instructions = count(j.at("guest_instructions"), "guest_instructions");
        for (const auto& p : j.at("phases")) {
            PhaseCounts c;
            const uint64_t phase = count(p.at("phase"), "a phase");
            if (phase > 15)  // the plugin keeps phases 0 to 15
                throw std::runtime_error(fmt::format("phase {} is unknown", phase));
            c.phase = static_cast<int>(phase);
            c.entered = count(p.at("entered"), "entered");
            c.instructions = count(p.at("instructions"), "instructions");
            for (const auto& [key, n] : p.at("classes").items())
                c.classes[key] = count(n, key);
            out.phases.push_back(std::move(c));
        }
        // the send marks (absent from counts made before them)
        if (j.contains("sends")) {
            for (const auto& r : j.at("sends")) {
                SendCounts c;
                const uint64_t phase = count(r.at("phase"), "a send's phase");
                if (phase > 15) throw std::runtime_error(fmt::format("phase {} is unknown", phase));
                c.phase = static_cast<int>(phase);
                c.commands = count(r.at("commands"), "a send's commands");
                c.instructions = count(r.at("instructions"), "a send's instructions");
                if (!out.sends.empty() && out.sends.back().phase == c.phase &&
                    c.commands < out.sends.back().commands)
                    throw std::runtime_error(
                        fmt::format("send {}: {} commands sent, fewer than the {} before it",
                                    out.sends.size(), c.commands, out.sends.back().commands));
                for (const auto& [key, n] : r.at("classes").items())
                    c.classes[key] = count(n, key);
                out.sends.push_back(std::move(c));
            }
        }
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(
            fmt::format("{}: not the counting plugin's JSON: {}", origin, e.what()));
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("{}: {}", origin, e.what()));
    }
    return out;
}

KeyPrice price_key(const HostProfile& p, std::string_view key) {
    std::string_view mnemonic;
    std::vector<std::string_view> operands;
    split_key(key, mnemonic, operands);
    for (const CostRule& rule : p.rules)
        if (matches(rule, mnemonic, operands))
            return {rule_cpu(p, rule, mnemonic, operands), rule.fpu, &rule};
    return {rule_cpu(p, p.fallback, mnemonic, operands), p.fallback.fpu, nullptr};
}

double HostCost::end_to_end_ms() const {
    return phases[static_cast<int>(Phase::Load)].ms + phases[static_cast<int>(Phase::Setup)].ms +
           phases[static_cast<int>(Phase::HiddenSurface)].ms;
}

HostCost price(const GuestCounts& counts, const HostProfile& profile) {
    HostCost cost;
    cost.profile = profile.name;
    const double cpu_khz = profile.cpu_clock_mhz * 1e3, fpu_khz = profile.fpu_clock_mhz * 1e3;
    // each key matched against the rules once: the send marks repeat the phases' keys
    std::unordered_map<std::string, KeyPrice> priced;
    auto price_of = [&](const std::string& key) -> const KeyPrice& {
        auto it = priced.find(key);
        if (it == priced.end()) it = priced.emplace(key, price_key(profile, key)).first;
        return it->second;
    };
    for (const PhaseCounts& c : counts.phases) {
        if (c.phase < 0 || c.phase >= kPhases) continue;
        PhaseCost& out = cost.phases[c.phase];
        out.instructions += c.instructions;
        for (const auto& [key, n] : c.classes) {
            const KeyPrice& k = price_of(key);
            const double cpu = k.cpu * static_cast<double>(n), fpu = k.fpu * static_cast<double>(n);
            if (key.starts_with('@') && (k.cpu > 0 || k.fpu > 0)) out.events[key] += n;
            auto& [executions, ms] = out.classes[key];
            executions += n;
            ms += cpu / cpu_khz + fpu / fpu_khz;
            out.cpu_cycles += cpu;
            out.fpu_cycles += fpu;
            if (!k.rule) {
                out.unpriced += n;
                cost.unpriced_keys[key] += n;
            } else if (k.rule->stand_in) {
                out.stand_in_ms += cpu / cpu_khz + fpu / fpu_khz;
                out.stand_ins += n;
            }
        }
        out.ms = out.cpu_cycles / cpu_khz + out.fpu_cycles / fpu_khz;
    }
    // each send mark at the time its phase had run to it, priced as the phase is
    double cpu = 0, fpu = 0;
    int phase = -1;
    for (const SendCounts& s : counts.sends) {
        if (s.phase != phase) cpu = fpu = 0, phase = s.phase;
        for (const auto& [key, n] : s.classes) {
            const KeyPrice& k = price_of(key);
            cpu += k.cpu * static_cast<double>(n);
            fpu += k.fpu * static_cast<double>(n);
        }
        cost.sends.push_back({s.phase, s.commands, cpu / cpu_khz + fpu / fpu_khz});
    }
    return cost;
}

}  // namespace fb89::period
