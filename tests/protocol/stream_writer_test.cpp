// Tests of protocol/stream_writer.h: encode -> decode -> encode is byte for byte, header
// properties survive, the frame index is written on close, files equal memory encodings,
// and write errors name the path.
#include "protocol/stream_writer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "protocol/memory_buffer.h"
#include "protocol/output_file.h"
#include "protocol/stream_reader.h"
#include "sample_streams.h"
#include "tests/scratch.h"
#include "tests/special_files.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

std::vector<Command> decode_all(const Bytes& bytes) {
    StreamReader reader(bytes);
    MemoryBuffer buffer;
    reader.replay_into(buffer);
    return buffer.commands();
}

Bytes read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::filesystem::path temp_path(const std::string& name) {
    return fb89::testing::scratch_path("writer_test_" + name);
}

TEST(StreamWriter, RoundTripIsByteForByte) {
    const std::vector<Command> commands = testing::every_opcode();
    const Bytes first = encode_stream(commands, testing::sample_properties());
    const std::vector<Command> decoded = decode_all(first);
    EXPECT_EQ(decoded, commands);
    StreamReader reader(first);
    const Bytes second = encode_stream(decoded, reader.properties());
    EXPECT_EQ(second, first);
}

TEST(StreamWriter, EveryOpcodeByteRoundTripsAlone) {
    for (const Command& c : testing::every_opcode()) {
        const Bytes bytes = encode_stream({c}, {}, false);
        ASSERT_EQ(decode_all(bytes), std::vector<Command>{c}) << to_string(c);
        EXPECT_EQ(encode_stream(decode_all(bytes), {}, false), bytes) << to_string(c);
    }
}

TEST(StreamWriter, HeaderPropertiesRoundTrip) {
    Properties properties = testing::sample_properties();
    properties["empty"] = "";
    properties["binary"] = std::string("a\0b\xff", 4);
    properties[std::string(kMaxPropertyKeyLength, 'k')] = std::string(kMaxPropertyValueLength, 'v');
    StreamReader reader(encode_stream(testing::two_frames(), properties));
    EXPECT_EQ(reader.version(), kChecksumVersion);
    EXPECT_EQ(reader.properties(), properties);
    StreamReader v1(encode_stream(testing::two_frames(), properties, true, Checksums::Off));
    EXPECT_EQ(v1.version(), kUntimedVersion);
    EXPECT_EQ(v1.properties(), properties);
}

TEST(StreamWriter, CloseWritesTheFrameIndex) {
    StreamWriter writer(testing::sample_properties());
    for (const Command& c : testing::two_frames())
        writer.submit(c);
    // version 4: the index in a batch of its own, after its BATCH record
    const uint64_t index_offset = writer.byte_count() + kBatchRecordSize;
    writer.close();
    writer.close();  // a second close does nothing
    const FrameIndex expected = {{0, 0, writer.frame_index()[0].offset},
                                 {1, 5, writer.frame_index()[1].offset}};
    EXPECT_EQ(writer.frame_index(), expected);
    EXPECT_EQ(writer.command_count(), 9u);
    EXPECT_EQ(writer.bytes().size(),
              index_offset + kIndexPrefixSize + 2 * kIndexEntrySize + kFooterSize);
    EXPECT_EQ(writer.bytes()[index_offset], kIndexOpcode);
    EXPECT_EQ(get_u64(&writer.bytes()[writer.bytes().size() - kFooterSize]), index_offset);
    EXPECT_EQ(writer.bytes()[index_offset - kBatchRecordSize], kBatchOpcode);
    EXPECT_EQ(writer.batch_count(), 3u);
}

TEST(StreamWriter, FileBytesEqualMemoryBytes) {
    const auto path = temp_path("file.fb89");
    {
        StreamWriter writer(path.string(), testing::sample_properties());
        for (const Command& c : testing::two_frames())
            writer.submit(c);
        writer.close();
        EXPECT_TRUE(writer.bytes().empty());
    }
    EXPECT_EQ(read_file(path), encode_stream(testing::two_frames(), testing::sample_properties()));
    std::filesystem::remove(path);
}

TEST(StreamWriter, LargeStreamIsWrittenInFull) {
    const auto path = temp_path("large.fb89");
    std::vector<Command> commands = {FrameBegin{0, 1024, 780, Rgb{}}};
    for (int32_t y = 0; y < 20000; ++y)
        commands.push_back(DrawSpan{y, 0, y, Rgb{1, 2, 3}});
    commands.push_back(FrameEnd{});
    {
        StreamWriter writer(path.string(), {});
        for (const Command& c : commands)
            writer.submit(c);
        writer.close();
    }
    EXPECT_EQ(read_file(path), encode_stream(commands));
    std::filesystem::remove(path);
}

