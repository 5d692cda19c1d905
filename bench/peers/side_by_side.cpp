// Interleaved timing of llvmpipe against our methods, exactness, and the CSV and human
// table of the results (see side_by_side.h).
#include "bench/peers/side_by_side.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "bench/peers/ours.h"
#include "host/methods.h"
#include "host/stats.h"
#include "protocol/memory_buffer.h"

namespace fb89::peers {

namespace {

std::unique_ptr<Ours> make_ours(const std::string& method, const host::ScreenScene& scene) {
    try {
        return std::make_unique<Ours>(scene, host::method_named(method));
    } catch (const std::invalid_argument&) {
        return nullptr;  // a method this build does not have
    }
}

uint64_t differing_pixels(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
    uint64_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        n += a[i] != b[i];
    return n;
}

std::string ratio(double num, double den) {
    return den > 0 ? fmt::format("{:.2f}", num / den) : "";
}

}  // namespace

SideBySideRow measure_side_by_side(LlvmpipeRenderer& llvmpipe, const PeerScene& scene,
                                   const SideBySideOptions& options) {
    const host::ScreenScene& s = scene.screen;
    llvmpipe.upload(s);
    std::unique_ptr<Ours> zbuffer = make_ours("zbuffer", s);
    std::unique_ptr<Ours> hybrid = make_ours("hybrid", s);
    if (!zbuffer) throw std::logic_error("no zbuffer method");

    // warm-up, then interleaved rounds: llvmpipe, zbuffer, hybrid, llvmpipe, ...
    std::vector<double> peer_samples;
    for (int round = 0; round < options.warmup + options.repeat; ++round) {
        const bool timed = round >= options.warmup;
        const double t_peer = llvmpipe.render();
        const double t_z = zbuffer->render(s);
        const double t_h = hybrid ? hybrid->render(s) : 0;
        if (!timed) continue;
        peer_samples.push_back(t_peer);
        zbuffer->samples.push_back(t_z);
        if (hybrid) hybrid->samples.push_back(t_h);
    }

    SideBySideRow row;
    row.scene = scene.name;
    row.faces = s.face_count;
    row.llvmpipe_ms = median_of(peer_samples);
    row.zbuffer_ms = median_of(zbuffer->samples);

    // exactness, off the clock, from the last frames
    const std::vector<uint32_t> theirs = llvmpipe.face_ids();
    const std::vector<uint32_t> ours = controller_face_ids(zbuffer->frame);
    row.exactness = compare_face_ids(s, ours, theirs);
    if (hybrid) {
        row.hybrid_ms = median_of(hybrid->samples);
        row.hybrid_diff = differing_pixels(controller_face_ids(hybrid->frame), ours);
    }
    return row;
}

std::vector<uint32_t> our_face_ids(const host::ScreenScene& scene, const std::string& method) {
    std::unique_ptr<Ours> ours = make_ours(method, scene);
    if (!ours) throw std::invalid_argument("unknown method '" + method + "'");
    ours->render(scene);
    return controller_face_ids(ours->frame);
}

std::string csv_header() {
    return "scene,faces,llvmpipe_ms,zbuffer_ms,ratio_llvmpipe_over_zbuffer,hybrid_ms,"
           "ratio_llvmpipe_over_hybrid,coverage_mismatches,id_mismatches,depth_ties,"
           "real_mismatches,real_within_llvmpipe_float_error,max_id_mismatch_dz,"
           "hybrid_vs_zbuffer_mismatches";
}

std::string csv_row(const SideBySideRow& r) {
    const Exactness& e = r.exactness;
    return fmt::format("\"{}\",{},{:.3f},{:.3f},{},{},{},{},{},{},{},{},{:.3g},{}", r.scene,
                       r.faces, r.llvmpipe_ms, r.zbuffer_ms, ratio(r.llvmpipe_ms, r.zbuffer_ms),
                       r.hybrid_ms ? fmt::format("{:.3f}", *r.hybrid_ms) : "",
                       r.hybrid_ms ? ratio(r.llvmpipe_ms, *r.hybrid_ms) : "", e.coverage_mismatches,
                       e.id_mismatches, e.depth_ties, e.real_mismatches, e.within_float_error,
                       e.max_dz, r.hybrid_diff ? std::to_string(*r.hybrid_diff) : "");
}

std::string human_table(const std::vector<SideBySideRow>& rows) {
    std::string out = fmt::format("{:<24} {:>7} {:>9} {:>9} {:>6} {:>9} {:>6}  {}\n", "scene",
                                  "faces", "llvmpipe", "zbuffer", "ratio", "hybrid", "ratio",
                                  "exactness (zbuffer vs llvmpipe)");
    for (const SideBySideRow& r : rows) {
        const Exactness& e = r.exactness;
        std::string exact =
            e.coverage_mismatches == 0 && e.id_mismatches == 0
                ? std::string("exact")
                : fmt::format("{} coverage, {} id ({} depth ties, {} real)", e.coverage_mismatches,
                              e.id_mismatches, e.depth_ties, e.real_mismatches);
        if (e.within_float_error)
            exact +=
                fmt::format(" of which {} within llvmpipe's float error", e.within_float_error);
        if (r.hybrid_diff && *r.hybrid_diff)
            exact += fmt::format("; hybrid != zbuffer at {} px", *r.hybrid_diff);
        out += fmt::format("{:<24} {:>7} {:>9.2f} {:>9.2f} {:>6} {:>9} {:>6}  {}\n", r.scene,
                           r.faces, r.llvmpipe_ms, r.zbuffer_ms, ratio(r.llvmpipe_ms, r.zbuffer_ms),
                           r.hybrid_ms ? fmt::format("{:.2f}", *r.hybrid_ms) : "-",
                           r.hybrid_ms ? ratio(r.llvmpipe_ms, *r.hybrid_ms) : "-", exact);
    }
    out += "ms: median wall-clock per frame; ratio: llvmpipe / ours (> 1: ours is faster)\n";
    return out;
}

}  // namespace fb89::peers
