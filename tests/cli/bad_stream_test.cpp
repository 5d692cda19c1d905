// Bad command streams, as a user would feed them to fb89 (docs/RELIABILITY.md, "Bad
// input"): cut short, corrupt, of a newer version or claiming gigabytes; missing, empty and
// directory files. Each must end with exit 2 and a message naming the file and what was
// wrong where (or, for input that is valid however odd, exit 0 with the right answer),
// never a crash, a hang or a half-written output that looks valid.
#include <gtest/gtest.h>

#include <climits>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "controller_sim/png_io.h"
#include "protocol/stream_writer.h"
#include "tests/cli/bad_input.h"

namespace {

namespace fs = std::filesystem;
namespace pr = fb89::protocol;

using fb89::testing::CliRun;
using fb89::testing::test_dir;
using fb89::testing::bad_input::expect_refused;
using fb89::testing::bad_input::put_u16;
using fb89::testing::bad_input::put_u32;
using fb89::testing::bad_input::run_with_timeout;
using fb89::testing::bad_input::scratch;
using fb89::testing::bad_input::write_bytes;
using fb89::testing::bad_input::write_file;

// Two 8x6 frames, no properties, in format version 1 (version 4's damage, which its checksums
// catch: stream_checksum_test.cpp): FRAME_BEGIN @12, FILL_RECT @28, FRAME_END @48,
// FRAME_BEGIN @49, FILL_RECT @65, FRAME_END @85, frame index @86 .. 150.
constexpr size_t kFirstRecord = 12, kFrame0End = 49, kIndexAt = 86, kStreamSize = 151;

std::vector<pr::Command> two_frame_commands() {
    return {pr::FrameBegin{0, 8, 6, pr::Rgb{0, 0, 0}},
            pr::FillRect{0, 0, 4, 4, pr::Rgb{255, 0, 0}},
            pr::FrameEnd{},
            pr::FrameBegin{1, 8, 6, pr::Rgb{0, 0, 64}},
            pr::FillRect{2, 2, 3, 3, pr::Rgb{9, 9, 9}},
            pr::FrameEnd{}};
}

std::vector<uint8_t> two_frames() {
    return pr::encode_stream(two_frame_commands(), {}, true, pr::Checksums::Off);
}

// Header of version 1 with no properties.
std::vector<uint8_t> bare_header() {
    std::vector<uint8_t> b = two_frames();
    b.resize(kFirstRecord);
    return b;
}

TEST(BadInputStream, NewerVersionsAreRefusedNamingBothVersions) {
    ASSERT_EQ(two_frames().size(), kStreamSize);
    for (const uint16_t version : {uint16_t{5}, uint16_t{7}, uint16_t{65535}}) {
        std::vector<uint8_t> b = two_frames();
        put_u16(b, 4, version);
        const std::string path = write_bytes("v.fb89", b);
        for (const char* tool : {"replay", "dump", "info", "trim"}) {
            SCOPED_TRACE(std::string(tool) + " version " + std::to_string(version));
            const std::string extra =
                std::string(tool) == "trim" ? " --calls 0- -o " + scratch("t.fb89") : "";
            expect_refused(run_with_timeout(std::string(tool) + " " + path + extra), "v.fb89",
                           {"version " + std::to_string(version), "up to 4"});
        }
    }
}

TEST(BadInputStream, TruncationWritesNothingAndSalvageKeepsCompleteFrames) {
    struct Cut {
        size_t size;
        const char* says;  // in the message
        int frames;        // complete frames before the cut
    };
    const Cut cuts[] = {{0, "truncated", 0},     {3, "truncated", 0},
                        {7, "truncated", 0},     {10, "truncated", 0},
                        {20, "truncated", 0},    {40, "truncated", 0},
                        {70, "truncated", 1},    {kIndexAt + 3, "truncated", 2},
                        {kStreamSize - 1, "", 2}};
    for (const Cut& cut : cuts) {
        SCOPED_TRACE("cut to " + std::to_string(cut.size) + " bytes");
        std::vector<uint8_t> b = two_frames();
        b.resize(cut.size);
        const std::string path = write_bytes("cut.fb89", b), png = scratch("cut.png");
        fs::remove(png);
        CliRun r = run_with_timeout("replay " + path + " --png " + png);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("fb89: error: " + path + ": " + cut.says), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("at byte"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(png)) << "a failed replay writes nothing";
        // a cut header leaves nothing to salvage: still an error
        const bool header_cut = r.err.find("truncated header") != std::string::npos;
        // nor does a stream without a complete frame: the PNG asked for is not written
        r = run_with_timeout("replay --salvage " + path + " --png " + png);
        EXPECT_EQ(r.exit_code, header_cut || cut.frames == 0 ? 2 : 0) << r.err;
        EXPECT_NE(r.err.find(std::string(header_cut ? "fb89: error: " : "fb89: warning: ") + path +
                             ": " + cut.says),
                  std::string::npos)
            << r.err;
        if (cut.frames == 0) {
            EXPECT_FALSE(fs::exists(png)) << "no complete frame: nothing to write";
            if (!header_cut) {
                EXPECT_NE(r.err.find("fb89: error: " + path + ": no complete frame; " + png +
                                     " not written"),
                          std::string::npos)
                    << r.err;
            }
        } else {
            ASSERT_TRUE(fs::exists(png));
            const auto image = fb89::controller::read_png(png);
            EXPECT_EQ(image.pixels[2], cut.frames == 1 ? 0 : 64) << "the last complete frame";
        }
        for (const char* tool : {"dump", "info"})
            EXPECT_EQ(run_with_timeout(std::string(tool) + " " + path).exit_code, 2) << tool;
    }
    // a stream cut right after a complete record is a valid (cut) stream
    std::vector<uint8_t> b = two_frames();
    b.resize(kFrame0End);
    EXPECT_EQ(run_with_timeout("replay " + write_bytes("cut.fb89", b)).exit_code, 0);
}

// A stream cut inside a frame: the summary says the frame is open, beside those closed.
TEST(BadInputStream, ACutStreamsSummarySaysItsLastFrameIsStillOpen) {
    std::vector<uint8_t> b = two_frames();
    b.resize(70);  // frame 0 whole, frame 1 begun, its FILL_RECT cut
    const CliRun r = run_with_timeout("replay " + write_bytes("open.fb89", b));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.out.find("frames: 1 closed (0 incomplete), 1 still open (begun, never ended"),
              std::string::npos)
        << r.out;
}

