// Damaged streams through the tools (docs/PROTOCOL.md, "Version 4: checksums"): a flipped bit
// in a recorded stream makes `fb89 replay` exit 2 naming the batch and its byte, never 0 with
// a different frame; `--salvage` keeps and writes the frames before the damaged batch, says
// what it dropped and still exits 2; `info` reports the checksums; `dump`, `trim` and `diff`
// refuse the damage; `trim` writes checksums of its own; older versions replay as before.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "controller_sim/png_io.h"
#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "tests/cli/bad_input.h"
#include "tests/text_contains.h"

namespace {

namespace fs = std::filesystem;
namespace pr = fb89::protocol;

using fb89::testing::CliRun;
using fb89::testing::contains;
using fb89::testing::slurp;
using fb89::testing::bad_input::run_with_timeout;
using fb89::testing::bad_input::scratch;
using fb89::testing::bad_input::write_bytes;

// Four 8x6 frames, each its own colour, one a batch; frame 2 with a marker and 300 spans, so
// that it takes two batches.
std::vector<pr::Command> four_frames() {
    std::vector<pr::Command> c;
    for (uint32_t f = 0; f < 4; ++f) {
        c.push_back(pr::FrameBegin{f, 8, 6, pr::Rgb{0, 0, static_cast<uint8_t>(16 * f)}});
        c.push_back(pr::FillRect{0, 0, 4, 4, pr::Rgb{255, static_cast<uint8_t>(f), 0}});
        if (f == 2) {
            c.push_back(pr::Marker{"spans"});
            for (int i = 0; i < 300; ++i)
                c.push_back(pr::DrawSpan{i % 6, 1, 7, pr::Rgb{0, static_cast<uint8_t>(i), 0}});
        }
        c.push_back(pr::FrameEnd{});
    }
    return c;
}

struct BatchAt {
    uint64_t at = 0;
    pr::BatchRecord record;
};

// The stream's batches, walked by their lengths.
std::vector<BatchAt> batches_of(const std::vector<uint8_t>& bytes) {
    pr::StreamReader reader(bytes);
    std::vector<BatchAt> out;
    for (uint64_t at = reader.header_size(); at < bytes.size();) {
        out.push_back({at, pr::decode_batch(&bytes[at])});
        at += pr::kBatchRecordSize + out.back().record.length;
    }
    return out;
}

TEST(StreamChecksumCli, AFlippedBitInTheCommandsExitsTwoNamingTheBatchAndWritesNothing) {
    const std::vector<uint8_t> good = pr::encode_stream(four_frames(), {{"scene", "built"}});
    const std::vector<BatchAt> batches = batches_of(good);
    ASSERT_EQ(batches.size(), 6u);  // frames 0 and 1, frame 2 in two, frame 3, the index
    std::vector<uint8_t> bad = good;
    // frame 1's FILL_RECT (after its FRAME_BEGIN): the red of its colour
    bad[batches[1].at + pr::kBatchRecordSize + pr::kFrameBeginRecordSize + 17] ^= 0x08;
    const std::string stream = write_bytes("flip.fb89", bad), png = scratch("flip.png");
    ASSERT_EQ(run_with_timeout("replay " + write_bytes("good.fb89", good)).exit_code, 0);

    const CliRun r = run_with_timeout("replay " + stream + " --png " + png);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(contains(r.err, fmt::format("fb89: error: {}: batch 1 fails its checksum at byte "
                                            "{} (commands 3-5): stored 0x",
                                            stream, batches[1].at)))
        << r.err;
    EXPECT_TRUE(contains(r.err, ": the stream is damaged")) << r.err;
    EXPECT_TRUE(contains(r.err, "replayed 1 complete frame(s) before the error")) << r.err;
    EXPECT_FALSE(fs::exists(png)) << "a damaged stream writes nothing without --salvage";
    // frame 0 only: nothing of the damaged batch was drawn
    EXPECT_TRUE(contains(r.out, "format version 4")) << r.out;
    EXPECT_TRUE(contains(r.out, "frames: 1 closed (0 incomplete);")) << r.out;

    // dump and diff refuse it too, naming the batch; info says which batch
    const CliRun dump = run_with_timeout("dump " + stream);
    EXPECT_EQ(dump.exit_code, 2);
    EXPECT_TRUE(contains(dump.err, "batch 1 fails its checksum")) << dump.err;
    EXPECT_FALSE(contains(dump.out, "      3 @")) << "no command of the batch is printed";
    const CliRun diff = run_with_timeout("diff " + write_bytes("good.fb89", good) + " " + stream);
    EXPECT_EQ(diff.exit_code, 2) << diff.err;
    EXPECT_TRUE(contains(diff.err, "batch 1 fails its checksum")) << diff.err;
}

TEST(StreamChecksumCli, SalvageKeepsTheFramesBeforeTheDamagedBatchSaysWhatItDroppedAndExitsTwo) {
    const std::vector<uint8_t> good = pr::encode_stream(four_frames(), {{"scene", "built"}});
    const std::vector<BatchAt> batches = batches_of(good);
    std::vector<uint8_t> bad = good;
    bad[batches[3].at + pr::kBatchRecordSize + 40] ^= 0x01;  // frame 2's second batch
    const std::string stream = write_bytes("salvage.fb89", bad);
    const std::string png = scratch("kept.png"), stats = scratch("kept.json");

    const CliRun r =
        run_with_timeout("replay --salvage " + stream + " --png " + png + " --stats " + stats);
    EXPECT_EQ(r.exit_code, 2) << "the input was damaged: " << r.err;
    EXPECT_TRUE(
        contains(r.err, "batch 3 fails its checksum at byte " + std::to_string(batches[3].at)))
        << r.err;
    EXPECT_TRUE(contains(r.err,
                         "--salvage: kept the 2 complete frame(s) before the damage and "
                         "wrote the outputs from them; dropped batch 3 and everything "
                         "after it: the commands from 262 on, bytes"))
        << r.err;
    EXPECT_TRUE(contains(r.err, "the stream's frame index lists 4 frame(s)")) << r.err;
    EXPECT_TRUE(contains(r.err, "frame 2, begun before the damage, is left open and not counted"))
        << r.err;
    // the frames kept are reported; the last complete one is written
    EXPECT_TRUE(contains(r.out, "frames: 2 closed")) << r.out;
    ASSERT_TRUE(fs::exists(png)) << "--salvage writes what came before the damage";
    const auto image = fb89::controller::read_png(png);
    EXPECT_EQ(image.pixels[0], 255);
    EXPECT_EQ(image.pixels[1], 1) << "frame 1's fill";
    EXPECT_EQ(image.pixels[(5 * 8 + 7) * 3 + 2], 16) << "frame 1's background";
    const auto j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["controller"]["frames_closed"], 2);
    EXPECT_EQ(j["error"]["offset"], batches[3].at);

