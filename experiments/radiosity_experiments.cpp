// The paper's §5 experiments: intervisibility by flux tracing against the decahedral
// hybrid, and form factors and radiosities against a reference.
//   radiosity  rays, volume queries and form-factor time, flux vs hybrid, per room, timed
//              interleaved (the paper's table; its numbers beside ours in RESULTS.md);
//   ff-error   form-factor error against time for flux tracing (centre form), the disk
//              form, hemicubes of several resolutions and the hybrid;
//   radiosity-error  radiosity error against time for the same methods, each solved.
// The reference: exact unoccluded form factors (contour integral) times a fractional
// visibility from many rays between points spread over both patches, and its own error is
// stated (the spread between two reference estimates of different ray counts).
#include <cmath>
#include <functional>
#include <iostream>

#include <fmt/format.h>

#include "experiments/experiments.h"
#include "experiments/measure.h"
#include "experiments/period_runs.h"
#include "host/radiosity/exact.h"
#include "host/radiosity/form_factors.h"
#include "host/radiosity/hemicube.h"
#include "host/radiosity/mesh.h"
#include "host/radiosity/solver.h"
#include "host/radiosity/visibility.h"
#include "host/scene/scene_loader.h"
#include "host/trace/grid.h"
#include "host/trace/trace_scene.h"

