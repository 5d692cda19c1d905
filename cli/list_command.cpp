// fb89 list [methods|profiles|hosts|scenes|experiments]: what fb89 can do, one line each,
// so that a user discovers names without reading the error messages.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "controller_sim/profile.h"
#include "experiments/catalog.h"
#include "frontend/data_dir.h"
#include "host/methods.h"
#include "period/host_profile.h"

namespace fb89::cli {

namespace {

// A profile's "description", or "" when it has none or cannot be read.
std::string description_of(std::string_view json_text) {
    try {
        const auto j = nlohmann::json::parse(json_text, nullptr, true, true);
        if (j.is_object() && j.contains("description") && j["description"].is_string())
            return j["description"].get<std::string>();
    } catch (const std::exception&) {
    }
    return "";
}

// What a scene is, in one sentence: its "description", else the first sentence of the
// comments it opens with (every bundled scene opens by saying what it is).
std::string scene_summary(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream whole;
    whole << in.rdbuf();
    const std::string text = whole.str();
    const std::string described = description_of(text);
    if (!described.empty()) return described;
    std::istringstream lines(text);
    std::string line, comment;
    while (std::getline(lines, line) && line.rfind("//", 0) == 0) {
        const size_t start = line.find_first_not_of("/ ");
        if (start == std::string::npos) break;
        comment += (comment.empty() ? "" : " ") + line.substr(start);
        // the first sentence ends at a full stop before a capital ("Fig. 4.8" goes on)
        for (size_t dot = comment.find(". "); dot != std::string::npos;
             dot = comment.find(". ", dot + 1))
            if (dot + 2 < comment.size() &&
                std::isupper(static_cast<unsigned char>(comment[dot + 2])))
                return comment.substr(0, dot + 1);
    }
    return comment;
}

void list_scenes() {
    const std::filesystem::path dir = data_dir() / "scenes";
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(dir))
        for (const auto& entry : std::filesystem::directory_iterator(dir))
            if (entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    fmt::print("scenes (in {}; name one by its name, e.g. fb89 render demo, or give a path):\n",
               dir.string());
    for (const auto& f : files)
        fmt::print("  {:<18} {}\n", f.stem().string(), scene_summary(f));
}

int run_list(const std::string& what) {
    const bool all = what.empty();
    if (all || what == "methods") {
        fmt::print("methods (render --method NAME):\n");
        for (const host::MethodInfo& m : host::methods())
            fmt::print("  {:<22} {}\n", m.name, m.description);
    }
    if (all || what == "profiles") {
        fmt::print("controller profiles (--profile NAME, or a .json file):\n");
        for (const auto& p : controller::builtin_profiles())
            fmt::print("  {:<22} {}\n", p.name, description_of(p.json));
    }
    if (all || what == "hosts") {
        fmt::print("hosts (--host NAME, or a .json host profile):\n");
        fmt::print("  {:<16} {:<6} {:<22} {}\n", "name", "isa", "CPU", "FPU");
        fmt::print("  {:<16} {:<6} {}\n", "native", "-",
                   "this machine, timed in interleaved rounds");
        for (const std::string& name : period::builtin_host_profile_names()) {
            const period::HostProfile p = period::load_host_profile(name);
            fmt::print("  {:<16} {:<6} {:<22} {}\n", p.name, p.isa, p.cpu, p.fpu);
        }
    }
    if (all || what == "experiments") {
        fmt::print("experiments (fb89 experiment NAME):\n");
        for (const experiments::ExperimentInfo& e : experiments::experiment_catalog())
            fmt::print("  {:<22} {}\n", e.name, e.description);
    }
    if (all || what == "scenes") list_scenes();
    return kSuccess;
}

}  // namespace

void register_list(CLI::App& app, int& exit_code) {
    auto what = std::make_shared<std::string>();
    CLI::App* sub = app.add_subcommand(
        "list", "List what fb89 knows: methods, profiles, hosts, scenes, experiments");
    static const std::vector<std::string> kinds = {"methods", "profiles", "hosts", "scenes",
                                                   "experiments"};
    sub->add_option("what", *what, "One kind only: methods, profiles, hosts, scenes or experiments")
        ->check(CLI::Validator(
            [](std::string& given) -> std::string {
                if (std::find(kinds.begin(), kinds.end(), given) != kinds.end()) return "";
                return "unknown kind '" + given + "'" + nearest_hint(given, kinds) +
                       " (methods, profiles, hosts, scenes or experiments)";
            },
            "KIND"));
    sub->callback([what, &exit_code] { exit_code = run_list(*what); });
}

}  // namespace fb89::cli
