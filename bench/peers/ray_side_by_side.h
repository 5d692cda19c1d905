// One row of the Embree comparison: a world scene's primary rays traced by Embree (single
// rays, 4x4 coherent packets, single rays in robust mode) and by our `raytrace` and `beam`
// methods (no reflections) in one process, timed in interleaved rounds after a warm-up
// (DESIGN.md "Measuring"), and the face-id buffers compared pixel for pixel.
//
// What is timed differs on purpose (docs/BENCHMARKS.md): Embree fills an id buffer and
// nothing else; ours runs through render_frame into a protocol::MemoryBuffer, so its time
// also covers emitting the frame's commands (DRAW_SPAN runs, and the beam method's
// FILL_RECTs). Both generate their rays inside the timed loop.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bench/peers/embree_tracer.h"
#include "bench/peers/exactness.h"
#include "bench/peers/peer_scenes.h"
#include "host/trace/kernel_level.h"

namespace fb89::peers {

// Our face-id buffer of one frame by `method` ("raytrace" or "beam") with no reflections,
// through the command stream and the controller.
std::vector<uint32_t> our_ray_face_ids(const RayScene& scene, const std::string& method,
                                       double beam_threshold = 0.5);

struct RaySideBySideOptions {
    int repeat = 9;  // timed rounds; each round runs Embree's three and ours at every level
    int warmup = 2;  // untimed rounds first, at least
    double warmup_seconds = 1.0;  // and untimed rounds until this much time has passed
    // our kernels' instruction sets (host/trace/kernel_level.h), each its own row
    std::vector<host::KernelLevel> levels;
    double beam_threshold = 0.5;
    EmbreeQuality quality = EmbreeQuality::High;
};

struct RayRow {
    std::string scene;
    std::string isa;  // the instruction set our kernels ran with (kernel_level_name)
    int width = 0, height = 0;
    uint64_t faces = 0, triangles = 0;
    // medians of wall-clock ms per frame
    double embree_single_ms = 0, embree_packets_ms = 0, embree_robust_ms = 0;
    double raytrace_ms = 0, beam_ms = 0;
    IdAgreement vs_robust, vs_default;  // our raytrace against Embree's single rays
    uint64_t packets_vs_single = 0;     // pixels where the packets' ids differ from rtcIntersect1's
    uint64_t beam_vs_raytrace = 0;      // pixels where our two methods' ids differ
    bool level_vs_first = false;        // our frames or counts differ from the first level's
    // our counters in one frame
    uint64_t rays = 0, nodes = 0, face_tests = 0;  // raytrace: rays, BVH nodes visited, tests
    uint64_t beam_rays = 0, pixels_by_beams = 0;   // beam
    std::string embree;                            // Embree's description

    double pixels() const { return double(width) * height; }
};

// One row per level in options.levels (the current level when empty), Embree's times shared:
// every round runs Embree single, each level's raytrace, Embree packets, each level's beam,
// Embree robust.
std::vector<RayRow> measure_ray_side_by_side(const RayScene& scene,
                                             const RaySideBySideOptions& options);

std::string ray_csv_header();
std::string ray_csv_row(const RayRow& row);
std::string ray_human_table(const std::vector<RayRow>& rows);

}  // namespace fb89::peers
