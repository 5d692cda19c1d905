// fb89_growth: how time and memory grow with the scene. A ladder of seeded terrains from
// 1,024 to 1,048,576 faces (bench/growth/ladder.h), the top rung also read back from an OBJ
// file, each rendered by the Z-buffer, the hybrid, the ray tracer and the beam hybrid in a
// child process of its own; writes growth.csv, growth_slopes.csv and growth.md into --out
// and prints the markdown. scripts/bench-growth runs it and draws the chart.
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/growth/child_process.h"
#include "bench/growth/growth_run.h"
#include "bench/growth/report.h"
#include "protocol/output_file.h"

namespace {

using namespace fb89;

// The largest rung the terrain generator makes (it stops at 10M faces): 2048 x 1024 cells.
constexpr uint64_t kMaxRungFaces = uint64_t{1} << 22;

void write_text(const std::filesystem::path& file, const std::string& text) {
    protocol::write_output(file, text);
}

int run(const std::filesystem::path& out, const growth::GrowthOptions& options) {
    std::filesystem::create_directories(out);
    const uint64_t baseline = growth::baseline_peak_rss();
    const std::vector<growth::Measurement> runs = growth::run_ladder(options);
    const std::vector<growth::Slope> slopes = growth::fit_slopes(runs, baseline);
    const std::string md = growth::markdown(runs, slopes, baseline);
    write_text(out / "growth.csv", growth::runs_csv(runs, baseline));
    write_text(out / "growth_slopes.csv", growth::slopes_csv(slopes));
    write_text(out / "growth.md", md);
    std::cout << md << "\nrows in " << (out / "growth.csv").string() << "\n";
    // exit 1 when a run failed or a method's memory outgrew its input
    int status = 0;
    for (const growth::Measurement& m : runs)
        status |= !m.ok || m.loaded_faces != m.faces;
    for (const growth::MemoryVerdict& v : growth::memory_verdicts(slopes))
        status |= v.faster_than_input;
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"fb89_growth: time and peak memory against face count, per method"};
    growth::GrowthOptions options;
    std::vector<std::string> methods{"zbuffer", "hybrid", "raytrace", "beam"};
    std::string obj = "top";
    std::filesystem::path out = "growth", scenes;
    app.add_option("--out", out, "folder for the tables")->capture_default_str();
    app.add_option("--scenes", scenes, "folder for the rungs' scene files (default OUT/scenes)");
    app.add_option("--max-faces", options.max_faces,
                   "largest rung (rungs have 4^k faces; suffixes k and M are 1024 and 1024^2)")
        ->transform(CLI::AsSizeValue(false))
        ->check(CLI::Range(uint64_t{1}, kMaxRungFaces, "at most 4M (the generator's limit)"))
        ->capture_default_str();
    app.add_option("--min-faces", options.min_faces, "smallest rung")
        ->transform(CLI::AsSizeValue(false))
        ->check(CLI::Range(uint64_t{1}, kMaxRungFaces, "at most 4M (the generator's limit)"))
        ->capture_default_str();
    app.add_option("--methods", methods, "methods to run")->capture_default_str();
    app.add_option("--obj", obj, "rungs also read from an OBJ file: top, all or none")
        ->check(CLI::IsMember({"top", "all", "none"}))
        ->capture_default_str();
    app.add_option("--repeat", options.repeat,
                   "runs per rung and method (median times, largest peak)")
        ->check(CLI::Range(1, 101))
        ->capture_default_str();
    app.add_flag("--keep-obj", options.keep_obj, "keep the OBJ files (removed by default)");
    app.add_option("--timeout", options.timeout_s, "seconds one run may take (0: no limit)")
        ->capture_default_str();
    app.add_flag(
        "--quiet", [&](int64_t) { options.progress = false; }, "no line per run");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;  // --help: 0; a usage error: 2, as fb89's own
    }
    try {
        options.methods.clear();
        for (const std::string& name : methods)
            options.methods.push_back(host::method_named(name));
        const std::map<std::string, growth::GrowthOptions::Obj> objs{
            {"top", growth::GrowthOptions::Obj::Top},
            {"all", growth::GrowthOptions::Obj::All},
            {"none", growth::GrowthOptions::Obj::None}};
        options.obj = objs.at(obj);
        options.scenes = scenes.empty() ? out / "scenes" : scenes;
        return run(out, options);
    } catch (const std::exception& e) {
        std::cerr << "fb89_growth: " << e.what() << "\n";
        return 2;
    }
}
