#include "frontend/runs.h"

#include <chrono>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "experiments/catalog.h"
#include "experiments/compare.h"
#include "experiments/experiments.h"
#include "experiments/period_runs.h"
#include "frontend/calibration.h"
#include "frontend/common.h"
#include "frontend/data_dir.h"
#include "frontend/names.h"
#include "host/raster/hybrid.h"

namespace fb89::frontend {

using namespace experiments;

namespace {

// An option's name as the request's caller spells it (the command line's, or Python's).
std::string named(const RunRequest& r, std::string_view option, std::string_view keyword) {
    return std::string(r.spelling == Spelling::Option ? option : keyword);
}

// A ramp's ends: 0 < from < to (Python's start and stop).
template <class Request>
void check_ramp(const Request& r) {
    if (!(r.from > 0 && r.to > r.from))
        throw UsageError(r.spelling == Spelling::Option ? "--from and --to: need 0 < from < to"
                                                        : "start and stop: need 0 < start < stop");
}

ExperimentSettings settings_of(const RunRequest& r, std::vector<std::string> default_scenes) {
    check_limit(limits::kRepeat, r.repeat, r.spelling);
    check_limit(limits::kJobs, r.host.jobs, r.spelling);
    ExperimentSettings s;
    s.scenes = r.scenes.empty() ? std::move(default_scenes) : r.scenes;
    s.repeat = r.repeat;
    s.profile = r.profile;
    s.progress = r.progress;
    profile_option(r.profile, named(r, "--profile", "profile"));  // one there is, before any work
    if (!r.size.empty()) s.size = parse_size(r.size, r.spelling);
    s.period = make_period_runs(r.host);
    return s;
}

// With --emit-jobs, the runs went to the job file and the table is incomplete.
bool jobs_emitted(const ExperimentSettings& s, const HostArgs& host) {
    return s.period && !host.emit_jobs.empty() && s.period->emitted() > 0;
}

std::vector<std::string> experiment_scenes(const std::string& name) {
    std::vector<std::string> out;
    if (const ExperimentInfo* e = find_experiment(name))
        for (std::string_view scene : e->scenes)
            out.push_back(bundled_scene(std::string(scene)));
    return out;
}

std::string known_experiments() {
    std::string known;
    for (const ExperimentInfo& e : experiment_catalog())
        known += (known.empty() ? "" : ", ") + std::string(e.name);
    return known;
}

std::vector<std::string> experiment_names() {
    std::vector<std::string> names;
    for (const ExperimentInfo& e : experiment_catalog())
        names.emplace_back(e.name);
    return names;
}

}  // namespace

RunOutcome run_experiment(const ExperimentRequest& r) {
    if (!find_experiment(r.name))
        throw UsageError(fmt::format("unknown experiment '{}'{} (known: {}; fb89 list experiments)",
                                     r.name, nearest_hint(r.name, experiment_names()),
                                     known_experiments()));
    if (r.accel != "bvh" && r.accel != "grid")
        throw UsageError(named(r, "--accel", "accel") + ": '" + r.accel + "': bvh or grid");
    check_limit(limits::kPatches, r.patches, r.spelling);
    check_limit(limits::kReferenceRays, r.reference_rays, r.spelling);
    RunOutcome out;
    ExperimentSettings& s = out.settings;
    s = settings_of(r, experiment_scenes(r.name));
    s.accel = host::parse_accel(r.accel);
    if (!r.methods.empty() && r.name != "split")
        throw UsageError(named(r, "--methods", "methods") + ": only with the split experiment");
    for (const std::string& m : r.methods) {
        try {
            s.methods.push_back(find_method(m));
        } catch (const UsageError& e) {
            throw UsageError(named(r, "--methods", "methods") + ": " + e.what());
        }
    }
    if (s.period) s.repeat = 1;  // a 1989 host's counts are exact: one run each
    const std::string& host = r.host.host;
    const auto threshold = [&] { return resolve_threshold(r.threshold, nullptr, host); };
    const auto beam_threshold = [&] {
        return resolve_beam_threshold(r.beam_threshold, nullptr, host);
    };
    // --sizes, or the paper's three and twice the largest
    const auto sizes = [&] {
        std::vector<ImageSize> out_sizes;
        for (const auto& text : r.sizes)
            out_sizes.push_back(parse_size(text, r.spelling));
        if (out_sizes.empty()) out_sizes = {{256, 195}, {512, 390}, {1024, 780}, {2048, 1560}};
        return out_sizes;
    };
    const std::string& name = r.name;
    Table& table = out.table;
    if (name == "fig2.1")
        table = experiment_fig2_1(s);
    else if (name == "fig2.4")
        table = experiment_fig2_4(s);
    else if (name == "fig3.1")
        table = experiment_fig3_1(s, threshold());
    else if (name == "hybrid")
        table = experiment_hybrid(s, threshold());
    else if (name == "accuracy")
        table = experiment_accuracy(s, threshold());
    else if (name == "fig4.8" || name == "fig4.11" || name == "fig4.12")
        table = experiment_beam_resolution(s, sizes(), beam_threshold());
    else if (name == "fig4.7")
        table = experiment_beam_masks(s, beam_threshold(), r.out_dir);
    else if (name == "beam-threshold")
        table = experiment_beam_threshold(s, beam_threshold_ramp());
    else if (name == "split")
        table = experiment_split(s);
    else if (name == "successors")
        table = experiment_successors(s);
    else if (name == "successors-rays")
        table = experiment_successors_rays(s, sizes(), beam_threshold());
    else if (name == "radiosity")
        table = experiment_radiosity(s, r.patches);
    else if (name == "ff-error" || name == "radiosity-error")
        table =
            experiment_form_factor_error(s, r.patches, r.reference_rays, name == "radiosity-error");
    else
        throw std::logic_error("experiment '" + name + "' is catalogued but not run");
    table.map_column("scene", scene_display_name);
    return out;
}

RunOutcome run_threshold_sweep(const SweepRequest& r) {
    check_ramp(r);
    if (r.window_test != "area" && r.window_test != "centres")
        throw UsageError(named(r, "--window-test", "window_test") + ": '" + r.window_test +
                         "': area or centres");
    if (r.depth_estimate != "window" && r.depth_estimate != "scene")
        throw UsageError(named(r, "--depth-estimate", "depth_estimate") + ": '" + r.depth_estimate +
                         "': window or scene");
    if (r.scenes.empty()) throw UsageError("sweep: give the scenes to sweep on");
    check_limit(limits::kSteps, r.steps, r.spelling);
    RunOutcome out;
    out.settings = settings_of(r, {});
    std::vector<double> thresholds{0.0};
    for (double t : threshold_ramp(r.from, r.to, r.steps))
        thresholds.push_back(t);
    thresholds.push_back(std::numeric_limits<double>::infinity());
    host::MethodOptions base(host::Method::Hybrid);
    base.warnock.window_test =
        r.window_test == "centres" ? host::WindowTest::Centres : host::WindowTest::Area;
    base.hybrid.depth =
        r.depth_estimate == "scene" ? host::DepthEstimate::Scene : host::DepthEstimate::Window;
    out.table = sweep_threshold(out.settings, thresholds, base);
    out.table.map_column("scene", scene_display_name);
    return out;
}

namespace {

// Every method with its defaults, the thresholds by render's rule (calibrated if saved,
// else the paper's / the built-in one); `said` gets the line that says which.
std::vector<host::MethodOptions> compare_settings(const CompareRequest& r, std::string& said) {
    std::string hybrid_source, beam_source;
    const double hybrid = resolve_threshold(r.threshold, &hybrid_source, r.host.host);
    const double beam = resolve_beam_threshold(r.beam_threshold, &beam_source, r.host.host);
    said = fmt::format("hybrid threshold {:.6g} ({}), beam threshold {:.6g} ({})\n", hybrid,
                       hybrid_source, beam, beam_source);
    std::vector<host::MethodOptions> settings = every_method();
    for (host::MethodOptions& o : settings) {
        o.hybrid.threshold = hybrid;
        o.beam.threshold = beam;
        try {
            host::validate(o);
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    }
    return settings;
}

nlohmann::json compare_rows_json(const Comparison& c) {
    nlohmann::json rows = nlohmann::json::array();
    for (const CompareRow& r : c.rows) {
        rows.push_back({{"scene", c.name},
                        {"method", r.method},
                        {"host", c.host},
                        {"host_ms", r.host_ms},
                        {"commands", r.controller.commands},
                        {"fills", r.controller.fills},
                        {"spans", r.controller.spans},
                        {"controller_ms", r.controller.frame_ms},
                        {"frame_ms", r.frame_ms},
                        {"bound_by", r.host_bound ? "host" : "controller"},
                        {"pixels_differing", r.ids.total()},
                        {"px_coverage", r.ids.coverage},
                        {"px_other_face", r.ids.other_face},
                        {"depth_spans", r.controller.depth_spans},
                        {"faces", r.controller.faces}});
        if (r.depth) {  // the depth commands: the ties of the profile's depth word
            rows.back()["px_ties"] = r.depth->ties;
            rows.back()["depth_bits"] = r.depth->depth_bits;
        }
        if (r.pipeline)
            rows.back()["pipeline"] =
                pipeline_json(*r.pipeline, send_times_source(c.host != "native"));
    }
    return rows;
}

}  // namespace

CompareOutcome run_compare(const CompareRequest& r) {
    if (r.scenes.size() != 1) throw UsageError("compare: give the one scene to compare on");
    CompareOutcome out;
    const std::vector<host::MethodOptions> methods = compare_settings(r, out.thresholds);
    out.settings = settings_of(r, {});
    // named as the console names it: a bundled scene by its name, a file as it was given
    const std::string shown = scene_display_name(r.scenes.front());
    out.comparison =
        compare_methods(r.scenes.front(), methods, out.settings,
                        shown != r.scenes.front() || r.given.empty() ? shown : r.given);
    if (jobs_emitted(out.settings, r.host)) return out;
    out.table = comparison_table(out.comparison);
    out.rows = compare_rows_json(out.comparison);
    return out;
}

namespace {

void calibrate_beam(const CalibrateRequest& r, CalibrationOutcome& out) {
    const ExperimentSettings& s = out.settings;
    const Calibration& c = out.calibration =
        calibrate_stably(s, [&] { return experiments::calibrate_beam(s); });
    nlohmann::json& details = out.details;
    details["scenes"] = s.scenes;
    details["repeat"] = s.repeat;
    details["raytrace_total_ms"] = c.reference_ms;
    details["total_ms_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, ms] : c.total)
        details["total_ms_by_threshold"].push_back({std::isinf(t) ? 1e300 : t, ms});
    details["chosen_total_ms"] = c.total.at(c.chosen);
    details["sweeps"] = nlohmann::json::array();
    for (double t : c.choices)  // JSON has no infinity: "inf", as the saved threshold
        details["sweeps"].push_back(std::isinf(t) ? nlohmann::json("inf") : nlohmann::json(t));
    details["stable"] = c.stable;
    if (r.dry_run || jobs_emitted(s, r.host)) return;
    save_beam_calibration(c.chosen, details.dump(), r.host.host);
    out.saved_to = calibration_path();
}

void calibrate_hybrid(const CalibrateRequest& r, CalibrationOutcome& out) {
    check_ramp(r);
    check_limit(limits::kSteps, r.steps, r.spelling);
    check_limit(limits::kTolerance, r.tolerance, r.spelling);
    const ExperimentSettings& s = out.settings;
    const auto ramp = threshold_ramp(r.from, r.to, r.steps);
    const Calibration& c = out.calibration =
        calibrate_stably(s, [&] { return experiments::calibrate_hybrid(s, ramp, r.tolerance); });
    const double zbuffer = c.reference_ms, chosen_ms = c.total.at(c.chosen);
    nlohmann::json& details = out.details;
    details["scenes"] = s.scenes;
    details["repeat"] = s.repeat;
    details["total_ms_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, ms] : c.total)
        details["total_ms_by_threshold"].push_back({t, ms});
    details["zbuffer_total_ms"] = zbuffer;
    details["tolerance"] = r.tolerance;
    details["worst_ratio_by_threshold"] = nlohmann::json::array();
    for (const auto& [t, w] : c.worst)
        details["worst_ratio_by_threshold"].push_back({t, w});
    details["chosen_total_ms"] = chosen_ms;
    details["sweeps"] = c.choices;
    details["stable"] = c.stable;
    details["calibrated_at_unix"] = std::chrono::duration_cast<std::chrono::seconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count();
    details["host"] = r.host.host;
    if (jobs_emitted(s, r.host)) return;
    if (!r.dry_run) {
        save_calibration(c.chosen, details.dump(), r.host.host);
        out.saved_to = calibration_path();
    }
    // a choice of 0 switches the hybrid off for every later hybrid render: say so, and why
    if (c.chosen == 0) {
        double best = 0, best_ms = std::numeric_limits<double>::infinity();
        for (const auto& [t, ms] : c.total)
            if (t > 0 && ms < best_ms) best = t, best_ms = ms;
        out.warning = fmt::format(
            "calibration chose threshold 0: the hybrid hands every window to the "
            "Z-buffer and runs as a plain Z-buffer. No threshold made it faster than the pure "
            "Z-buffer without a scene more than {:.0f}% slower (its best total, at {:.6g}, is "
            "{:+.1f}% against the Z-buffer's). `--threshold paper` still gives the paper's 0.04.",
            100 * r.tolerance, best, 100 * (best_ms / zbuffer - 1));
    }
}

}  // namespace

CalibrationOutcome run_calibration(const CalibrateRequest& r) {
    if (r.method != "hybrid" && r.method != "beam")
        throw UsageError(named(r, "--method", "method") + ": '" + r.method + "': hybrid or beam");
    CalibrationOutcome out;
    std::vector<std::string> defaults;
    if (r.method == "beam")
        defaults = {bundled_scene("G.json"), bundled_scene("H.json"), bundled_scene("I.json"),
                    bundled_scene("cornell_mirror.json")};
    else
        for (char c = 'A'; c <= 'F'; ++c)
            defaults.push_back(bundled_scene(fmt::format("{}.json", c)));
    out.settings = settings_of(r, std::move(defaults));
    if (r.method == "beam")
        calibrate_beam(r, out);
    else
        calibrate_hybrid(r, out);
    out.calibration.sweep.map_column("scene", scene_display_name);
    return out;
}

}  // namespace fb89::frontend