    // a stream merely cut short is salvaged as before: a warning, exit 0
    std::vector<uint8_t> cut = good;
    cut.resize(batches[3].at + 30);
    const CliRun c =
        run_with_timeout("replay --salvage " + write_bytes("cut.fb89", cut) + " --png " + png);
    EXPECT_EQ(c.exit_code, 0) << c.err;
    EXPECT_TRUE(contains(c.err, "fb89: warning: ")) << c.err;
    EXPECT_TRUE(contains(c.err, "truncated batch 3")) << c.err;
}

TEST(StreamChecksumCli, InfoReportsTheChecksumsAllGoodOrTheFirstDamagedBatch) {
    const std::vector<uint8_t> good = pr::encode_stream(four_frames(), {{"scene", "built"}});
    const std::vector<BatchAt> batches = batches_of(good);
    CliRun r = run_with_timeout("info " + write_bytes("good.fb89", good));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "checksums      6 batches, all good")) << r.out;
    r = run_with_timeout("info --json " + write_bytes("good.fb89", good));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["version"], 4);
    EXPECT_EQ(j["checksums"]["batches_checked"], 6);
    EXPECT_EQ(j["checksums"]["all_good"], true);
    EXPECT_TRUE(j["checksums"]["first_bad"].is_null());

    std::vector<uint8_t> bad = good;
    bad[batches[2].at + 12] ^= 0x40;  // frame 2's first BATCH record: its batch number
    const std::string stream = write_bytes("bad.fb89", bad);
    r = run_with_timeout("info " + stream);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.out, fmt::format("checksums      batch 2 at byte {} is damaged, after 2 "
                                            "good ones (commands from 6 not read)",
                                            batches[2].at)))
        << r.out;
    EXPECT_TRUE(contains(r.err, "batch 2 fails its checksum")) << r.err;
    r = run_with_timeout("info --json " + stream);
    EXPECT_EQ(r.exit_code, 2);
    j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["checksums"]["all_good"], false);
    EXPECT_EQ(j["checksums"]["first_bad"]["batch"], 2);
    EXPECT_EQ(j["checksums"]["first_bad"]["offset"], batches[2].at);
    EXPECT_EQ(j["checksums"]["first_bad"]["after_commands"], 6);
    EXPECT_EQ(j["frames"].size(), 2u) << "frames 0 and 1, whole";

    // a stream of an older version has none
    r = run_with_timeout("info " + write_bytes("v1.fb89", pr::encode_stream(four_frames(), {}, true,
                                                                            pr::Checksums::Off)));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "checksums      none (format version 1; version 4 has them)"))
        << r.out;
}

