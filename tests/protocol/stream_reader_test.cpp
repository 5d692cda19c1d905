// Tests of protocol/stream_reader.h on commands and the header: numbers and offsets,
// truncation at every byte, versions, bad magic, unknown opcodes, fields out of range,
// bounded lengths, random corruption, files and pipes. The rules every version keeps, on
// version-1 streams (what version 4's checksums add: stream_checksum_test.cpp).
#include "protocol/stream_reader.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <random>
#include <thread>

#include "protocol/stream_writer.h"
#include "sample_streams.h"
#include "tests/scratch.h"
#include "tests/text_contains.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;
using fb89::testing::contains;
using testing::read_all;
using testing::ReadResult;

// A version-1 stream: the records back to back, as this file's offsets count them.
Bytes encode_v1(const std::vector<Command>& commands, const Properties& properties = {},
                bool with_index = true) {
    return encode_stream(commands, properties, with_index, Checksums::Off);
}

// Byte offsets of every command record of a stream, then of its index (or its end).
std::vector<uint64_t> record_offsets(const Bytes& bytes) {
    StreamReader reader(bytes);
    std::vector<uint64_t> offsets;
    Command c;
    while (reader.next(c))
        offsets.push_back(reader.command_offset());
    const uint64_t tail = reader.frame_index() ? kIndexPrefixSize + kFooterSize +
                                                     reader.frame_index()->size() * kIndexEntrySize
                                               : 0;
    offsets.push_back(bytes.size() - tail);
    return offsets;
}

TEST(StreamReader, NumbersCommandsFromZeroWithTheirByteOffsets) {
    const Bytes bytes = encode_v1(testing::two_frames(), testing::sample_properties());
    StreamReader reader(bytes);
    const std::vector<std::size_t> sizes = {16, 1 + 2 + 7, 20, 16, 1, 16, 16, 1 + 2 + 4, 1};
    uint64_t offset = reader.header_size();
    Command c;
    for (std::size_t i = 0; i < sizes.size(); ++i) {
        ASSERT_TRUE(reader.next(c));
        EXPECT_EQ(c, testing::two_frames()[i]);
        EXPECT_EQ(reader.command_number(), i);
        EXPECT_EQ(reader.command_offset(), offset);
        offset += sizes[i];
    }
    EXPECT_FALSE(reader.next(c));
    EXPECT_FALSE(reader.next(c));  // the end stays the end
    EXPECT_EQ(reader.next_command_number(), 9u);
}

TEST(StreamReader, TruncationAtEveryByteDeliversExactlyTheCompleteCommands) {
    const Bytes full = encode_v1(testing::two_frames(), testing::sample_properties());
    const std::vector<Command> all = testing::two_frames();
    const std::vector<uint64_t> starts = record_offsets(full);  // records, then the index
    const uint64_t index_at = starts.back();
    for (uint64_t cut = 0; cut <= full.size(); ++cut) {
        SCOPED_TRACE(fmt::format("cut at {} of {} bytes", cut, full.size()));
        const ReadResult r = read_all(Bytes(full.begin(), full.begin() + cut));
        if (cut < starts.front()) {  // inside the header
            ASSERT_TRUE(r.error);
            EXPECT_EQ(r.error->command(), 0u);
            EXPECT_TRUE(contains(r.error->what(), "truncated")) << r.error->what();
            EXPECT_TRUE(contains(r.error->what(), "(header, before command 0)"));
            continue;
        }
        std::size_t complete = 0;
        while (complete < all.size() && starts[complete + 1] <= cut)
            ++complete;
        EXPECT_EQ(r.commands, std::vector<Command>(all.begin(), all.begin() + complete));
        const bool boundary = std::find(starts.begin(), starts.end(), cut) != starts.end();
        if (boundary || cut == full.size()) {
            EXPECT_FALSE(r.error) << r.error->what();
            EXPECT_EQ(r.index.has_value(), cut == full.size());
        } else if (cut < index_at) {
            ASSERT_TRUE(r.error);
            const std::string expected = fmt::format(
                "stream.fb89: truncated {} at byte {} (command {}): the stream ends "
                "at byte {}",
                to_string(opcode_of(all[complete])), starts[complete], complete, cut);
            EXPECT_EQ(r.error->what(), expected);
            EXPECT_EQ(r.error->offset(), starts[complete]);
            EXPECT_EQ(r.error->command(), complete);
        } else {
            ASSERT_TRUE(r.error);
            EXPECT_EQ(r.error->what(),
                      fmt::format("stream.fb89: truncated frame index at byte {} (frame index, "
                                  "after 9 commands): the stream ends at byte {}",
                                  index_at, cut));
            EXPECT_EQ(r.error->command(), all.size());
        }
    }
}

