// Tests of the trailing frame index (protocol/stream_writer.h writes it, stream_reader.h
// checks and exposes it): read back after the commands, optional for readers, every kind
// of inconsistency refused, read through the footer alone, and seeking to a frame. The index's
// own rules on version 1 (in version 4 its checksum refuses a changed byte first:
// stream_checksum_test.cpp); reading and seeking in versions 1 and 4.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <functional>

#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "sample_streams.h"

namespace fb89::protocol {
namespace {

using Bytes = std::vector<uint8_t>;
using testing::read_all;

// Where the parts of the trailing index of a stream with n frames start.
struct IndexLayout {
    uint64_t at, entries, footer;
    IndexLayout(const Bytes& b, std::size_t n)
        : at(b.size() - kFooterSize - n * kIndexEntrySize - kIndexPrefixSize),
          entries(at + kIndexPrefixSize),
          footer(b.size() - kFooterSize) {}
};

constexpr Checksums kBoth[] = {Checksums::Off, Checksums::On};

Bytes two_frame_stream(Checksums checksums = Checksums::Off) {
    return encode_stream(testing::two_frames(), {}, true, checksums);
}

FrameIndex expected_index(Checksums checksums = Checksums::Off) {
    const Bytes bytes = two_frame_stream(checksums);
    StreamReader reader(bytes);
    FrameIndex index;
    Command c;
    while (reader.next(c)) {
        if (const auto* f = std::get_if<FrameBegin>(&c)) {
            index.push_back({f->frame, reader.command_number(), reader.command_offset()});
        }
    }
    return index;
}

TEST(StreamIndex, IsReadBackAfterTheLastCommand) {
    for (const Checksums checksums : kBoth) {
        const testing::ReadResult r = read_all(two_frame_stream(checksums));
        EXPECT_FALSE(r.error);
        EXPECT_EQ(r.commands, testing::two_frames());
        ASSERT_TRUE(r.index);
        EXPECT_EQ(*r.index, expected_index(checksums));
        EXPECT_EQ(r.index->at(1).command, 5u);
    }
}

TEST(StreamIndex, AStreamWithoutItStillReads) {
    for (const Checksums checksums : kBoth) {
        const Bytes bytes = encode_stream(testing::two_frames(), {}, false, checksums);
        const testing::ReadResult r = read_all(bytes);
        EXPECT_FALSE(r.error);
        EXPECT_EQ(r.commands, testing::two_frames());
        EXPECT_FALSE(r.index);
        StreamReader reader(bytes);
        EXPECT_EQ(reader.read_trailing_index(), std::nullopt);
    }
}

TEST(StreamIndex, AnEmptyStreamHasAnEmptyIndex) {
    for (const Checksums checksums : kBoth) {
        const testing::ReadResult r = read_all(encode_stream({}, {}, true, checksums));
        EXPECT_FALSE(r.error);
        ASSERT_TRUE(r.index);
        EXPECT_TRUE(r.index->empty());
    }
}

// Corrupts one part of the index of the two-frame stream and returns the error message.
std::string error_after(const std::function<void(Bytes&, const IndexLayout&)>& corrupt) {
    Bytes bytes = two_frame_stream();
    corrupt(bytes, IndexLayout(bytes, 2));
    const testing::ReadResult r = read_all(bytes);
    EXPECT_EQ(r.commands, testing::two_frames());  // every command came before the index
    EXPECT_FALSE(r.index);
    return r.error ? r.error->what() : "no error";
}

TEST(StreamIndex, InconsistentIndexIsRefused) {
    const IndexLayout layout(two_frame_stream(), 2);
    EXPECT_EQ(error_after([](Bytes& b, const IndexLayout& l) { b[l.at + 1] = 0xff; }),
              fmt::format("stream.fb89: frame index at byte {} (frame index, after 9 commands): "
                          "lists 255 frames; the stream has 2",
                          layout.at));
    const std::string huge_count = error_after([](Bytes& b, const IndexLayout& l) {
        for (int i = 1; i <= 4; ++i)
            b[l.at + i] = 0xff;  // checked before any allocation
    });
    EXPECT_NE(huge_count.find("lists 4294967295 frames"), std::string::npos) << huge_count;
    const std::string wrong_frame =
        error_after([](Bytes& b, const IndexLayout& l) { b[l.entries + kIndexEntrySize] = 7; });
    EXPECT_NE(wrong_frame.find("entry 1 says frame 7, command 5"), std::string::npos)
        << wrong_frame;
    const std::string wrong_offset =
        error_after([](Bytes& b, const IndexLayout& l) { b[l.entries + 12] ^= 1; });
    EXPECT_NE(wrong_offset.find("entry 0 says frame 0, command 0, byte"), std::string::npos)
        << wrong_offset;
}

TEST(StreamIndex, InconsistentFooterIsRefused) {
    const auto has = [](const std::string& message, const std::string& part) {
        return message.find(part) != std::string::npos;
    };
    EXPECT_TRUE(has(error_after([](Bytes& b, const IndexLayout& l) { b[l.footer] ^= 1; }),
                    "footer at byte"));
    EXPECT_TRUE(has(error_after([](Bytes& b, const IndexLayout& l) { b[l.footer + 8] = 99; }),
                    "after 99 commands; it is at byte"));
    EXPECT_TRUE(has(error_after([](Bytes& b, const IndexLayout&) { b.back() = 'Y'; }),
                    "magic \"FBIX\" missing"));
    EXPECT_TRUE(has(error_after([](Bytes& b, const IndexLayout&) { b.push_back(0); }),
                    "unexpected data after the footer"));
}

TEST(StreamIndex, TrailingIndexIsReadThroughTheFooterAlone) {
    for (const Checksums checksums : kBoth) {
        StreamReader reader(two_frame_stream(checksums));
        EXPECT_EQ(reader.read_trailing_index(), expected_index(checksums));
        Command c;
        ASSERT_TRUE(reader.next(c));  // reading the index did not move next()
        EXPECT_EQ(c, testing::two_frames()[0]);
        EXPECT_FALSE(reader.frame_index());  // not yet reached by next()
    }
}

TEST(StreamIndex, MalformedTrailingIndexIsIgnoredByTheFooterPath) {
    for (const std::size_t part : {std::size_t{0}, std::size_t{1}, std::size_t{2}}) {
        Bytes bytes = two_frame_stream();
        const IndexLayout l(bytes, 2);
        if (part == 0) bytes[l.at] = 0x05;                          // not the index opcode
        if (part == 1) bytes[l.footer] = 0x10;                      // index offset points elsewhere
        if (part == 2) bytes[l.entries + kIndexEntrySize + 4] = 0;  // frame 1 at command 0
        StreamReader reader(bytes);
        EXPECT_EQ(reader.read_trailing_index(), std::nullopt) << "part " << part;
    }
}

TEST(StreamIndex, SeekResumesAtTheFramesFrameBegin) {
    for (const Checksums checksums : kBoth) {
        StreamReader reader(two_frame_stream(checksums));
        const std::optional<FrameIndex> index = reader.read_trailing_index();
        ASSERT_TRUE(index);
        reader.seek(index->at(1));
        Command c;
        std::vector<Command> rest;
        while (reader.next(c)) {
            if (rest.empty()) {
                EXPECT_EQ(reader.command_number(), 5u);
                EXPECT_EQ(reader.command_offset(), index->at(1).offset);
            }
            rest.push_back(c);
        }
        const std::vector<Command> all = testing::two_frames();
        EXPECT_EQ(rest, std::vector<Command>(all.begin() + 5, all.end()));
        EXPECT_EQ(reader.frame_index(), index);  // checked against the stream's size and footer
        reader.seek(index->at(0));
        ASSERT_TRUE(reader.next(c));
        EXPECT_EQ(c, all[0]);
    }
}

TEST(StreamIndex, SeekToAnEntryThatIsNoFrameBeginThrows) {
    for (const Checksums checksums : kBoth) {
        StreamReader reader(two_frame_stream(checksums));
        const FrameIndex index = expected_index(checksums);
        EXPECT_THROW(reader.seek({1, 5, index[1].offset + 1}), StreamError);
        EXPECT_THROW(reader.seek({2, 5, index[1].offset}), StreamError);  // wrong frame number
        EXPECT_THROW(reader.seek({0, 0, 3}), StreamError);                // inside the header
        EXPECT_THROW(reader.seek({0, 0, 1u << 20}), StreamError);         // past the end
        reader.seek(index[0]);  // a good entry clears the error
        Command c;
        EXPECT_TRUE(reader.next(c));
    }
}

}  // namespace
}  // namespace fb89::protocol
