// Tests of the stream format's version 2 (docs/PROTOCOL.md, "Version 2: send times"): the
// SEND_TIME and HOST_END records as the writer writes them and the reader reads them back,
// beside the same commands numbered as in version 1; and every time the format refuses, by
// the writer before it writes and by the reader with the byte and the command. On version-2
// streams (a writer without checksums); version 4 carries the same records.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "sample_streams.h"
#include "tests/text_contains.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

using fb89::testing::contains;

// two_frames() timed: frame 0's fill sent at 1000 ns, its span and FRAME_END at 2500 ns,
// the host done at 3000 ns; frame 1 without a HOST_END, its span at 40 ns.
Bytes timed_two_frames() {
    const std::vector<Command> c = testing::two_frames();
    StreamWriter w(testing::sample_properties(), Timing::Timed, Commands::Tiling, Checksums::Off);
    w.submit(c[0]);  // FRAME_BEGIN: 0
    w.submit(c[1]);  // MARKER: still 0
    w.send_time(1000);
    w.submit(c[2]);
    w.send_time(2500);
    w.submit(c[3]);
    w.send_time(2500);  // unchanged: no record
    w.host_end(3000);
    w.submit(c[4]);
    w.submit(c[5]);
    w.send_time(40);  // a new frame counts from its own set-up
    w.submit(c[6]);
    w.submit(c[7]);
    w.submit(c[8]);
    w.close();
    return w.take_bytes();
}

const std::vector<int64_t> kSendNs = {0, 0, 1000, 2500, 2500, 0, 40, 40, 40};

TEST(SendTimes, ATimedStreamIsVersionTwoWithTheSameCommandsAndNumbers) {
    const Bytes v1 =
        encode_stream(testing::two_frames(), testing::sample_properties(), true, Checksums::Off);
    const Bytes v2 = timed_two_frames();
    // three SEND_TIMEs and a HOST_END, 9 bytes each; the header's version says 2
    EXPECT_EQ(v2.size(), v1.size() + 4 * kTimeRecordSize);
    EXPECT_EQ(get_u16(&v2[4]), kTimedVersion);
    EXPECT_EQ(get_u16(&v1[4]), kUntimedVersion);

    StreamReader reader(v2);
    EXPECT_TRUE(reader.timed());
    Command c;
    for (std::size_t i = 0; i < kSendNs.size(); ++i) {
        ASSERT_TRUE(reader.next(c)) << i;
        EXPECT_EQ(c, testing::two_frames()[i]);
        EXPECT_EQ(reader.command_number(), i);
        EXPECT_EQ(reader.send_time_ns(), kSendNs[i]) << i;
        if (i == 4) {
            EXPECT_EQ(reader.host_end_ns(), 3000);
        }
        if (i == 5) {
            EXPECT_FALSE(reader.host_end_ns());  // a new frame
        }
    }
    EXPECT_FALSE(reader.host_end_ns());  // frame 1 has none
    EXPECT_FALSE(reader.next(c));
    ASSERT_TRUE(reader.frame_index());  // the index points at the FRAME_BEGINs as ever
    EXPECT_EQ(reader.frame_index()->size(), 2u);

    StreamReader untimed(v1);
    EXPECT_FALSE(untimed.timed());
    while (untimed.next(c))
        EXPECT_EQ(untimed.send_time_ns(), 0);
}

TEST(SendTimes, ReadInBatchesEachCommandGetsItsTime) {
    const Bytes v2 = timed_two_frames();
    StreamReader reader(v2);
    std::vector<Command> batch(16);
    std::vector<int64_t> ns(16, -1);
    std::vector<int64_t> got;
    while (const std::size_t n = reader.read_batch(batch, ns)) {
        got.insert(got.end(), ns.begin(), ns.begin() + static_cast<std::ptrdiff_t>(n));
        if (got.size() == 5) {  // batches end at FRAME_END
            EXPECT_EQ(reader.host_end_ns(), 3000);
        }
    }
    EXPECT_EQ(got, kSendNs);
}

TEST(SendTimes, AVersionOneStreamHasNoTimeRecords) {
    // 0x06 in a version-1 stream is the unknown opcode it always was
    Bytes v1 = encode_stream({FrameBegin{0, 4, 4, Rgb{}}, FrameEnd{}}, {}, true, Checksums::Off);
    const std::size_t at = v1.size() - (kIndexPrefixSize + kIndexEntrySize + kFooterSize) - 1;
    v1[at] = kSendTimeOpcode;  // the FRAME_END
    const auto r = testing::read_all(v1);
    ASSERT_TRUE(r.error);
    EXPECT_TRUE(contains(r.error->what(), "unknown opcode 0x06")) << r.error->what();
}

// A timed one-frame stream with the record `opcode` of `ns` put after its first `after`
// commands (FRAME_BEGIN, a fill sent at 500 ns, FRAME_END).
Bytes with_time_record(std::size_t after, uint8_t opcode, int64_t ns) {
    Bytes out;
    encode_header(out, {}, kTimedVersion);
    const std::vector<Command> c = {FrameBegin{0, 4, 4, Rgb{}}, FillRect{0, 0, 1, 1, Rgb{}},
                                    FrameEnd{}};
    for (std::size_t i = 0; i <= c.size(); ++i) {
        if (i == after) encode_time(out, opcode, ns);
        if (i == 1) encode_time(out, kSendTimeOpcode, 500);
        if (i < c.size()) encode_command(out, c[i]);
    }
    return out;
}

