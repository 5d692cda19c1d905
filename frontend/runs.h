// The long-running commands -- experiment, sweep threshold, compare, calibrate -- as requests that
// return their tables: the option rules (defaults, which threshold a name means, which
// options go together) live here once, for the command line and the Python module alike.
// The commands print and write what comes back; the Python module hands it over as tables.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiments/calibration.h"
#include "experiments/compare.h"
#include "experiments/settings.h"
#include "experiments/table.h"
#include "frontend/option_limits.h"
#include "frontend/period_host.h"

namespace fb89::frontend {

// What the three requests share: the scenes (resolved, see resolve_scene; empty: each one's
// default set), an image size "WxH" ("": the scenes' own), timing rounds, the controller
// profile, the host (and its --jobs/--results/--emit-jobs) and whether a progress line shows.
// Every value is checked here (numbers against frontend/option_limits.h), and a UsageError
// names the option as `spelling` says: the command line's "--repeat", Python's "repeat".
struct RunRequest {
    std::vector<std::string> scenes;
    std::string size;
    int repeat = 7;
    std::string profile = "tms34010-50mhz";
    HostArgs host;
    bool progress = false;
    Spelling spelling = Spelling::Option;
};

// A request's settings and the table it made. With --emit-jobs the table is incomplete
// (report_emitted() says so and the commands write nothing).
struct RunOutcome {
    experiments::ExperimentSettings settings;
    experiments::Table table;  // scene column as scene_display_name() shows it
};

// `fb89 experiment NAME` (experiments/catalog.h): throws UsageError for an unknown name.
struct ExperimentRequest : RunRequest {
    std::string name;
    std::string threshold = "calibrated";       // fig3.1, hybrid, accuracy
    std::string beam_threshold = "calibrated";  // fig4.*
    std::vector<std::string> sizes;             // fig4.8, fig4.11, fig4.12 ("WxH" each)
    std::string out_dir = "out/masks";          // fig4.7
    std::string accel = "bvh";                  // fig4.*, beam-threshold, split
    std::vector<std::string> methods;           // split (empty: every method)
    int patches = 0;                            // radiosity, ff-error, radiosity-error
    int reference_rays = 4;                     // ff-error, radiosity-error
};
RunOutcome run_experiment(const ExperimentRequest& request);

// `fb89 sweep threshold`: the hybrid at 0, `steps` log-spaced thresholds from `from` to `to`,
// and inf.
struct SweepRequest : RunRequest {
    double from = 0.001, to = 1.0;
    int steps = 13;
    std::string window_test = "area";       // or centres
    std::string depth_estimate = "window";  // or scene
};
RunOutcome run_threshold_sweep(const SweepRequest& request);

// `fb89 compare SCENE` (experiments/compare.h): every method with its defaults on one scene
// (scenes holds that one), the hybrids' thresholds by render's rule.
struct CompareRequest : RunRequest {
    CompareRequest() { repeat = 3; }
    std::string threshold = "calibrated", beam_threshold = "calibrated";
    std::string given;  // the scene as the user named it, for a file's name in the outputs
};
struct CompareOutcome {
    experiments::ExperimentSettings settings;
    experiments::Comparison comparison;
    // With --emit-jobs (report_emitted()) the two are empty and the commands write nothing.
    experiments::Table table;  // --csv: the scene column as scene_display_name() shows it
    nlohmann::json rows;       // --json: one object a method
    std::string thresholds;    // "hybrid threshold 0.04 (paper), beam threshold ...\n"
};
CompareOutcome run_compare(const CompareRequest& request);

// `fb89 calibrate`: the hybrid's Expr. 3.1 threshold (method "hybrid", on A-F by default) or
// the beam-ray hybrid's Expr. 2.7 threshold ("beam", on G, H, I and cornell_mirror), chosen
// and, unless dry_run, saved where `--threshold calibrated` finds it.
struct CalibrateRequest : RunRequest {
    CalibrateRequest() { repeat = 5; }
    std::string method = "hybrid";
    double from = 0.0005, to = 2.0;  // hybrid only
    int steps = 12;
    double tolerance = 0.03;
    bool dry_run = false;
};
struct CalibrationOutcome {
    experiments::ExperimentSettings settings;
    experiments::Calibration calibration;  // its sweep's scene column as shown
    nlohmann::json details;                // what is saved beside the threshold
    std::string saved_to;                  // empty when not saved (dry run, or jobs emitted)
    std::string warning;                   // why a choice of 0 switches the hybrid off, or ""
};
CalibrationOutcome run_calibration(const CalibrateRequest& request);

}  // namespace fb89::frontend
