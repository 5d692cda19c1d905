// Every output option writes into what its target is (docs/RELIABILITY.md, "Outputs"): a
// character device, a FIFO and standard output get the bytes and stay what they were; none
// is ever renamed over. The devices are the test's own (mknod in its folder), the FIFO too;
// standard output is reached as "-", through a link of the test's own to /proc/self/fd/1,
// and as /dev/stdout through a pipe.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"
#include "tests/cli/every_output.h"
#include "tests/scenes_dir.h"
#include "tests/special_files.h"

namespace fs = std::filesystem;
using fb89::testing::CliRun;
using fb89::testing::describe;
using fb89::testing::every_output;
using fb89::testing::FifoReader;
using fb89::testing::identity_of;
using fb89::testing::make_char_device;
using fb89::testing::OutputCase;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;
using fb89::testing::with_target;

namespace {

using fb89::testing::kScenes;

// compare --sheet is the one whose other outputs are files: an own sheet for each run
std::string fresh_sheet(const OutputCase& c) {
    fs::remove(test_dir() / "sheet.png");
    return c.command;
}

TEST(OutputTargets, EveryOutputWritesIntoACharacterDeviceAndLeavesItOne) {
    const fs::path device = test_dir() / "null";
    if (const auto why = make_char_device(device, 3)) GTEST_SKIP() << *why;
    const auto before = identity_of(device);
    for (const OutputCase& c : every_output()) {
        SCOPED_TRACE(c.option);
        const CliRun r = run_fb89(with_target(fresh_sheet(c), device.string()));
        EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
        EXPECT_EQ(identity_of(device), before)
            << c.option << " left " << describe(identity_of(device)) << " where "
            << describe(before) << " was";
        for (const auto& e : fs::directory_iterator(test_dir()))
            EXPECT_NE(e.path().filename().string()[0], '.') << "left beside it: " << e.path();
    }
}

TEST(OutputTargets, EveryOutputToAFullDeviceExitsTwoWithNoSpaceLeftAndLeavesItOne) {
    const fs::path device = test_dir() / "full";
    if (const auto why = make_char_device(device, 7)) GTEST_SKIP() << *why;
    const auto before = identity_of(device);
    for (const OutputCase& c : every_output()) {
        SCOPED_TRACE(c.option);
        const CliRun r = run_fb89(with_target(fresh_sheet(c), device.string()));
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find(device.string()), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << r.err;
        EXPECT_EQ(identity_of(device), before) << describe(identity_of(device));
    }
}

TEST(OutputTargets, EveryOutputWritesIntoAFifoAndLeavesItOne) {
    const fs::path fifo = test_dir() / "fifo";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto before = identity_of(fifo);
    for (const OutputCase& c : every_output()) {
        SCOPED_TRACE(c.option);
        FifoReader reader(fifo);
        ASSERT_TRUE(reader.opened());
        const CliRun r = run_fb89(with_target(fresh_sheet(c), fifo.string()));
        const std::string bytes = reader.stop();
        EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
        EXPECT_FALSE(bytes.empty()) << c.option << " sent nothing through the FIFO";
        EXPECT_EQ(identity_of(fifo), before) << describe(identity_of(fifo));
    }
}

// What `fb89 ARGS` gives with the output as "-", with no other word on stdout, and the same
// bytes as a file where the output does not depend on time.
TEST(OutputTargets, EveryOutputGoesToStandardOutputAsDash) {
    const fs::path file = test_dir() / "as_file";
    for (const OutputCase& c : every_output()) {
        SCOPED_TRACE(c.option);
        const CliRun r = run_fb89(with_target(fresh_sheet(c), "-"));
        EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
        ASSERT_FALSE(r.out.empty());
        const bool timed = c.option.find("--stats") != std::string::npos ||
                           c.option.find("--csv") != std::string::npos ||
                           c.option.find("--json") != std::string::npos ||
                           c.option.find("--timeline") != std::string::npos ||
                           c.option == "compare --sheet" ||  // the sheet prints its times
                           c.option == "render --stream";    // it keeps measured send times
        fs::remove(file);
        const CliRun f = run_fb89(with_target(fresh_sheet(c), file.string()));
        EXPECT_EQ(f.exit_code, c.exit_code) << f.err;
        const std::string as_file = slurp(file);
        if (!timed) {
            EXPECT_TRUE(r.out == as_file)
                << "stdout holds exactly what the file would: " << r.out.size() << " bytes against "
                << as_file.size();
        } else {
            EXPECT_EQ(r.out.substr(0, 4), as_file.substr(0, 4)) << r.out.substr(0, 200);
        }
    }
}

TEST(OutputTargets, TwoOutputsCannotBothBeStandardOutput) {
    const CliRun r = run_fb89("render " + kScenes + "/demo.json --size 64x48 -q --png - --stats -");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err,
              "fb89: usage: --png and --stats both write to standard output ('-'); give one "
              "of them a file\n");
    EXPECT_EQ(r.out, "");
}

