// The paper's §5 experiments: intervisibility by flux tracing against the decahedral
// hybrid, and form factors and radiosities against a reference.
//   radiosity  rays, volume queries and form-factor time, flux vs hybrid, per room, timed
//              interleaved (the paper's table; its numbers beside ours in RESULTS.md);
//   ff-error   form-factor error against time for flux tracing (centre form), the disk
//              form, hemicubes of several resolutions and the hybrid;
//   radiosity-error  radiosity error against time for the same methods, each solved, and
//              for the methods that mesh as they go: the adaptive mesh (disk form) and
//              hierarchical radiosity (Hanrahan et al. 1991) at several ε, their radiosities
//              read at the reference patches' centres.
// Hierarchical radiosity also joins the paper's table (its rays, links and time, every stage
// included, since it meshes, links and solves in one), natively and on the 1989 hosts.
// The reference: exact unoccluded form factors (contour integral) times a fractional
// visibility from many rays between points spread over both patches, and its own error is
// stated (the spread between two reference estimates of different ray counts).
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>

#include <fmt/format.h>

#include "experiments/experiments.h"
#include "experiments/measure.h"
#include "experiments/period_runs.h"
#include "host/radiosity/exact.h"
#include "host/radiosity/form_factors.h"
#include "host/radiosity/hemicube.h"
#include "host/radiosity/hierarchical.h"
#include "host/radiosity/mesh.h"
#include "host/radiosity/pipeline.h"
#include "host/radiosity/solver.h"
#include "host/radiosity/visibility.h"
#include "host/scene/scene_loader.h"
#include "host/trace/grid.h"
#include "host/trace/trace_scene.h"

