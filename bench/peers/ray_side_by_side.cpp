// Interleaved timing of Embree against our ray tracer, beam-ray hybrid and multi-level ray
// tracer, face-id
// agreement, and the CSV and human table of the results (see ray_side_by_side.h).
#include "bench/peers/ray_side_by_side.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "bench/peers/ours.h"
#include "host/methods.h"
#include "host/stats.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_writer.h"

namespace fb89::peers {

namespace {

// One of our methods with no reflections (primary visibility, as Embree's side).
host::MethodOptions primary(const std::string& method, double beam_threshold) {
    host::MethodOptions options(host::method_named(method));
    options.trace.max_reflections = 0;
    options.beam.threshold = beam_threshold;
    return options;
}

// One Embree frame, timed like render_frame: wall-clock ms.
template <class Trace>
double time_embree(Trace&& trace) {
    const auto start = std::chrono::steady_clock::now();
    trace();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

uint64_t differing_pixels(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
    uint64_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        n += a[i] != b[i];
    return n;
}

double mrays(double pixels, double ms) {
    return ms > 0 ? pixels / ms / 1000.0 : 0;
}

// a paired ratio's median, as the tables print it
std::string paired(const RayRow& r, double RayRow::Round::*num, double RayRow::Round::*den) {
    const RayRow::Spread q = r.ratio(num, den);
    return q.median > 0 ? fmt::format("{:.2f}", q.median) : "";
}

// half the interquartile range of a paired ratio, in % of its median
std::string spread_cell(const RayRow& r, double RayRow::Round::*num, double RayRow::Round::*den) {
    const RayRow::Spread q = r.ratio(num, den);
    return q.median > 0 ? fmt::format("{:.1f}", 50.0 * (q.high - q.low) / q.median) : "";
}

std::string agreement_cell(const IdAgreement& a) {
    return fmt::format("{:.4f}% ({} px: {} edge, {} diag, {} inside)", 100.0 * a.agreement(),
                       a.differ, a.on_boundary, a.diagonal, a.interior);
}

}  // namespace

// A fixed load of scalar integer work, eight independent chains (many instructions a cycle, as
// our ray tracer's scalar code).
double CanaryGauge::time() {
    const auto start = std::chrono::steady_clock::now();
    uint64_t v[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    for (int i = 0; i < 800000; ++i)
        for (uint64_t& x : v) {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            asm volatile("" : "+r"(x));  // kept scalar: no vector form of the chains
        }
    uint64_t all = 0;
    for (uint64_t x : v)
        all += x;
    asm volatile("" : : "r"(all));
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, ms);
    return ms;
}

bool measured_in_a_spell(const RayRow& row, double best, double tolerance) {
    return CanaryGauge{best}.slow(row.canary_ms, tolerance);
}

RayRow::Spread RayRow::ratio(double Round::*num, double Round::*den) const {
    std::vector<double> v;
    for (const Round& r : rounds)
        if (r.*den > 0) v.push_back(r.*num / r.*den);
    if (v.empty()) return {};
    std::sort(v.begin(), v.end());
    // quartiles by nearest rank; with 9 rounds the 3rd and 7th ratios
    const size_t n = v.size();
    return {median_of(v), v[(n - 1) / 4], v[(3 * (n - 1) + 3) / 4]};
}

std::vector<uint32_t> our_ray_face_ids(const RayScene& scene, const std::string& method,
                                       double beam_threshold) {
    Ours ours(scene.screen, primary(method, beam_threshold));
    ours.render(scene.screen);
    return controller_face_ids(ours.frame);
}

std::vector<RayRow> measure_ray_side_by_side(const RayScene& scene,
                                             const RaySideBySideOptions& options) {
    const host::ScreenScene& s = scene.screen;
    // set-up, untimed: Embree's BVHs, and ours at each level (a tracer keeps the level it was
    // made at)
    EmbreeOptions eo;
    eo.quality = options.quality;
    EmbreeTracer embree(*scene.world, eo);
    eo.robust = true;
    EmbreeTracer robust(*scene.world, eo);
    const std::vector<host::KernelLevel> levels =
        options.levels.empty() ? std::vector<host::KernelLevel>{host::kernel_level()}
                               : options.levels;
    const host::KernelLevel was = host::kernel_level();
    std::vector<std::unique_ptr<Ours>> raytrace, beam, mlrta;
    for (host::KernelLevel level : levels) {
        host::set_kernel_level(level);
        raytrace.push_back(std::make_unique<Ours>(s, primary("raytrace", options.beam_threshold)));
        beam.push_back(std::make_unique<Ours>(s, primary("beam", options.beam_threshold)));
        mlrta.push_back(std::make_unique<Ours>(s, primary("mlrta", options.beam_threshold)));
    }
    host::set_kernel_level(was);

    // warm-up (at least `warmup` rounds and `warmup_seconds`: the first scene of a run meets
    // cold pages and clocks), then interleaved rounds
    std::vector<uint32_t> single_ids, packet_ids, robust_ids;
    std::vector<double> single_t, packet_t, robust_t, canary_t;
    CanaryGauge own;
    CanaryGauge& canary = options.canary ? *options.canary : own;
    int discarded = 0;
    const auto start = std::chrono::steady_clock::now();
    auto warm = [&](int round) {
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return round < options.warmup || seconds < options.warmup_seconds;
    };
    int timed_rounds = 0;
    // the canary before a round is the one after the round before it (run once at the start)
    double t_canary = canary.time();
    for (int round = 0; timed_rounds < options.repeat; ++round) {
        const bool timed = !warm(round);
        const double calm_before = t_canary;
        const double t1 = time_embree([&] { embree.trace_single(single_ids); });
        std::vector<double> t_ray, t_beam;
        for (auto& r : raytrace)
            t_ray.push_back(r->render(s));
        const double t16 = time_embree([&] { embree.trace_packets(packet_ids); });
        for (auto& b : beam)
            t_beam.push_back(b->render(s));
        const double t_robust = time_embree([&] { robust.trace_single(robust_ids); });
        std::vector<double> t_ml;
        for (auto& m : mlrta)
            t_ml.push_back(m->render(s));
        t_canary = canary.time();
        if (!timed) continue;
        // a round the core ran it slower, before or after, is done again (up to a limit)
        if ((canary.slow(calm_before, options.canary_tolerance) ||
             canary.slow(t_canary, options.canary_tolerance)) &&
            discarded < options.max_discarded) {
            ++discarded;
            continue;
        }
        canary_t.push_back(t_canary);
        ++timed_rounds;
        single_t.push_back(t1);
        packet_t.push_back(t16);
        robust_t.push_back(t_robust);
        for (size_t l = 0; l < levels.size(); ++l) {
            raytrace[l]->samples.push_back(t_ray[l]);
            beam[l]->samples.push_back(t_beam[l]);
            mlrta[l]->samples.push_back(t_ml[l]);
        }
    }

    std::vector<RayRow> rows;
    for (size_t l = 0; l < levels.size(); ++l) {
        RayRow row;
        row.scene = scene.name;
        row.isa = std::string(host::kernel_level_name(levels[l]));
        row.width = s.width;
        row.height = s.height;
        row.faces = s.face_count;
        row.triangles = embree.triangles();
        row.embree = embree.description();
        row.embree_single_ms = median_of(single_t);
        row.embree_packets_ms = median_of(packet_t);
        row.embree_robust_ms = median_of(robust_t);
        row.raytrace_ms = median_of(raytrace[l]->samples);
        row.beam_ms = median_of(beam[l]->samples);
        row.mlrta_ms = median_of(mlrta[l]->samples);
        row.discarded = discarded;
        row.canary_ms = median_of(canary_t);
        for (size_t i = 0; i < single_t.size(); ++i)
            row.rounds.push_back({single_t[i], raytrace[l]->samples[i], packet_t[i],
                                  beam[l]->samples[i], robust_t[i], mlrta[l]->samples[i],
                                  canary_t[i]});

        // agreement, off the clock, from the last frames
        const std::vector<uint32_t> ours = controller_face_ids(raytrace[l]->frame);
        row.vs_robust = compare_with_boundaries(s.width, s.height, ours, robust_ids);
        row.vs_default = compare_with_boundaries(s.width, s.height, ours, single_ids);
        row.packets_vs_single = differing_pixels(packet_ids, single_ids);
        row.beam_vs_raytrace = differing_pixels(controller_face_ids(beam[l]->frame), ours);
        row.mlrta_vs_raytrace = differing_pixels(controller_face_ids(mlrta[l]->frame), ours);
        // every level makes the same frame, to the byte
        auto bytes = [](const Ours& o) { return protocol::encode_stream(o.frame.commands()); };
        row.level_vs_first = bytes(*raytrace[l]) != bytes(*raytrace[0]) ||
                             bytes(*beam[l]) != bytes(*beam[0]) ||
                             bytes(*mlrta[l]) != bytes(*mlrta[0]);

        // our counters, from the last frames
        const host::Counters& rc = raytrace[l]->stats.counters;
        row.rays = rc.get("rays");
        row.nodes = rc.get("bvh_nodes_visited");
        row.face_tests = rc.get("ray_face_tests");
        row.beam_rays = beam[l]->stats.counters.get("rays");
        row.pixels_by_beams = beam[l]->stats.counters.get("pixels_by_beams");
        row.mlrta_rays = mlrta[l]->stats.counters.get("rays");
        row.mlrta_packets = mlrta[l]->stats.counters.get("packets");
        row.level_vs_first =
            row.level_vs_first ||
            rc.get("bvh_nodes_visited") != raytrace[0]->stats.counters.get("bvh_nodes_visited");
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string ray_csv_header() {
    return "scene,isa,width,height,faces,triangles,embree_single_ms,embree_packets_ms,"
           "embree_robust_ms,raytrace_ms,beam_ms,embree_single_mrays,embree_packets_mrays,"
           "embree_robust_mrays,raytrace_mrays,beam_mpixels,raytrace_over_embree_single,"
           "raytrace_over_embree_robust,beam_over_embree_single,beam_over_embree_packets,"
           "vs_robust_differ,vs_robust_coverage,vs_robust_boundary,vs_robust_diagonal,"
           "vs_robust_interior,vs_default_differ,vs_default_coverage,vs_default_boundary,"
           "vs_default_diagonal,vs_default_interior,"
           "packets_vs_single,beam_vs_raytrace,raytrace_rays,nodes_per_ray,face_tests_per_ray,"
           "beam_rays,pixels_by_beams,rounds,raytrace_over_embree_single_q1,"
           "raytrace_over_embree_single_q3,beam_over_embree_packets_q1,"
           "beam_over_embree_packets_q3,embree_single_min_ms,raytrace_min_ms,beam_min_ms,canary_ms,"
           "discarded_rounds,measured_again,mlrta_ms,mlrta_mpixels,mlrta_over_raytrace,"
           "embree_packets_over_mlrta,embree_packets_over_mlrta_q1,embree_packets_over_mlrta_q3,"
           "mlrta_vs_raytrace,mlrta_rays,mlrta_packets";
}

std::string ray_csv_row(const RayRow& r) {
    using R = RayRow::Round;
    const double px = r.pixels();
    const IdAgreement &a = r.vs_robust, &b = r.vs_default;
    const double rays = r.rays ? double(r.rays) : 1.0;
    const RayRow::Spread rt = r.ratio(&R::embree_single, &R::raytrace),
                         bm = r.ratio(&R::embree_packets, &R::beam),
                         ml = r.ratio(&R::embree_packets, &R::mlrta);
    auto least = [&](double R::*field) {
        double m = INFINITY;
        for (const R& round : r.rounds)
            m = std::min(m, round.*field);
        return r.rounds.empty() ? 0.0 : m;
    };
    return fmt::format(
        "\"{}\",{},{},{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.2f},{:.2f},{:.2f},{:.2f},{:."
        "2f},"
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{:.2f},{:.2f},{},{},"
        "{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{},{},{:.3f},{:.2f},{},{},"
        "{:.3f},{:.3f},{},{},{}",
        r.scene, r.isa, r.width, r.height, r.faces, r.triangles, r.embree_single_ms,
        r.embree_packets_ms, r.embree_robust_ms, r.raytrace_ms, r.beam_ms,
        mrays(px, r.embree_single_ms), mrays(px, r.embree_packets_ms),
        mrays(px, r.embree_robust_ms), mrays(px, r.raytrace_ms), mrays(px, r.beam_ms),
        paired(r, &R::embree_single, &R::raytrace), paired(r, &R::embree_robust, &R::raytrace),
        paired(r, &R::embree_single, &R::beam), paired(r, &R::embree_packets, &R::beam), a.differ,
        a.coverage, a.on_boundary, a.diagonal, a.interior, b.differ, b.coverage, b.on_boundary,
        b.diagonal, b.interior, r.packets_vs_single, r.beam_vs_raytrace, r.rays,
        double(r.nodes) / rays, double(r.face_tests) / rays, r.beam_rays, r.pixels_by_beams,
        r.rounds.size(), rt.low, rt.high, bm.low, bm.high, least(&R::embree_single),
        least(&R::raytrace), least(&R::beam), r.canary_ms, r.discarded, r.measured_again,
        r.mlrta_ms, mrays(px, r.mlrta_ms), paired(r, &R::raytrace, &R::mlrta),
        paired(r, &R::embree_packets, &R::mlrta), ml.low, ml.high, r.mlrta_vs_raytrace,
        r.mlrta_rays, r.mlrta_packets);
}

std::string ray_rounds_csv(const std::vector<RayRow>& rows) {
    std::string out =
        "scene,isa,round,embree_single_ms,raytrace_ms,embree_packets_ms,beam_ms,"
        "embree_robust_ms,mlrta_ms,canary_ms\n";
    for (const RayRow& r : rows)
        for (size_t i = 0; i < r.rounds.size(); ++i) {
            const RayRow::Round& t = r.rounds[i];
            out += fmt::format("\"{}\",{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f}\n",
                               r.scene, r.isa, i + 1, t.embree_single, t.raytrace, t.embree_packets,
                               t.beam, t.embree_robust, t.mlrta, t.canary);
        }
    return out;
}

std::string ray_human_table(const std::vector<RayRow>& rows) {
    using R = RayRow::Round;
    std::string out = fmt::format(
        "{:<32} {:<8} {:>6} {:>8} {:>8} {:>8} {:>8} {:>8} {:>6} {:>5} {:>6} {:>6} {:>6} {:>5} "
        "{:>6}\n",
        "scene", "isa", "faces", "embree1", "embree16", "robust1", "raytrace", "beam", "rt/e1",
        "±%", "rt/rb", "bm/e1", "bm/e16", "±%", "bm/rt");
    for (const RayRow& r : rows)
        out += fmt::format(
            "{:<32} {:<8} {:>6} {:>8.2f} {:>8.2f} {:>8.2f} {:>8.2f} {:>8.2f} {:>6} {:>5} {:>6} "
            "{:>6} {:>6} {:>5} {:>6}\n",
            r.scene, r.isa, r.faces, r.embree_single_ms, r.embree_packets_ms, r.embree_robust_ms,
            r.raytrace_ms, r.beam_ms, paired(r, &R::embree_single, &R::raytrace),
            spread_cell(r, &R::embree_single, &R::raytrace),
            paired(r, &R::embree_robust, &R::raytrace), paired(r, &R::embree_single, &R::beam),
            paired(r, &R::embree_packets, &R::beam), spread_cell(r, &R::embree_packets, &R::beam),
            paired(r, &R::beam, &R::raytrace));
    out +=
        "ms: median wall-clock per frame; ratios: Embree time / ours (> 1: ours is faster), the\n"
        "median of each round's ratio; ±%: half their interquartile range, in % of the median;\n"
        "bm/rt: our beam hybrid's time over our ray tracer's (< 1: the beams pay)\n\n";
    out += fmt::format("{:<32} {:<8} {:>8} {:>8} {:>6} {:>6} {:>5} {:>9} {:>9}\n", "mlrta", "isa",
                       "ms", "embree16", "rt/ml", "e16/ml", "±%", "rays", "packets");
    for (const RayRow& r : rows)
        out += fmt::format(
            "{:<32} {:<8} {:>8.2f} {:>8.2f} {:>6} {:>6} {:>5} {:>9} {:>9}\n", r.scene, r.isa,
            r.mlrta_ms, r.embree_packets_ms, paired(r, &R::raytrace, &R::mlrta),
            paired(r, &R::embree_packets, &R::mlrta), spread_cell(r, &R::embree_packets, &R::mlrta),
            r.mlrta_rays, r.mlrta_packets);
    out +=
        "mlrta: the multi-level ray tracer (its beams, then packets of 8 rays); rt/ml: our ray\n"
        "tracer's time over it, e16/ml: Embree's 16-ray packets' (> 1: mlrta is faster)\n";
    // the canary per scene (its rounds are shared by the scene's rows)
    std::string last;
    for (const RayRow& r : rows) {
        if (r.scene == last) continue;
        last = r.scene;
        out += fmt::format("canary {:<32} {:.3f} ms, {} round{} done again{}\n", r.scene,
                           r.canary_ms, r.discarded, r.discarded == 1 ? "" : "s",
                           r.measured_again > 0
                               ? fmt::format(", the scene measured again {}x", r.measured_again)
                               : "");
    }
    out +=
        "canary: a fixed scalar load timed before and after each round; a round either ran\n"
        "over --canary-tolerance slower than its best is done again, and a scene whose canary\n"
        "ran so throughout is measured again, twice at most (BENCHMARKS.md, round 3)\n\n";

    out += fmt::format("{:<32} {:<8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>7} {:>7} {:>9}\n", "Mrays/s",
                       "isa", "embree1", "embree16", "robust1", "raytrace", "beam*", "nodes/r",
                       "tests/r", "beam rays");
    for (const RayRow& r : rows) {
        const double px = r.pixels(), rays = r.rays ? double(r.rays) : 1.0;
        out += fmt::format(
            "{:<32} {:<8} {:>8.2f} {:>8.2f} {:>8.2f} {:>8.2f} {:>8.2f} {:>7.2f} {:>7.2f} {:>9}\n",
            r.scene, r.isa, mrays(px, r.embree_single_ms), mrays(px, r.embree_packets_ms),
            mrays(px, r.embree_robust_ms), mrays(px, r.raytrace_ms), mrays(px, r.beam_ms),
            double(r.nodes) / rays, double(r.face_tests) / rays, r.beam_rays);
    }
    out +=
        "beam*: Mpixels/s (it traces fewer rays than pixels); nodes/r, tests/r: our raytrace's\n"
        "BVH nodes visited and ray-face tests per ray\n\n";

    out += fmt::format("{:<32} {:<8} {:<46} {:<46} {:>9} {:>9} {:>9} {:>9}\n",
                       "agreement (our raytrace)", "isa", "vs Embree robust", "vs Embree default",
                       "e16!=e1", "beam!=rt", "mlrta!=rt", "levels");
    for (const RayRow& r : rows)
        out += fmt::format("{:<32} {:<8} {:<46} {:<46} {:>9} {:>9} {:>9} {:>9}\n", r.scene, r.isa,
                           agreement_cell(r.vs_robust), agreement_cell(r.vs_default),
                           r.packets_vs_single, r.beam_vs_raytrace, r.mlrta_vs_raytrace,
                           r.level_vs_first ? "DIFFER" : "same");
    out +=
        "edge: on an id boundary of ours (a 4-neighbour with another id); diag: another id\n"
        "only diagonally; inside: all 8 neighbours have ours' id; levels: our frames (commands,\n"
        "byte for byte) and counts against the first level's\n";
    return out;
}

}  // namespace fb89::peers
