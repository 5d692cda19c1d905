// fb89_peers: our Z-buffer (and hybrid) side by side with Mesa's llvmpipe, in one process,
// on ideal scenes, seeded random triangles and scenes A-F (docs/BENCHMARKS.md).
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/peers/side_by_side.h"

int main(int argc, char** argv) {
    using namespace fb89::peers;
    CLI::App app{"fb89_peers: Z-buffer and hybrid against Mesa llvmpipe (OSMesa), interleaved"};
    SideBySideOptions options;
    std::string scenes_dir = FB89_SCENES_DIR, csv;
    bool quick = false;
    app.add_option("--repeat", options.repeat, "timed rounds per scene (median)")
        ->check(CLI::Range(1, 1000));
    app.add_option("--warmup", options.warmup, "untimed rounds first")->check(CLI::Range(0, 100));
    app.add_option("--scenes-dir", scenes_dir, "where A.json ... F.json are");
    app.add_option("--csv", csv, "write the rows as CSV to this file");
    app.add_flag("--quick", quick, "three small scenes, for tests");
    CLI11_PARSE(app, argc, argv);

    // single-threaded llvmpipe unless told otherwise, read when the context is made
    setenv("LP_NUM_THREADS", "0", 0);
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    std::cerr << "LP_NUM_THREADS=" << std::getenv("LP_NUM_THREADS")
              << " GLIBC_TUNABLES=" << (tunables ? tunables : "(unset)") << "\n";

    try {
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
            std::ofstream out(csv);
            out << csv_header() << "\n";
            for (const SideBySideRow& r : rows)
                out << csv_row(r) << "\n";
            if (!out) throw std::runtime_error("cannot write " + csv);
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
    } catch (const std::exception& e) {
        std::cerr << "fb89_peers: error: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
