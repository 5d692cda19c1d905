// One row of the Embree comparison: a world scene's primary rays traced by Embree (single
// rays, 4x4 coherent packets, single rays in robust mode) and by our `raytrace`, `beam` and
// `mlrta` methods (no reflections) in one process, timed in interleaved rounds after a warm-up
// (DESIGN.md "Measuring"), and the face-id buffers compared pixel for pixel.
//
// What is timed differs on purpose (docs/BENCHMARKS.md): Embree fills an id buffer and
// nothing else; ours runs through render_frame into a protocol::MemoryBuffer, so its time
// also covers emitting the frame's commands (DRAW_SPAN runs, and the beam method's
// FILL_RECTs). Both generate their rays inside the timed loop.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "bench/peers/embree_tracer.h"
#include "bench/peers/exactness.h"
#include "bench/peers/peer_scenes.h"
#include "host/trace/kernel_level.h"

namespace fb89::peers {

// Our face-id buffer of one frame by `method` ("raytrace", "beam" or "mlrta") with no reflections,
// through the command stream and the controller.
std::vector<uint32_t> our_ray_face_ids(const RayScene& scene, const std::string& method,
                                       double beam_threshold = 0.5);

// What slows the core for a while from outside the process (another virtual machine on its
// hardware) slows scalar code far more than Embree's vector code: our ray tracer by up to
// 1.8x where Embree's single rays lose under 10% (docs/BENCHMARKS.md, round 3). The canary,
// a fixed load of scalar work timed before and after every round, shows such spells; the
// fastest it ran in this process is the calm reference.
struct CanaryGauge {
    double best = INFINITY;  // ms
    double time();           // runs it once: ms
    // True when `ms` of the canary ran more than `tolerance` above its best (0: never): the
    // one rule for a round and for a whole scene
    bool slow(double ms, double tolerance) const {
        return tolerance > 0 && ms > best * (1 + tolerance);
    }
};

struct RaySideBySideOptions {
    int repeat = 9;  // timed rounds; each round runs Embree's three and ours at every level
    int warmup = 2;  // untimed rounds first, at least
    double warmup_seconds = 1.0;  // and untimed rounds until this much time has passed
    // our kernels' instruction sets (host/trace/kernel_level.h), each its own row
    std::vector<host::KernelLevel> levels;
    double beam_threshold = 0.5;
    EmbreeQuality quality = EmbreeQuality::High;
    // a round whose canary, before or after it, ran more than this fraction slower than its
    // best is done again, up to max_discarded times a scene (0: every round counts)
    double canary_tolerance = 0.20;
    int max_discarded = 40;
    CanaryGauge* canary = nullptr;  // shared across scenes; null: one of the scene's own
};

struct RayRow {
    std::string scene;
    std::string isa;  // the instruction set our kernels ran with (kernel_level_name)
    int width = 0, height = 0;
    uint64_t faces = 0, triangles = 0;
    // medians of wall-clock ms per frame
    double embree_single_ms = 0, embree_packets_ms = 0, embree_robust_ms = 0;
    double raytrace_ms = 0, beam_ms = 0, mlrta_ms = 0;
    // every timed round's wall-clock ms, in order: a round runs each of them once, within a
    // fraction of a second, so what slows the machine for a while slows a round's six alike
    struct Round {
        double embree_single = 0, raytrace = 0, embree_packets = 0, beam = 0, embree_robust = 0;
        double mlrta = 0;
        double canary = 0;  // a fixed scalar load timed after them (ray_side_by_side.cpp)
    };
    std::vector<Round> rounds;
    int discarded = 0;       // rounds done again, the canary slow
    double canary_ms = 0;    // the canary's median over the rounds kept
    int measured_again = 0;  // times the scene was measured again, its canary slow throughout
    // A ratio of two of a round's times (e.g. &Round::embree_single, &Round::raytrace) over
    // the rounds: the median, and the lower and upper quartiles. The ratios the tables give:
    // taken round by round, they are not moved by a slow spell that a median of each side's
    // times alone would catch on one side and not the other.
    struct Spread {
        double median = 0, low = 0, high = 0;
    };
    Spread ratio(double Round::*num, double Round::*den) const;
    IdAgreement vs_robust, vs_default;  // our raytrace against Embree's single rays
    uint64_t packets_vs_single = 0;     // pixels where the packets' ids differ from rtcIntersect1's
    uint64_t beam_vs_raytrace = 0;      // pixels where our beam hybrid's ids differ from raytrace's
    uint64_t mlrta_vs_raytrace = 0;     // and mlrta's
    bool level_vs_first = false;        // our frames or counts differ from the first level's
    // our counters in one frame
    uint64_t rays = 0, nodes = 0, face_tests = 0;  // raytrace: rays, BVH nodes visited, tests
    uint64_t beam_rays = 0, pixels_by_beams = 0;   // beam
    uint64_t mlrta_rays = 0, mlrta_packets = 0;    // mlrta: rays traced, packets of 8
    std::string embree;                            // Embree's description

    double pixels() const { return double(width) * height; }
};

// True when a scene's rows were measured in a spell: their canary's median ran more than
// `tolerance` above `best`, the fastest canary of the whole run. A spell can last a whole
// scene, or be on when the run starts; then every round of the scene was slow alike, the
// canary's best at the time with them, and no round was done again, so only the run's best
// tells (the harness measures such a scene again).
bool measured_in_a_spell(const RayRow& row, double best, double tolerance);

// One row per level in options.levels (the current level when empty), Embree's times shared:
// every round runs Embree single, each level's raytrace, Embree packets, each level's beam,
// Embree robust, each level's mlrta.
std::vector<RayRow> measure_ray_side_by_side(const RayScene& scene,
                                             const RaySideBySideOptions& options);

std::string ray_csv_header();
std::string ray_csv_row(const RayRow& row);
std::string ray_human_table(const std::vector<RayRow>& rows);
// Every timed round of every row, one line each: scene, isa, round, and its six times.
std::string ray_rounds_csv(const std::vector<RayRow>& rows);

}  // namespace fb89::peers
