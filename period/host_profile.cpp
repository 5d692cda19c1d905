#include "period/host_profile.h"

#include "period/isa.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace fb89::period {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
    throw std::runtime_error(fmt::format("host profile {}: {}", origin, what));
}

double number(const json& j, const char* key, const std::string& origin, const std::string& at) {
    if (!j.contains(key) || !j[key].is_number())
        fail(origin, fmt::format("{}\"{}\" must be a number", at, key));
    const double v = j[key].get<double>();
    if (!(v >= 0)) fail(origin, fmt::format("{}\"{}\" must be >= 0, got {}", at, key, v));
    return v;
}

std::vector<int> indices(const json& rule, const char* key, const std::string& origin,
                         const std::string& at) {
    std::vector<int> out;
    if (!rule.contains(key)) return out;
    if (!rule[key].is_array()) fail(origin, fmt::format("{}\"{}\" must be a list", at, key));
    for (const json& v : rule[key]) {
        if (!v.is_number_integer() || v.get<int64_t>() < 0 || v.get<int64_t>() > 7)
            fail(origin, fmt::format("{}\"{}\" holds operand indices 0..7", at, key));
        out.push_back(static_cast<int>(v.get<int64_t>()));
    }
    return out;
}

// "mem,reg" -> {{ind, postinc, ...}, {dreg, areg}}: each class or group of the profile's
// (HostProfile::operand_groups) among a pattern's '|' alternatives.
std::vector<std::vector<std::string>> operand_pattern(const std::string& text,
                                                      const OperandGroups& groups) {
    std::vector<std::vector<std::string>> out;
    if (text.empty()) return out;
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
        std::vector<std::string> classes;
        std::stringstream alternatives(item);
        std::string c;
        while (std::getline(alternatives, c, '|')) {
            const auto group = groups.find(c);
            if (group != groups.end())
                classes.insert(classes.end(), group->second.begin(), group->second.end());
            else
                classes.push_back(c);
        }
        out.push_back(std::move(classes));
    }
    return out;
}

CostRule rule_of(const json& r, const OperandGroups& groups, const std::string& origin,
                 const std::string& at) {
    CostRule rule;
    if (r.contains("mnemonic")) {
        if (!r["mnemonic"].is_string()) fail(origin, at + "\"mnemonic\" must be a regex string");
        rule.mnemonic_text = r["mnemonic"].get<std::string>();
    } else {
        rule.mnemonic_text = ".*";
    }
    try {
        rule.mnemonic = std::regex(rule.mnemonic_text, std::regex::ECMAScript);
    } catch (const std::regex_error& e) {
        fail(origin, fmt::format("{}\"mnemonic\" '{}' is not a regex: {}", at, rule.mnemonic_text,
                                 e.what()));
    }
    if (r.contains("operands")) {
        if (!r["operands"].is_string()) fail(origin, at + "\"operands\" must be a string");
        rule.any_operands = false;
        rule.operands = operand_pattern(r["operands"].get<std::string>(), groups);
    }
    rule.cpu = number(r, "cpu", origin, at);
    if (r.contains("fpu")) rule.fpu = number(r, "fpu", origin, at);
    rule.fetch = indices(r, "fetch", origin, at);
    rule.calc = indices(r, "calc", origin, at);
    if (r.contains("accesses")) {
        // memory accesses an instruction makes: a small count (without it, its memory operands)
        const json& a = r["accesses"];
        if (!a.is_number_integer() || a.get<int64_t>() < 0 || a.get<int64_t>() > 64)
            fail(origin, at + "\"accesses\" must be an integer from 0 to 64");
        rule.accesses = static_cast<int>(a.get<int64_t>());
    }
    if (r.contains("stand_in")) {
        if (!r["stand_in"].is_boolean()) fail(origin, at + "\"stand_in\" must be true or false");
        rule.stand_in = r["stand_in"].get<bool>();
    }
    if (r.contains("source") && r["source"].is_string()) rule.source = r["source"];
    return rule;
}

std::map<std::string, double> table(const json& ea, const char* key, const std::string& origin) {
    std::map<std::string, double> out;
    if (!ea.contains(key) || !ea[key].is_object())
        fail(origin,
             fmt::format("\"ea\".\"{}\" must be an object of cycles by operand class", key));
    for (const auto& [cls, v] : ea[key].items()) {
        if (!v.is_number() || !(v.get<double>() >= 0))
            fail(origin, fmt::format("\"ea\".\"{}\".\"{}\" must be a number >= 0", key, cls));
        out[cls] = v.get<double>();
    }
    return out;
}

}  // namespace

