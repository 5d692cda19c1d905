// Experiments on a 1989 host: counted runs are deterministic, so fanning them out over
// processes here, or writing them out as jobs that GNU parallel runs and joining their
// results, gives the table a single run gives, byte for byte.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "tests/cli/cli_runner.h"
#include "tests/scenes_dir.h"

namespace {

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

using fb89::testing::kScenes;
const std::string kSweep = "sweep threshold " + kScenes + "/A.json " + kScenes +
                           "/B.json --size 128x98 --steps 3 " + "--host sun3-60 -q --csv ";

TEST(PeriodExperiments, RunsFannedOutGiveTheTableOfOneProcess) {
    const std::string one = (test_dir() / "one.csv").string(),
                      two = (test_dir() / "two.csv").string();
    ASSERT_EQ(run_fb89(kSweep + one).exit_code, 0);
    CliRun r = run_fb89(kSweep + two + " --jobs 2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurp(one), slurp(two));
    EXPECT_NE(slurp(one).find("\nA,"), std::string::npos) << "a bundled scene, by name";
}

TEST(PeriodExperiments, EmittedJobsRunByGnuParallelJoinIntoTheSameTable) {
    const auto dir = test_dir();
    std::filesystem::remove_all(dir / "results");
    const std::string single = (dir / "single.csv").string(),
                      merged = (dir / "merged.csv").string(), jobs = (dir / "jobs.txt").string(),
                      results = (dir / "results").string();
    std::filesystem::remove(merged);
    ASSERT_EQ(run_fb89(kSweep + single).exit_code, 0);
    // write the jobs, no table yet
    CliRun emit = run_fb89(kSweep + merged + " --results " + results + " --emit-jobs " + jobs);
    ASSERT_EQ(emit.exit_code, 0) << emit.err;
    EXPECT_NE(emit.err.find("emulated runs written to"), std::string::npos) << emit.err;
    EXPECT_FALSE(std::filesystem::exists(merged)) << "an incomplete table is not written";
    // 2 scenes x (0, 3 ramp steps, inf) = 10 runs, one line each
    std::ifstream lines(jobs);
    int n = 0;
    for (std::string line; std::getline(lines, line);)
        n += !line.empty();
    EXPECT_EQ(n, 10);
    ASSERT_EQ(std::system(("parallel --will-cite -j 2 < " + jobs + " > " + jobs + ".out").c_str()),
              0);
    // join
    CliRun join = run_fb89(kSweep + merged + " --results " + results);
    ASSERT_EQ(join.exit_code, 0) << join.err;
    EXPECT_EQ(slurp(merged), slurp(single));
}

// Emitting says how much work the jobs are: runs seen before (their instructions and time,
// kept beside the results), the others by their scenes' size; a join says which runs it is
// about to make itself.
TEST(PeriodExperiments, EmittedJobsComeWithTheirWorkAndAJoinSaysWhatItRunsItself) {
    namespace fs = std::filesystem;
    const auto dir = test_dir();
    fs::remove_all(dir / "results");
    const std::string csv = (dir / "t.csv").string(), jobs = (dir / "jobs.txt").string(),
                      results = (dir / "results").string();
    const std::string sweep = "sweep threshold " + kScenes +
                              "/A.json --size 96x73 --steps 1 --host sun3-60 -q --csv " + csv +
                              " --results " + results;
    CliRun emit = run_fb89(sweep + " --emit-jobs " + jobs);
    ASSERT_EQ(emit.exit_code, 0) << emit.err;
    // 0, one ramp step, inf: 3 runs, never run before
    EXPECT_NE(emit.err.find("3 emulated runs written to " + jobs), std::string::npos) << emit.err;
    EXPECT_NE(emit.err.find("3 never ran with these results, so their work is known only by "
                            "their size: 72 faces and 0.021 million pixels in all (A.json "),
              std::string::npos)
        << emit.err;
    ASSERT_EQ(std::system(("sh " + jobs + " > " + jobs + ".out").c_str()), 0);
    // as if the guest had changed: the counts gone, the work they took kept
    std::vector<fs::path> counts;
    for (const auto& e : fs::directory_iterator(results))
        if (e.path().filename().string().rfind("work-", 0) != 0) counts.push_back(e.path());
    ASSERT_EQ(counts.size(), 3u);
    fs::remove(counts[0]);
    fs::remove(counts[1]);
    CliRun again = run_fb89(sweep + " --emit-jobs " + jobs);
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_NE(again.err.find("2 emulated runs written to"), std::string::npos) << again.err;
    EXPECT_NE(again.err.find("2 of them ran before (by this or an earlier guest): "),
              std::string::npos)
        << again.err;
    EXPECT_NE(again.err.find(" billion guest instructions, "), std::string::npos) << again.err;
    // the join runs the two missing runs itself, and says so first
    CliRun join = run_fb89(sweep);
    ASSERT_EQ(join.exit_code, 0) << join.err;
    EXPECT_NE(join.err.find("fb89: 2 of 3 runs are not in " + results +
                            "; running them here: A.json hybrid 96x73"),
              std::string::npos)
        << join.err;
}

// The Sun-4 the same way: its jobs name the SPARC guest (host-run --isa sparc).
TEST(PeriodExperiments, Sun4JobsNameTheirInstructionSetAndJoinIntoTheSameTable) {
    const auto dir = test_dir();
    std::filesystem::remove_all(dir / "results4");
    const std::string sweep =
        "sweep threshold " + kScenes + "/A.json --size 96x73 --steps 1 --host sun4-260 -q --csv ";
    const std::string single = (dir / "single4.csv").string(),
                      merged = (dir / "merged4.csv").string(), jobs = (dir / "jobs4.txt").string(),
                      results = (dir / "results4").string();
    ASSERT_EQ(run_fb89(sweep + single).exit_code, 0);
    CliRun emit = run_fb89(sweep + merged + " --results " + results + " --emit-jobs " + jobs);
    ASSERT_EQ(emit.exit_code, 0) << emit.err;
    const std::string lines = slurp(jobs);
    EXPECT_NE(lines.find(" host-run "), std::string::npos) << lines;
    EXPECT_NE(lines.find(" --isa sparc "), std::string::npos) << lines;
    ASSERT_EQ(std::system(("sh " + jobs + " > " + jobs + ".out").c_str()), 0);
    CliRun join = run_fb89(sweep + merged + " --results " + results);
    ASSERT_EQ(join.exit_code, 0) << join.err;
    EXPECT_EQ(slurp(merged), slurp(single));
}

// After the paper on a 1989 host: every row's time is the emulated run's, counted, so two runs
// give the same table; the ideal ladder's rungs go to the guest as scene files in a scratch
// folder, which is gone afterwards.
TEST(PeriodExperiments, TheSuccessorsRunOnA1989HostAndGiveOneTable) {
    const auto dir = test_dir();
    const std::string one = (dir / "successors1.csv").string(),
                      two = (dir / "successors2.csv").string();
    const std::string run =
        "experiment successors " + kScenes + "/A.json --size 64x48 --host sun4-260 -q --csv ";
    const auto scratch_folders = [] {
        int n = 0;
        for (const auto& entry :
             std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
            n += entry.path().filename().string().rfind("fb89-successors-", 0) == 0;
        return n;
    };
    const int before = scratch_folders();
    CliRun r = run_fb89(run + one);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_EQ(run_fb89(run + two).exit_code, 0);
    EXPECT_LE(scratch_folders(), before);
    const std::string table = slurp(one);
    EXPECT_EQ(table, slurp(two));
    EXPECT_NE(table.find("\nideal-16,hzb,"), std::string::npos) << table;

    const std::string rays = (dir / "successors_rays.csv").string();
    CliRun t = run_fb89("experiment successors-rays " + kScenes +
                        "/cornell_box.json --sizes 48x36 --host sun4-260 -q --csv " + rays);
    ASSERT_EQ(t.exit_code, 0) << t.err;
    const std::string rows = slurp(rays);
    EXPECT_NE(rows.find(",mlrta,"), std::string::npos) << rows;
    EXPECT_EQ(rows.find(",NO"), std::string::npos) << rows;
}

TEST(PeriodExperiments, JobOptionsNeedA1989Host) {
    CliRun r = run_fb89(kSweep.substr(0, kSweep.find("--host")) + "--jobs 2");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("only with a 1989 --host"), std::string::npos) << r.err;
}

}  // namespace
