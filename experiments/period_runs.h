// The experiments on a 1989 host: every (scene, setting) runs once on the emulated period
// host of the profile's instruction set (period/emulator.h) -- its counts are exact, so there is
// nothing to repeat and no noise to take a median of -- and is priced by the host profile. Runs are
// independent: they fan out over `jobs` emulator processes here, or, with `emit_jobs`, are written
// out as one command each (`fb89 host-run ...`) for GNU parallel or a Slurm job array on other
// machines; their outputs land in a results folder, and running the experiment again with
// that folder joins them into the same table a single run writes.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "host/methods.h"
#include "period/emulator.h"
#include "period/host_cost.h"
#include "period/host_profile.h"

namespace fb89::experiments {

// The guest's options for a method (thresholds as numbers) at a size ("" for the scene's).
std::vector<std::string> guest_options(const host::MethodOptions& options, const std::string& size);

struct GuestJob {
    std::string scene;                 // as given (a path)
    std::vector<std::string> options;  // the guest's own options (guest_options()' form)
};

// One job's result: its priced counts and, when it was emulated here (not answered from the
// results folder, not emitted), what the emulation gave besides.
struct GuestOutcome {
    period::HostCost cost;
    uint64_t instructions = 0;
    bool emulated = false;        // run here now
    double emulated_seconds = 0;  // how long that took
    std::vector<uint8_t> stream;  // the guest's command stream (emulated runs only)
};

class PeriodRuns {
  public:
    // `host`: a built-in host profile or a .json file. Throws std::runtime_error.
    PeriodRuns(const std::string& host, int jobs, std::string results_dir, std::string emit_jobs,
               std::string fb89_path);

    // The priced counts of every job, in order. A job whose counts are in the results
    // folder is not run again; with emit_jobs, a missing one is written out and priced as
    // zero (emitted() says how many).
    std::vector<period::HostCost> run(const std::vector<GuestJob>& jobs);
    // The same with what each emulated run gave besides its counts.
    std::vector<GuestOutcome> run_outcomes(const std::vector<GuestJob>& jobs);

    // With progress on, run() shows "label: i/n emulated runs, about T s left" on stderr.
    void set_progress(bool on, std::string label) {
        m_progress = on;
        m_label = std::move(label);
    }

    // What the emitted jobs amount to: those a results folder saw run before (by any guest of
    // this instruction set), with their instructions and emulation time, and the others.
    struct EmittedWork {
        uint64_t known = 0, instructions = 0;
        double seconds = 0;
        uint64_t unknown = 0, unknown_faces = 0, unknown_pixels = 0;  // faces and pixels summed
        std::vector<std::string> unknown_names;                       // "A.json zbuffer"
    };

    const period::HostProfile& profile() const { return m_profile; }
    uint64_t emitted() const { return m_emitted; }
    const EmittedWork& emitted_work() const { return m_work; }
    uint64_t emulated() const { return m_emulated; }

  private:
    std::string key(const GuestJob& job);
    // The job's counts (from the results folder, or emulated into `out`); "" when emitted.
    std::string counts_of(const GuestJob& job, const std::string& key, GuestOutcome& out);
    void estimate(const GuestJob& job);                        // adds an emitted job to m_work
    void announce_missing(const std::vector<GuestJob>& jobs);  // a join's own runs, on stderr

    period::HostProfile m_profile;
    int m_jobs = 1;
    std::string m_results, m_emit, m_fb89;
    std::string m_emit_list;  // the jobs emitted so far, one shell line each
    period::EmulatorParts m_parts;
    std::string m_guest_fingerprint;
    std::mutex m_mutex;
    uint64_t m_emitted = 0, m_emulated = 0;
    EmittedWork m_work;
    bool m_progress = false;
    std::string m_label;
};

// A results folder's file name for a job: a hash of the guest program, the scene file's
// bytes and the options, so a changed scene or guest is never answered from an old run.
std::string job_key(const std::string& guest_fingerprint, const GuestJob& job);

// `fb89 host-run`: one job on the guest of instruction set `isa` (period/isa.h), its counts
// written (whole or not at all) into `results_dir`. A job whose counts the folder already
// holds is not run again (a job array submitted again recomputes only what is missing): the
// counts file's path is returned, with `ran` saying whether this call made it.
struct OneJob {
    std::string counts;
    bool ran = false;
};
OneJob run_one_job(const GuestJob& job, const std::string& isa, const std::string& results_dir);

}  // namespace fb89::experiments