TEST(StreamReader, RefusesANewerVersionNamingBothVersions) {
    Bytes bytes = encode_v1(testing::two_frames());
    bytes[4] = 5;
    const ReadResult r = read_all(bytes);
    ASSERT_TRUE(r.error);
    EXPECT_STREQ(r.error->what(),
                 "stream.fb89: stream is format version 5; this fb89 reads versions up to 4");
    // a newer version may lay out everything after the version differently
    const ReadResult short_header = read_all(Bytes{'F', 'B', '8', '9', 0x00, 0x01});
    ASSERT_TRUE(short_header.error);
    EXPECT_STREQ(short_header.error->what(),
                 "stream.fb89: stream is format version 256; this fb89 reads versions up to 4");
}

TEST(StreamReader, RefusesVersionZeroAndNonZeroFlags) {
    Bytes bytes = encode_v1(testing::two_frames());
    bytes[4] = 0;
    EXPECT_TRUE(contains(read_all(bytes).error->what(), "format version 0 at byte 4"));
    bytes[4] = 1;
    bytes[6] = 1;
    EXPECT_EQ(std::string(read_all(bytes).error->what()),
              "stream.fb89: header flags at byte 6 (header, before command 0): 0x0001 is not 0");
}

TEST(StreamReader, RejectsBadMagic) {
    const ReadResult r = read_all(Bytes{'M', 'Z', 0x90, 0x00, 0x03, 0x00, 0x00, 0x00});
    ASSERT_TRUE(r.error);
    EXPECT_STREQ(r.error->what(),
                 "stream.fb89: bad magic at byte 0 (header, before command 0): expected "
                 "\"FB89\", found 4d 5a 90 00; not an fb89 stream");
    EXPECT_TRUE(contains(read_all(Bytes{'F', 'X'}).error->what(), "bad magic"));
    EXPECT_TRUE(contains(read_all(Bytes{'F', 'B'}).error->what(), "truncated header"));
}

TEST(StreamReader, RejectsUnknownOpcodesWithOffsetAndCommandNumber) {
    const Bytes good = encode_v1(testing::two_frames());
    const std::vector<uint64_t> starts = record_offsets(good);
    for (const uint8_t opcode : {uint8_t{0x00}, uint8_t{0x06}, uint8_t{0x7f}, uint8_t{0xff}}) {
        Bytes bytes = good;
        bytes[starts[3]] = opcode;
        const ReadResult r = read_all(bytes);
        ASSERT_TRUE(r.error);
        EXPECT_EQ(r.error->what(), fmt::format("stream.fb89: unknown opcode {:#04x} at byte {} "
                                               "(command 3)",
                                               opcode, starts[3]));
        EXPECT_EQ(r.commands.size(), 3u);
    }
}

TEST(StreamReader, RejectsFrameSizesOutsideOneTo16384) {
    const Bytes good = encode_v1(testing::two_frames());
    const uint64_t at = record_offsets(good)[5];  // second FRAME_BEGIN
    Bytes bytes = good;
    bytes[at + 5] = 0;  // width 8 -> 0
    ReadResult r = read_all(bytes);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->what(), fmt::format("stream.fb89: FRAME_BEGIN at byte {} (command 5): "
                                           "width 0 is outside 1..16384",
                                           at));
    EXPECT_EQ(r.commands.size(), 5u);  // the whole first frame
    bytes = good;
    bytes[at + 9] = 0x01;  // height 6 -> 16385 (0x4001)
    bytes[at + 10] = 0x40;
    r = read_all(bytes);
    EXPECT_TRUE(contains(r.error->what(), "height 16385 is outside 1..16384"));
}

