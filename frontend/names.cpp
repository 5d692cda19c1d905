#include "frontend/names.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <regex>
#include <sstream>

#include "controller_sim/profile.h"
#include "frontend/common.h"
#include "frontend/data_dir.h"
#include "period/host_profile.h"
#include "period/isa.h"

namespace fb89::frontend {

namespace fs = std::filesystem;

std::vector<std::string> method_names() {
    std::vector<std::string> names;
    for (const host::MethodInfo& m : host::methods())
        names.emplace_back(m.name);
    return names;
}

std::vector<std::string> profile_names() {
    return controller::list_profiles();
}

std::vector<std::string> host_profile_names() {
    return period::builtin_host_profile_names();
}

std::vector<std::string> host_names() {
    std::vector<std::string> names{"native"};
    for (const std::string& h : host_profile_names())
        names.push_back(h);
    return names;
}

std::vector<std::string> scene_names() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(data_dir() / "scenes", ec))
        if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::vector<std::string> instruction_set_names() {
    // a description opens with the CPU and FPU: "Intel 80386 + 80387, 32-bit (qemu-i386; ...)"
    std::vector<std::string> names;
    for (const period::InstructionSet& isa : period::instruction_sets()) {
        std::string name = isa.description.substr(0, isa.description.find_first_of(",("));
        while (!name.empty() && name.back() == ' ')
            name.pop_back();
        names.push_back(name.empty() ? isa.name : name);
    }
    return names;
}

std::string name_list(const std::vector<std::string>& names, const std::string& last) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " " + last + " " : ", ") + names[i];
    return out;
}

namespace {

bool is_one_of(const std::string& name, const std::vector<std::string>& names) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

bool ends_with_json(const std::string& name) {
    return name.size() > 5 && name.ends_with(".json");
}

[[noreturn]] void unknown(const std::string& kind, const std::string& name,
                          const std::vector<std::string>& known, const std::string& others,
                          const std::string& list) {
    std::vector<std::string> shown = known;
    if (!others.empty()) shown.push_back(others);
    throw UsageError("unknown " + kind + " '" + name + "'" + nearest_hint(name, known) + " (" +
                     name_list(shown) + "; fb89 list " + list + ")");
}

// A check as a CLI11 validator: its UsageError's text is the validator's message.
CLI::Validator validator_of(std::function<void(const std::string&)> check) {
    return CLI::Validator(
        [check](std::string& given) -> std::string {
            try {
                check(given);
            } catch (const UsageError& e) {
                return e.what();
            }
            return "";
        },
        "");
}

}  // namespace

host::Method find_method(const std::string& name) {
    for (const host::MethodInfo& m : host::methods())
        if (m.name == name) return m.method;
    unknown("method", name, method_names(), "", "methods");
}

void check_profile_name(const std::string& name) {
    // as controller::load_profile reads it: a built-in name, else a file
    std::error_code ec;
    if (is_one_of(name, profile_names()) || name.find('/') != std::string::npos ||
        ends_with_json(name) || fs::exists(name, ec))
        return;
    unknown("profile", name, profile_names(), "a .json profile", "profiles");
}

void check_host_name(const std::string& name) {
    // as period::load_host_profile reads it: a built-in name, else a .json file
    if (is_one_of(name, host_names()) || ends_with_json(name)) return;
    unknown("host", name, host_names(), "a .json host profile", "hosts");
}

void check_host_profile_name(const std::string& name) {
    if (is_one_of(name, host_profile_names()) || ends_with_json(name)) return;
    unknown("host profile", name, host_profile_names(), "a .json host profile", "hosts");
}

CLI::Validator method_validator() {
    return validator_of([](const std::string& n) { find_method(n); });
}

CLI::Validator profile_validator() {
    return validator_of(check_profile_name);
}

CLI::Validator host_validator() {
    return validator_of(check_host_name);
}

CLI::Validator host_profile_validator() {
    return validator_of(check_host_profile_name);
}

CLI::Validator one_of_validator(const std::string& kind, std::vector<std::string> names) {
    return CLI::Validator(
        [kind, names](std::string& given) -> std::string {
            if (is_one_of(given, names)) return "";
            return "unknown " + kind + " '" + given + "'" + nearest_hint(given, names) + " (" +
                   name_list(names) + ")";
        },
        "");
}

std::string with_nearest_name(const std::string& message) {
    if (message.find("did you mean") != std::string::npos) return message;
    std::smatch m;
    // "unknown filter '/spna'; expected a step or one of /fill /span ..."
    static const std::regex listed(R"(.*unknown [^']*'([^']*)'; expected .*one of (.*))");
    if (std::regex_match(message, m, listed)) {
        std::vector<std::string> names;
        std::istringstream words(m[2].str());
        for (std::string w; words >> w;)
            names.push_back(w);
        return message + nearest_hint(m[1], names);
    }
    // "--isa: expected baseline, v3 or v4, got 'v5'"
    static const std::regex got(R"((.*expected ([^:;]*), got '([^']*)')(.*))");
    if (std::regex_match(message, m, got)) {
        std::vector<std::string> names;
        const std::string list = std::regex_replace(m[2].str(), std::regex(" or "), ", ");
        std::istringstream items(list);
        for (std::string w; std::getline(items, w, ',');)
            if (const size_t a = w.find_first_not_of(' '); a != std::string::npos)
                names.push_back(w.substr(a));
        return m[1].str() + nearest_hint(m[3], names) + m[4].str();
    }
    return message;
}

std::string method_option_help(const std::string& what) {
    return what + ": " + name_list(method_names()) + " (fb89 list methods)";
}

std::string profile_option_help(const std::string& what) {
    std::vector<std::string> names = profile_names();
    names.emplace_back("a .json file");
    return what + ": " + name_list(names) + " (fb89 list profiles)";
}

std::string host_option_help(const std::string& what) {
    return what + ": native (this machine), a 1989 host (" + name_list(host_profile_names()) +
           ") or a .json host profile (fb89 list hosts); a 1989 host runs fb89's host code on its "
           "emulated CPU (" +
           name_list(instruction_set_names()) + ") and models its time";
}

std::string names_summary() {
    return "Methods: " + name_list(method_names(), "and") +
           ".\nHosts: " + name_list(host_names(), "and") +
           ".\nController profiles: " + name_list(profile_names(), "and") +
           ".\nBundled scenes: " + name_list(scene_names(), "and") +
           ".\nfb89 list says what each is; fb89 help COMMAND (or fb89 COMMAND --help) gives a "
           "command's options.";
}

std::string scene_argument_help(const std::string& what) {
    return what + " (a relative path is read from the current folder), or a bundled scene by " +
           "name: " + name_list(scene_names()) + " (fb89 list scenes)";
}

}  // namespace fb89::frontend
