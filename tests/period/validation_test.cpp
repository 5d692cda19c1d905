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
    for (const InstructionSet& s : instruction_sets())
        for (const char* name : {"linpack", "intloop"}) {
            const std::string& isa = s.name;
            SCOPED_TRACE(isa + " " + name);
            const KernelRun& first = kernel_run(name, isa);
            const KernelRun again = run_validation_kernel(find_emulator_parts(instruction_set(isa)),
                                                          data().kernel(name));
            EXPECT_EQ(timed(again).classes, timed(first).classes);
            EXPECT_EQ(again.counts.instructions, first.counts.instructions);
            EXPECT_EQ(again.output, first.output);
        }
}

TEST(PeriodValidation, FbenchTracesTheObjectiveToItsReferenceResults) {
    for (const InstructionSet& s : instruction_sets()) {
        const std::string& isa = s.name;
        SCOPED_TRACE(isa);
        const KernelRun& run = kernel_run("fbench", isa);
        // the kernel exits 1 unless every aberration matches FBENCH's reference to 11 decimals
        EXPECT_NE(run.output.find("marginal=47.09479120920 0.04178472683"), std::string::npos)
            << run.output;
        EXPECT_NE(run.output.find("wrong=0"), std::string::npos) << run.output;
        // the program's own square root and trigonometry: no fsqrt, and a divide in every
        // Newton step
        const PhaseCounts& t = timed(run);
        uint64_t sqrt = 0, div = 0;
        for (const auto& [key, n] : t.classes) {
            if (key.starts_with("fsqrt")) sqrt += n;
            if (key.starts_with("fdiv")) div += n;
        }
        EXPECT_EQ(sqrt, 0u);
        EXPECT_GT(div, 100u * 100);  // 100 iterations
    }
}

// The caches the plugin follows on SPARC (period/isa.cpp), on FFBENCH's 1 MB array: the
// write-back cache writes back only lines a store made dirty, never more than it filled; the
// write-through ones write nothing back.
TEST(PeriodValidation, OnlyTheWriteBackCacheWritesLinesBack) {
    const PhaseCounts& t = timed(kernel_run("fft2d", "sparc"));
    const auto n = [&](const std::string& key) {
        const auto it = t.classes.find(key);
        return it == t.classes.end() ? uint64_t{0} : it->second;
    };
    const uint64_t fills = n("@dcache_128k_16b_wb_read_miss") + n("@dcache_128k_16b_wb_write_miss");
    EXPECT_GT(n("@dcache_128k_16b_wb_writeback"), 0u);
    EXPECT_LE(n("@dcache_128k_16b_wb_writeback"), fills);
    // every pass reads and writes the whole array: at least its 65,536 lines go back once
    EXPECT_GE(n("@dcache_128k_16b_wb_writeback"), 65536u - 131072u / 16);
    for (const char* wt : {"@dcache_64k_16b_wt_writeback", "@dcache_64k_32b_wt_writeback"})
        EXPECT_EQ(n(wt), 0u) << wt;
    // 32-byte lines hold twice the data: fewer read misses than the 16-byte lines of a cache
    // of the same size
    EXPECT_LT(n("@dcache_64k_32b_wt_read_miss"), n("@dcache_64k_16b_wt_read_miss"));
}

TEST(PeriodValidation, TolerancesAndRatiosAreCheckedOnLoading) {
    const std::string kernel =
        R"({"name": "k", "program": "p", "operations": 1, "operation": "pass", "unit": "s/pass"})";
    const auto figure = [](const std::string& id, const std::string& extra) {
        return R"({"id": ")" + id +
               R"(", "machine": "m", "benchmark": "b", "kernel": "k", "value": 2, "unit": "s/pass",
                 "profiles": ["sun4-260"], "source": "s")" +
               extra + "}";
    };
    const auto doc = [&](const std::string& figures, const std::string& ratios) {
        return R"({"schema": 1, "kernels": [)" + kernel + R"(], "figures": [)" + figures + "]" +
               (ratios.empty() ? "" : R"(, "ratios": [)" + ratios + "]") + "}";
    };
    const ValidationData d =
        parse_validation(doc(figure("a", R"(, "tolerance": 0.15)") + "," + figure("b", ""),
                             R"({"id": "r", "numerator": "a", "denominator": "b",
                                 "tolerance": 0.2})"),
                         "t");
    EXPECT_DOUBLE_EQ(d.figure("a").tolerance, 0.15);
    EXPECT_DOUBLE_EQ(d.figure("b").tolerance, kValidationTolerance);
    ASSERT_EQ(d.ratios.size(), 1u);
    EXPECT_TRUE(passes(d.figure("a"), -0.149));
    EXPECT_FALSE(passes(d.figure("a"), 0.151));
    const auto refused = [&](const std::string& text, const std::string& says) {
        try {
            parse_validation(text, "t.json");
            ADD_FAILURE() << "accepted: " << text;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("t.json"), std::string::npos) << e.what();
        }
    };
    refused(doc(figure("a", R"(, "tolerance": 15)"), ""), "tolerance");
    refused(doc(figure("a", ""), R"({"id": "r", "numerator": "a", "denominator": "x",
                                      "tolerance": 0.2})"),
            "no figure 'x'");
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
            EXPECT_TRUE(passes(f, error))
                << f.kernel << ": modelled " << modelled << " " << f.unit << ", published "
                << f.value << " (" << f.machine << "), error " << 100 * error << "%, check "
                << check_name(f.check) << " within " << 100 * f.tolerance << "%";
            const HostCost cost = price(run.counts, profile);
            EXPECT_EQ(cost.phases[static_cast<int>(Phase::HiddenSurface)].unpriced, 0u)
                << "instruction classes the profile's rules do not price";
        }
    }
}