namespace fb89::experiments {

namespace {

// A room made ready: scene, mesh, traced scene and grid.
struct Room {
    host::Scene scene;
    host::Mesh mesh;
    std::unique_ptr<host::TraceScene> trace;
    std::unique_ptr<host::UniformGrid> grid;
    host::RadiosityWorld world() const { return {*trace, *grid}; }
};

// The --patches that mesh the bundled rooms nearest the paper's counts (832 and 1,348
// patches; scenes/README.md), else about 800.
int default_patches(const std::string& file) {
    if (file.find("garish_room") != std::string::npos) return 820;
    if (file.find("programmers_cell") != std::string::npos) return 1070;
    return 800;
}

Room load_room(const std::string& file, int patches) {
    Room r;
    if (patches <= 0) patches = default_patches(file);
    r.scene = host::load_scene(file);
    r.mesh = host::mesh_scene(r.scene, {host::patch_size_for(r.scene, patches), 64});
    r.trace = std::make_unique<host::TraceScene>(r.scene, true, 0);
    r.grid = std::make_unique<host::UniformGrid>(*r.trace);
    return r;
}

struct VisibilityRun {
    host::Visibility delta;
    host::VisibilityCounts counts;
    std::vector<double> form_factors;
    host::Timing time;
};

VisibilityRun run_visibility(const Room& room, bool hybrid) {
    VisibilityRun run;
    host::Stopwatch clock;
    run.delta = hybrid ? host::decahedral_hybrid(room.mesh, room.world(), {}, run.counts)
                       : host::flux_tracing(room.mesh, room.world(), run.counts);
    run.form_factors =
        host::centre_form_factors(room.mesh, run.delta, host::CentreForm::PointToPoint);
    run.time = clock.elapsed();
    return run;
}

// Fractional visibility by `n` x `n` points on each patch (n^4 rays per pair), times the
// exact unoccluded form factor: the reference.
std::vector<double> reference_form_factors(const Room& room, int n);

}  // namespace

Table experiment_radiosity(const ExperimentSettings& s, int patches) {
    Table table({"scene", "faces", "patches", "facing_pairs", "method", "rays", "volume_queries",
                 "empty_queries", "pairs_by_queries", "ff_cpu_ms", "ratio_to_flux", "same_delta"});
    for (const auto& file : s.scenes) {
        const Room room = load_room(file, patches);
        std::vector<host::Timing> flux_t, hybrid_t;
        VisibilityRun flux, hybrid;
        interleave(2, s.period ? 0 : s.repeat, file, s.progress && !s.period,
                   [&](size_t m, bool timed) {
                       const bool use_hybrid = m == 1;
                       VisibilityRun run = run_visibility(room, use_hybrid);
                       if (timed) (use_hybrid ? hybrid_t : flux_t).push_back(run.time);
                       (use_hybrid ? hybrid : flux) = std::move(run);
                   });
        double flux_ms = host::median(flux_t).cpu_ms;
        double hybrid_ms = host::median(hybrid_t).cpu_ms;
        if (s.period) {
            // on a 1989 host: the same δ and form factors, counted once each and priced
            const std::string n = std::to_string(patches > 0 ? patches : default_patches(file));
            s.period->set_progress(s.progress, file);
            const auto costs = s.period->run({{file, {"--radiosity", "flux", "--patches", n}},
                                              {file, {"--radiosity", "hybrid", "--patches", n}}});
            const int hs = static_cast<int>(period::Phase::HiddenSurface);
            flux_ms = costs[0].phases[hs].ms;
            hybrid_ms = costs[1].phases[hs].ms;
        }
        const bool same = flux.delta == hybrid.delta;
        for (int m = 0; m < 2; ++m) {
            const VisibilityRun& r = m == 0 ? flux : hybrid;
            const double ms = m == 0 ? flux_ms : hybrid_ms;
            table.add({file, std::to_string(room.scene.face_count),
                       std::to_string(room.mesh.patches.size()),
                       std::to_string(r.counts.facing_pairs), m == 0 ? "flux" : "hybrid",
                       std::to_string(r.counts.rays), std::to_string(r.counts.queries),
                       std::to_string(r.counts.empty_queries),
                       std::to_string(r.counts.pairs_by_queries), fixed(ms, 2),
                       fixed(ms / flux_ms, 3), same ? "yes" : "NO"});
        }
    }
    return table;
}

namespace {

std::vector<double> reference_form_factors(const Room& room, int n) {
    const auto& mesh = room.mesh;
    const uint32_t count = static_cast<uint32_t>(mesh.patches.size());
    host::Visibility visible(count);
    for (uint32_t p = 0; p < count; ++p)
        for (uint32_t q = p + 1; q < count; ++q)
            if (host::facing(mesh, p, q)) visible.set(p, q, host::Delta::Visible);
    std::vector<double> f = host::exact_form_factors(mesh, visible);
    // fractional visibility: the share of n^2 x n^2 point pairs whose segment is clear
    auto point = [&](const host::Patch& patch, int a, int b) {
        const host::Element& e = mesh.elements[patch.element];
        const double s = (patch.i + (a + 0.5) / n) / e.nu, t = (patch.j + (b + 0.5) / n) / e.nv;
        return e.point(s, t);
    };
    host::FluxTracer segments(mesh, room.world());
    for (uint32_t p = 0; p < count; ++p)
        for (uint32_t q = p + 1; q < count; ++q) {
            if (f[static_cast<size_t>(p) * count + q] == 0) continue;
            const host::Patch& pp = mesh.patches[p];
            const host::Patch& qq = mesh.patches[q];
            const uint32_t skip_a = mesh.elements[pp.element].piece;
            const uint32_t skip_b = mesh.elements[qq.element].piece;
            int clear = 0, all = 0;
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b)
                    for (int c = 0; c < n; ++c)
                        for (int d = 0; d < n; ++d) {
                            clear +=
                                !segments.blocked(point(pp, a, b), point(qq, c, d), skip_a, skip_b);
                            ++all;
                        }
            const double share = static_cast<double>(clear) / all;
            f[static_cast<size_t>(p) * count + q] *= share;
            f[static_cast<size_t>(q) * count + p] *= share;
        }
    return f;
}

// Mean absolute form-factor error, weighted by the source patch's area over the total.
double form_factor_error(const host::Mesh& mesh, const std::vector<double>& f,
                         const std::vector<double>& ref) {
    const size_t n = mesh.patches.size();
    double total_area = 0, err = 0;
    for (size_t i = 0; i < n; ++i) {
        double row = 0;
        for (size_t j = 0; j < n; ++j)
            row += std::abs(f[i * n + j] - ref[i * n + j]);
        err += mesh.patches[i].area * row;
        total_area += mesh.patches[i].area;
    }
    return err / total_area;
}

struct Method {
    std::string name;
    std::function<std::vector<double>(const Room&)> form_factors;
};

std::vector<Method> form_factor_methods(const std::vector<int>& hemicube_resolutions) {
    std::vector<Method> out;
    auto flux = [](const Room& r, host::CentreForm form, bool hybrid) {
        host::VisibilityCounts c;
        host::Visibility d = hybrid ? host::decahedral_hybrid(r.mesh, r.world(), {}, c)
                                    : host::flux_tracing(r.mesh, r.world(), c);
        return host::centre_form_factors(r.mesh, d, form);
    };
    out.push_back(
        {"flux", [=](const Room& r) { return flux(r, host::CentreForm::PointToPoint, false); }});
    out.push_back(
        {"hybrid", [=](const Room& r) { return flux(r, host::CentreForm::PointToPoint, true); }});
    out.push_back({"disk", [=](const Room& r) { return flux(r, host::CentreForm::Disk, false); }});
    for (int res : hemicube_resolutions)
        out.push_back({fmt::format("hemicube{}", res),
                       [res](const Room& r) { return host::hemicube_form_factors(r.mesh, res); }});
    return out;
}

}  // namespace

