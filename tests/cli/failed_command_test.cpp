// A command that fails leaves every file as it was (docs/RELIABILITY.md, "Outputs"): walked
// over every output option of every command (tests/cli/every_output.h) × every way a run
// can fail -- another output of the same command that cannot be written, a file size limit,
// a full disk, an input found damaged part way, a selection that matches nothing -- each
// with an old file at the target and with none. After the failure the test's folder holds
// exactly the files it held before, byte for byte: no partial new file, no hidden
// temporary, no old file set aside, and the exit code is 2.
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "tests/cli/cli_runner.h"
#include "tests/cli/every_output.h"

namespace fs = std::filesystem;
using fb89::testing::CliRun;
using fb89::testing::every_output;
using fb89::testing::OutputCase;
using fb89::testing::put;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::streams;
using fb89::testing::test_dir;
using fb89::testing::with_target;

namespace {

const std::string kOldBytes = "the old file, which must survive\n";

// Every file under `dir` (but the captured stdout and stderr, and a full disk's filler) with
// its bytes: what a failed command must leave as it found.
std::map<std::string, std::string> files_in(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(dir)) {
        const std::string name = fs::relative(e.path(), dir).string();
        if (name == "out" || name == "err" || e.path().filename() == "filler") continue;
        files[name] = e.is_regular_file() ? slurp(e.path()) : std::string("<folder>");
    }
    return files;
}

// What to do to a case's command to make it fail; nullopt where the way does not apply.
using Breaker = std::function<std::optional<std::string>(const OutputCase&, std::string)>;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// Runs every case broken by `breaker`, the target at `where` (old file there, then none),
// and checks that nothing changed. Returns how many runs it checked.
int expect_failures_change_nothing(const Breaker& breaker, const fs::path& where,
                                   const std::string& prefix = "") {
    int checked = 0;
    for (const OutputCase& c : every_output()) {
        for (const bool old : {true, false}) {
            SCOPED_TRACE(c.option + (old ? ", over an old file" : ", to a new path"));
            const fs::path target = where / "target.out";
            fs::remove(test_dir() / "sheet.png");  // compare's other output, when a file
            fs::remove(target);
            if (old) {
                put(target, kOldBytes);
                put(test_dir() / "sheet.png", kOldBytes);
            }
            const std::optional<std::string> command =
                breaker(c, with_target(c.command, target.string()));
            if (!command) continue;
            const auto before = files_in(test_dir());
            const CliRun r = run_fb89(*command, prefix);
            EXPECT_EQ(r.exit_code, 2) << *command << "\n" << r.err;
            EXPECT_FALSE(r.err.empty()) << "a failure says why";
            EXPECT_EQ(files_in(test_dir()), before) << *command << "\n" << r.err;
            ++checked;
        }
    }
    return checked;
}

// The other output a command of the case's kind writes, aimed under a file where a folder
// would have to be: it fails after, or before, the target is written.
std::optional<std::string> blocked_sibling(const OutputCase& c, const std::string& command) {
    const std::string kind = c.option.substr(0, c.option.find(' '));
    static const std::map<std::string, std::pair<std::string, std::string>> siblings = {
        {"render", {"--stats", "--png"}},
        {"radiosity", {"--stats", "--png"}},
        {"compare", {"--json", "--csv"}},
        {"replay", {"--stats", "--png"}}};
    const auto s = siblings.find(kind);
    if (s == siblings.end()) return std::nullopt;
    const std::string option =
        c.option == kind + " " + s->second.first ? s->second.second : s->second.first;
    put(test_dir() / "a_file", kOldBytes);
    return command + " " + option + " " + (test_dir() / "a_file" / "x.out").string();
}

TEST(FailedCommand, AnotherOutputThatCannotBeWrittenLeavesEveryFileAsItWas) {
    EXPECT_GT(expect_failures_change_nothing(blocked_sibling, test_dir()), 20);
}

// Under `ulimit -f 1` (1 KiB), for each output that a successful run makes larger than that.
TEST(FailedCommand, AFileSizeLimitLeavesEveryFileAsItWas) {
    std::map<std::string, bool> large;
    for (const OutputCase& c : every_output()) {
        const fs::path probe = test_dir() / "probe.out";
        fs::remove(probe);
        const CliRun r = run_fb89(with_target(c.command, probe.string()));
        ASSERT_EQ(r.exit_code, c.exit_code) << c.option << ": " << r.err;
        large[c.option] = fs::file_size(probe) > 2048;
        fs::remove(probe);
        fs::remove(test_dir() / "sheet.png");
    }
    const Breaker big_only = [&](const OutputCase& c, std::string command) {
        return large[c.option] ? std::optional<std::string>(command) : std::nullopt;
    };
    EXPECT_GT(expect_failures_change_nothing(big_only, test_dir(),
                                             "bash -c 'ulimit -f 1; exec \"$0\" \"$@\"' "),
              20);
}

// A 64 KiB tmpfs of the test's own, filled to the last block; needs root (CAP_SYS_ADMIN).
TEST(FailedCommand, AFullDiskLeavesEveryFileAsItWas) {
    const fs::path disk = test_dir() / "tmpfs";
    fs::create_directories(disk);
    if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=64k") != 0)
        GTEST_SKIP() << "cannot mount a small tmpfs (needs root with CAP_SYS_ADMIN): "
                     << std::strerror(errno);
    const Breaker fill = [&](const OutputCase&, std::string command) {
        fs::remove(disk / "filler");
        std::ofstream f(disk / "filler", std::ios::binary);
        const std::string block(512, 'f');
        while (f.write(block.data(), block.size()) && f.flush()) {
        }
        return std::optional<std::string>(command);
    };
    const int checked = expect_failures_change_nothing(fill, disk);
    ::umount2(disk.c_str(), MNT_DETACH);
    EXPECT_EQ(checked, 2 * static_cast<int>(every_output().size()));
}

// replay, trim and diff read a stream cut inside its frame: the damage shows part way.
TEST(FailedCommand, AnInputFoundDamagedPartWayLeavesEveryFileAsItWas) {
    const Breaker damage = [](const OutputCase&, std::string command) {
        const std::string cut = replaced(command, streams().demo, streams().cut);
        return cut == command ? std::nullopt : std::optional<std::string>(cut);
    };
    EXPECT_EQ(expect_failures_change_nothing(damage, test_dir()), 2 * 5);
}

// trim's frames and calls, replay's snapshots: a selection that matches no command.
TEST(FailedCommand, ASelectionMatchingNothingLeavesEveryFileAsItWas) {
    const Breaker nothing = [](const OutputCase& c,
                               std::string command) -> std::optional<std::string> {
        if (c.option == "trim -o") return replaced(command, "--frames 0", "--frames 7");
        if (c.option == "replay --png") return command + " --snapshot 1000000-";
        return std::nullopt;
    };
    EXPECT_EQ(expect_failures_change_nothing(nothing, test_dir()), 2 * 2);
    const Breaker no_calls = [](const OutputCase& c,
                                std::string command) -> std::optional<std::string> {
        if (c.option == "trim -o") return replaced(command, "--frames 0", "--calls 1000000-");
        return std::nullopt;
    };
    EXPECT_EQ(expect_failures_change_nothing(no_calls, test_dir()), 2);
}

}  // namespace