// The same program on two machines: the ratio of the profiles' modelled figures against the
// published one, within the ratio's tolerance (the Sun-3/60 : Sun-4/260 speed on FFBENCH, the
// Sun-4 : SPARCstation 2 one).
TEST(PeriodValidation, TheProfilesMeetThePublishedRatios) {
    ASSERT_FALSE(data().ratios.empty());
    const auto modelled = [](const PublishedFigure& f) {
        const HostProfile profile = load_host_profile(f.profiles.at(0));
        const KernelRun& run = kernel_run(f.kernel, profile.isa);
        return modelled_value(data().kernel(f.kernel), f.unit, timed_seconds(run.counts, profile));
    };
    for (const RatioCheck& r : data().ratios) {
        SCOPED_TRACE(r.id);
        const PublishedFigure &one = data().figure(r.numerator),
                              &other = data().figure(r.denominator);
        const double error =
            relative_error(modelled(one) / modelled(other), one.value / other.value);
        EXPECT_LE(std::fabs(error), r.tolerance) << "modelled " << modelled(one) / modelled(other)
                                                 << ", published " << one.value / other.value;
    }
}

// The pairs host-validate shows beside its checks: one line per two machines over all their
// figures, none of a machine with itself, none for figures at another clock or of another
// kind of check, none for a pair a ratio check covers; and one machine's figures' spread.
TEST(Validation, UncheckedRatiosPairMachinesNotFigures) {
    const auto figure = [](std::string id, double value, FigureCheck check = FigureCheck::Within,
                           double clock = 0) {
        PublishedFigure f;
        f.id = std::move(id);
        f.kernel = "fft2d";
        f.benchmark = "ffbench";
        f.unit = "s/pass";
        f.value = value;
        f.check = check;
        f.clock_mhz = clock;
        return f;
    };
    const std::vector<PublishedFigure> figures = {figure("a", 60),
                                                  figure("pc-1", 50),
                                                  figure("pc-2", 40),
                                                  figure("pc-3", 55),
                                                  figure("b", 12),
                                                  figure("c-fast", 30, FigureCheck::Within, 33),
                                                  figure("a-slow", 80, FigureCheck::AtLeast)};
    const std::vector<ModelledFigure> rows = {{&figures[0], "a", 66},  {&figures[1], "pc", 44},
                                              {&figures[2], "pc", 44}, {&figures[3], "pc", 44},
                                              {&figures[4], "b", 11},  {&figures[5], "pc", 33},
                                              {&figures[6], "a", 66}};
    const std::vector<RatioCheck> checks = {{"a-over-b", "b", "a", 0.2, ""}};

    const std::vector<UncheckedRatio> r = unchecked_ratios(rows, checks);
    ASSERT_EQ(r.size(), 2u);  // a/pc and pc/b; not a/b (checked), not pc/pc
    EXPECT_EQ(r[0].numerator, "a");
    EXPECT_EQ(r[0].denominator, "pc");
    EXPECT_DOUBLE_EQ(r[0].modelled, 1.5);
    EXPECT_EQ(r[0].pairs, 3);  // a against each of pc's three own-clock figures
    EXPECT_DOUBLE_EQ(r[0].published_low, 60.0 / 55);
    EXPECT_DOUBLE_EQ(r[0].published_high, 60.0 / 40);
    EXPECT_EQ(r[1].numerator, "pc");
    EXPECT_EQ(r[1].denominator, "b");
    EXPECT_DOUBLE_EQ(r[1].modelled, 4);
    EXPECT_EQ(r[1].pairs, 3);
    EXPECT_DOUBLE_EQ(r[1].published_low, 40.0 / 12);
    EXPECT_DOUBLE_EQ(r[1].published_high, 55.0 / 12);

    const std::vector<FigureSpread> s = figure_spreads(rows);
    ASSERT_EQ(s.size(), 1u);  // pc's three; the 33 MHz figure is at another clock
    EXPECT_EQ(s[0].profile, "pc");
    EXPECT_EQ(s[0].figures, 3);
    EXPECT_EQ(s[0].low, 40);
    EXPECT_EQ(s[0].high, 55);
    EXPECT_EQ(s[0].modelled, 44);
    EXPECT_EQ(s[0].unit, "s/pass");
}

}  // namespace
}  // namespace fb89::period