// A link of the test's own to /proc/self/fd/1 is what /dev/stdout is: first through it (if
// that went wrong, only a scratch link would suffer), then /dev/stdout itself. Both stay
// links; the bytes arrive through the pipe.
TEST(OutputTargets, DevStdoutThroughAPipeIsWrittenIntoAndStaysALink) {
    const fs::path link = test_dir() / "stdout";
    fs::remove(link);
    fs::create_symlink("/proc/self/fd/1", link);
    const fs::path count = test_dir() / "count";
    const std::string png = (test_dir() / "demo.png").string();
    ASSERT_EQ(run_fb89("render " + kScenes + "/demo.json --size 64x48 -q --png " + png).exit_code,
              0);
    const std::string expected = std::to_string(fs::file_size(png)) + "\n";
    const std::string render =
        std::string(FB89_CLI_PATH) + " render " + kScenes + "/demo.json --size 64x48 -q --png ";

    const auto link_before = identity_of(link);
    std::string shell = "sh -c '" + render + link.string() + " | wc -c > " + count.string() + "'";
    ASSERT_EQ(std::system(shell.c_str()), 0);
    EXPECT_EQ(slurp(count), expected) << "the PNG went through the pipe";
    ASSERT_EQ(identity_of(link), link_before) << describe(identity_of(link));

    if (identity_of("/dev/stdout").type != S_IFLNK)
        GTEST_SKIP() << "/dev/stdout is not a symbolic link on this machine";
    shell = "sh -c '" + render + "/dev/stdout | wc -c > " + count.string() + "'";
    ASSERT_EQ(std::system(shell.c_str()), 0);
    EXPECT_EQ(slurp(count), expected);
    EXPECT_EQ(identity_of("/dev/stdout").type, static_cast<mode_t>(S_IFLNK))
        << "/dev/stdout is now " << describe(identity_of("/dev/stdout"));
}

// /dev/stdout redirected to a file by the shell: written through the descriptor, so the
// file the shell opened gets the bytes (a rename would leave them in a file of its own).
TEST(OutputTargets, DevStdoutRedirectedToAFileFillsThatFile) {
    const fs::path link = test_dir() / "stdout";
    fs::remove(link);
    fs::create_symlink("/proc/self/fd/1", link);
    const fs::path out = test_dir() / "redirected.png";
    const std::string shell = "sh -c '" + std::string(FB89_CLI_PATH) + " render " + kScenes +
                              "/demo.json --size 64x48 -q --png " + link.string() + " > " +
                              out.string() + "'";
    ASSERT_EQ(std::system(shell.c_str()), 0);
    EXPECT_EQ(slurp(out).substr(1, 3), "PNG");
    EXPECT_EQ(identity_of(link).type, static_cast<mode_t>(S_IFLNK));
}

}  // namespace
