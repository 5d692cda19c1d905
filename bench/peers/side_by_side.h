// One row of the llvmpipe comparison: a scene rendered by llvmpipe and by our Z-buffer (and
// the hybrid, when make_renderer knows it) in one process, timed in interleaved rounds after
// a warm-up (DESIGN.md "Measuring"), and the face-id buffers compared for exactness.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "bench/peers/exactness.h"
#include "bench/peers/llvmpipe_renderer.h"
#include "bench/peers/peer_scenes.h"

namespace fb89::peers {

struct SideBySideOptions {
    int repeat = 21;  // timed rounds; each round is llvmpipe, zbuffer, hybrid
    int warmup = 2;   // untimed rounds first
};

struct SideBySideRow {
    std::string scene;
    uint64_t faces = 0;  // distinct ids
    double llvmpipe_ms = 0;
    double zbuffer_ms = 0;                // medians of wall-clock time per frame
    std::optional<double> hybrid_ms;      // absent when there is no "hybrid" method
    Exactness exactness;                  // zbuffer against llvmpipe
    std::optional<uint64_t> hybrid_diff;  // pixels where the hybrid's ids differ from zbuffer's
};

SideBySideRow measure_side_by_side(LlvmpipeRenderer& llvmpipe, const PeerScene& scene,
                                   const SideBySideOptions& options);

// Ours: the face-id buffer of one frame by `method` (ids + 1, row 0 at the top), through the
// command stream and the controller.
std::vector<uint32_t> our_face_ids(const host::ScreenScene& scene, const std::string& method);

std::string csv_header();
std::string csv_row(const SideBySideRow& row);
std::string human_table(const std::vector<SideBySideRow>& rows);

}  // namespace fb89::peers
