// `--host`: the frame's host side timed on a 1989 host. fb89's host code runs on the
// emulated period host of the profile's instruction set (period/emulator.h) with the same
// method and options as the native run, its counts are priced by the host profile
// (period/host_cost.h), and its command stream is checked against the native one.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json_fwd.hpp>

#include "controller_sim/timed_pipeline.h"
#include "experiments/render_job.h"
#include "experiments/settings.h"
#include "host/methods.h"
#include "period/host_cost.h"

namespace fb89::frontend {

// A method's 1989-host run (experiments/render_job.h) as "load 1.2 ms, set-up 3.4 ms, ..."
// lines for people, and as the JSON for --stats.
std::string period_summary(const experiments::PeriodFrame& run);
nlohmann::json period_json(const experiments::PeriodFrame& run);
// The `n` instruction classes (and events) that take most of a phase's modelled time, with
// their executions and shares: where the 1989 host's time goes.
std::string period_classes(const experiments::PeriodFrame& run, period::Phase phase, int n);

// The two-stage pipeline at a glance: host per frame (set-up + hidden-surface) against the
// controller's frame time; the frame time is the larger, the side that bounds it named.
std::string split_line(const std::string& host_name, double host_ms, const std::string& profile,
                       double controller_ms);

// The same frame through the pipeline in time (controller_sim/timed_pipeline.h) from its send
// times -- "measured" natively, "counted" on a 1989 host: its frame time beside max(host,
// controller alone) and their sum, how much of the smaller side it hides, the host's stalls
// and both sides' utilization; and, where the buffer slows the controller itself, the
// controller alone through it beside `controller_ms`, the split's unbounded frame.
std::string pipeline_line(const experiments::FramePipeline& p, double controller_ms,
                          std::string_view sends);
nlohmann::json pipeline_json(const experiments::FramePipeline& p, std::string_view sends);

// How a run's send times were had: "counted" on a 1989 host, else "measured".
inline std::string_view send_times_source(bool period) {
    return period ? "counted" : "measured";
}

// --host, --jobs, --results and --emit-jobs, as experiment, sweep and calibrate take them.
struct HostArgs {
    std::string host = "native";
    int jobs = 1;
    std::string results, emit_jobs;
};
void add_host_options(CLI::App* sub, HostArgs& args);
// Null for the native host; throws UsageError for a bad combination or an unknown host.
std::shared_ptr<experiments::PeriodRuns> make_period_runs(const HostArgs& args);
// After an experiment: with --emit-jobs, says where the jobs went and returns true (the
// table is incomplete and is not written).
bool report_emitted(const experiments::ExperimentSettings& s, const HostArgs& args);

}  // namespace fb89::frontend