// A footer that disagrees with the stream says both, in words, whole.
TEST(BadInputStream, AFooterThatDisagreesSaysWhatItClaimsAndWhatIsSo) {
    std::vector<uint8_t> b = two_frames();
    ASSERT_EQ(b.size(), kStreamSize);
    b[kStreamSize - 20 + 8] = 7;  // the footer's command count: 7, where there are 6
    const CliRun r = run_with_timeout("info " + write_bytes("footer.fb89", b));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("says the index is at byte 86 after 7 commands; it is at byte 86 after "
                         "6 commands"),
              std::string::npos)
        << r.err;
}

TEST(BadInputStream, CorruptOpcodesNameTheOffsetAndCommand) {
    for (const int opcode : {0x00, 0x06, 0x42, 0xFD, 0xFF}) {
        SCOPED_TRACE("opcode " + std::to_string(opcode));
        std::vector<uint8_t> b = two_frames();
        b[kFrame0End] = static_cast<uint8_t>(opcode);  // command 3
        const std::string path = write_bytes("bad.fb89", b), png = scratch("bad.png");
        expect_refused(run_with_timeout("replay " + path + " --png " + png), "bad.fb89",
                       {"at byte 49", "command 3"});
        EXPECT_FALSE(fs::exists(png)) << "a failed replay writes nothing";
        EXPECT_EQ(run_with_timeout("replay --salvage " + path + " --png " + png).exit_code, 0);
        EXPECT_TRUE(fs::exists(png)) << "frame 0 stays usable with --salvage";
        fs::remove(png);
    }
    // garbage from the first byte: not a stream at all
    const std::string text = write_file("text.fb89", "this is not an fb89 stream\n");
    expect_refused(run_with_timeout("info " + text), "text.fb89", {"magic"});
}

