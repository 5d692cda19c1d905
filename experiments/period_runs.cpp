#include "experiments/period_runs.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "experiments/progress.h"
#include "host/scene/scene_loader.h"
#include "period/stop.h"
#include "protocol/output_file.h"

namespace fb89::experiments {

namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open");
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

uint64_t fnv1a(std::string_view bytes, uint64_t h = 1469598103934665603ull) {
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

std::string shell_quoted(const std::string& s) {
    std::string out(1, '\'');
    for (char c : s) {
        if (c == '\'')
            out.append("'\\''");
        else
            out.push_back(c);
    }
    out.push_back('\'');
    return out;
}

// Written beside the target and renamed when whole, so a folder never holds half a result.
// A results file is put in place at once: it is a cache that later runs resume from, kept
// even when the command that made it fails later.
void write_whole(const fs::path& path, const std::string& text,
                 protocol::Publish publish = protocol::Publish::WithCommand) {
    protocol::write_output(path, text, publish);
}

// What decides a run's counts besides its job: the guest program, the counting plugin and the
// plugin's options (the caches and register windows it follows). A change to any of them makes
// every kept run stale.
std::string fingerprint(const period::EmulatorParts& parts) {
    uint64_t h = fnv1a(slurp(parts.guest));
    h = fnv1a(slurp(parts.plugin), h);
    for (const std::string_view o : parts.isa->plugin_options)
        h = fnv1a(std::string(o) + '\0', h);
    return fmt::format("{:016x}", h);
}

std::string number(double v) {
    return std::isinf(v) ? "inf" : fmt::format("{}", v);
}

// `salt` (the guest's fingerprint, or the instruction set), the scene file's bytes and name,
// and the options, hashed.
uint64_t job_hash(std::string_view salt, const GuestJob& job) {
    uint64_t h = fnv1a(salt);
    h = fnv1a(slurp(job.scene), h);
    h = fnv1a(fs::path(job.scene).filename().string(), h);
    for (const std::string& o : job.options)
        h = fnv1a(o + '\0', h);
    return h;
}

// A job's work, whatever guest ran it: the scene, its options and the instruction set, hashed.
// The results folder keeps, beside each run's counts, `work-KEY.json` with its instructions
// and emulation time, so emitting the same job again (after the guest changed, say) can say
// how much work it is.
std::string work_key(const std::string& isa, const GuestJob& job) {
    return fmt::format("work-{:016x}.json", job_hash(isa, job));
}

void write_work(const std::string& results, const std::string& isa, const GuestJob& job,
                const period::GuestRun& run) {
    const uint64_t instructions =
        period::parse_guest_counts(run.counts_json, job.scene).instructions;
    const nlohmann::json work = {{"instructions", instructions}, {"seconds", run.wall_s}};
    write_whole(fs::path(results) / work_key(isa, job), work.dump() + "\n", protocol::Publish::Now);
}

// The value of `option` among a job's options, or "".
std::string option_of(const GuestJob& job, std::string_view option) {
    for (size_t i = 0; i + 1 < job.options.size(); ++i)
        if (job.options[i] == option) return job.options[i + 1];
    return "";
}

// "A.json zbuffer" or "G.json beam 512x390": a job as a person names it.
std::string job_name(const GuestJob& job) {
    std::string name = fs::path(job.scene).filename().string() + " " + option_of(job, "--method");
    if (const std::string size = option_of(job, "--size"); !size.empty()) name += " " + size;
    return name;
}

}  // namespace

std::vector<std::string> guest_options(const host::MethodOptions& o, const std::string& size) {
    std::vector<std::string> args{
        "--method",         std::string(host::method_info(o.method).name),
        "--window-test",    o.warnock.window_test == host::WindowTest::Centres ? "centres" : "area",
        "--approx-min",     std::to_string(o.warnock.approx.min_side),
        "--approx-eps",     number(o.warnock.approx.epsilon),
        "--threshold",      number(o.hybrid.threshold),
        "--depth-estimate", o.hybrid.depth == host::DepthEstimate::Scene ? "scene" : "window",
        "--beam-threshold", number(o.beam.threshold),
        "--reflections",    std::to_string(o.trace.max_reflections),
        "--grid-density",   number(o.beam.grid_density)};
    // only when not the default, so that the runs kept from before --accel keep their keys
    if (o.trace.accel != host::Accel::Bvh)
        args.insert(args.end(), {"--accel", std::string(host::accel_name(o.trace.accel))});
    if (!o.trace.packets) args.insert(args.end(), {"--packets", "off"});
    if (!size.empty()) args.insert(args.end(), {"--size", size});
    return args;
}

std::string job_key(const std::string& guest_fingerprint, const GuestJob& job) {
    return fmt::format("{:016x}", job_hash(guest_fingerprint, job));
}

PeriodRuns::PeriodRuns(const std::string& host, int jobs, std::string results_dir,
                       std::string emit_jobs, std::string fb89_path)
    : m_profile(period::load_host_profile(host)),
      m_jobs(std::max(1, jobs)),
      m_results(std::move(results_dir)),
      m_emit(std::move(emit_jobs)),
      m_fb89(std::move(fb89_path)),
      m_parts(period::find_emulator_parts(period::instruction_set(m_profile.isa))),
      m_guest_fingerprint(fingerprint(m_parts)) {
    if (!m_emit.empty() && m_results.empty())
        throw std::runtime_error("--emit-jobs needs --results DIR, where the jobs write");
    if (!m_results.empty()) fs::create_directories(m_results);
    if (!m_emit.empty()) write_whole(m_emit, "");  // a fresh list
}

std::string PeriodRuns::counts_of(const GuestJob& job, const std::string& key, GuestOutcome& out) {
    const fs::path cached = m_results.empty() ? fs::path() : fs::path(m_results) / (key + ".json");
    if (!m_results.empty() && fs::exists(cached)) return slurp(cached.string());
    if (!m_emit.empty()) {
        estimate(job);
        std::string line = shell_quoted(m_fb89) + " host-run " + shell_quoted(job.scene) +
                           " --isa " + m_profile.isa + " --results " + shell_quoted(m_results) +
                           " --";
        for (const std::string& o : job.options) {
            line.push_back(' ');
            line.append(shell_quoted(o));
        }
        std::lock_guard lock(m_mutex);
        m_emit_list += line + "\n";
        ++m_emitted;
        return "";
    }
    period::GuestRun run = period::run_guest(m_parts, job.scene, job.options);
    if (!m_results.empty()) {
        write_whole(cached, run.counts_json, protocol::Publish::Now);
        write_work(m_results, m_profile.isa, job, run);
    }
    out.emulated = true;
    out.emulated_seconds = run.wall_s;
    out.stream = std::move(run.stream);
    std::lock_guard lock(m_mutex);
    ++m_emulated;
    return run.counts_json;
}

std::vector<period::HostCost> PeriodRuns::run(const std::vector<GuestJob>& jobs) {
    std::vector<period::HostCost> costs;
    for (GuestOutcome& o : run_outcomes(jobs))
        costs.push_back(std::move(o.cost));
    return costs;
}

void PeriodRuns::estimate(const GuestJob& job) {
    const fs::path work = fs::path(m_results) / work_key(m_profile.isa, job);
    std::lock_guard lock(m_mutex);
    std::error_code ec;
    if (fs::exists(work, ec)) {
        try {
            const nlohmann::json j = nlohmann::json::parse(slurp(work.string()));
            const auto instructions = j.at("instructions").get<uint64_t>();
            const auto seconds = j.at("seconds").get<double>();
            m_work.instructions += instructions;
            m_work.seconds += seconds;
            m_work.known += 1;
            return;
        } catch (const std::exception&) {  // unreadable: counted as unknown
        }
    }
    m_work.unknown += 1;
    m_work.unknown_names.push_back(job_name(job));
    try {  // the scene's size: its faces and the image's pixels
        const host::Scene scene = host::load_scene(job.scene);
        uint64_t width = static_cast<uint64_t>(scene.width),
                 height = static_cast<uint64_t>(scene.height);
        if (const std::string size = option_of(job, "--size"); !size.empty())
            std::sscanf(size.c_str(), "%lux%lu", &width, &height);
        m_work.unknown_faces += scene.face_count;
        m_work.unknown_pixels += width * height;
    } catch (const std::exception&) {  // the run will say what is wrong with it
    }
}

// Before a join runs anything itself: which of the jobs the results folder lacks.
void PeriodRuns::announce_missing(const std::vector<GuestJob>& jobs) {
    if (m_results.empty() || !m_emit.empty()) return;
    std::vector<std::string> missing;
    for (const GuestJob& job : jobs) {
        std::error_code ec;
        const fs::path cached = fs::path(m_results) / (job_key(m_guest_fingerprint, job) + ".json");
        if (!fs::exists(cached, ec)) missing.push_back(job_name(job));
    }
    if (missing.empty() || missing.size() == jobs.size()) return;  // all found, or none: no join
    std::string names;
    for (const std::string& n : missing)
        names += (names.empty() ? "" : ", ") + n;
    std::cerr << fmt::format("fb89: {} of {} runs are not in {}; running them here: {}\n",
                             missing.size(), jobs.size(), m_results, names);
}

std::vector<GuestOutcome> PeriodRuns::run_outcomes(const std::vector<GuestJob>& jobs) {
    announce_missing(jobs);
    std::vector<GuestOutcome> out(jobs.size());
    std::vector<std::string> errors(jobs.size());
    std::atomic<size_t> next{0};
    size_t done = 0;
    ProgressLine line(m_progress);
    line.start(m_label);
    auto report = [&] {  // under m_mutex
        ++done;
        line.step(done, jobs.size(), "emulated runs");
    };
    // a stop asked for (period/stop.h) or thrown by the progress observer ends every worker
    // after its run; the first such throw reaches the caller
    std::exception_ptr stopped;
    auto worker = [&] {
        for (size_t i = next++; i < jobs.size(); i = next++) {
            if (period::stop_requested()) break;
            try {
                const std::string text =
                    counts_of(jobs[i], job_key(m_guest_fingerprint, jobs[i]), out[i]);
                if (!text.empty()) {  // else emitted, not run
                    const period::GuestCounts counts =
                        period::parse_guest_counts(text, jobs[i].scene);
                    out[i].cost = period::price(counts, m_profile);
                    out[i].instructions = counts.instructions;
                }
            } catch (const std::exception& e) {
                errors[i] = e.what();
            } catch (const period::Stopped&) {
                std::lock_guard lock(m_mutex);
                if (!stopped) stopped = std::current_exception();
                break;
            }
            std::lock_guard lock(m_mutex);
            try {
                report();
            } catch (...) {  // the observer's: stop the others too
                if (!stopped) stopped = std::current_exception();
                period::request_stop();
                break;
            }
        }
    };
    const size_t n = std::min<size_t>(static_cast<size_t>(m_jobs), jobs.size());
    auto all = [&] {
        std::vector<std::thread> threads;
        for (size_t t = 1; t < n; ++t)
            threads.emplace_back(worker);
        worker();
        for (auto& t : threads)
            t.join();
    };
    // when every job runs at once, no job ends before the others to measure by: the time so far
    if (n == jobs.size())
        line.ticking(all);
    else
        all();
    line.clear();
    if (stopped) std::rethrow_exception(stopped);
    if (period::stop_requested()) throw period::Stopped{};
    if (!m_emit.empty()) write_whole(m_emit, m_emit_list);  // the whole list so far, at once
    for (const std::string& e : errors)
        if (!e.empty()) throw period::EmulatorError(e);
    return out;
}

OneJob run_one_job(const GuestJob& job, const std::string& isa, const std::string& results_dir) {
    const period::EmulatorParts parts = period::find_emulator_parts(period::instruction_set(isa));
    const fs::path counts = fs::path(results_dir) / (job_key(fingerprint(parts), job) + ".json");
    // only ever put in place whole (write_whole), so a file there is a finished run
    std::error_code ec;
    if (fs::is_regular_file(counts, ec)) return {counts.string(), false};
    const period::GuestRun run = period::run_guest(parts, job.scene, job.options);
    fs::create_directories(results_dir);
    write_whole(counts, run.counts_json, protocol::Publish::Now);
    write_work(results_dir, isa, job, run);
    return {counts.string(), true};
}

}  // namespace fb89::experiments