TEST(SendTimes, TheReaderRefusesATimeThatCannotBeNamingItsByteAndCommand) {
    struct Case {
        std::size_t after;
        uint8_t opcode;
        int64_t ns;
        std::string message;
    };
    // the header is 12 bytes, FRAME_BEGIN 16; the fill's SEND_TIME at byte 28, the fill at 37
    const Case cases[] = {
        {0, kSendTimeOpcode, 10, "SEND_TIME at byte 12 (command 0): outside a frame"},
        {3, kHostEndOpcode, 900, "HOST_END at byte 58 (command 3): outside a frame"},
        {2, kSendTimeOpcode, 400,
         "SEND_TIME at byte 57 (command 2): 400 ns goes back from the frame's send time 500 ns"},
        {2, kHostEndOpcode, 499,
         "HOST_END at byte 57 (command 2): 499 ns goes back from the frame's send time 500 ns"},
        {1, kSendTimeOpcode, -1,
         "SEND_TIME at byte 28 (command 1): -1 ns is before the frame's set-up"},
    };
    for (const Case& k : cases) {
        const auto r = testing::read_all(with_time_record(k.after, k.opcode, k.ns));
        ASSERT_TRUE(r.error) << k.message;
        EXPECT_TRUE(contains(r.error->what(), k.message)) << r.error->what();
        EXPECT_EQ(r.commands.size(), k.after);  // every command before it delivered
    }
    // a send time after the frame's HOST_END
    Bytes late;
    encode_header(late, {}, kTimedVersion);
    encode_command(late, FrameBegin{0, 4, 4, Rgb{}});
    encode_time(late, kHostEndOpcode, 100);
    encode_time(late, kSendTimeOpcode, 200);
    const auto r = testing::read_all(late);
    ASSERT_TRUE(r.error);
    EXPECT_TRUE(contains(r.error->what(),
                         "SEND_TIME at byte 37 (command 1): after the frame's "
                         "HOST_END (100 ns)"))
        << r.error->what();
    // cut inside a time record
    Bytes cut = with_time_record(2, kSendTimeOpcode, 600);
    cut.resize(cut.size() - 1 - 4);  // FRAME_END and half the SEND_TIME before it go
    const auto t = testing::read_all(cut);
    ASSERT_TRUE(t.error);
    EXPECT_TRUE(contains(t.error->what(), "truncated SEND_TIME at byte 57 (command 2)"))
        << t.error->what();
}

TEST(SendTimes, TheWriterRefusesWhatTheReaderWouldBeforeWritingIt) {
    StreamWriter untimed(Properties{});
    EXPECT_THROW(untimed.send_time(0), std::logic_error);

    StreamWriter w(Properties{}, Timing::Timed);
    EXPECT_THROW(w.send_time(5), std::invalid_argument);  // outside a frame
    w.submit(FrameBegin{0, 4, 4, Rgb{}});
    EXPECT_THROW(w.send_time(-1), std::invalid_argument);
    w.send_time(700);
    EXPECT_THROW(w.send_time(699), std::invalid_argument);
    EXPECT_THROW(w.host_end(600), std::invalid_argument);
    w.host_end(800);
    EXPECT_THROW(w.send_time(900), std::invalid_argument);
    EXPECT_THROW(w.host_end(900), std::invalid_argument);
    w.submit(FrameEnd{});
    EXPECT_THROW(w.host_end(900), std::invalid_argument);  // outside a frame
    w.close();
    // what it refused left no record: the stream reads clean
    const auto r = testing::read_all(w.bytes());
    EXPECT_FALSE(r.error);
    EXPECT_EQ(r.commands.size(), 2u);
}

TEST(SendTimes, TruncationAtEveryByteOfATimedStreamDeliversTheCompleteCommands) {
    const Bytes whole = timed_two_frames();
    StreamReader full(whole);
    Command c;
    std::vector<uint64_t> starts;  // each command record's first byte
    while (full.next(c))
        starts.push_back(full.command_offset());
    for (std::size_t size = full.header_size(); size < whole.size(); ++size) {
        const auto r = testing::read_all(
            Bytes(whole.begin(), whole.begin() + static_cast<std::ptrdiff_t>(size)));
        // every command that ends before the cut, and none that does not, never a crash
        std::size_t started = 0;
        for (const uint64_t at : starts)
            started += at < size;
        EXPECT_LE(r.commands.size(), started) << size;
        EXPECT_GE(r.commands.size() + 1, started) << size;
    }
}

// docs/PROTOCOL.md, "Version 2: send times": the example's 67 bytes.
TEST(SendTimes, SpecHexExampleIsWhatTheWriterProduces) {
    StreamWriter w(Properties{}, Timing::Timed, Commands::Tiling, Checksums::Off);
    w.submit(FrameBegin{0, 4, 3, Rgb{0, 0, 0}});
    w.send_time(1500);
    w.submit(FillRect{0, 0, 2, 2, Rgb{255, 0, 0}});
    w.host_end(2000);
    w.submit(FrameEnd{});
    const Bytes expected = {0x46, 0x42, 0x38, 0x39, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                            0x01, 0x00, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x03, 0x00, 0x00,
                            0x00, 0x00, 0x00, 0x00, 0x06, 0xdc, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00,
                            0x00, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x00,
                            0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0xff, 0x00, 0x00, 0x07, 0xd0, 0x07,
                            0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x05};
    EXPECT_EQ(w.bytes(), expected);
}

}  // namespace
}  // namespace fb89::protocol