TEST(BadInputStream, SizesClaimingGigabytesAreRefusedBeforeAllocating) {
    struct Case {
        const char* name;
        std::vector<uint8_t> bytes;
        const char* says;
    };
    std::vector<Case> cases;
    {  // 4 G properties
        std::vector<uint8_t> b = bare_header();
        put_u32(b, 8, 0xFFFFFFFF);
        cases.push_back({"property count", b, "property count"});
    }
    {  // a 64 KiB key, a 4 GiB value
        std::vector<uint8_t> b = bare_header();
        put_u32(b, 8, 1);
        b.insert(b.end(), {0xFF, 0xFF, 'k'});
        cases.push_back({"key length", b, "key"});
        b = bare_header();
        put_u32(b, 8, 1);
        b.insert(b.end(), {1, 0, 'k', 0xFF, 0xFF, 0xFF, 0xFF, 'v'});
        cases.push_back({"value length", b, "value"});
    }
    {  // a 64 KiB marker
        std::vector<uint8_t> b = bare_header();
        b.insert(b.end(), {0x04, 0xFF, 0xFF, 'm', 'm'});
        cases.push_back({"marker length", b, "MARKER"});
    }
    {  // a frame 4 G pixels wide, one 16385 high
        std::vector<uint8_t> b = two_frames();
        put_u32(b, kFirstRecord + 5, 0xFFFFFFFF);
        cases.push_back({"frame width", b, "width"});
        b = two_frames();
        put_u32(b, kFirstRecord + 9, 16385);
        cases.push_back({"frame height", b, "height"});
    }
    {  // a frame index of 4 G entries (80 GB)
        std::vector<uint8_t> b = two_frames();
        put_u32(b, kIndexAt + 1, 0xFFFFFFFF);
        cases.push_back({"index entries", b, "index"});
    }
    {  // version 4: a batch of 4 GiB (its BATCH record right after the 20-byte header)
        std::vector<uint8_t> b = pr::encode_stream(two_frame_commands());
        put_u32(b, 20 + 23, 0xFFFFFFFF);
        cases.push_back({"batch length", b, "batch 0"});
    }
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = write_bytes("huge.fb89", c.bytes);
        for (const char* tool : {"replay", "dump", "info"})
            expect_refused(run_with_timeout(std::string(tool) + " " + path), "huge.fb89",
                           {c.says, "byte"});
    }
}

TEST(BadInputStream, FillsAndSpansReachingFarOutsideAreClippedNotRefused) {
    const std::string path = write_bytes(
        "far.fb89",
        pr::encode_stream({pr::FrameBegin{0, 16384, 16384, pr::Rgb{0, 0, 0}},
                           pr::FillRect{INT_MIN, INT_MIN, 0xFFFFFFFF, 0xFFFFFFFF, pr::Rgb{1, 2, 3}},
                           pr::DrawSpan{INT_MAX, INT_MIN, INT_MAX, pr::Rgb{4, 5, 6}},
                           pr::DrawSpan{5, INT_MIN, INT_MAX, pr::Rgb{7, 8, 9}},
                           pr::FillRect{INT_MAX, INT_MAX, 0xFFFFFFFF, 1, pr::Rgb{1, 1, 1}},
                           pr::FrameEnd{}}));
    const std::string stats = scratch("far.json");
    CliRun r = run_with_timeout("replay " + path + " -q --stats " + stats);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(fb89::testing::slurp(stats).find("\"frames_closed\": 1"), std::string::npos);
}

TEST(BadInputStream, MissingEmptyAndDirectoryStreamsNameThePath) {
    const std::string dir = scratch("dir.fb89");
    fs::create_directories(dir);
    const std::string empty = write_file("empty.fb89", "");
    for (const char* tool : {"replay", "dump", "info"}) {
        SCOPED_TRACE(tool);
        expect_refused(run_with_timeout(std::string(tool) + " /nonexistent/s.fb89"),
                       "/nonexistent/s.fb89", {});
        expect_refused(run_with_timeout(std::string(tool) + " " + empty), "empty.fb89",
                       {"truncated"});
        expect_refused(run_with_timeout(std::string(tool) + " " + dir), "dir.fb89", {});
    }
}

}  // namespace