TEST(StreamReader, RejectsASpanWhoseX1IsBeforeX0) {
    const Bytes good = encode_v1(testing::two_frames());
    const uint64_t at = record_offsets(good)[3];  // DRAW_SPAN y=5 x0=1 x1=6
    Bytes bytes = good;
    bytes[at + 9] = 0;
    const ReadResult r = read_all(bytes);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->what(),
              fmt::format("stream.fb89: DRAW_SPAN at byte {} (command 3): x1 0 < x0 1", at));
}

TEST(StreamReader, RejectsAMarkerLongerThanTheLimit) {
    Bytes bytes = encode_v1({FrameBegin{0, 1, 1, Rgb{}}, Marker{"abc"}}, {}, false);
    const uint64_t at = record_offsets(bytes)[1];
    for (const uint16_t length : {uint16_t{kMaxMarkerLength + 1}, uint16_t{0xffff}}) {
        bytes[at + 1] = static_cast<uint8_t>(length);
        bytes[at + 2] = static_cast<uint8_t>(length >> 8);
        const ReadResult r = read_all(bytes);
        ASSERT_TRUE(r.error);
        EXPECT_EQ(r.error->what(),
                  fmt::format("stream.fb89: MARKER at byte {} (command 1): length {} is longer "
                              "than 1024",
                              at, length));
    }
}

TEST(StreamReader, BoundsHeaderLengthsBeforeAllocating) {
    const Bytes fixed = {'F', 'B', '8', '9', 1, 0, 0, 0};
    auto with = [&](Bytes tail) {
        Bytes b = fixed;
        b.insert(b.end(), tail.begin(), tail.end());
        return std::string(read_all(b).error.value().what());
    };
    EXPECT_TRUE(contains(with({0xff, 0xff, 0xff, 0xff}), "property count at byte 8"));
    EXPECT_TRUE(contains(with({1, 0, 0, 0, 0xff, 0xff}), "key length 65535 is outside 1..256"));
    EXPECT_TRUE(contains(with({1, 0, 0, 0, 0, 0}), "key length 0 is outside 1..256"));
    EXPECT_TRUE(contains(with({1, 0, 0, 0, 1, 0, 'k', 0xff, 0xff, 0xff, 0xff}),
                         "value length 4294967295 is more than 65536"));
    EXPECT_TRUE(contains(with({2, 0, 0, 0, 1, 0, 'k', 0, 0, 0, 0, 1, 0, 'k', 0, 0, 0, 0}),
                         "property 1 at byte 19 (header, before command 0): key \"k\" appears "
                         "twice"));
}

TEST(StreamReader, KeepsThrowingAfterAnError) {
    Bytes bytes = encode_v1(testing::two_frames());
    bytes[record_offsets(bytes)[2]] = 0x42;
    StreamReader reader(bytes);
    Command c;
    ASSERT_TRUE(reader.next(c));
    ASSERT_TRUE(reader.next(c));
    EXPECT_THROW(reader.next(c), StreamError);
    EXPECT_THROW(reader.next(c), StreamError);
}

TEST(StreamReader, RandomCorruptionGivesCommandsOrStreamErrorsOnly) {
    for (const Checksums checksums : {Checksums::Off, Checksums::On}) {
        const Bytes good =
            encode_stream(testing::every_opcode(), testing::sample_properties(), true, checksums);
        std::mt19937 random(89);
        for (int trial = 0; trial < 4000; ++trial) {
            Bytes bytes = good;
            const int flips = 1 + trial % 4;
            for (int i = 0; i < flips; ++i) {
                bytes[random() % bytes.size()] = static_cast<uint8_t>(random());
            }
            if (trial % 3 == 0) bytes.resize(random() % bytes.size());
            const ReadResult r = read_all(bytes);  // anything but a StreamError escapes and fails
            if (r.error) {
                EXPECT_LE(r.error->offset(), bytes.size());
            }
            EXPECT_LE(r.commands.size(), bytes.size());  // every record is at least a byte
        }
    }
}

std::filesystem::path reader_temp_path(const std::string& name) {
    return fb89::testing::scratch_path("reader_test_" + name);
}

