// Outputs are never half-written (docs/RELIABILITY.md, "Outputs"): under a file size limit,
// on a full disk and when killed at random points, every output file is either the old
// file, byte for byte, or a whole new one.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/png_io.h"
#include "tests/cli/cli_process.h"
#include "tests/cli/cli_runner.h"
#include "tests/scenes_dir.h"

namespace fs = std::filesystem;
using fb89::testing::CliRun;
using fb89::testing::put;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;

namespace {

using fb89::testing::kScenes;
const std::string kOld = "the old file, which must survive\n";

// A fresh folder for the outputs (test_dir() also holds the captured stdout and stderr).
fs::path outputs() {
    const fs::path dir = test_dir() / "outputs";
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Hidden temporaries (".NAME.tmp-XXXXXX") left in `dir`.
std::vector<std::string> temporaries(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos)
            names.push_back(e.path().filename().string());
    return names;
}

// `render OPTION FILE` over an old FILE under `ulimit -f blocks` (KiB in bash).
void expect_file_too_large_keeps_the_old(const std::string& option, const std::string& name,
                                         int blocks) {
    const fs::path dir = outputs(), target = dir / name;
    put(target, kOld);
    const CliRun r =
        run_fb89("render " + kScenes + "/demo.json -q " + option + " " + target.string(),
                 "bash -c 'ulimit -f " + std::to_string(blocks) + "; exec \"$0\" \"$@\"' ");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err, "fb89: error: " + target.string() + ": File too large\n");
    EXPECT_EQ(slurp(target), kOld);
    EXPECT_TRUE(temporaries(dir).empty());
}

TEST(AtomicOutput, PngOverAnOldFileUnderAFileSizeLimitExitsTwoAndKeepsTheOld) {
    expect_file_too_large_keeps_the_old("--png", "out.png", 8);
}

TEST(AtomicOutput, IdsOverAnOldFileUnderAFileSizeLimitExitsTwoAndKeepsTheOld) {
    expect_file_too_large_keeps_the_old("--ids", "out.ids.png", 8);
}

TEST(AtomicOutput, StatsOverAnOldFileUnderAFileSizeLimitExitsTwoAndKeepsTheOld) {
    expect_file_too_large_keeps_the_old("--stats", "out.json", 1);
}

TEST(AtomicOutput, CsvOverAnOldFileUnderAFileSizeLimitExitsTwoAndKeepsTheOld) {
    const fs::path dir = outputs(), target = dir / "model.csv";
    put(target, kOld);
    const CliRun r =
        run_fb89("model --es 16..1024*2 --fv 1..1048576*4 --d 2 --csv " + target.string(),
                 "bash -c 'ulimit -f 1; exec \"$0\" \"$@\"' ");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(target.string() + ": File too large"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(target), kOld);
    EXPECT_TRUE(temporaries(dir).empty());
}

TEST(AtomicOutput, ASuccessfulRenderReplacesEveryOutputAndLeavesNoTemporary) {
    const fs::path dir = outputs();
    for (const char* name : {"out.png", "out.ids.png", "out.json"})
        put(dir / name, kOld);
    const CliRun r = run_fb89(
        "render " + kScenes + "/demo.json -q --size 64x48 --png " + (dir / "out.png").string() +
        " --ids " + (dir / "out.ids.png").string() + " --stats " + (dir / "out.json").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(fb89::controller::read_png(dir / "out.png").width, 64u);
    EXPECT_EQ(fb89::controller::read_png(dir / "out.ids.png").height, 48u);
    EXPECT_TRUE(nlohmann::json::parse(slurp(dir / "out.json"), nullptr, false).is_object());
    EXPECT_TRUE(temporaries(dir).empty());
}

// A stream is written in place, by design (live, for a viewer), the old file waiting aside;
// the cut is an error naming the stream, and the old file is put back.
TEST(AtomicOutput, AStreamUnderAFileSizeLimitIsAnErrorAndKeepsTheOldStream) {
    const fs::path dir = outputs(), target = dir / "out.fb89";
    put(target, kOld);
    const CliRun r = run_fb89("render " + kScenes + "/demo.json -q --stream " + target.string(),
                              "bash -c 'ulimit -f 1; exec \"$0\" \"$@\"' ");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err, "fb89: error: cannot write stream " + target.string() + ": File too large\n");
    // the command failed: the old file is back, byte for byte, and nothing beside it
    EXPECT_EQ(slurp(target), kOld);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicOutput, AFailureAfterTheStreamIsWrittenLeavesNoStreamAndNoOtherOutput) {
    // --stats into a folder that is not there fails after --png and --stream were written
    const fs::path dir = outputs();
    put(dir / "out.png", kOld);
    const std::string blocked = (dir / "file" / "stats.json").string();
    put(dir / "file", kOld);  // a file where the stats' folder would have to be
    const CliRun r =
        run_fb89("render " + kScenes + "/demo.json -q --png " + (dir / "out.png").string() +
                 " --stream " + (dir / "out.fb89").string() + " --stats " + blocked);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("stats.json"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir / "out.png"), kOld);
    EXPECT_FALSE(fs::exists(dir / "out.fb89"));
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir))
        names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"file", "out.png"}));
}