TEST(StreamWriter, DiscardRemovesAFileOfItsOwnAndCloseKeepsIt) {
    const auto path = temp_path("discarded.fb89");
    {
        StreamWriter writer(path.string(), {});
        writer.frame_begin(FrameBegin{0, 4, 4, Rgb{}});
        writer.discard();
    }
    EXPECT_FALSE(std::filesystem::exists(path));
    StreamWriter writer(path.string(), {});
    writer.close();
    writer.discard();  // after close(): kept
    EXPECT_TRUE(std::filesystem::exists(path));
    std::filesystem::remove(path);
}

// Under an OutputBatch (as in every fb89 command), a stream is written live at its path and
// removed with the batch unless the batch is published.
TEST(StreamWriter, AnUnpublishedOutputBatchRemovesTheStreamAPublishedOneKeepsIt) {
    const auto path = temp_path("batched.fb89");
    for (const bool publish : {false, true}) {
        {
            OutputBatch batch;
            StreamWriter writer(path.string(), {});
            for (const Command& c : testing::two_frames())
                writer.submit(c);
            writer.close();
            EXPECT_TRUE(std::filesystem::exists(path)) << "written live, at its path";
            if (publish) batch.publish();
        }
        EXPECT_EQ(std::filesystem::exists(path), publish);
    }
    std::filesystem::remove(path);
}

// A stream replacing an old file: written live at the path, the old file aside under a
// hidden name; put back byte for byte when the stream is discarded, when an unpublished batch
// ends, or when a writer without a batch is destroyed unclosed; gone when the stream stands.
namespace {
const std::string kOldStream = "an old stream, which must survive\n";

void put_old(const std::filesystem::path& path) {
    std::ofstream(path, std::ios::binary) << kOldStream;
    std::filesystem::permissions(path, std::filesystem::perms::owner_read |
                                           std::filesystem::perms::owner_write |
                                           std::filesystem::perms::group_read);
}

std::string slurp_text(const std::filesystem::path& path) {
    const Bytes b = read_file(path);
    return std::string(b.begin(), b.end());
}

// Files beside `path` whose names start with its hidden prefix (".NAME.").
std::size_t hidden_beside(const std::filesystem::path& path) {
    std::size_t n = 0;
    const std::string prefix = "." + path.filename().string() + ".";
    for (const auto& e : std::filesystem::directory_iterator(path.parent_path()))
        n += e.path().filename().string().rfind(prefix, 0) == 0;
    return n;
}
}  // namespace

TEST(StreamWriter, DiscardPutsBackTheFileItReplaced) {
    const auto path = temp_path("replaced_discarded.fb89");
    put_old(path);
    {
        StreamWriter writer(path.string(), {});
        writer.frame_begin(FrameBegin{0, 4, 4, Rgb{}});
        writer.frame_end(FrameEnd{});
        EXPECT_NE(slurp_text(path), kOldStream) << "written live at its path";
        EXPECT_EQ(hidden_beside(path), 1u) << "the old file waits beside it";
        writer.discard();
    }
    EXPECT_EQ(slurp_text(path), kOldStream);
    EXPECT_EQ(hidden_beside(path), 0u);
    std::filesystem::remove(path);
}

TEST(StreamWriter, AnUnpublishedBatchPutsBackTheOldStreamAPublishedOneReplacesIt) {
    const auto path = temp_path("replaced_batched.fb89");
    for (const bool publish : {false, true}) {
        put_old(path);
        {
            OutputBatch batch;
            StreamWriter writer(path.string(), {});
            for (const Command& c : testing::two_frames())
                writer.submit(c);
            writer.close();
            if (publish) batch.publish();
        }
        if (publish) {
            EXPECT_EQ(read_file(path), encode_stream(testing::two_frames(), {}));
            // the new file takes the old one's permissions
            EXPECT_EQ(std::filesystem::status(path).permissions() & std::filesystem::perms::all,
                      std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                          std::filesystem::perms::group_read);
        } else {
            EXPECT_EQ(slurp_text(path), kOldStream);
        }
        EXPECT_EQ(hidden_beside(path), 0u) << "publish " << publish;
    }
    std::filesystem::remove(path);
}

