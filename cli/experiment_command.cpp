// fb89 experiment NAME: the paper's experiments, re-run. Each writes CSV (a header row,
// one row per scene and method) and prints a table.
//   fig2.1  Warnock vs scan-line vs Z-buffer on scenes A-F: host hidden-surface time as
//           medians of interleaved repeats, counted operations, controller commands and
//           modelled cost (paper Fig. 2.1).
//   fig2.4  Eq. 2.4's predicted window samples against the counts of an instrumented
//           Warnock, on A-F and on ideal scenes (paper Fig. 2.4).
#include <unistd.h>

#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "cli/common.h"
#include "cli/experiments.h"

namespace fb89::cli {

namespace {

struct ExperimentArgs {
    std::string name;
    std::vector<std::string> scenes;
    std::string csv;
    std::string size;
    std::string profile = "tms34010-50mhz";
    int repeat = 7;
    bool quiet = false;
};

std::vector<std::string> default_scenes() {
    std::vector<std::string> out;
    for (char c = 'A'; c <= 'F'; ++c)
        out.push_back(fmt::format("scenes/{}.json", c));
    return out;
}

void write_csv(const std::string& path, const Table& table) {
    std::string text = table.csv();
    if (path == "-") {
        std::cout << text;
        return;
    }
    make_parent_dirs(path);
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(fmt::format("{}: cannot write the file", path));
}

int run_experiment(const ExperimentArgs& args) {
    ExperimentSettings settings;
    settings.scenes = args.scenes.empty() ? default_scenes() : args.scenes;
    settings.repeat = args.repeat;
    settings.profile = args.profile;
    settings.progress = !args.quiet && isatty(STDERR_FILENO);
    if (!args.size.empty()) settings.size = parse_size(args.size);

    Table table;
    if (args.name == "fig2.1")
        table = experiment_fig2_1(settings);
    else if (args.name == "fig2.4")
        table = experiment_fig2_4(settings);
    else
        throw UsageError(fmt::format("unknown experiment '{}' (known: fig2.1, fig2.4)", args.name));

    if (!args.csv.empty()) write_csv(args.csv, table);
    if (!args.quiet && args.csv != "-") std::cout << table.text();
    return kSuccess;
}

}  // namespace

void register_experiment(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ExperimentArgs>();
    CLI::App* sub = app.add_subcommand("experiment", "Re-run one of the paper's experiments");
    sub->add_option("name", args->name,
                    "fig2.1 (method times on A-F) or fig2.4 (Eq. 2.4 vs counts)")
        ->required();
    sub->add_option("scenes", args->scenes, "Scenes (default scenes/A.json ... scenes/F.json)");
    sub->add_option("--csv", args->csv, "Write the results as CSV ('-' for stdout)");
    sub->add_option("--size", args->size, "Image size WxH, overriding the scenes'");
    sub->add_option("--repeat", args->repeat, "Interleaved timing rounds per method (median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--profile", args->profile, "Controller cost profile")->capture_default_str();
    sub->add_flag("--quiet,-q", args->quiet, "Print nothing but errors");
    sub->callback([args, &exit_code] { exit_code = run_experiment(*args); });
}

}  // namespace fb89::cli