// True when `png` is the old file or a whole 4096x3120 image.
::testing::AssertionResult old_or_whole_png(const fs::path& png) {
    const std::string bytes = slurp(png);
    if (bytes == kOld) return ::testing::AssertionSuccess();
    try {
        const auto img = fb89::controller::read_png(png);
        if (img.width == 4096 && img.height == 3120) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << png << " is " << img.width << "x" << img.height;
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << e.what();
    }
}

::testing::AssertionResult old_or_whole_json(const fs::path& json) {
    const std::string bytes = slurp(json);
    if (bytes == kOld || nlohmann::json::accept(bytes)) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << json << " is neither the old file nor JSON";
}

// Kills a large render after seeded delays spread over one whole run's length (measured
// first, so the kills land in rendering and in writing on any machine).
TEST(AtomicOutput, KilledAtRandomPointsEachOutputIsTheOldFileOrAWholeNewOne) {
    const fs::path dir = outputs(), png = dir / "big.png", json = dir / "big.json";
    const std::vector<std::string> args{
        "render", kScenes + "/demo.json", "-q",      "--size",     "4096x3120",
        "--png",  png.string(),           "--stats", json.string()};
    const auto start = std::chrono::steady_clock::now();
    fb89::testing::Process whole = fb89::testing::spawn_fb89(args, "whole");
    ASSERT_EQ(whole.wait(std::chrono::seconds(600)), 0) << slurp(whole.err);
    const auto length = std::chrono::steady_clock::now() - start;
    ASSERT_TRUE(old_or_whole_png(png));

    std::mt19937 random(1989);
    std::uniform_real_distribution<double> share(0.0, 1.1);
    for (int i = 0; i < 6; ++i) {
        put(png, kOld);
        put(json, kOld);
        fb89::testing::Process p = fb89::testing::spawn_fb89(args, "killed");
        std::this_thread::sleep_for(
            std::chrono::duration_cast<std::chrono::microseconds>(length * share(random)));
        ::kill(p.pid, SIGKILL);
        p.wait(std::chrono::seconds(60));
        EXPECT_TRUE(old_or_whole_png(png)) << "kill " << i;
        EXPECT_TRUE(old_or_whole_json(json)) << "kill " << i;
    }
}

// A 64 KiB tmpfs filled to the last block. Mounting needs root (CAP_SYS_ADMIN).
struct SmallTmpfs {
    fs::path dir;
    bool mounted = false;
    explicit SmallTmpfs(fs::path where) : dir(std::move(where)) {
        fs::create_directories(dir);
        mounted = ::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") == 0;
    }
    ~SmallTmpfs() {
        if (mounted) ::umount2(dir.c_str(), MNT_DETACH);
    }
    void fill() const {
        std::ofstream f(dir / "filler", std::ios::binary);
        const std::string block(512, 'f');
        while (f.write(block.data(), block.size()) && f.flush()) {
        }
    }
};

TEST(AtomicOutput, OnAFullDiskEveryOutputExitsTwoAndKeepsTheOld) {
    SmallTmpfs disk(test_dir() / "tmpfs");
    if (!disk.mounted)
        GTEST_SKIP() << "cannot mount a small tmpfs (needs root with CAP_SYS_ADMIN): "
                     << std::strerror(errno);
    for (const char* option : {"--png", "--ids", "--stats"}) {
        const fs::path target = disk.dir / (std::string("out") + option + ".out");
        put(target, kOld);
        disk.fill();
        const CliRun r =
            run_fb89("render " + kScenes + "/demo.json -q " + option + " " + target.string());
        EXPECT_EQ(r.exit_code, 2) << option << ": " << r.err;
        EXPECT_EQ(r.err, "fb89: error: " + target.string() + ": No space left on device\n");
        EXPECT_EQ(slurp(target), kOld) << option;
        EXPECT_TRUE(temporaries(disk.dir).empty()) << option;
        fs::remove(disk.dir / "filler");
    }
}

}  // namespace
