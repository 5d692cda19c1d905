// The depth commands through the command line: a face method's ids held to the Z-buffer's,
// its version-3 stream through every replay tool, and a depth command the stream gives no
// depth buffer for refused with exit 2 and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "controller_sim/controller.h"

#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
namespace pr = fb89::protocol;
using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::test_dir;

TEST(DepthStreams, AFaceMethodsIdsAreTheZBuffersButForTheCountedTies) {
    const fs::path ids = test_dir() / "ids.png", stream = test_dir() / "f.fb89";
    const CliRun r = run_fb89("render A --method faces --size 256x195 --ids " + ids.string() +
                              " --stream " + stream.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("ids against the host Z-buffer's (16-bit depth word)"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("0 covered differently, 0 wrong"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(ids));
    pr::StreamReader reader(stream.string());
    EXPECT_EQ(reader.version(), pr::kChecksumVersion);  // version 3's commands, checksummed
    // every replay tool reads it
    for (const std::string tool : {"replay", "info", "dump --calls /face"}) {
        const CliRun t = run_fb89(tool + " " + stream.string());
        EXPECT_EQ(t.exit_code, 0) << tool << ": " << t.err;
        EXPECT_NE(t.out.find("FACE"), std::string::npos) << tool << ": " << t.out;
    }
    const fs::path trimmed = test_dir() / "t.fb89";
    const CliRun trim =
        run_fb89("trim " + stream.string() + " --calls 3-10/face -o " + trimmed.string());
    ASSERT_EQ(trim.exit_code, 0) << trim.err;
    // the kept frame keeps its DEPTH_CLEAR, so its faces replay
    const CliRun again = run_fb89("replay " + trimmed.string());
    EXPECT_EQ(again.exit_code, 0) << again.err;
    const CliRun diff = run_fb89("diff " + stream.string() + " " + stream.string());
    EXPECT_EQ(diff.exit_code, 0) << diff.err << diff.out;
}

// The pixels in the frame following the "differing px" heading's row for frame 0.
uint64_t differing_pixels(const std::string& out) {
    const size_t row = out.find("\n     0 ");
    if (row == std::string::npos) return ~uint64_t{0};
    std::istringstream line(out.substr(row + 1, out.find('\n', row + 1) - row - 1));
    std::string frame, a, b, count;
    line >> frame >> a >> b >> count;
    count.erase(std::remove(count.begin(), count.end(), ','), count.end());
    return count.empty() ? ~uint64_t{0} : std::stoull(count);
}

// diff draws both streams as the profile's controller draws them: the default profile's
// 16-bit word ties the demo's faces where the ideal profile's 32-bit one tells them apart.
TEST(DepthStreams, DiffCountsThePixelsTheProfilesDepthWordDraws) {
    const fs::path zb = test_dir() / "demo_zbuffer.fb89", zs = test_dir() / "demo_zspans.fb89";
    ASSERT_EQ(run_fb89("render demo -q --stream " + zb.string()).exit_code, 0);
    ASSERT_EQ(run_fb89("render demo -q --method zspans --stream " + zs.string()).exit_code, 0);
    const CliRun board = run_fb89("diff " + zb.string() + " " + zs.string());
    const CliRun ideal = run_fb89("diff --profile ideal " + zb.string() + " " + zs.string());
    EXPECT_EQ(board.exit_code, 1) << board.err;
    EXPECT_GT(differing_pixels(board.out), 1000u) << board.out;
    EXPECT_LT(differing_pixels(ideal.out), 100u) << ideal.out;
    const CliRun ids = run_fb89("render demo --method zspans --ids " +
                                (test_dir() / "demo_zspans.ids.png").string());
    EXPECT_NE(ids.out.find(fmt::format("depth word): {} of",
                                       fb89::controller::grouped(differing_pixels(board.out)))),
              std::string::npos)
        << "diff's count is the face ids' count on the demo (no two tying faces share a colour)\n"
        << ids.out << board.out;
}

TEST(DepthStreams, ADepthCommandWithoutADepthBufferIsExit2AndWritesNothing) {
    pr::StreamWriter w(test_dir() / "bad.fb89", {}, pr::Timing::Untimed, pr::Commands::Depth);
    w.frame_begin({0, 16, 8, {}});
    w.depth_span({2, 0, 5, 0, 0, {}});
    w.frame_end({});
    w.close();
    const fs::path png = test_dir() / "out.png";
    const CliRun r =
        run_fb89("replay " + (test_dir() / "bad.fb89").string() + " --png " + png.string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("no depth buffer in this frame"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("command 1"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(png));
}

}  // namespace
