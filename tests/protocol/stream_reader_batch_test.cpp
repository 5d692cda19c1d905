// Tests of StreamReader's fast path (decode_common_record, and the buffered records it
// decodes in place) and of read_batch: the same commands, numbers, offsets and errors as
// the general path and next() give, from memory and from a file whose records straddle
// the read buffer's ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "sample_streams.h"
#include "tests/scratch.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;

// Fills and spans of every sign and size, a few of every other opcode, in two frames.
std::vector<Command> many_commands() {
    std::vector<Command> out = testing::every_opcode();
    for (uint32_t frame = 0; frame < 2; ++frame) {
        out.push_back(FrameBegin{frame, 640, 480, Rgb{4, 5, 6}});
        for (int32_t i = -300; i < 5000; ++i) {
            const Rgb c{static_cast<uint8_t>(i), static_cast<uint8_t>(i >> 8), 7};
            if (i % 3 == 0) {
                out.push_back(FillRect{i, -i, static_cast<uint32_t>(i * 7), 3, c});
            } else {
                out.push_back(DrawSpan{i, i * 5, i * 5 + (i & 63), c});
            }
            if (i % 1001 == 0)
                out.push_back(Marker{std::string(static_cast<std::size_t>(i % 97), 'k')});
        }
        out.push_back(FrameEnd{});
    }
    return out;
}

// What next() gives, command by command: the command, its number and its byte offset.
struct Read {
    Command command;
    uint64_t number = 0;
    uint64_t offset = 0;
    friend bool operator==(const Read&, const Read&) = default;
};

std::vector<Read> read_with_next(StreamReader& reader) {
    std::vector<Read> out;
    Command c;
    while (reader.next(c))
        out.push_back({c, reader.command_number(), reader.command_offset()});
    return out;
}

// The same through read_batch, checking that only a batch's last command is a FRAME_END.
std::vector<Read> read_with_batches(StreamReader& reader, std::size_t batch) {
    std::vector<Read> out;
    std::vector<Command> commands(batch);
    while (const std::size_t n = reader.read_batch(commands)) {
        for (std::size_t i = 0; i < n; ++i) {
            EXPECT_TRUE(i + 1 == n || !std::holds_alternative<FrameEnd>(commands[i]));
            out.push_back({commands[i], reader.next_command_number() - n + i, 0});
        }
        out.back().offset = reader.command_offset();  // the last command read
        EXPECT_EQ(reader.command_number(), out.back().number);
    }
    return out;
}

TEST(StreamReaderFastPath, DecodesCommonRecordsAsTheGeneralDecoderDoes) {
    std::vector<Command> records = many_commands();
    records.push_back(DrawSpan{0, std::numeric_limits<int32_t>::min(), 0, Rgb{}});
    records.push_back(DepthSpan{3, -2, 7, 0x0FFFE000u, -5, Rgb{1, 2, 3}});
    records.push_back(DepthClear{});
    records.push_back(Face{Rgb{4, 5, 6}, 1, 2, 99, -3, 4, {{0, 0}, {512, 0}, {0, 512}}});
    for (const bool depth : {false, true})
        for (const Command& c : records) {
            Bytes bytes;
            encode_command(bytes, c);
            bytes.resize(std::max(bytes.size(), kDepthSpanRecordSize));  // what it may read
            Command out = Marker{"before"};
            const std::size_t size = decode_common_record(bytes.data(), out, depth);
            const Opcode op = opcode_of(c);
            if (op == Opcode::FillRect || op == Opcode::DrawSpan || op == Opcode::FrameEnd ||
                (depth && op == Opcode::DepthSpan)) {
                EXPECT_EQ(size, 1 + *payload_size(bytes[0])) << to_string(c);
                EXPECT_EQ(out, decode_fixed_payload(op, bytes.data() + 1)) << to_string(c);
            } else {
                EXPECT_EQ(size, 0u) << to_string(c);
                EXPECT_EQ(out, Command{Marker{"before"}}) << to_string(c);
            }
        }
}