Table experiment_form_factor_error(const ExperimentSettings& s, int patches, int reference_n,
                                   bool solve) {
    Table table({"scene", "patches", "method", "cpu_ms", "ff_error", "reference_error",
                 "radiosity_rms_error", "solve_iterations", "converged"});
    for (const auto& file : s.scenes) {
        const Room room = load_room(file, patches);
        // the reference, and its own error: the spread against a coarser estimate
        const std::vector<double> ref = reference_form_factors(room, reference_n);
        const std::vector<double> coarse = reference_form_factors(room, reference_n / 2);
        const double ref_err = form_factor_error(room.mesh, coarse, ref);
        std::vector<glm::dvec3> ref_b;
        if (solve) ref_b = host::solve_gauss_seidel(room.mesh, ref, 1e-7, 500).radiosity;
        for (const Method& m : form_factor_methods({16, 32, 64, 128})) {
            std::vector<host::Timing> times;
            std::vector<double> f;
            for (int round = 0; round < s.repeat; ++round) {
                host::Stopwatch clock;
                f = m.form_factors(room);
                times.push_back(clock.elapsed());
            }
            std::string b_err, iterations, converged;
            if (solve) {
                const auto b = host::solve_gauss_seidel(room.mesh, f, 1e-7, 500);
                double sum = 0, norm = 0;
                for (size_t i = 0; i < b.radiosity.size(); ++i) {
                    const glm::dvec3 d = b.radiosity[i] - ref_b[i];
                    sum += glm::dot(d, d) * room.mesh.patches[i].area;
                    norm += glm::dot(ref_b[i], ref_b[i]) * room.mesh.patches[i].area;
                }
                b_err = fmt::format("{:.6g}", std::sqrt(sum / std::max(norm, 1e-300)));
                iterations = std::to_string(b.iterations);
                // a solve that stopped at its limit is marked, its error not to be trusted
                converged = b.converged ? "yes" : "NO (diverged or cut short)";
            }
            table.add({file, std::to_string(room.mesh.patches.size()), m.name,
                       fixed(host::median(times).cpu_ms, 2),
                       fmt::format("{:.6g}", form_factor_error(room.mesh, f, ref)),
                       fmt::format("{:.6g}", ref_err), b_err, iterations, converged});
        }
    }
    return table;
}

}  // namespace fb89::experiments
