// Stream format version 4 (docs/PROTOCOL.md, "Version 4: checksums"): the header's checksum
// and the batches the writer seals, the spec's example, and the reader's refusal of every
// damaged byte -- each bit of a stream of every kind of record flipped in turn is caught, and
// no command of a damaged batch (or after it) is ever delivered. Versions 1 to 3 read as ever.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "protocol/xxhash64.h"
#include "sample_streams.h"
#include "tests/scratch.h"
#include "tests/text_contains.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;
using fb89::testing::contains;
using testing::read_all;
using testing::ReadResult;

// A batch as the stream holds it: its BATCH record's offset, where it ends, its record.
struct Batch {
    uint64_t at = 0, end = 0;
    BatchRecord record;
};

// Walks a whole version-4 stream's batches by their lengths (nothing decoded).
std::vector<Batch> batches_of(const Bytes& bytes, uint64_t header_size) {
    std::vector<Batch> out;
    for (uint64_t at = header_size; at < bytes.size();) {
        EXPECT_EQ(bytes[at], kBatchOpcode) << "at byte " << at;
        Batch b{at, 0, decode_batch(&bytes[at])};
        b.end = at + kBatchRecordSize + b.record.length;
        out.push_back(b);
        at = b.end;
    }
    return out;
}

// Reads with read_batch(), as replay does: the commands delivered, and the error.
ReadResult read_in_batches(Bytes bytes) {
    ReadResult result;
    try {
        StreamReader reader(std::move(bytes), "stream.fb89");
        std::vector<Command> batch(4096);
        std::vector<int64_t> send_ns(4096);
        while (const std::size_t n = reader.read_batch(batch, send_ns))
            result.commands.insert(result.commands.end(), batch.begin(),
                                   batch.begin() + static_cast<std::ptrdiff_t>(n));
        result.index = reader.frame_index();
    } catch (const StreamError& e) {
        result.error = e;
    }
    return result;
}

TEST(StreamChecksums, TheWriterWritesVersion4WithChecksumsByDefault) {
    EXPECT_EQ(kFormatVersion, kChecksumVersion);
    EXPECT_EQ(StreamWriter(Properties{}).version(), kChecksumVersion);
    EXPECT_EQ(StreamWriter(Properties{}, Timing::Timed, Commands::Depth).version(),
              kChecksumVersion);
    // without checksums, the oldest version that carries the stream, as before
    EXPECT_EQ(
        StreamWriter(Properties{}, Timing::Untimed, Commands::Tiling, Checksums::Off).version(),
        kUntimedVersion);
    EXPECT_EQ(StreamWriter(Properties{}, Timing::Timed, Commands::Tiling, Checksums::Off).version(),
              kTimedVersion);
    EXPECT_EQ(StreamWriter(Properties{}, Timing::Timed, Commands::Depth, Checksums::Off).version(),
              kDepthVersion);
    const Bytes bytes = encode_stream(testing::two_frames(), testing::sample_properties());
    EXPECT_EQ(get_u16(&bytes[4]), kChecksumVersion);
    StreamReader reader(bytes);
    EXPECT_TRUE(reader.checksummed());
    EXPECT_FALSE(reader.timed());
    MemoryBuffer buffer;
    EXPECT_EQ(reader.replay_into(buffer), testing::two_frames().size());
    EXPECT_EQ(buffer.commands(), testing::two_frames());
    EXPECT_EQ(reader.batches_checked(), 3u);  // a batch a frame, and the index's
}

