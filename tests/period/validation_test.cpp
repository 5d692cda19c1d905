// The modelled host against published figures (docs/HOST_COST_MODEL.md, "Validation"): the
// validation kernels run on the emulated MC68020 + MC68881 and pass their own checks, their counts
// are the same run after run, the embedded figures are well formed, and every host profile that a
// figure names prices the kernels within the figure's check. The target is the published figure:
// when a profile misses it, the profile's table is what is wrong. (ctest label `period`: these run
// the emulator.)
#include "period/validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "period/host_profile.h"

namespace fb89::period {
namespace {

const ValidationData& data() {
    static const ValidationData d = builtin_validation();
    return d;
}

// A kernel's run on an instruction set, once per test process.
const KernelRun& kernel_run(const std::string& name, const std::string& isa = "m68k") {
    static std::map<std::pair<std::string, std::string>, KernelRun> runs;
    const std::pair key{isa, name};
    if (!runs.contains(key))
        runs.emplace(key, run_validation_kernel(find_emulator_parts(instruction_set(isa)),
                                                data().kernel(name)));
    return runs.at(key);
}

const PhaseCounts& timed(const KernelRun& run) {
    const PhaseCounts* p = run.counts.phase(static_cast<int>(Phase::HiddenSurface));
    if (!p) throw std::runtime_error("no timed phase");
    return *p;
}

TEST(PeriodValidation, TheEmbeddedFiguresAreWellFormed) {
    const ValidationData& d = data();
    ASSERT_FALSE(d.figures.empty());
    for (const PublishedFigure& f : d.figures) {
        SCOPED_TRACE(f.id);
        EXPECT_FALSE(f.source.empty());
        EXPECT_NO_THROW((void)d.kernel(f.kernel));
        EXPECT_GT(f.value, 0);
    }
    EXPECT_THROW(parse_validation(R"({"schema": 1, "kernels": [], "figures": []})", "t"),
                 std::runtime_error);
}

TEST(PeriodValidation, LinpackSolvesTheBenchmarksSystem) {
    const KernelRun& run = kernel_run("linpack");
    // the kernel exits 1 when its check fails, which run_kernel reports as an error
    EXPECT_NE(run.output.find("linpack n=100 info=0"), std::string::npos) << run.output;
    const size_t at = run.output.find("normalised=");
    ASSERT_NE(at, std::string::npos) << run.output;
    const double normalised = std::stod(run.output.substr(at + 11));
    EXPECT_LT(normalised, 10.0);
    EXPECT_GT(normalised, 0.0);
    const PhaseCounts& t = timed(run);
    EXPECT_EQ(t.entered, 1u);
    // dgefa + dgesl: about n^3/3 multiply-adds, each one FPU multiply and one FPU add
    uint64_t fmul = 0, fadd = 0;
    for (const auto& [key, n] : t.classes) {
        if (key.starts_with("fmul")) fmul += n;
        if (key.starts_with("fadd")) fadd += n;
    }
    EXPECT_NEAR(static_cast<double>(fmul), 100.0 * 100 * 100 / 3, 100.0 * 100 * 100 / 3 * 0.05);
    EXPECT_NEAR(static_cast<double>(fadd), static_cast<double>(fmul),
                0.05 * static_cast<double>(fmul));
}

TEST(PeriodValidation, IntloopRunsVmpupsAdds) {
    const KernelRun& run = kernel_run("intloop");
    EXPECT_NE(run.output.find("adds=900000 j=2700000 expected=2700000"), std::string::npos)
        << run.output;
    const PhaseCounts& t = timed(run);
    ASSERT_TRUE(t.classes.contains("addl dreg,dreg"));
    EXPECT_EQ(t.classes.at("addl dreg,dreg"), 900000u);
    EXPECT_LT(t.instructions, 900000u + 3 * 50000u + 100);
}

TEST(PeriodValidation, KernelCountsAreTheSameRunAfterRun) {
    for (const char* isa : {"m68k", "sparc"})
        for (const char* name : {"linpack", "intloop"}) {
            SCOPED_TRACE(std::string(isa) + " " + name);
            const KernelRun& first = kernel_run(name, isa);
            const KernelRun again = run_validation_kernel(find_emulator_parts(instruction_set(isa)),
                                                          data().kernel(name));
            EXPECT_EQ(timed(again).classes, timed(first).classes);
            EXPECT_EQ(again.counts.instructions, first.counts.instructions);
            EXPECT_EQ(again.output, first.output);
        }
}

TEST(PeriodValidation, AMissingKernelIsAClearError) {
    try {
        find_kernel(instruction_set("sparc"), "fb89_kernel_no_such_kernel");
        ADD_FAILURE() << "found";
    } catch (const EmulatorError& e) {
        EXPECT_NE(std::string(e.what()).find("fb89_kernel_no_such_kernel"), std::string::npos);
    }
}

// The validation itself: every figure against every profile it names, within its check.
// A failure here means a profile's table is wrong (docs/HOST_COST_MODEL.md, "Validation" says how
// to find which entries), not that the target should move.
TEST(PeriodValidation, TheProfilesMeetThePublishedFigures) {
    for (const PublishedFigure& f : data().figures) {
        for (const std::string& name : f.profiles) {
            SCOPED_TRACE(f.id + " on " + name);
            HostProfile profile;
            ASSERT_NO_THROW(profile = load_host_profile(name)) << "profile " << name;
            const ValidationKernel& k = data().kernel(f.kernel);
            const KernelRun& run = kernel_run(f.kernel, profile.isa);
            const double modelled =
                modelled_value(k, f.unit, timed_seconds(run.counts, profile, f.clock_mhz));
            const double error = relative_error(modelled, f.value);
            EXPECT_TRUE(passes(f.check, error))
                << f.kernel << ": modelled " << modelled << " " << f.unit << ", published "
                << f.value << " (" << f.machine << "), error " << 100 * error << "%, check "
                << check_name(f.check);
            const HostCost cost = price(run.counts, profile);
            EXPECT_EQ(cost.phases[static_cast<int>(Phase::HiddenSurface)].unpriced, 0u)
                << "instruction classes the profile's rules do not price";
        }
    }
}

}  // namespace
}  // namespace fb89::period
