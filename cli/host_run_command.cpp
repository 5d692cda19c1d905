// fb89 host-run SCENE --isa ISA --results DIR -- GUEST-OPTIONS...: one emulated run of fb89's
// host code on a period host's instruction set (m68k, sparc), its counts written whole into DIR.
// The commands that `experiment|sweep|calibrate --host H --emit-jobs FILE` write are of this form,
// for GNU parallel or a Slurm job array; the experiment run again with --results DIR joins them.
#include "cli/common.h"
#include "cli/data_dir.h"
#include "experiments/period_runs.h"
#include "period/isa.h"

namespace fb89::cli {

namespace {

struct HostRunArgs {
    std::string scene, results, isa = "m68k";
    std::vector<std::string> options;
};

}  // namespace

void register_host_run(CLI::App& app, int& exit_code) {
    auto a = std::make_shared<HostRunArgs>();
    CLI::App* sub = app.add_subcommand(
        "host-run", "Run one emulated 1989-host job (as written by --emit-jobs) into --results");
    sub->add_option("scene", a->scene, "Scene: a file, or a bundled scene by name")->required();
    sub->add_option("options", a->options, "The guest's options, after --");
    sub->add_option("--results", a->results, "Folder the counts go to")->required();
    std::vector<std::string> isas;
    for (const auto& isa : period::instruction_sets())
        isas.emplace_back(isa.name);
    sub->add_option("--isa", a->isa, "The guest's instruction set")
        ->check(CLI::IsMember(isas))
        ->capture_default_str();
    sub->callback([a, &exit_code] {
        experiments::run_one_job({resolve_scene(a->scene), a->options}, a->isa, a->results);
        exit_code = kSuccess;
    });
}

}  // namespace fb89::cli