// The version-4 example of docs/PROTOCOL.md, byte for byte: the version-1 example's stream
// with the header's checksum and its two batches.
TEST(StreamChecksums, Version4ExampleIsWhatTheWriterProduces) {
    const Bytes expected = {
        0x46, 0x42, 0x38, 0x39, 0x04, 0x00, 0x00, 0x00,        // 0: "FB89", version 4, flags 0
        0x01, 0x00, 0x00, 0x00,                                // 8: 1 property
        0x05, 0x00, 0x73, 0x63, 0x65, 0x6e, 0x65,              // 12: key "scene"
        0x05, 0x00, 0x00, 0x00, 0x69, 0x64, 0x65, 0x61, 0x6c,  // 19: value "ideal"
        0xbf, 0xef, 0xf6, 0x33, 0x1d, 0x51, 0x02, 0x53,        // 28: header checksum
        0x0b,                                                  // 36: BATCH
        0xe2, 0xc4, 0x68, 0xfd, 0x70, 0xe0, 0xf7, 0x96,        //     checksum
        0x00, 0x00, 0x00, 0x00,                                //     batch 0
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //     first command 0
        0x05, 0x00,                                            //     5 commands
        0x3a, 0x00, 0x00, 0x00,                                //     58 bytes
        0x01,                                                  // 63: FRAME_BEGIN
        0x00, 0x00, 0x00, 0x00,                                //     frame 0
        0x04, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00,        //     4 x 3
        0x00, 0x00, 0x00,                                      //     background #000000
        0x02,                                                  // 79: FILL_RECT
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //     x 0, y 0
        0x02, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,        //     w 2, h 2
        0xff, 0x00, 0x00,                                      //     #ff0000
        0x03,                                                  // 99: DRAW_SPAN
        0x02, 0x00, 0x00, 0x00, 0xff, 0xff, 0xff, 0xff,        //     y 2, x0 -1
        0x03, 0x00, 0x00, 0x00, 0x00, 0xff, 0x00,              //     x1 3, #00ff00
        0x04, 0x02, 0x00, 0x68, 0x69,                          // 115: MARKER "hi"
        0x05,                                                  // 120: FRAME_END
        0x0b,                                                  // 121: BATCH
        0x1c, 0x08, 0xfb, 0xb9, 0x1a, 0x59, 0x72, 0x45,        //      checksum
        0x01, 0x00, 0x00, 0x00,                                //      batch 1
        0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //      first command 5
        0x00, 0x00,                                            //      no commands
        0x2d, 0x00, 0x00, 0x00,                                //      45 bytes
        0xfe, 0x01, 0x00, 0x00, 0x00,                          // 148: frame index, 1 entry:
        0x00, 0x00, 0x00, 0x00,                                //      frame 0
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //      command 0
        0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //      byte 63
        0x94, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        // 173: footer: index at 148
        0x05, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,        //      5 commands
        0x46, 0x42, 0x49, 0x58};                               //      "FBIX"
    const std::vector<Command> commands = {
        FrameBegin{0, 4, 3, Rgb{}}, FillRect{0, 0, 2, 2, Rgb{0xff, 0, 0}},
        DrawSpan{2, -1, 3, Rgb{0, 0xff, 0}}, Marker{"hi"}, FrameEnd{}};
    const Bytes written = encode_stream(commands, {{"scene", "ideal"}});
    EXPECT_EQ(written, expected);
    ASSERT_EQ(written.size(), 193u);
    // the checksums are what XXH64 makes of the bytes they cover
    EXPECT_EQ(get_u64(&written[28]), xxh64(written.data(), 28));
    EXPECT_EQ(get_u64(&written[37]), xxh64(&written[45], 18 + 58));
    EXPECT_EQ(get_u64(&written[122]), xxh64(&written[130], 18 + 45));
    const ReadResult r = read_all(written);
    EXPECT_FALSE(r.error);
    EXPECT_EQ(r.commands, commands);
    // cut after the first batch, it is a cut stream of the same commands; inside it, nothing
    const ReadResult cut = read_all(Bytes(written.begin(), written.begin() + 121));
    EXPECT_FALSE(cut.error);
    EXPECT_EQ(cut.commands, commands);
    const ReadResult inside = read_all(Bytes(written.begin(), written.begin() + 105));
    ASSERT_TRUE(inside.error);
    EXPECT_STREQ(inside.error->what(),
                 "stream.fb89: truncated batch 0 at byte 36 (commands 0-4): the stream ends at "
                 "byte 105");
    EXPECT_TRUE(inside.commands.empty());
}