TEST(StreamReaderFastPath, LeavesWhatTheGeneralPathRefusesToIt) {
    Bytes span;
    encode_command(span, DrawSpan{1, 5, 9, Rgb{}});
    span[9] = 4;  // x1 = 4 < x0 = 5
    span.resize(kDepthSpanRecordSize);
    Bytes zspan;
    encode_command(zspan, DepthSpan{1, 5, 9, 0, 0, Rgb{}});
    zspan[9] = 4;  // x1 = 4 < x0 = 5
    for (Bytes bytes :
         {span, zspan, Bytes(kDepthSpanRecordSize, 0x00), Bytes(kDepthSpanRecordSize, 0x06),
          Bytes(kDepthSpanRecordSize, kIndexOpcode)}) {
        Command out = FrameEnd{};
        EXPECT_EQ(decode_common_record(bytes.data(), out, true), 0u) << int{bytes[0]};
        EXPECT_EQ(out, Command{FrameEnd{}});
    }
}

TEST(StreamReader, BatchesOfEverySizeGiveWhatNextGives) {
    const Bytes bytes = encode_stream(many_commands(), testing::sample_properties());
    StreamReader one(bytes);
    const std::vector<Read> expected = read_with_next(one);
    ASSERT_EQ(expected.size(), many_commands().size());
    for (std::size_t batch : {1u, 2u, 3u, 64u, 4096u, 100000u}) {
        StreamReader reader(bytes);
        std::vector<Read> got = read_with_batches(reader, batch);
        ASSERT_EQ(got.size(), expected.size()) << "batches of " << batch;
        for (std::size_t i = 0; i < got.size(); ++i) {
            ASSERT_EQ(got[i].command, expected[i].command) << "command " << i;
            ASSERT_EQ(got[i].number, expected[i].number) << "command " << i;
            if (got[i].offset != 0) {
                ASSERT_EQ(got[i].offset, expected[i].offset) << "command " << i;
            }
        }
        EXPECT_EQ(reader.frame_index(), one.frame_index());
    }
}

TEST(StreamReader, BatchesFromAFileGiveWhatABufferGives) {
    const auto path = fb89::testing::scratch_path("batch_test.fb89");
    const std::vector<Command> commands = many_commands();  // 170 KB: many read buffers
    {
        StreamWriter writer(path.string(), testing::sample_properties());
        for (const Command& c : commands)
            writer.submit(c);
        writer.close();
    }
    StreamReader from_file(path.string());
    StreamReader from_memory(encode_stream(commands, testing::sample_properties()));
    EXPECT_EQ(read_with_batches(from_file, 4096), read_with_batches(from_memory, 4096));
    std::filesystem::remove(path);
}

// A batch stops short of an error and the next call throws it: every complete command
// before it is delivered, and the error is the one next() reports.
TEST(StreamReader, BatchesDeliverEveryCommandBeforeAnErrorThenThrowIt) {
    const std::vector<Command> commands = many_commands();
    const Bytes good = encode_stream(commands);
    for (const std::size_t victim : {std::size_t{0}, std::size_t{20}, std::size_t{5000}}) {
        StreamReader probe(good);
        Command c;
        for (std::size_t i = 0; i <= victim || !std::holds_alternative<DrawSpan>(c); ++i)
            ASSERT_TRUE(probe.next(c));
        const uint64_t at = probe.command_offset();
        // an unknown opcode, another, and a span whose x1 is before its x0
        for (int corruption = 0; corruption < 3; ++corruption) {
            Bytes bytes = good;
            if (corruption < 2) bytes[at] = corruption == 0 ? 0x42 : 0x00;
            if (corruption == 2) {  // x0 = 10, x1 = 9
                const uint8_t x0_x1[8] = {10, 0, 0, 0, 9, 0, 0, 0};
                std::copy(x0_x1, x0_x1 + 8, bytes.begin() + static_cast<std::ptrdiff_t>(at + 5));
            }
            const testing::ReadResult expected = testing::read_all(bytes);
            ASSERT_TRUE(expected.error);
            StreamReader reader(bytes, "stream.fb89");
            std::vector<Command> got, batch(64);
            try {
                while (const std::size_t n = reader.read_batch(batch))
                    got.insert(got.end(), batch.begin(), batch.begin() + n);
                FAIL() << "no error";
            } catch (const StreamError& e) {
                EXPECT_STREQ(e.what(), expected.error->what());
                EXPECT_EQ(e.offset(), expected.error->offset());
                EXPECT_EQ(e.command(), expected.error->command());
            }
            EXPECT_EQ(got, expected.commands);
            EXPECT_THROW(reader.read_batch(batch), StreamError);
        }
    }
}

}  // namespace
}  // namespace fb89::protocol
