// How fast the emulated GSP executes the executive (controller_sim/gsp_board.h), beside the
// C++ controller's model on the same commands: rounds interleaved (the order alternating),
// medians of wall time, each stream read into memory first. Issue 67 asks for at least 100
// million TMS34010 instructions a second on the depth-tested replay of F, and for the demo's
// Z-buffer stream replayed through the GSP at no more than 20 times the model's cost.
//
//     build/bench/fb89_gsp_bench DEPTH_STREAM DEPTH_PROFILE ZBUFFER_STREAM [ROUNDS]
//
// scripts/bench-gsp renders the streams and runs it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "controller_sim/controller.h"
#include "controller_sim/gsp_board.h"
#include "controller_sim/gsp_listing.h"
#include "controller_sim/profile.h"
#include "protocol/stream_reader.h"

namespace {

using namespace fb89;

std::vector<protocol::Command> read_all(const std::string& file) {
    protocol::StreamReader reader(file);
    std::vector<protocol::Command> all, batch(4096);
    while (const std::size_t n = reader.read_batch(batch))
        all.insert(all.end(), batch.begin(), batch.begin() + static_cast<std::ptrdiff_t>(n));
    return all;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct GspRun {
    double seconds = 0;
    uint64_t instructions = 0;
};

GspRun run_gsp(const controller::CostProfile& p, const std::vector<protocol::Command>& c) {
    controller::gsp::GspBoard board(p, "tms34010.asm", controller::builtin_listing(p.gsp).text);
    const auto start = std::chrono::steady_clock::now();
    board.execute(c);
    const auto end = std::chrono::steady_clock::now();
    return {std::chrono::duration<double>(end - start).count(),
            board.cpu().counters().instructions};
}

double run_model(const controller::CostProfile& p, const std::vector<protocol::Command>& c) {
    controller::Controller ctl(p);
    const auto start = std::chrono::steady_clock::now();
    ctl.execute(c);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr,
                     "usage: fb89_gsp_bench DEPTH_STREAM DEPTH_PROFILE ZBUFFER_STREAM [ROUNDS]\n");
        return 2;
    }
    const int rounds = argc > 4 ? std::atoi(argv[4]) : 9;
    if (rounds < 1 || rounds > 1000) {
        std::fprintf(stderr, "fb89_gsp_bench: ROUNDS \"%s\": a whole number from 1 to 1000\n",
                     argv[4]);
        return 2;
    }
    try {
        const auto depth = read_all(argv[1]);
        const auto zbuffer = read_all(argv[3]);
        const controller::CostProfile depth_profile = controller::load_profile(argv[2]);
        const controller::CostProfile profile = controller::default_profile();
        std::vector<double> depth_rate, gsp_s, model_s;
        uint64_t instructions = 0, zbuffer_instructions = 0;
        for (int r = -1; r < rounds; ++r) {  // round -1 warms up
            const GspRun d = run_gsp(depth_profile, depth);
            double g = 0, m = 0;
            for (int k = 0; k < 2; ++k) {
                if ((k + r) % 2 == 0) {
                    const GspRun z = run_gsp(profile, zbuffer);
                    g = z.seconds;
                    zbuffer_instructions = z.instructions;
                } else {
                    m = run_model(profile, zbuffer);
                }
            }
            if (r < 0) continue;
            instructions = d.instructions;
            depth_rate.push_back(static_cast<double>(d.instructions) / d.seconds / 1e6);
            gsp_s.push_back(g);
            model_s.push_back(m);
        }
        std::printf(
            "depth-tested replay of %s: %llu instructions, %.1f M instructions/s "
            "(median of %d)\n",
            argv[1], static_cast<unsigned long long>(instructions), median(depth_rate), rounds);
        std::printf(
            "%s: %llu instructions; the GSP %.4f s, the model %.4f s: %.1f times the "
            "model's cost (medians of %d, interleaved)\n",
            argv[3], static_cast<unsigned long long>(zbuffer_instructions), median(gsp_s),
            median(model_s), median(gsp_s) / median(model_s), rounds);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fb89_gsp_bench: %s\n", e.what());
        return 2;
    }
    return 0;
}