TEST(StreamChecksums, BatchesStartAtEachFrameAndEndAfterItsEndOrTheir256thRecord) {
    const testing::WrittenStream s = testing::mixed_stream();
    StreamReader reader(s.bytes);
    const std::vector<Batch> batches = batches_of(s.bytes, reader.header_size());
    // frame 0 (9 commands, 3 time records); frame 1: 302 commands and 5 SEND_TIMEs, its
    // first batch ending at its 256th record (FRAME_BEGIN, 4 SEND_TIMEs and 251 spans), its
    // second at its FRAME_END; frame 2; the frame index
    ASSERT_EQ(batches.size(), 5u);
    const std::vector<uint16_t> commands = {9, 252, 50, 3, 0};
    const std::vector<uint64_t> first = {0, 9, 261, 311, 314};
    for (std::size_t i = 0; i < batches.size(); ++i) {
        SCOPED_TRACE(fmt::format("batch {}", i));
        const BatchRecord& b = batches[i].record;
        EXPECT_EQ(b.batch, i);
        EXPECT_EQ(b.first_command, first[i]);
        EXPECT_EQ(b.commands, commands[i]);
        EXPECT_LE(b.length, kMaxBatchBytes);
        EXPECT_EQ(b.checksum, batch_checksum(&s.bytes[batches[i].at], b.length));
    }
    ASSERT_EQ(s.bytes[batches.back().at + kBatchRecordSize], kIndexOpcode);
    MemoryBuffer buffer;
    EXPECT_EQ(reader.replay_into(buffer), s.commands.size());
    EXPECT_EQ(buffer.commands(), s.commands);
    EXPECT_EQ(reader.batches_checked(), batches.size());
    // each frame's FRAME_BEGIN is its batch's first record
    ASSERT_TRUE(reader.frame_index());
    for (const FrameIndexEntry& e : *reader.frame_index())
        EXPECT_TRUE(
            std::any_of(batches.begin(), batches.end(),
                        [&](const Batch& b) { return b.at + kBatchRecordSize == e.offset; }))
            << "frame " << e.frame;
}

// The heart of version 4: a flipped bit anywhere -- header, properties, its checksum, a BATCH
// record, a command, a time record, the frame index, the footer -- is an error, and no command
// from the damaged batch on is delivered (so no frame drawn from it is complete). Byte i gets
// bit i % 8 flipped, through next() and through read_batch(); a smaller stream gets every bit
// of every byte.
void expect_every_flip_caught(const Bytes& good, const std::vector<Command>& commands,
                              bool every_bit) {
    const uint64_t header_size = StreamReader(good).header_size();
    const std::vector<Batch> batches = batches_of(good, header_size);
    for (uint64_t i = 0; i < good.size(); ++i) {
        // commands before the batch holding byte i: all a reader may deliver
        uint64_t before = 0;
        for (const Batch& b : batches)
            if (b.end <= i) before = b.record.first_command + b.record.commands;
        for (int bit = every_bit ? 0 : static_cast<int>(i % 8); bit < 8; bit += every_bit ? 1 : 8) {
            SCOPED_TRACE(fmt::format("byte {} of {}, bit {}", i, good.size(), bit));
            Bytes bad = good;
            bad[i] ^= static_cast<uint8_t>(1u << bit);
            for (const ReadResult& r : {read_all(bad), read_in_batches(bad)}) {
                ASSERT_TRUE(r.error) << "a flipped bit read as a good stream";
                const std::string said = r.error->what();
                EXPECT_LE(r.commands.size(), before) << said;
                EXPECT_TRUE(std::equal(r.commands.begin(), r.commands.end(), commands.begin()))
                    << "a delivered command differs: " << said;
                EXPECT_TRUE(contains(said, "stream.fb89: ")) << said;
                if (i < header_size) continue;  // the header's own errors, or its checksum's
                // in a batch: named with its byte, and damaged -- or, a length grown past the
                // end of the stream, a batch cut short
                EXPECT_TRUE(r.error->batch().has_value()) << said;
                EXPECT_TRUE(contains(said, " at byte ")) << said;
                EXPECT_TRUE(r.error->damaged() ? contains(said, ": the stream is damaged")
                                               : contains(said, "truncated batch"))
                    << said;
            }
        }
    }
}

TEST(StreamChecksums, EveryFlippedBitOfAStreamOfEveryRecordIsCaught) {
    const testing::WrittenStream s = testing::mixed_stream();
    ASSERT_GT(s.bytes.size(), 5000u);
    expect_every_flip_caught(s.bytes, s.commands, false);
}

TEST(StreamChecksums, EveryBitOfEveryByteOfASmallStreamIsCaught) {
    const testing::WrittenStream s = testing::mixed_stream(Checksums::On, 20);
    expect_every_flip_caught(s.bytes, s.commands, true);
}