TEST(StreamWriter, WithoutABatchAnUnclosedWriterPutsBackTheOldAndACloseReplacesIt) {
    const auto path = temp_path("replaced_unbatched.fb89");
    put_old(path);
    {
        StreamWriter writer(path.string(), {});
        for (const Command& c : testing::two_frames())
            writer.submit(c);
    }
    EXPECT_EQ(slurp_text(path), kOldStream) << "a writer given up never loses the old file";
    {
        StreamWriter writer(path.string(), {});
        for (const Command& c : testing::two_frames())
            writer.submit(c);
        writer.close();
    }
    EXPECT_EQ(read_file(path), encode_stream(testing::two_frames(), {}));
    EXPECT_EQ(hidden_beside(path), 0u);
    std::filesystem::remove(path);
}

TEST(StreamWriter, AFifoIsWrittenInPlaceAndStaysAFifo) {
    const auto fifo = temp_path("fifo");
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fb89::testing::FifoReader reader(fifo);
    {
        StreamWriter writer(fifo.string(), {});
        for (const Command& c : testing::two_frames())
            writer.submit(c);
        writer.close();
    }
    const std::string got = reader.stop();
    const Bytes expected = encode_stream(testing::two_frames(), {});
    EXPECT_EQ(Bytes(got.begin(), got.end()), expected);
    EXPECT_EQ(fb89::testing::identity_of(fifo).type, static_cast<mode_t>(S_IFIFO));
    std::filesystem::remove(fifo);
}

TEST(StreamWriter, DestroyedWithoutCloseLeavesAStreamWithoutIndex) {
    const auto path = temp_path("abandoned.fb89");
    {
        StreamWriter writer(path.string(), {});
        for (const Command& c : testing::two_frames())
            writer.submit(c);
    }
    EXPECT_EQ(read_file(path), encode_stream(testing::two_frames(), {}, false));
    std::filesystem::remove(path);
}

TEST(StreamWriter, BadPathThrowsNamingThePath) {
    const std::string path = "/nonexistent-fb89-dir/out.fb89";
    try {
        StreamWriter writer(path, {});
        FAIL() << "opened " << path;
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos);
    }
}

// A full device of the test's own (mknod, as root), never the system's /dev/full.
TEST(StreamWriter, DiskFullThrowsNamingThePathAndLeavesTheDeviceADevice) {
    const auto full = temp_path("full");
    if (const auto why = fb89::testing::make_char_device(full, 7)) GTEST_SKIP() << *why;
    const auto before = fb89::testing::identity_of(full);
    StreamWriter writer(full.string(), {});
    writer.frame_begin(FrameBegin{0, 4, 4, Rgb{}});
    try {
        writer.frame_end(FrameEnd{});  // FRAME_END flushes
        FAIL() << "write to a full device succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "cannot write stream " + full.string() + ": No space left on device");
    }
    EXPECT_EQ(fb89::testing::identity_of(full), before);
    EXPECT_THROW(writer.frame_begin(FrameBegin{1, 4, 4, Rgb{}}), std::runtime_error);
    EXPECT_THROW(writer.close(), std::runtime_error);
}

TEST(StreamWriter, RefusesCommandsVersion1CannotCarry) {
    StreamWriter writer(Properties{});
    writer.frame_begin(FrameBegin{0, 4, 4, Rgb{}});
    EXPECT_THROW(writer.frame_begin(FrameBegin{1, 0, 4, Rgb{}}), std::invalid_argument);
    EXPECT_THROW(writer.frame_begin(FrameBegin{1, 4, kMaxFrameDimension + 1, Rgb{}}),
                 std::invalid_argument);
    EXPECT_THROW(writer.draw_span(DrawSpan{0, 3, 2, Rgb{}}), std::invalid_argument);
    EXPECT_THROW(writer.marker(Marker{std::string(kMaxMarkerLength + 1, 'x')}),
                 std::invalid_argument);
    EXPECT_EQ(writer.command_count(), 1u);  // nothing refused was written
    EXPECT_EQ(writer.frame_index().size(), 1u);
    const Properties empty_key = {{"", "x"}};
    EXPECT_THROW(StreamWriter{empty_key}, std::invalid_argument);
}

TEST(StreamWriter, CommandAfterCloseIsALogicError) {
    StreamWriter writer(Properties{});
    writer.close();
    EXPECT_THROW(writer.frame_end(FrameEnd{}), std::logic_error);
}

TEST(StreamWriter, MemoryBufferReplayEncodesInSubmissionOrder) {
    MemoryBuffer buffer;
    for (const Command& c : testing::two_frames())
        buffer.submit(c);
    StreamWriter writer(Properties{});
    buffer.replay_into(writer);
    writer.close();
    EXPECT_EQ(writer.bytes(), encode_stream(testing::two_frames()));
    EXPECT_EQ(decode_all(writer.take_bytes()), testing::two_frames());
}

}  // namespace
}  // namespace fb89::protocol