// Many frames with markers of varying lengths, so records straddle the read buffer's ends.
std::vector<Command> long_stream() {
    std::vector<Command> commands;
    for (uint32_t frame = 0; frame < 40; ++frame) {
        commands.push_back(FrameBegin{frame, 640, 480, Rgb{}});
        for (int32_t y = 0; y < 400; ++y) {
            commands.push_back(DrawSpan{y, 0, y, Rgb{1, 2, 3}});
            if (y % 37 == 0) commands.push_back(Marker{std::string((y * 7) % 1000, 'a')});
        }
        commands.push_back(FrameEnd{});
    }
    return commands;
}

TEST(StreamReader, ReadsAFileIncrementallyLikeABuffer) {
    for (const Checksums checksums : {Checksums::Off, Checksums::On}) {
        SCOPED_TRACE(checksums == Checksums::On ? "version 4" : "version 1");
        const auto path = reader_temp_path("long.fb89");
        const std::vector<Command> commands = long_stream();
        const Bytes bytes = encode_stream(commands, testing::sample_properties(), true, checksums);
        {
            StreamWriter writer(path.string(), testing::sample_properties(), Timing::Untimed,
                                Commands::Tiling, checksums);
            for (const Command& c : commands)
                writer.submit(c);
            writer.close();
        }
        StreamReader reader(path.string());
        EXPECT_EQ(reader.properties(), testing::sample_properties());
        MemoryBuffer buffer;
        EXPECT_EQ(reader.replay_into(buffer), commands.size());
        EXPECT_EQ(buffer.commands(), commands);
        ASSERT_TRUE(reader.frame_index());
        EXPECT_EQ(reader.frame_index()->size(), 40u);

        // the same file cut inside a record: the same error as from memory
        std::size_t victim = commands.size() * 2 / 3;
        while (!std::holds_alternative<DrawSpan>(commands[victim]))
            ++victim;
        const uint64_t cut = record_offsets(bytes)[victim] + 7;
        std::filesystem::resize_file(path, cut);
        const ReadResult from_memory =
            read_all(Bytes(bytes.begin(), bytes.begin() + cut), path.string());
        ASSERT_TRUE(from_memory.error);
        StreamReader cut_reader(path.string());
        MemoryBuffer partial;
        try {
            cut_reader.replay_into(partial);
            FAIL() << "no error reading a file cut at byte " << cut;
        } catch (const StreamError& e) {
            EXPECT_STREQ(e.what(), from_memory.error->what());
        }
        EXPECT_EQ(partial.commands(), from_memory.commands);
        std::filesystem::remove(path);
    }
}

TEST(StreamReader, MissingFileThrowsNamingThePath) {
    try {
        StreamReader reader("/nonexistent-fb89-dir/in.fb89");
        FAIL() << "opened a missing file";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(),
                     "cannot open stream /nonexistent-fb89-dir/in.fb89: No such file or directory");
    }
}

TEST(StreamReader, DeliversEachFrameFromAPipeBeforeTheNextIsWritten) {
    const auto path = reader_temp_path("pipe");
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    std::promise<void> first_frame_read;
    std::future<void> go = first_frame_read.get_future();
    bool writer_waited_in_vain = false;
    std::thread writer_thread([&] {
        StreamWriter writer(path.string(), {});  // opens when the reader does
        const std::vector<Command> commands = testing::two_frames();
        for (std::size_t i = 0; i < 5; ++i)
            writer.submit(commands[i]);
        // generous time-out: this only guards against a hang if the reader waits for more
        writer_waited_in_vain = go.wait_for(std::chrono::seconds(30)) != std::future_status::ready;
        for (std::size_t i = 5; i < commands.size(); ++i)
            writer.submit(commands[i]);
        writer.close();
    });
    {
        StreamReader reader(path.string());
        Command c;
        std::vector<Command> got;
        while (reader.next(c)) {
            got.push_back(c);
            if (std::holds_alternative<FrameEnd>(c) && got.size() == 5)
                first_frame_read.set_value();
        }
        EXPECT_EQ(got, testing::two_frames());
        EXPECT_TRUE(reader.frame_index());
        EXPECT_EQ(reader.read_trailing_index(), reader.frame_index());   // already read
        EXPECT_THROW(reader.seek(FrameIndexEntry{}), std::logic_error);  // a pipe cannot seek
    }
    writer_thread.join();
    EXPECT_FALSE(writer_waited_in_vain);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace fb89::protocol