TEST(StreamChecksums, ADamagedBatchIsNamedWithItsOffsetAndCommandsAndDeliversNothing) {
    const testing::WrittenStream s = testing::mixed_stream();
    const std::vector<Batch> batches = batches_of(s.bytes, StreamReader(s.bytes).header_size());
    const Batch& third = batches[2];  // frame 1's second batch: commands 261-310
    Bytes bad = s.bytes;
    bad[third.at + kBatchRecordSize + 100] ^= 0x10;  // inside a DRAW_SPAN
    const uint64_t computed = batch_checksum(&bad[third.at], third.record.length);
    const ReadResult r = read_all(bad);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->what(),
              fmt::format("stream.fb89: batch 2 fails its checksum at byte {} (commands 261-310): "
                          "stored {:#018x}, computed {:#018x}: the stream is damaged",
                          third.at, third.record.checksum, computed));
    EXPECT_EQ(r.error->offset(), third.at);
    EXPECT_EQ(r.error->command(), 261u);
    EXPECT_EQ(r.error->batch(), 2u);
    EXPECT_TRUE(r.error->damaged());
    EXPECT_EQ(r.commands, std::vector<Command>(s.commands.begin(), s.commands.begin() + 261));

    // the header's own checksum
    Bytes header = s.bytes;
    header[16] ^= 0x01;  // inside the first property's key, "method"
    const ReadResult h = read_all(header);
    ASSERT_TRUE(h.error);
    EXPECT_TRUE(contains(h.error->what(), "header fails its checksum at byte"));
    EXPECT_TRUE(contains(h.error->what(), "(header, before command 0): stored 0x"));
    EXPECT_TRUE(h.error->damaged());

    // a BATCH record's opcode: no batch where one must start
    Bytes opcode = s.bytes;
    opcode[third.at] = 0x0a;
    const ReadResult o = read_all(opcode);
    ASSERT_TRUE(o.error);
    EXPECT_EQ(o.error->what(),
              fmt::format("stream.fb89: no BATCH record for batch 2 at byte {} (after 261 "
                          "commands): found 0x0a where a batch must start: the stream is damaged",
                          third.at));

    // the frame index's batch
    Bytes index = s.bytes;
    index[index.size() - 30] ^= 0x80;
    const ReadResult x = read_all(index);
    ASSERT_TRUE(x.error);
    EXPECT_TRUE(contains(x.error->what(), fmt::format("stream.fb89: batch 4 fails its checksum at "
                                                      "byte {} (the frame index, after 314 "
                                                      "commands)",
                                                      batches[4].at)))
        << x.error->what();
    EXPECT_EQ(x.commands, s.commands) << "every command before the index is whole";
    EXPECT_FALSE(x.index);
}

TEST(StreamChecksums, AStreamCutBetweenBatchesReadsAndOneCutInsideABatchDeliversNoneOfIt) {
    const testing::WrittenStream s = testing::mixed_stream(Checksums::On, 20);
    const uint64_t header_size = StreamReader(s.bytes).header_size();
    const std::vector<Batch> batches = batches_of(s.bytes, header_size);
    for (uint64_t cut = header_size; cut <= s.bytes.size(); ++cut) {
        SCOPED_TRACE(fmt::format("cut at {} of {}", cut, s.bytes.size()));
        uint64_t whole = 0;  // commands of the batches wholly before the cut
        bool boundary = cut == header_size;
        for (const Batch& b : batches) {
            if (b.end <= cut) whole = b.record.first_command + b.record.commands;
            boundary = boundary || b.end == cut;
        }
        const ReadResult r = read_all(Bytes(s.bytes.begin(), s.bytes.begin() + cut));
        EXPECT_EQ(r.commands, std::vector<Command>(s.commands.begin(), s.commands.begin() + whole));
        EXPECT_EQ(r.error.has_value(), !boundary);
        if (r.error) {
            EXPECT_TRUE(contains(r.error->what(), "truncated")) << r.error->what();
            EXPECT_FALSE(r.error->damaged()) << "cut short, not damaged";
        }
    }
}

TEST(StreamChecksums, SeekingToAFrameChecksItsBatchAndADamagedIndexIsAnError) {
    const testing::WrittenStream s = testing::mixed_stream();
    {
        StreamReader reader(s.bytes);
        const std::optional<FrameIndex> index = reader.read_trailing_index();
        ASSERT_TRUE(index);
        ASSERT_EQ(index->size(), 3u);
        reader.seek((*index)[2]);
        Command c;
        ASSERT_TRUE(reader.next(c));
        EXPECT_EQ(c, s.commands[311]);
        EXPECT_EQ(reader.command_number(), 311u);
    }
    // frame 2's batch damaged: seeking to it is an error naming it
    StreamReader good(s.bytes);
    const FrameIndexEntry frame2 = good.read_trailing_index()->at(2);
    Bytes bad = s.bytes;
    bad[frame2.offset + 20] ^= 0x04;
    StreamReader reader(bad);
    const std::optional<FrameIndex> index = reader.read_trailing_index();
    ASSERT_TRUE(index) << "the index itself is whole";
    try {
        reader.seek((*index)[2]);
        FAIL() << "seek() into a damaged batch";
    } catch (const StreamError& e) {
        EXPECT_TRUE(contains(e.what(), "batch 3 fails its checksum")) << e.what();
        EXPECT_TRUE(e.damaged());
    }
    // a damaged index found through the footer is an error, not an absent index
    Bytes index_bad = s.bytes;
    index_bad[index_bad.size() - 25] ^= 0x01;
    StreamReader through_footer(index_bad);
    EXPECT_THROW(through_footer.read_trailing_index(), StreamError);
}