// Bytes of a small recorded stream flipped (byte i, bit i % 8) across the whole of it -- about
// 50 bytes a stride apart, and the magic, version, header checksum, BATCH records and footer
// -- replayed by the command line: never exit 0, and each time the stream and where it is
// wrong named. (Every bit of every byte, read by the reader: stream_checksum_test.cpp in
// tests/protocol.)
TEST(StreamChecksumCli, FlippedBytesAcrossARecordedStreamAreRefusedByReplay) {
    const std::string recorded = scratch("tiny.fb89");
    CliRun r = run_with_timeout("render " + std::string(FB89_SCENES_DIR) +
                                "/A.json --size 24x18 -q --stream " + recorded);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<uint8_t> good;
    {
        std::ifstream in(recorded, std::ios::binary);
        good.assign(std::istreambuf_iterator<char>(in), {});
    }
    pr::StreamReader reader(good);
    ASSERT_TRUE(reader.checksummed());
    ASSERT_TRUE(reader.timed()) << "render records the send times";
    const uint64_t header = reader.header_size();
    std::vector<uint64_t> flips = {0, 4, 6, 9, header - 3, good.size() - 1};
    for (const BatchAt& b : batches_of(good))
        flips.insert(flips.end(), {b.at, b.at + 5, b.at + 24});  // opcode, checksum, length
    const uint64_t stride = (good.size() / 50) | 1;              // odd: every bit position in turn
    for (uint64_t i = 1; i < good.size(); i += stride)
        flips.push_back(i);
    for (const uint64_t i : flips) {
        std::vector<uint8_t> bad = good;
        bad[i] ^= static_cast<uint8_t>(1u << (i % 8));
        const std::string stream = write_bytes("flipped.fb89", bad);
        r = run_with_timeout("replay -q " + stream);
        ASSERT_EQ(r.exit_code, 2) << "byte " << i << ": " << r.err;
        EXPECT_TRUE(contains(r.err, "fb89: error: " + stream + ": ")) << r.err;
        if (i >= header) {
            EXPECT_TRUE(contains(r.err, " at byte ") && contains(r.err, "batch ")) << r.err;
        }
    }
}

TEST(StreamChecksumCli, TrimWritesChecksumsOfItsOwnWhateverTheInputsVersion) {
    for (const auto checksums : {pr::Checksums::On, pr::Checksums::Off}) {
        const std::string in = write_bytes(
            "in.fb89", pr::encode_stream(four_frames(), {{"scene", "built"}}, true, checksums));
        const std::string out = scratch("trimmed.fb89");
        CliRun r = run_with_timeout("trim " + in + " --frames 1-2 -o " + out);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        r = run_with_timeout("info --json " + out);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_EQ(j["version"], 4);
        EXPECT_EQ(j["checksums"]["all_good"], true);
        EXPECT_EQ(j["frames"].size(), 2u);
        EXPECT_EQ(j["checksums"]["batches_checked"], 4);  // frame 1, frame 2 in two, the index
    }
    // a damaged input is refused, naming the batch
    std::vector<uint8_t> bad = pr::encode_stream(four_frames(), {{"scene", "built"}});
    bad[bad.size() / 2] ^= 0x02;
    const CliRun r = run_with_timeout("trim " + write_bytes("bad.fb89", bad) + " --calls 0- -o " +
                                      scratch("t.fb89"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_TRUE(contains(r.err, "fails its checksum")) << r.err;
    EXPECT_FALSE(fs::exists(scratch("t.fb89")));
}

TEST(StreamChecksumCli, StreamsOfVersions1To3StillReplayAsBefore) {
    for (const bool depth : {false, true}) {
        std::vector<pr::Command> commands = four_frames();
        if (depth) commands.insert(commands.begin() + 1, pr::DepthClear{});
        const std::vector<uint8_t> v13 =
            pr::encode_stream(commands, {{"scene", "old"}}, true, pr::Checksums::Off);
        const std::vector<uint8_t> v4 = pr::encode_stream(commands, {{"scene", "old"}});
        ASSERT_EQ(pr::get_u16(&v13[4]), depth ? pr::kDepthVersion : pr::kUntimedVersion);
        const std::string stats13 = scratch("v13.json"), stats4 = scratch("v4.json");
        ASSERT_EQ(
            run_with_timeout("replay -q " + write_bytes("v13.fb89", v13) + " --stats " + stats13)
                .exit_code,
            0);
        ASSERT_EQ(run_with_timeout("replay -q " + write_bytes("v4.fb89", v4) + " --stats " + stats4)
                      .exit_code,
                  0);
        const auto a = nlohmann::json::parse(slurp(stats13)),
                   b = nlohmann::json::parse(slurp(stats4));
        EXPECT_EQ(a["controller"]["frames"], b["controller"]["frames"])
            << "the same frames, checksums and all";
    }
}

}  // namespace
