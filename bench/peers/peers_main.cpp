// fb89_peers: our Z-buffer (and hybrid) side by side with Mesa's llvmpipe, in one process,
// on ideal scenes, seeded random triangles and scenes A-F; with --rays, our ray tracer and
// beam-ray hybrid side by side with Embree 3 on scenes G, H, I and the Cornell boxes
// (docs/BENCHMARKS.md).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "bench/peers/ray_side_by_side.h"
#include "bench/peers/side_by_side.h"
#include "host/trace/beam_ray_hybrid.h"
#include "host/trace/kernel_level.h"
#include "protocol/output_file.h"

namespace {

using namespace fb89::peers;

struct Args {
    int repeat = 21, warmup = 2;
    double warmup_seconds = 1.0;
    double canary_tolerance = 0.20;
    std::vector<std::string> isa;   // --rays: our kernel levels; empty: every one supported
    std::vector<std::string> only;  // --rays: these scenes; empty: all
    bool repeat_given = false;
    std::string scenes_dir = FB89_SCENES_DIR, csv, rounds_csv, size = "1024x780", quality = "high";
    bool quick = false;
    double beam_threshold = fb89::host::kDefaultBeamThreshold;  // what calibrate chose (RESULTS.md)
};

// Embree against our raytrace and beam: the scenes that exist, at the chosen size (G also
// at twice it), and a seeded world of 1,000 random triangles.
int run_rays(const Args& args) {
    RaySideBySideOptions options;
    options.repeat = args.repeat_given ? args.repeat : 9;
    options.warmup = args.warmup;
    options.warmup_seconds = args.warmup_seconds;
    options.beam_threshold = args.beam_threshold;
    for (const std::string& name : args.isa)
        options.levels.push_back(fb89::host::parse_kernel_level(name));
    if (options.levels.empty()) options.levels = fb89::host::supported_kernel_levels();
    for (fb89::host::KernelLevel level : options.levels)
        fb89::host::set_kernel_level(level);  // refused here, before any work, if unsupported
    std::cerr << "our kernels:";
    for (fb89::host::KernelLevel level : options.levels)
        std::cerr << " " << fb89::host::kernel_level_name(level) << " ("
                  << fb89::host::kernel_level_description(level) << ")";
    std::cerr << "\n";
    options.quality = parse_embree_quality(args.quality);
    options.canary_tolerance = args.canary_tolerance;
    CanaryGauge canary;
    options.canary = &canary;
    int w = 0, h = 0;
    if (std::sscanf(args.size.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1)
        throw std::invalid_argument("--size must be WxH, not '" + args.size + "'");
    if (args.quick) w = 256, h = 195;

    auto wanted = [&](const std::string& name) {
        return args.only.empty() ||
               std::find(args.only.begin(), args.only.end(), name) != args.only.end();
    };

    // each scene's rows, and how to make the scene again
    struct Measured {
        std::function<RayScene()> make;
        std::vector<RayRow> rows;
    };
    std::vector<Measured> measured;
    auto measure = [&](const Measured& m) {
        const RayScene scene = m.make();
        std::cerr << "  " << scene.name << "...\n";
        return measure_ray_side_by_side(scene, options);
    };
    for (const char* name : {"G", "H", "I", "cornell_box", "cornell_mirror"}) {
        if (!wanted(name)) continue;
        const std::filesystem::path file = args.scenes_dir + "/" + name + ".json";
        if (!std::filesystem::exists(file)) {
            std::cerr << "  " << file.string() << " does not exist: skipped\n";
            continue;
        }
        measured.push_back({[file, w, h] { return ray_file_scene(file, w, h); }, {}});
        if (name[0] == 'G' && !args.quick)
            measured.push_back({[file, w, h] { return ray_file_scene(file, 2 * w, 2 * h); }, {}});
    }
    if (!args.quick && wanted("random"))
        measured.push_back({[w, h] { return random_world_triangles(w, h, 1000, 1989); }, {}});
    for (Measured& m : measured) {
        m.rows = measure(m);
        if (&m == &measured.front() && !m.rows.empty())
            std::cerr << "peer: " << m.rows.front().embree << "\n";
    }
    // a scene measured in a spell throughout is measured again, twice at most, and the calmer
    // of its measurements kept
    for (int pass = 0; pass < 2; ++pass)
        for (Measured& m : measured) {
            if (m.rows.empty() ||
                !measured_in_a_spell(m.rows.front(), canary.best, options.canary_tolerance))
                continue;
            std::cerr << fmt::format(
                "  {} again: its canary ran {:.3f} ms, the run's best {:.3f}\n",
                m.rows.front().scene, m.rows.front().canary_ms, canary.best);
            std::vector<RayRow> again = measure(m);
            const int times = m.rows.front().measured_again + 1;
            if (!again.empty() && again.front().canary_ms < m.rows.front().canary_ms)
                m.rows = std::move(again);
            for (RayRow& r : m.rows)
                r.measured_again = times;
        }
    std::vector<RayRow> rows;
    for (Measured& m : measured)
        for (RayRow& r : m.rows)
            rows.push_back(std::move(r));

    std::cout << ray_human_table(rows);
    if (!args.csv.empty()) {
        std::string text = ray_csv_header() + "\n";
        for (const RayRow& r : rows)
            text += ray_csv_row(r) + "\n";
        fb89::protocol::write_output(args.csv, text);
    }
    if (!args.rounds_csv.empty())
        fb89::protocol::write_output(args.rounds_csv, ray_rounds_csv(rows));
    // exit 1 when our ray tracer and Embree's robust mode disagree inside a face, or when
    // the beam hybrid's or the multi-level ray tracer's ids differ from the ray tracer's
    int status = 0;
    for (const RayRow& r : rows) {
        if (r.vs_robust.interior)
            std::cerr << r.scene << ": first interior disagreement with Embree robust "
                      << r.vs_robust.first_interior << "\n";
        if (r.vs_robust.interior || r.beam_vs_raytrace || r.mlrta_vs_raytrace) {
            std::cerr << "fb89_peers: " << r.scene << " disagrees off id boundaries\n";
            status = 1;
        }
        if (r.level_vs_first) {
            std::cerr << "fb89_peers: " << r.scene << ": level " << r.isa
                      << " made another frame or other counts than the first level\n";
            status = 1;
        }
    }
    return status;
}

int run_llvmpipe(const Args& args) {
    SideBySideOptions options;
    options.repeat = args.repeat;
    options.warmup = args.warmup;
    const std::string& scenes_dir = args.scenes_dir;
    const std::string& csv = args.csv;
    const bool quick = args.quick;

    // single-threaded llvmpipe unless told otherwise, read when the context is made
    setenv("LP_NUM_THREADS", "0", 0);
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    std::cerr << "LP_NUM_THREADS=" << std::getenv("LP_NUM_THREADS")
              << " GLIBC_TUNABLES=" << (tunables ? tunables : "(unset)") << "\n";

    LlvmpipeRenderer llvmpipe;
    std::vector<SideBySideRow> rows;
    auto run = [&](const PeerScene& scene) {
        std::cerr << "  " << scene.name << "...\n";
        rows.push_back(measure_side_by_side(llvmpipe, scene, options));
        if (rows.size() == 1) std::cerr << "peer: " << llvmpipe.renderer_string() << "\n";
    };
    const int w = 1024, h = 780;
    if (quick) {
        run(random_onscreen_triangles(w, h, 1000, 700, 1989));
        run(ideal_scene(w, h, 2, 1024));
        run(file_scene(scenes_dir + "/A.json"));
    } else {
        for (int layers : {1, 2, 4})
            for (int f_v : {64, 1024, 16384})
                run(ideal_scene(w, h, layers, f_v));
        run(random_onscreen_triangles(w, h, 100, 8000, 1989));
        run(random_onscreen_triangles(w, h, 1000, 700, 1989));
        run(random_onscreen_triangles(w, h, 10000, 270, 1989));
        run(random_onscreen_triangles(w, h, 100000, 8, 1989));
        for (const char* name : {"A", "B", "C", "D", "E", "F"})
            run(file_scene(scenes_dir + "/" + name + ".json"));
    }

    std::cout << human_table(rows);
    if (!csv.empty()) {
        std::string text = csv_header() + "\n";
        for (const SideBySideRow& r : rows)
            text += csv_row(r) + "\n";
        fb89::protocol::write_output(csv, text);
    }
    // exit 1 when a check failed: coverage, or an id mismatch that is neither a depth tie
    // nor within llvmpipe's float error, or the hybrid differing from the Z-buffer
    int status = 0;
    for (const SideBySideRow& r : rows) {
        const Exactness& e = r.exactness;
        if (e.real_mismatches) std::cerr << r.scene << ": first mismatch " << e.first << "\n";
        if (e.coverage_mismatches || e.real_mismatches > e.within_float_error ||
            (r.hybrid_diff && *r.hybrid_diff)) {
            std::cerr << "fb89_peers: " << r.scene << " is not exact\n";
            status = 1;
        }
    }
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "fb89_peers: Z-buffer and hybrid against Mesa llvmpipe (OSMesa), or with "
        "--rays the ray tracer and beam-ray hybrid against Embree 3, interleaved"};
    Args args;
    bool rays = false;
    app.add_flag("--rays", rays, "Embree against our raytrace and beam instead of llvmpipe");
    app.add_option("--repeat", args.repeat, "timed rounds per scene (median; 21, with --rays 9)")
        ->check(CLI::Range(1, 1000));
    app.add_option("--warmup", args.warmup, "untimed rounds first, at least")
        ->check(CLI::Range(0, 100));
    app.add_option("--warmup-seconds", args.warmup_seconds,
                   "--rays: untimed rounds until this many seconds have passed, at least")
        ->check(CLI::Range(0.0, 600.0));
    app.add_option("--isa", args.isa,
                   "--rays: our kernels' instruction sets, each its own row: baseline, v3, v4 "
                   "(default: every one this machine runs)");
    app.add_option("--canary-tolerance", args.canary_tolerance,
                   "--rays: do a round again when the canary ran this fraction slower than its "
                   "best (0: never)")
        ->check(CLI::Range(0.0, 10.0));
    app.add_option("--only", args.only,
                   "--rays: only these scenes (G also at twice the size; random: the random world)")
        ->check(CLI::IsMember({"G", "H", "I", "cornell_box", "cornell_mirror", "random"}));
    app.add_option("--scenes-dir", args.scenes_dir, "where the scene files are");
    app.add_option("--csv", args.csv, "write the rows as CSV to this file");
    app.add_option("--rounds-csv", args.rounds_csv,
                   "--rays: write every timed round's times as CSV to this file");
    app.add_flag("--quick", args.quick, "a few small scenes, for tests");
    app.add_option("--size", args.size, "--rays: image size WxH (G also at twice it)");
    app.add_option("--beam-threshold", args.beam_threshold,
                   "--rays: the beam method's Expr. 2.7 threshold");
    app.add_option("--embree-quality", args.quality, "--rays: Embree build quality")
        ->check(CLI::IsMember({"low", "medium", "high"}));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;  // --help: 0; a usage error: 2, as fb89's own
    }
    args.repeat_given = app.count("--repeat") > 0;

    try {
        return rays ? run_rays(args) : run_llvmpipe(args);
    } catch (const std::exception& e) {
        std::cerr << "fb89_peers: error: " << e.what() << "\n";
        return 2;
    }
}