TEST(StreamChecksums, AFileAndAPipeReadAsMemoryDoes) {
    const testing::WrittenStream s = testing::mixed_stream();
    const auto path = fb89::testing::scratch_path("checksum_test.fb89");
    {
        StreamWriter w(path.string(), testing::sample_properties(), Timing::Timed,
                       Commands::Tiling);
        EXPECT_EQ(w.version(), kChecksumVersion);
        StreamReader r(s.bytes);
        Command c;
        while (r.next(c)) {
            if (!std::holds_alternative<FrameBegin>(c) && w.timed() && r.send_time_ns() > 0)
                w.send_time(r.send_time_ns());
            if (std::holds_alternative<FrameEnd>(c) && r.host_end_ns())
                w.host_end(*r.host_end_ns());
            w.submit(c);
        }
        w.close();
    }
    Bytes from_file;
    {
        std::ifstream in(path, std::ios::binary);
        from_file.assign(std::istreambuf_iterator<char>(in), {});
    }
    EXPECT_EQ(from_file, s.bytes) << "the same records make the same bytes, in a file too";
    from_file[from_file.size() / 2] ^= 0x20;
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(from_file.data()),
                  static_cast<std::streamsize>(from_file.size()));
    }
    StreamReader reader(path.string());
    MemoryBuffer buffer;
    std::string said;
    try {
        reader.replay_into(buffer);
    } catch (const StreamError& e) {
        said = e.what();
    }
    const ReadResult from_memory = read_all(from_file, path.string());
    ASSERT_TRUE(from_memory.error);
    EXPECT_EQ(said, from_memory.error->what());
    EXPECT_EQ(buffer.commands(), from_memory.commands);
    std::filesystem::remove(path);
}

// Versions 1, 2 and 3 are read as ever: written without checksums, they read back the same
// commands, with no checksums to check.
TEST(StreamChecksums, StreamsOfEarlierVersionsStillRead) {
    const testing::WrittenStream v3 = testing::mixed_stream(Checksums::Off);
    const testing::WrittenStream v4 = testing::mixed_stream(Checksums::On);
    EXPECT_EQ(get_u16(&v3.bytes[4]), kDepthVersion);
    EXPECT_EQ(v3.commands, v4.commands);
    for (const Bytes& bytes :
         {v3.bytes, encode_stream(testing::two_frames(), {}, true, Checksums::Off),
          encode_stream(testing::every_opcode(), testing::sample_properties(), false,
                        Checksums::Off)}) {
        StreamReader reader(bytes);
        EXPECT_FALSE(reader.checksummed());
        MemoryBuffer buffer;
        reader.replay_into(buffer);
        EXPECT_EQ(reader.batches_checked(), 0u);
    }
    const ReadResult r3 = read_all(v3.bytes);
    EXPECT_FALSE(r3.error);
    EXPECT_EQ(r3.commands, v3.commands);
    // version 2: the timed two frames of the send-time tests, without depth commands
    StreamWriter w2(Properties{}, Timing::Timed, Commands::Tiling, Checksums::Off);
    for (const Command& c : testing::two_frames())
        w2.submit(c);
    w2.close();
    const Bytes v2 = w2.take_bytes();
    EXPECT_EQ(get_u16(&v2[4]), kTimedVersion);
    const ReadResult r2 = read_all(v2);
    EXPECT_FALSE(r2.error);
    EXPECT_EQ(r2.commands, testing::two_frames());
    // and a version-1 stream's flipped bit is what it always was: read, or refused by its
    // record's rules (version 1 has no checksum)
    Bytes v1 = encode_stream(testing::two_frames(), {}, true, Checksums::Off);
    EXPECT_EQ(get_u16(&v1[4]), kUntimedVersion);
    v1[12 + 16 + 7 + 17] ^= 0x01;  // the FILL_RECT's colour
    const ReadResult r1 = read_all(v1);
    EXPECT_FALSE(r1.error);
    EXPECT_NE(r1.commands, testing::two_frames());
}

}  // namespace
}  // namespace fb89::protocol
