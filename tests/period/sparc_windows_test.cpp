// Register windows on the Sun-4 (period/sparc/classify.c): the recursion kernel
// (period/kernels/recurse.cpp) calls itself DEPTH times inside phase 3, so that phase runs
// DEPTH + 1 saves and restores. With W windows, W - 1 are resident (one is kept invalid for
// the trap handler): once the register file is full every further save spills a window,
// and on the way back every restore past the W - 2 that are still resident fills one.
// QEMU itself restarts a save or restore after its own window trap; the counts must show
// each instruction once. (ctest label `period`: these run the emulator.)
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "period/emulator.h"
#include "period/host_cost.h"

namespace fb89::period {
namespace {

struct Windows {
    uint64_t instructions = 0, saves = 0, restores = 0, overflows = 0, underflows = 0;
};

uint64_t class_count(const PhaseCounts& p, const std::string& key) {
    const auto it = p.classes.find(key);
    return it == p.classes.end() ? 0 : it->second;
}

// The recursion at `depth` on an MB86900 with `windows` windows (QEMU's set to the same).
Windows recurse(int depth, int windows) {
    const InstructionSet& sparc = instruction_set("sparc");
    EmulatorParts parts = find_emulator_parts(sparc);
    InstructionSet isa = sparc;
    const std::string cpu = "TI UltraSparc II,nwindows=" + std::to_string(windows);
    const std::string option = "windows=" + std::to_string(windows);
    isa.qemu_options = {"-cpu", cpu};
    isa.plugin_options = {option};
    parts.isa = &isa;
    const GuestRun run =
        run_kernel(parts, find_kernel(sparc, "fb89_kernel_recurse"), {std::to_string(depth)});
    EXPECT_NE(run.counts_json.find("\"restart_mismatches\":0,"), std::string::npos);
    const PhaseCounts* timed = run.counts.phase(static_cast<int>(Phase::HiddenSurface));
    EXPECT_NE(timed, nullptr);
    if (!timed) return {};
    return {timed->instructions, class_count(*timed, "save"), class_count(*timed, "restore"),
            class_count(*timed, "@window_overflow"), class_count(*timed, "@window_underflow")};
}

TEST(PeriodSparcWindows, EachLevelOfARecursionPastTheRegisterFileSpillsAndFillsOneWindow) {
    for (const int windows : {7, 8}) {
        SCOPED_TRACE(std::to_string(windows) + " windows");
        const Windows shallow = recurse(20, windows), deep = recurse(100, windows);
        // every level one save and one restore, counted once though QEMU restarts them
        EXPECT_EQ(shallow.saves, 21u);
        EXPECT_EQ(shallow.restores, 21u);
        EXPECT_EQ(deep.saves, 101u);
        EXPECT_EQ(deep.restores, 101u);
        // ten instructions a level: save, cmp, bne, nop, st, call, add, ld, ret, restore
        EXPECT_EQ(deep.instructions - shallow.instructions, 80u * 10);
        // eighty more levels: eighty more spills and eighty more fills
        EXPECT_EQ(deep.overflows - shallow.overflows, 80u);
        EXPECT_EQ(deep.underflows - shallow.underflows, 80u);
        // on the way back W - 2 restores find their window resident; every other one fills
        const uint64_t resident = static_cast<uint64_t>(windows) - 2;
        EXPECT_EQ(shallow.underflows, shallow.restores - resident);
        EXPECT_EQ(deep.underflows, deep.restores - resident);
    }
}

// The SPARCstation 2's 8 windows followed beside QEMU's 7 (also_windows=8, as fb89 runs the
// guest: period/isa.cpp) count what QEMU set to 8 counts itself.
TEST(PeriodSparcWindows, AWindowCountFollowedBesideQemusCountsAsQemuSetToItDoes) {
    const InstructionSet& sparc = instruction_set("sparc");
    EmulatorParts parts = find_emulator_parts(sparc);
    InstructionSet isa = sparc;
    isa.qemu_options = {"-cpu", "TI UltraSparc II,nwindows=7"};
    isa.plugin_options = {"windows=7", "also_windows=8"};
    parts.isa = &isa;
    const GuestRun run = run_kernel(parts, find_kernel(sparc, "fb89_kernel_recurse"), {"50"});
    const PhaseCounts* timed = run.counts.phase(static_cast<int>(Phase::HiddenSurface));
    ASSERT_NE(timed, nullptr);
    const Windows seven = recurse(50, 7), eight = recurse(50, 8);
    EXPECT_EQ(class_count(*timed, "@window_overflow"), seven.overflows);
    EXPECT_EQ(class_count(*timed, "@window_underflow"), seven.underflows);
    EXPECT_EQ(class_count(*timed, "@window_overflow_8w"), eight.overflows);
    EXPECT_EQ(class_count(*timed, "@window_underflow_8w"), eight.underflows);
}

TEST(PeriodSparcWindows, MoreWindowsTakeOneTrapFewerEachWay) {
    const Windows seven = recurse(50, 7), eight = recurse(50, 8);
    EXPECT_EQ(seven.overflows - eight.overflows, 1u);
    EXPECT_EQ(seven.underflows - eight.underflows, 1u);
    EXPECT_EQ(seven.instructions, eight.instructions);
}

// V7 purity: fb89_v7_check (period/sparc/v7_check.c) is built like the guest, with fb89's V7
// 64-bit helpers and libgcc's .umul and .udiv but no C library, and runs on a CPU that has
// nothing newer than V7, which stops it on any V8 or V9 instruction.
TEST(PeriodSparcV7, TheHelpersAndTheCodeGenRunOnACpuWithNothingNewerThanV7) {
    const std::filesystem::path guest = instruction_set("sparc").guest_path;
    if (guest.empty()) GTEST_SKIP() << "the SPARC guest is not built";
    const std::filesystem::path check =
        guest.parent_path().parent_path().parent_path() / "fb89_v7_check";
    ASSERT_TRUE(std::filesystem::exists(check)) << check;
    const std::string command =
        "qemu-sparc -cpu 'Fujitsu MB86904,-mul,-div,-fsqrt' " + check.string() + " 2>&1";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << "stopped by a signal: an instruction V7 does not have";
    EXPECT_EQ(WEXITSTATUS(status), 0) << "a wrong answer (exit 1) or no V7 CPU (127)";
}

}  // namespace
}  // namespace fb89::period
