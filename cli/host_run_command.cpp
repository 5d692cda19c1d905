// fb89 host-run SCENE --isa ISA --results DIR -- GUEST-OPTIONS...: one emulated run of fb89's
// host code on a period host's instruction set (m68k, sparc), its counts written whole into DIR.
// The commands that `experiment|sweep|calibrate --host H --emit-jobs FILE` write are of this form,
// for GNU parallel or a Slurm job array (scripts/slurm-sweep); the experiment run again with
// --results DIR joins them. A run already in DIR is not run again, and SIGTERM or SIGINT (a
// cancelled or timed-out Slurm task) ends the emulator and writes nothing.
#include <csignal>

#include "cli/commands.h"
#include "experiments/period_runs.h"
#include "frontend/data_dir.h"
#include "period/isa.h"
#include "period/stop.h"

namespace fb89::cli {

namespace {

struct HostRunArgs {
    std::string scene, results, isa = "m68k";
    std::vector<std::string> options;
};

volatile std::sig_atomic_t g_host_run_signal = 0;

extern "C" void ask_stop(int signal) {
    g_host_run_signal = signal;
    period::request_stop();  // a lock-free atomic store: safe in a handler
}

}  // namespace

void register_host_run(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<HostRunArgs>();
    CLI::App* sub = app.add_subcommand(
        "host-run",
        "Run one emulated 1989-host job (as written by --emit-jobs) into --results, unless it is "
        "there already; SIGTERM or SIGINT ends it writing nothing (exit 143 or 130)");
    sub->add_option("scene", a->scene, scene_argument_help("Scene: a file"))->required();
    sub->add_option("options", a->options, "The guest's options, after --");
    sub->add_option("--results", a->results, "Folder the counts go to")->required();
    std::vector<std::string> isas;
    for (const auto& isa : period::instruction_sets())
        isas.emplace_back(isa.name);
    sub->add_option("--isa", a->isa, "The guest's instruction set")
        ->check(CLI::IsMember(isas))
        ->capture_default_str();
    sub->callback([a, &exit_code] {
        struct sigaction sa = {};
        sa.sa_handler = ask_stop;
        ::sigemptyset(&sa.sa_mask);
        ::sigaction(SIGTERM, &sa, nullptr);
        ::sigaction(SIGINT, &sa, nullptr);
        try {
            const experiments::OneJob done =
                experiments::run_one_job({resolve_scene(a->scene), a->options}, a->isa, a->results);
            if (!done.ran)
                fmt::print(stderr, "fb89 host-run: {} is there already: not run again\n",
                           done.counts);
            exit_code = kSuccess;
        } catch (const period::Stopped&) {
            fmt::print(stderr,
                       "fb89 host-run: stopped by {} before the run ended; nothing written to {}\n",
                       g_host_run_signal == SIGINT ? "SIGINT" : "SIGTERM", a->results);
            exit_code =
                128 + (g_host_run_signal != 0 ? static_cast<int>(g_host_run_signal) : SIGTERM);
        }
    });
}

}  // namespace fb89::cli