HostProfile parse_host_profile(std::string_view text, const std::string& origin) {
    json j;
    try {
        j = json::parse(text, nullptr, true, true);
    } catch (const json::exception& e) {  // a syntax error, or a number too large for a double
        fail(origin, std::string("not valid JSON: ") + e.what());
    }
    if (!j.is_object()) fail(origin, "must be a JSON object");
    if (!j.contains("schema") || j["schema"] != 1) fail(origin, "\"schema\" must be 1");
    HostProfile p;
    if (!j.contains("name") || !j["name"].is_string()) fail(origin, "\"name\" must be a string");
    p.name = j["name"];
    for (auto [key, field] : {std::pair{"description", &p.description},
                              {"cpu", &p.cpu},
                              {"fpu", &p.fpu},
                              {"isa", &p.isa}}) {
        if (!j.contains(key)) continue;
        if (!j[key].is_string()) fail(origin, fmt::format("\"{}\" must be a string", key));
        *field = j[key].get<std::string>();
    }
    try {
        instruction_set(p.isa);
    } catch (const std::runtime_error& e) {
        fail(origin, fmt::format("\"isa\": {}", e.what()));
    }
    p.cpu_clock_mhz = number(j, "cpu_clock_mhz", origin, "");
    p.fpu_clock_mhz = number(j, "fpu_clock_mhz", origin, "");
    if (p.cpu_clock_mhz <= 0 || p.fpu_clock_mhz <= 0) fail(origin, "clocks must be > 0 MHz");
    p.memory_wait_states = number(j, "memory_wait_states", origin, "");
    // the instruction set's operand classes: which are memory (one data access each), and the
    // names a rule's pattern may use for several (without these fields, the MC68020's)
    for (auto [key, list] : {std::pair{"memory_classes", &p.memory_classes}}) {
        if (!j.contains(key)) continue;
        if (!j[key].is_array()) fail(origin, fmt::format("\"{}\" must be a list of strings", key));
        list->clear();
        for (const json& c : j[key]) {
            if (!c.is_string()) fail(origin, fmt::format("\"{}\" must be a list of strings", key));
            list->push_back(c.get<std::string>());
        }
    }
    if (j.contains("operand_groups")) {
        const json& g = j["operand_groups"];
        if (!g.is_object()) fail(origin, "\"operand_groups\" must be an object of lists");
        p.operand_groups.clear();
        for (const auto& [name, classes] : g.items()) {
            if (!classes.is_array())
                fail(origin, fmt::format("\"operand_groups\": \"{}\" must be a list", name));
            for (const json& c : classes) {
                if (!c.is_string())
                    fail(origin, fmt::format("\"operand_groups\": \"{}\" must list strings", name));
                p.operand_groups[name].push_back(c.get<std::string>());
            }
        }
    }
    if (!j.contains("ea") || !j["ea"].is_object()) fail(origin, "\"ea\" must be an object");
    p.ea_fetch = table(j["ea"], "fetch", origin);
    p.ea_calc = table(j["ea"], "calc", origin);
    if (!j.contains("rules") || !j["rules"].is_array() || j["rules"].empty())
        fail(origin, "\"rules\" must be a non-empty list");
    for (size_t i = 0; i < j["rules"].size(); ++i) {
        if (!j["rules"][i].is_object()) fail(origin, fmt::format("rule {} must be an object", i));
        p.rules.push_back(
            rule_of(j["rules"][i], p.operand_groups, origin, fmt::format("rule {}: ", i)));
    }
    if (!j.contains("default") || !j["default"].is_object())
        fail(origin, "\"default\" must be an object with \"cpu\"");
    p.fallback = rule_of(j["default"], p.operand_groups, origin, "default: ");
    return p;
}

std::vector<std::string> builtin_host_profile_names() {
    std::vector<std::string> names;
    for (const BuiltinProfile& b : builtin_profiles())
        names.emplace_back(b.name);
    return names;
}

HostProfile load_host_profile(std::string_view name_or_path) {
    for (const BuiltinProfile& b : builtin_profiles())
        if (b.name == name_or_path) return parse_host_profile(b.json, std::string(b.name));
    const std::string path(name_or_path);
    if (path.size() < 5 || path.substr(path.size() - 5) != ".json") {
        std::string known;
        for (const auto& n : builtin_host_profile_names())
            known += (known.empty() ? "" : ", ") + n;
        throw std::runtime_error(fmt::format(
            "unknown host '{}' (known: native, {}, or a .json host profile)", path, known));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open the host profile");
    std::stringstream text;
    text << in.rdbuf();
    return parse_host_profile(text.str(), path);
}

}  // namespace fb89::period
