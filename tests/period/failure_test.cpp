// A 1989-host run that goes wrong: a guest that crashes, loops, runs out of memory or exits
// non-zero under the emulator is stopped within its bounds, reported with the phase it was
// in, and leaves no output behind (period/kernels/fault.cpp fails on purpose).
#include "period/emulator.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tests/cli/cli_runner.h"

namespace fb89::period {
namespace {

// The message of the EmulatorError the fault kernel's `mode` raises.
std::string failure(const std::string& mode) {
    try {
        const InstructionSet& m68k = instruction_set("m68k");
        run_kernel(find_emulator_parts(m68k), find_kernel(m68k, "fb89_kernel_fault"), {mode});
    } catch (const EmulatorError& e) {
        return e.what();
    }
    return "(no error)";
}

// Sets an environment variable for the life of the object.
struct ScopedEnv {
    ScopedEnv(const char* variable, const char* value) : name(variable) {
        ::setenv(name, value, 1);
    }
    ~ScopedEnv() { ::unsetenv(name); }
    const char* name;
};

TEST(PeriodFailure, ACrashIsReportedWithItsSignalAndPhase) {
    const std::string e = failure("crash");
    EXPECT_NE(e.find("crashed (signal 11, SIGSEGV) in phase hidden_surface"), std::string::npos)
        << e;
    EXPECT_NE(e.find("fb89_kernel_fault"), std::string::npos) << e;
}

// A guest ended by a signal sent to it (here its own SIGTERM, as `kill` from a shell sends)
// did not crash, and the message says so.
TEST(PeriodFailure, ASignalFromOutsideIsNotCalledACrash) {
    const std::string e = failure("term");
    EXPECT_NE(e.find("was ended from outside (signal 15, SIGTERM) in phase hidden_surface"),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find("crashed"), std::string::npos) << e;
}

TEST(PeriodFailure, ALoopIsStoppedAtTheTimeLimit) {
    ScopedEnv limit("FB89_GUEST_TIME_LIMIT", "2");
    const std::string e = failure("loop");
    EXPECT_NE(e.find("ran past its limit of 2 s in phase hidden_surface"), std::string::npos) << e;
}

TEST(PeriodFailure, RunningOutOfMemoryIsStoppedAtTheMemoryLimit) {
    ScopedEnv memory("FB89_GUEST_MEMORY_LIMIT", "96");
    ScopedEnv time("FB89_GUEST_TIME_LIMIT", "120");  // so a missed bound fails, not hangs
    const std::string e = failure("hog");
    EXPECT_NE(e.find("ran out of memory (limit 96 MiB) in phase hidden_surface"), std::string::npos)
        << e;
}

TEST(PeriodFailure, ANonZeroExitIsReportedWithItsPhase) {
    const std::string e = failure("exit");
    EXPECT_NE(e.find("failed (exit 3) in phase hidden_surface"), std::string::npos) << e;
}

// Through the command line, with the fault kernel standing in for the guest program: exit 2,
// one line naming the phase, and no --png, --stats or --stream written.
TEST(PeriodFailure, RenderWritesNothingWhenTheGuestCrashes) {
    const std::filesystem::path dir = fb89::testing::test_dir();
    const std::string kernel = find_kernel(instruction_set("m68k"), "fb89_kernel_fault").string();
    const fb89::testing::CliRun r = fb89::testing::run_fb89(
        "render " + std::string(FB89_SCENES_DIR) + "/A.json --size 64x48 --host sun3-60 --png " +
            (dir / "a.png").string() + " --stats " + (dir / "a.json").string() + " --stream " +
            (dir / "a.fb89").string(),
        "FB89_M68K_GUEST=" + kernel + " ");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("crashed (signal 11, SIGSEGV) in phase hidden_surface"), std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
    EXPECT_FALSE(std::filesystem::exists(dir / "a.json"));
    EXPECT_FALSE(std::filesystem::exists(dir / "a.fb89"));
}

}  // namespace
}  // namespace fb89::period
