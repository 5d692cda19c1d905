// fb89_soak: reliability over time. Runs one of three soaks (soak_modes.h) for --cycles
// cycles over the bundled scenes and the six methods, samples resident memory and open
// descriptors every --every cycles, prints a summary (and with --json, writes it) and exits
// 0 when no frame was lost or changed, no descriptor leaked, no file was left behind and
// resident memory stayed flat; 1 when any of these failed; 2 on a usage error.
// scripts/soak builds it and runs all three.
#include <fstream>
#include <iostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "bench/soak/soak_modes.h"
#include "host/methods.h"

namespace {

using namespace fb89;
namespace fs = std::filesystem;

// ../../cli/fb89 from build/bench/soak/fb89_soak
fs::path default_fb89(const char* argv0) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return (ec ? fs::path(argv0) : self).parent_path() / ".." / ".." / "cli" / "fb89";
}

void write_json(const fs::path& file, const nlohmann::json& j) {
    std::ofstream out(file);
    out << j.dump(2) << "\n";
    if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "fb89_soak: render -> stream -> replay -> diff for many cycles, in one process, "
        "through the CLI, or against one controller process; resident memory, descriptors "
        "and frames watched"};
    soak::SoakOptions options;
    std::string mode;
    fs::path scenes_dir = fs::path(FB89_SOURCE_DIR) / "scenes", json_file;
    std::vector<std::string> scenes;
    for (const host::MethodInfo& m : host::methods())
        options.methods.emplace_back(m.name);
    options.fb89 = default_fb89(argv[0]);
    app.add_option("mode", mode, "inprocess, cli or controller")
        ->required()
        ->check(CLI::IsMember({"inprocess", "cli", "controller"}));
    app.add_option("--cycles,-n", options.cycles, "cycles (controller: host connections)")
        ->check(CLI::Range(1, 10'000'000))
        ->capture_default_str();
    app.add_option("--every,-k", options.every, "sample RSS and descriptors every K cycles")
        ->check(CLI::Range(1, 10'000'000))
        ->capture_default_str();
    app.add_option("--scenes-dir", scenes_dir, "where the scenes are")->capture_default_str();
    app.add_option("--scene", scenes, "scenes to use, by name (default: every .json there)");
    app.add_option("--method,-m", options.methods, "methods to use")->capture_default_str();
    app.add_option("--fb89", options.fb89, "the fb89 executable (cli, controller)")
        ->capture_default_str();
    app.add_option("--work", options.work,
                   "work folder (default: a new temporary one, removed at the end)");
    app.add_flag("--keep-work", options.keep_work, "keep the temporary work folder");
    app.add_option("--max-rss-growth", options.max_rss_growth_kib,
                   "KiB the RSS may grow over the second half (slope x cycles/2; 0: unchecked)")
        ->capture_default_str();
    app.add_option("--timeout", options.child_timeout_s, "seconds one fb89 process may take")
        ->capture_default_str();
    app.add_flag("--controller-stats,!--no-controller-stats", options.controller_stats,
                 "controller: run it with --stats and check every frame's checksum there "
                 "(default), or without (its answers to the hosts are checked)");
    app.add_option("--json", json_file, "also write the summary as JSON");
    app.add_flag(
        "--quiet,-q", [&](int64_t) { options.progress = false; }, "no progress lines");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;  // --help: 0; a usage error: 2, as fb89's own
    }
    try {
        for (const std::string& m : options.methods)
            host::method_named(m);  // throws for an unknown name
        options.scenes = soak::scene_files(scenes_dir, scenes);
        if (mode != "inprocess" && !fs::exists(options.fb89))
            throw std::invalid_argument("no fb89 executable at " + options.fb89.string() +
                                        " (--fb89 PATH)");
    } catch (const std::exception& e) {
        std::cerr << "fb89_soak: " << e.what() << "\n";
        return 2;
    }
    try {
        const soak::SoakResult r = mode == "inprocess" ? soak::run_inprocess(options)
                                   : mode == "cli"     ? soak::run_cli(options)
                                                       : soak::run_controller(options);
        const soak::Verdict v = soak::judge(r);
        std::cout << soak::summary(r, v) << std::flush;
        if (!json_file.empty()) write_json(json_file, soak::to_json(r, v));
        return v.pass() ? 0 : 1;
    } catch (const std::exception& e) {
        std::cerr << "fb89_soak: " << e.what() << "\n";
        return 2;
    }
}
