// Reading fb89's help as the tests of help and man pages need it: the commands `fb89 --help`
// lists, each option's paragraph of a command's --help or of its man page, and the names
// every registry holds (read from the registries, not from the front end under test).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "controller_sim/profile.h"
#include "host/methods.h"
#include "period/host_profile.h"
#include "tests/cli/cli_runner.h"

namespace fb89::testing {

// The commands of `fb89 --help`, in its order: "  NAME  description" lines after
// "Subcommands:", up to the blank line.
inline std::vector<std::string> listed_commands() {
    const std::string help = run_fb89("--help").out;
    std::istringstream in(help.substr(help.find("Subcommands:")));
    std::vector<std::string> names;
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line) && !line.empty()) {
        std::istringstream words(line);
        std::string name;
        words >> name;
        names.push_back(name);
    }
    return names;
}

// A man page's text as it reads: "\-" a hyphen, font changes gone.
inline std::string unroff(std::string text) {
    for (const std::string from : {"\\fB", "\\fR", "\\fI", "\\fP"})
        for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
            text.erase(at, from.size());
    for (size_t at = text.find("\\-"); at != std::string::npos; at = text.find("\\-", at))
        text.erase(at, 1);
    return text;
}

// Each option's or positional's paragraph, keyed by its names ("-m", "--method", "scene"):
// from `--help` text (an entry opens two spaces in, its description goes on further in) or
// from a man page (".TP", the option line, its description up to the next request).
inline std::map<std::string, std::string> option_paragraphs(const std::string& text,
                                                            bool man_page) {
    std::map<std::string, std::string> out;
    std::istringstream in(man_page ? unroff(text) : text);
    std::vector<std::string> keys;
    std::string line, paragraph;
    auto close = [&] {
        for (const std::string& k : keys)
            out[k] = paragraph;
        keys.clear();
        paragraph.clear();
    };
    bool after_tp = false;
    while (std::getline(in, line)) {
        const bool opens =
            man_page ? after_tp : line.size() > 2 && line.rfind("  ", 0) == 0 && line[2] != ' ';
        const bool ends = man_page ? line.rfind(".", 0) == 0 : line.empty() || line[0] != ' ';
        after_tp = man_page && line == ".TP";
        if (opens || ends) close();
        if (opens) {
            std::istringstream words(line);
            std::string first;
            words >> first;
            std::stringstream names(first);
            for (std::string name; std::getline(names, name, ',');)
                keys.push_back(name);
        }
        if (!keys.empty()) paragraph += line + " ";
    }
    close();
    return out;
}

// Whether `name` appears in `text` as a whole name (not inside a longer one).
inline bool names(const std::string& text, const std::string& name) {
    auto part = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
    };
    for (size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) {
        const bool before = at == 0 || !part(text[at - 1]);
        const size_t end = at + name.size();
        if (before && (end == text.size() || !part(text[end]))) return true;
    }
    return false;
}

// The registries' names.
inline std::vector<std::string> registered_methods() {
    std::vector<std::string> out;
    for (const host::MethodInfo& m : host::methods())
        out.emplace_back(m.name);
    return out;
}
inline std::vector<std::string> registered_profiles() {
    std::vector<std::string> out;
    for (const controller::BuiltinProfile& p : controller::builtin_profiles())
        out.emplace_back(p.name);
    return out;
}
inline std::vector<std::string> registered_host_profiles() {
    std::vector<std::string> out;
    for (const period::BuiltinProfile& p : period::builtin_profiles())
        out.emplace_back(p.name);
    return out;
}
inline std::vector<std::string> registered_hosts() {
    std::vector<std::string> out{"native"};
    for (const std::string& h : registered_host_profiles())
        out.push_back(h);
    return out;
}
inline std::vector<std::string> bundled_scenes() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(FB89_SCENES_DIR))
        if (e.path().extension() == ".json") out.push_back(e.path().stem().string());
    std::sort(out.begin(), out.end());
    return out;
}

// What an option or positional of a command takes by name, for the commands whose help
// offers it: --method and --methods the methods, --profile the controller profiles (the
// period hosts' for host-validate), --host the hosts, scene and scenes the bundled scenes.
// calibrate's --method takes the two methods it calibrates, not the registry.
inline std::vector<std::string> names_taken(const std::string& command, const std::string& key) {
    if (key == "--method" && command == "calibrate") return {"hybrid", "beam"};
    if (key == "--method" || key == "--methods") return registered_methods();
    if (key == "--profile")
        return command == "host-validate" ? registered_host_profiles() : registered_profiles();
    if (key == "--host") return registered_hosts();
    if (key == "scene" || key == "scenes") return bundled_scenes();
    return {};
}

// Checks that each option paragraph of `command`'s text (its --help, or its man page) names
// every name the option takes; `where` says which text in messages. Returns the
// "command key" pairs it checked.
inline std::set<std::string> expect_every_name_in(
    const std::string& command, const std::map<std::string, std::string>& paragraphs,
    const std::string& where) {
    std::set<std::string> checked;
    for (const auto& [key, paragraph] : paragraphs) {
        const std::vector<std::string> taken = names_taken(command, key);
        if (taken.empty()) continue;
        checked.insert(command + " " + key);
        for (const std::string& name : taken)
            EXPECT_TRUE(names(paragraph, name))
                << where << ": " << key << " does not name " << name << "\n"
                << paragraph;
    }
    return checked;
}

}  // namespace fb89::testing