namespace fb89::experiments {

namespace {

// A room made ready: scene, mesh, traced scene and grid; the hierarchy's roots (one element
// a face piece, the same elements as the mesh's) and the patch size.
struct Room {
    host::Scene scene;
    host::Mesh mesh, roots;
    double patch_size = 0;
    int patches_asked = 0;
    std::unique_ptr<host::TraceScene> trace;
    std::unique_ptr<host::UniformGrid> grid;
    host::RadiosityWorld world() const { return {*trace, *grid}; }
};

// The exhibition hall's --patches: the garish room's patch side (0.405 m at 820 there), so
// 4,475 patches; and for the error experiments the same ratio to their 250 a room.
constexpr int kHallPatches = 4700;
constexpr int kHallErrorPatches = 1430;

// The --patches that mesh the bundled rooms nearest the paper's counts (832 and 1,348
// patches; scenes/README.md), the exhibition hall at the garish room's patch size, else
// about 800. The error experiments, whose reference casts n^4 rays a pair, ask for fewer:
// 250 a room, the hall again at the garish room's patch size.
int default_patches(const std::string& file, bool error_experiment) {
    const bool hall = file.find("exhibition_hall") != std::string::npos;
    if (error_experiment) return hall ? kHallErrorPatches : 250;
    if (file.find("garish_room") != std::string::npos) return 820;
    if (file.find("programmers_cell") != std::string::npos) return 1070;
    if (hall) return kHallPatches;
    return 800;
}

Room load_room(const std::string& file, int patches, bool error_experiment = false) {
    Room r;
    if (patches <= 0) patches = default_patches(file, error_experiment);
    r.scene = host::load_scene(file);
    r.patches_asked = patches;
    r.patch_size = host::patch_size_for(r.scene, patches);
    r.mesh = host::mesh_scene(r.scene, {r.patch_size, 64});
    r.roots = host::mesh_scene(r.scene, {std::numeric_limits<double>::infinity(), 64});
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

// The hierarchical runs of both tables: ε from coarse to fine, 4 rays a link, elements down
// to half the room's patch side (pipeline.h's default).
constexpr std::array<double, 3> kHierarchicalEpsilons{0.05, 0.01, 0.002};

std::string hierarchical_name(double epsilon, bool shafts = false) {
    return fmt::format("hierarchical e={:g}{}", epsilon, shafts ? " shafts" : "");
}

struct HierarchicalRun {
    host::HierarchicalResult result;
    host::Timing time;
};

HierarchicalRun run_hierarchical(const Room& room, double epsilon, double tolerance = 1e-4,
                                 bool shafts = false) {
    host::HierarchicalOptions o;
    o.epsilon = epsilon;
    o.shaft_culling = shafts;
    o.tolerance = tolerance;
    o.min_area = room.patch_size * room.patch_size / 4;
    HierarchicalRun run;
    host::Stopwatch clock;
    run.result = host::hierarchical_radiosity(room.roots, room.world(), o);
    run.time = clock.elapsed();
    return run;
}

// Fractional visibility by `n` x `n` points on each patch (n^4 rays per pair), times the
// exact unoccluded form factor: the reference.
std::vector<double> reference_form_factors(const Room& room, int n);

}  // namespace

Table experiment_radiosity(const ExperimentSettings& s, int patches) {
    Table table({"scene", "faces", "patches", "facing_pairs", "method", "rays", "volume_queries",
                 "empty_queries", "pairs_by_queries", "links", "elements", "ff_cpu_ms",
                 "ratio_to_flux", "same_delta"});
    // flux, hybrid; then the hierarchical runs, and the same with shaft culling (the same
    // links and radiosities, fewer rays)
    constexpr size_t kUniform = 2;
    const size_t hierarchies = kHierarchicalEpsilons.size() * 2;
    const size_t methods = kUniform + hierarchies;
    auto epsilon_of = [](size_t m) {
        return kHierarchicalEpsilons[(m - kUniform) % kHierarchicalEpsilons.size()];
    };
    auto shafts_of = [](size_t m) { return m - kUniform >= kHierarchicalEpsilons.size(); };
    for (const auto& file : s.scenes) {
        const Room room = load_room(file, patches);
        std::vector<std::vector<host::Timing>> times(methods);
        VisibilityRun flux, hybrid;
        std::vector<host::HierarchicalResult> hierarchical(hierarchies);
        interleave(methods, s.period ? 0 : s.repeat, file, s.progress && !s.period,
                   [&](size_t m, bool timed) {
                       if (m >= kUniform) {
                           HierarchicalRun run =
                               run_hierarchical(room, epsilon_of(m), 1e-4, shafts_of(m));
                           if (timed) times[m].push_back(run.time);
                           hierarchical[m - kUniform] = std::move(run.result);
                           return;
                       }
                       const bool use_hybrid = m == 1;
                       VisibilityRun run = run_visibility(room, use_hybrid);
                       if (timed) times[m].push_back(run.time);
                       (use_hybrid ? hybrid : flux) = std::move(run);
                   });
        std::vector<double> ms(methods);
        for (size_t m = 0; m < methods; ++m)
            ms[m] = host::median(times[m]).cpu_ms;
        if (s.period) {
            // on a 1989 host: the same δ and form factors, counted once each and priced
            const std::string n = std::to_string(room.patches_asked);
            s.period->set_progress(s.progress, file);
            std::vector<GuestJob> jobs{{file, {"--radiosity", "flux", "--patches", n}},
                                       {file, {"--radiosity", "hybrid", "--patches", n}}};
            for (size_t m = kUniform; m < methods; ++m) {
                GuestJob job{file,
                             {"--radiosity", "hierarchical", "--patches", n, "--epsilon",
                              fmt::format("{:g}", epsilon_of(m))}};
                if (shafts_of(m)) job.options.push_back("--shaft-culling");
                jobs.push_back(std::move(job));
            }
            const auto costs = s.period->run(jobs);
            const int hs = static_cast<int>(period::Phase::HiddenSurface);
            for (size_t m = 0; m < methods; ++m)
                ms[m] = costs[m].phases[hs].ms;
        }
        const bool same = flux.delta == hybrid.delta;
        for (size_t m = 0; m < methods; ++m) {
            const std::string ratio = fixed(ms[m] / ms[0], 3);
            if (m >= kUniform) {
                const host::HierarchicalCounts& h = hierarchical[m - kUniform].counts;
                table.add({file, std::to_string(room.scene.face_count),
                           std::to_string(room.mesh.patches.size()),
                           std::to_string(flux.counts.facing_pairs),
                           hierarchical_name(epsilon_of(m), shafts_of(m)), std::to_string(h.rays),
                           "", "", "", std::to_string(h.links), std::to_string(h.leaves),
                           fixed(ms[m], 2), ratio, ""});
                continue;
            }
            const VisibilityRun& r = m == 0 ? flux : hybrid;
            table.add({file, std::to_string(room.scene.face_count),
                       std::to_string(room.mesh.patches.size()),
                       std::to_string(r.counts.facing_pairs), m == 0 ? "flux" : "hybrid",
                       std::to_string(r.counts.rays), std::to_string(r.counts.queries),
                       std::to_string(r.counts.empty_queries),
                       std::to_string(r.counts.pairs_by_queries), "",
                       std::to_string(room.mesh.patches.size()), fixed(ms[m], 2), ratio,
                       same ? "yes" : "NO"});
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

namespace {

// The radiosity a mesh shows at `point` on face piece `piece`: its patch on that piece whose
// outline holds the point (where rounding leaves none, the one with the nearest centre).
class PointLookup {
  public:
    PointLookup(const host::Mesh& mesh, const std::vector<glm::dvec3>& radiosity)
        : m_mesh(mesh), m_radiosity(radiosity) {
        for (uint32_t p = 0; p < mesh.patches.size(); ++p) {
            const uint32_t piece = mesh.elements[mesh.patches[p].element].piece;
            if (piece >= m_by_piece.size()) m_by_piece.resize(piece + 1);
            m_by_piece[piece].push_back(p);
        }
    }
    glm::dvec3 at(uint32_t piece, const glm::dvec3& point) const {
        if (piece >= m_by_piece.size() || m_by_piece[piece].empty()) return glm::dvec3(0);
        uint32_t nearest = m_by_piece[piece][0];
        double best = 1e300;
        for (uint32_t p : m_by_piece[piece]) {
            const host::Patch& patch = m_mesh.patches[p];
            if (inside(patch, point)) return m_radiosity[p];
            const double d = glm::length(patch.centre - point);
            if (d < best) best = d, nearest = p;
        }
        return m_radiosity[nearest];
    }

  private:
    bool inside(const host::Patch& patch, const glm::dvec3& point) const {
        const glm::dvec3& n = m_mesh.elements[patch.element].normal;
        const double slack = 1e-9 * std::sqrt(patch.area);
        for (int k = 0; k < patch.corner_count; ++k) {
            const glm::dvec3& a = patch.corners[k];
            const glm::dvec3& b = patch.corners[(k + 1) % patch.corner_count];
            if (glm::dot(glm::cross(b - a, point - a), n) < -slack * glm::length(b - a))
                return false;
        }
        return true;
    }
    const host::Mesh& m_mesh;
    const std::vector<glm::dvec3>& m_radiosity;
    std::vector<std::vector<uint32_t>> m_by_piece;
};

// Relative RMS over the room's patches, weighted by area.
double relative_rms(const host::Mesh& mesh, const std::vector<glm::dvec3>& b,
                    const std::vector<glm::dvec3>& ref) {
    double sum = 0, norm = 0;
    for (size_t i = 0; i < b.size(); ++i) {
        const glm::dvec3 d = b[i] - ref[i];
        sum += glm::dot(d, d) * mesh.patches[i].area;
        norm += glm::dot(ref[i], ref[i]) * mesh.patches[i].area;
    }
    return std::sqrt(sum / std::max(norm, 1e-300));
}

// Another mesh's radiosities read at the room's patch centres.
std::vector<glm::dvec3> at_room_patches(const Room& room, const host::Mesh& mesh,
                                        const std::vector<glm::dvec3>& radiosity) {
    const PointLookup lookup(mesh, radiosity);
    std::vector<glm::dvec3> out;
    out.reserve(room.mesh.patches.size());
    for (const host::Patch& p : room.mesh.patches)
        out.push_back(lookup.at(room.mesh.elements[p.element].piece, p.centre));
    return out;
}

// The adaptive runs of radiosity-error: the disk form, refined where neighbours differ by
// more than these, two passes.
constexpr std::array<double, 2> kAdaptiveThresholds{0.5, 0.2};

}  // namespace

Table experiment_form_factor_error(const ExperimentSettings& s, int patches, int reference_n,
                                   bool solve) {
    Table table({"scene", "patches", "method", "cpu_ms", "total_cpu_ms", "elements", "links",
                 "rays", "ff_error", "reference_error", "radiosity_rms_error", "solve_iterations",
                 "converged"});
    for (const auto& file : s.scenes) {
        const Room room = load_room(file, patches, true);
        // the reference, and its own error: the spread against a coarser estimate
        const std::vector<double> ref = reference_form_factors(room, reference_n);
        const std::vector<double> coarse = reference_form_factors(room, reference_n / 2);
        const double ref_err = form_factor_error(room.mesh, coarse, ref);
        std::vector<glm::dvec3> ref_b;
        if (solve) ref_b = host::solve_gauss_seidel(room.mesh, ref, 1e-7, 500).radiosity;
        const std::string n = std::to_string(room.mesh.patches.size());
        const std::string ref_error = fmt::format("{:.6g}", ref_err);
        for (const Method& m : form_factor_methods({16, 32, 64, 128})) {
            std::vector<host::Timing> times, solve_times;
            std::vector<double> f;
            host::RadiositySolution b;
            for (int round = 0; round < s.repeat; ++round) {
                host::Stopwatch clock;
                f = m.form_factors(room);
                times.push_back(clock.elapsed());
                if (!solve) continue;
                clock.restart();
                b = host::solve_gauss_seidel(room.mesh, f, 1e-7, 500);
                solve_times.push_back(clock.elapsed());
            }
            const double ms = host::median(times).cpu_ms;
            std::string b_err, iterations, converged, total;
            if (solve) {
                b_err = fmt::format("{:.6g}", relative_rms(room.mesh, b.radiosity, ref_b));
                iterations = std::to_string(b.iterations);
                // a solve that stopped at its limit is marked, its error not to be trusted
                converged = b.converged ? "yes" : "NO (diverged or cut short)";
                total = fixed(ms + host::median(solve_times).cpu_ms, 2);
            }
            table.add({file, n, m.name, fixed(ms, 2), total, n, "", "",
                       fmt::format("{:.6g}", form_factor_error(room.mesh, f, ref)), ref_error,
                       b_err, iterations, converged});
        }
        if (!solve) continue;
        // the methods that mesh as they go, timed whole (meshing, visibility, form factors,
        // solving), their radiosities read at the room's patch centres
        for (double threshold : kAdaptiveThresholds) {
            host::RadiosityOptions o;
            o.form_factors = host::FormFactorMethod::Disk;
            o.patches = room.patches_asked;
            o.adaptive = threshold;
            o.adaptive_passes = 2;
            o.tolerance = 1e-7;
            o.max_iterations = 500;
            std::vector<host::Timing> times;
            host::RadiosityResult r;
            for (int round = 0; round < s.repeat; ++round) {
                host::Stopwatch clock;
                r = host::solve_radiosity(room.scene, o);
                times.push_back(clock.elapsed());
            }
            const double ms = host::median(times).cpu_ms;
            table.add({file, n, fmt::format("adaptive t={:g}", threshold), fixed(ms, 2),
                       fixed(ms, 2), std::to_string(r.mesh.patches.size()), "",
                       std::to_string(r.counts.rays), "", ref_error,
                       fmt::format("{:.6g}",
                                   relative_rms(room.mesh,
                                                at_room_patches(room, r.mesh, r.solution.radiosity),
                                                ref_b)),
                       std::to_string(r.solution.iterations),
                       r.solution.converged ? "yes" : "NO (diverged or cut short)"});
        }
        for (double epsilon : kHierarchicalEpsilons) {
            std::vector<host::Timing> times;
            HierarchicalRun run;
            for (int round = 0; round < s.repeat; ++round) {
                run = run_hierarchical(room, epsilon, 1e-7);
                times.push_back(run.time);
            }
            const double ms = host::median(times).cpu_ms;
            const host::HierarchicalResult& h = run.result;
            table.add({file, n, hierarchical_name(epsilon), fixed(ms, 2), fixed(ms, 2),
                       std::to_string(h.counts.leaves), std::to_string(h.counts.links),
                       std::to_string(h.counts.rays), "", ref_error,
                       fmt::format("{:.6g}", relative_rms(room.mesh,
                                                          at_room_patches(room, h.leaves,
                                                                          h.solution.radiosity),
                                                          ref_b)),
                       std::to_string(h.solution.iterations),
                       h.solution.converged ? "yes" : "NO (cut short)"});
        }
    }
    return table;
}

}  // namespace fb89::experiments
