#include "frontend/period_host.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"
#include "experiments/measure.h"
#include "experiments/period_runs.h"
#include "experiments/timeline.h"
#include "frontend/common.h"
#include "frontend/names.h"
#include "frontend/option_limits.h"
#include "period/emulator.h"
#include "protocol/stream_reader.h"

namespace fb89::frontend {

std::string period_summary(const experiments::PeriodFrame& run) {
    const auto& p = run.cost.phases;
    auto phase = [&](period::Phase ph) { return p[static_cast<int>(ph)]; };
    const std::string chips =
        run.cpu.empty() ? "" : run.cpu + (run.fpu.empty() ? "" : " + " + run.fpu) + ", ";
    std::string out = fmt::format("host {} ({}modelled from {} emulated instructions):\n",
                                  run.cost.profile, chips, run.guest_instructions);
    double stand_in_ms = 0, ms = 0;
    for (auto [name, ph] : {std::pair{"load", period::Phase::Load},
                            {"set-up", period::Phase::Setup},
                            {"hidden-surface", period::Phase::HiddenSurface}}) {
        out += fmt::format("  {:<16} {:>12.3f} ms  {:>14} instructions\n", name, phase(ph).ms,
                           phase(ph).instructions);
        stand_in_ms += phase(ph).stand_in_ms;
        ms += phase(ph).ms;
    }
    out += fmt::format("  {:<16} {:>12.3f} ms\n", "end to end", run.cost.end_to_end_ms());
    // register-window traps (SPARC), per phase, for the machine's own window count: the plugin
    // counts 7 windows as "@window_overflow" and other counts as "@window_overflow_<N>w"; the
    // profile prices its own
    std::string overflow = "@window_overflow", underflow = "@window_underflow";
    for (const auto& cost : p)  // events holds only what the machine pays for
        for (const auto& [key, n] : cost.events)
            if (key.starts_with("@window_overflow_")) {
                overflow = key;
                underflow =
                    "@window_underflow" + key.substr(std::string_view("@window_overflow").size());
            }
    const auto events = [&](period::Phase ph, const std::string& key) {
        const auto& e = phase(ph).events;
        const auto it = e.find(key);
        return it == e.end() ? uint64_t{0} : it->second;
    };
    uint64_t traps = 0;
    for (const std::string& key : {overflow, underflow})
        for (auto ph : {period::Phase::Load, period::Phase::Setup, period::Phase::HiddenSurface})
            traps += events(ph, key);
    if (traps > 0)
        out += fmt::format(
            "  window traps     overflow/underflow: load {}/{}, set-up {}/{}, hidden-surface "
            "{}/{}\n",
            events(period::Phase::Load, overflow), events(period::Phase::Load, underflow),
            events(period::Phase::Setup, overflow), events(period::Phase::Setup, underflow),
            events(period::Phase::HiddenSurface, overflow),
            events(period::Phase::HiddenSurface, underflow));
    if (stand_in_ms > 0)
        out += fmt::format(
            "  stand-ins        {:.2f}% of the modelled time: instructions the machine does "
            "not have (newer forms in the C libraries: SPARC V8/V9, i686), priced as the code of "
            "its own that would stand in\n",
            ms > 0 ? 100 * stand_in_ms / ms : 0.0);
    if (run.checked)
        out += fmt::format(
            "  its command stream: {}; emulated in {:.2f} s here ({:.0f} M "
            "instructions/s)\n",
            run.same_frame
                ? "the same frame as the native run's"
                : fmt::format("{} pixels differ from the native run's frame", run.differing_pixels),
            run.emulated_seconds,
            static_cast<double>(run.guest_instructions) / run.emulated_seconds / 1e6);
    uint64_t unpriced = 0;
    for (const auto& [key, n] : run.cost.unpriced_keys)
        unpriced += n;
    if (unpriced > 0)
        out += fmt::format(
            "  note: {} executions of {} instruction classes had no rule in the "
            "profile and took its default\n",
            unpriced, run.cost.unpriced_keys.size());
    return out;
}

nlohmann::json period_json(const experiments::PeriodFrame& run) {
    nlohmann::json j;
    j["profile"] = run.cost.profile;
    j["guest_instructions"] = run.guest_instructions;
    j["emulated_seconds"] = run.emulated_seconds;
    j["frame_checked"] = run.checked;
    j["same_frame"] = run.same_frame;
    j["differing_pixels"] = run.differing_pixels;
    j["end_to_end_ms"] = run.cost.end_to_end_ms();
    for (int ph = 0; ph < period::kPhases; ++ph) {
        const period::PhaseCost& c = run.cost.phases[ph];
        j["phases"][std::string(period::phase_name(ph))] = {{"instructions", c.instructions},
                                                            {"cpu_cycles", c.cpu_cycles},
                                                            {"fpu_cycles", c.fpu_cycles},
                                                            {"unpriced", c.unpriced},
                                                            {"ms", c.ms},
                                                            {"stand_in_ms", c.stand_in_ms},
                                                            {"stand_ins", c.stand_ins},
                                                            {"events", c.events}};
    }
    return j;
}

std::string period_classes(const experiments::PeriodFrame& run, period::Phase phase, int n) {
    const period::PhaseCost& c = run.cost.phases[static_cast<int>(phase)];
    std::vector<std::pair<std::string, std::pair<uint64_t, double>>> shares(c.classes.begin(),
                                                                            c.classes.end());
    std::sort(shares.begin(), shares.end(),
              [](const auto& a, const auto& b) { return a.second.second > b.second.second; });
    std::string out = fmt::format("  {} phase, the classes that take most of its {:.3f} ms:\n",
                                  period::phase_name(static_cast<int>(phase)), c.ms);
    for (int i = 0; i < n && i < static_cast<int>(shares.size()); ++i) {
        const auto& [key, figures] = shares[static_cast<size_t>(i)];
        out += fmt::format("    {:>5.1f}%  {:<28} {:>12} x  {:>12.3f} ms\n",
                           c.ms > 0 ? 100 * figures.second / c.ms : 0.0, key, figures.first,
                           figures.second);
    }
    return out;
}

std::string split_line(const std::string& host_name, double host_ms, const std::string& profile,
                       double controller_ms) {
    const experiments::FrameSplit f = experiments::frame_split(host_ms, controller_ms);
    // what the host's figure is: this machine's CPU time, or a 1989 host's modelled time
    const char* kind = host_name == "native" ? "CPU" : "modelled";
    return fmt::format(
        "split: host {} {:.3f} ms {} | controller {} {:.3f} ms modelled | frame {:.3f} ms, "
        "bounded by the {} ({})\n",
        host_name, host_ms, kind, profile, controller_ms, f.frame_ms,
        f.host_bounds ? "host" : "controller",
        f.ratio > 0 ? fmt::format("{:.2f}x the {}", f.ratio, f.host_bounds ? "controller" : "host")
                    : "the other side takes no time");
}

std::string pipeline_line(const experiments::FramePipeline& p, double controller_ms,
                          std::string_view sends) {
    const double alone_ms = p.controller_alone_us / 1e3;
    // a bounded buffer that slows the controller itself: say so, beside the split's figure
    const std::string alone =
        std::abs(alone_ms - controller_ms) >= 5e-4
            ? fmt::format("; the controller alone {:.3f} ms through this buffer, {:.3f} unbounded",
                          alone_ms, controller_ms)
            : "";
    return fmt::format(
        "pipeline (send times {}, buffer {}): frame {:.3f} ms (max {:.3f}, sum {:.3f}; {:.1f}% "
        "of the smaller side overlapped{}), {}, utilization host {:.1f}% "
        "controller {:.1f}%\n",
        sends, controller::command_buffer_text(p.buffer_bytes), p.frame_us / 1e3, p.max_us() / 1e3,
        p.sum_us() / 1e3, 100 * p.overlap(), alone,
        controller::host_stall_text(p.buffer_bytes, p.host_stalled_us / 1e3),
        100 * p.host_utilization(), 100 * p.controller_utilization());
}

nlohmann::json pipeline_json(const experiments::FramePipeline& p, std::string_view sends) {
    nlohmann::json j = experiments::pipeline_figures_json(p);
    j.update({{"send_times", sends},
              {"max_ms", p.max_us() / 1e3},
              {"sum_ms", p.sum_us() / 1e3},
              {"overlap", p.overlap()},
              {"controller_alone_ms", p.controller_alone_us / 1e3}});
    return j;
}

void add_host_options(CLI::App* sub, HostArgs& a) {
    sub->add_option("--host", a.host,
                    host_option_help("Host the times are taken on") +
                        " (natively timed in rounds; on a 1989 host each run once)")
        ->check(host_validator())
        ->capture_default_str();
    sub->add_option("--jobs,-j", a.jobs, "1989 host: emulated runs at once on this machine")
        ->check(cli_check(limits::kJobs))
        ->capture_default_str();
    sub->add_option("--results", a.results,
                    "1989 host: a folder keeping each run's counts; runs found there are not "
                    "run again (the merge step for --emit-jobs)");
    sub->add_option("--emit-jobs", a.emit_jobs,
                    "1989 host: write one command per run missing from --results to this file "
                    "instead of running them: run it with GNU parallel (parallel < FILE) or as "
                    "a Slurm job array (scripts/slurm-sweep FILE -- this command without "
                    "--emit-jobs), then this command again joins them");
}

std::shared_ptr<experiments::PeriodRuns> make_period_runs(const HostArgs& a) {
    if (a.host == "native") {
        if (a.jobs != 1 || !a.results.empty() || !a.emit_jobs.empty())
            throw UsageError(
                "--jobs, --results and --emit-jobs: only with a 1989 --host "
                "(native times are taken in interleaved rounds, one at a time)");
        return nullptr;
    }
    try {
        check_host_name(a.host);
    } catch (const UsageError& e) {
        throw UsageError(std::string("--host: ") + e.what());
    }
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
    const std::string fb89 = n > 0 ? std::string(self, static_cast<size_t>(n)) : "fb89";
    try {
        return std::make_shared<experiments::PeriodRuns>(a.host, a.jobs, a.results, a.emit_jobs,
                                                         fb89);
    } catch (const period::EmulatorError&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw UsageError(std::string("--host: ") + e.what());
    }
}

bool report_emitted(const experiments::ExperimentSettings& s, const HostArgs& a) {
    if (!s.period || a.emit_jobs.empty() || s.period->emitted() == 0) return false;
    const auto& work = s.period->emitted_work();
    std::string known, unknown;
    if (work.known > 0)
        known = fmt::format(
            "; {} of them ran before (by this or an earlier guest): {:.3g} billion guest "
            "instructions, {:.0f} s of emulation where they ran",
            work.known, static_cast<double>(work.instructions) / 1e9, work.seconds);
    if (work.unknown > 0) {
        std::string names;
        for (size_t i = 0; i < work.unknown_names.size() && i < 6; ++i)
            names += (i ? ", " : "") + work.unknown_names[i];
        if (work.unknown_names.size() > 6) names += ", ...";
        unknown = fmt::format(
            "; {} never ran with these results, so their work is known only "
            "by their size: {} faces and {:.3g} million pixels in all ({})",
            work.unknown, work.unknown_faces, static_cast<double>(work.unknown_pixels) / 1e6,
            names);
    }
    fmt::print(stderr,
               "fb89: {} emulated runs written to {}{}{}. Run them, e.g. `parallel < {}` or as "
               "a Slurm job array (scripts/slurm-sweep {} -- this command without "
               "--emit-jobs), then this command again with --results {} to join them into "
               "its table\n",
               s.period->emitted(), a.emit_jobs, known, unknown, a.emit_jobs, a.emit_jobs,
               a.results);
    return true;
}

}  // namespace fb89::frontend
