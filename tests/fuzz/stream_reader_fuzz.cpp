// Fuzz target: protocol::StreamReader, over the same bytes three times -- from memory, from
// a path (a memfd's /proc/self/fd/N: a regular file) and from a descriptor (read as it
// arrives, like a socket). Bad input must throw StreamError; all readers must agree on the
// commands delivered and on whether the stream failed. The seekable ones then read the
// trailing index without reading commands, and seek to each indexed frame (StreamError for
// an entry that does not point at its frame).
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocol/memory_buffer.h"
#include "protocol/stream_reader.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using fb89::fuzz::finding;
using fb89::protocol::Command;
using fb89::protocol::StreamError;
using fb89::protocol::StreamReader;

struct Outcome {
    std::vector<Command> commands;
    bool failed = false;
};

// Reads to the end or the first error; then exercises the index and seeking.
Outcome read_through(StreamReader& reader, bool seekable) {
    Outcome o;
    fb89::protocol::MemoryBuffer buffer;
    try {
        reader.replay_into(buffer);
    } catch (const StreamError&) {
        o.failed = true;
    }
    o.commands = buffer.commands();
    for (const Command& c : o.commands)
        (void)fb89::protocol::to_string(c);
    if (!seekable) return o;
    try {
        std::optional<fb89::protocol::FrameIndex> index = reader.read_trailing_index();
        if (index && index->size() <= 64) {
            for (const auto& entry : *index) {
                reader.seek(entry);
                Command c;
                if (reader.next(c) && !std::holds_alternative<fb89::protocol::FrameBegin>(c))
                    finding("seek() to an index entry delivered no FRAME_BEGIN");
            }
        }
    } catch (const StreamError&) {
    }
    return o;
}

int make_memfd(const uint8_t* data, size_t size) {
    int fd = ::memfd_create("fb89-fuzz-stream", MFD_CLOEXEC);
    if (fd < 0) finding("memfd_create failed");
    size_t done = 0;
    while (done < size) {
        ssize_t n = ::write(fd, data + done, size - done);
        if (n <= 0) finding("write to memfd failed");
        done += static_cast<size_t>(n);
    }
    if (::lseek(fd, 0, SEEK_SET) != 0) finding("lseek on memfd failed");
    return fd;
}

template <typename Open>
void read_with(Open open, bool seekable, bool& opened, Outcome& out) {
    try {
        StreamReader reader = open();
        out = read_through(reader, seekable);
    } catch (const StreamError&) {
        opened = false;
    }
}

void agree(const Outcome& a, bool a_opened, const Outcome& b, bool b_opened, const char* what) {
    if (a_opened != b_opened) finding(std::string(what) + ": readers disagree on the header");
    if (a.failed != b.failed)
        finding(std::string(what) + ": readers disagree on whether the stream is corrupt");
    if (a.commands != b.commands)
        finding(std::string(what) + ": readers delivered different commands");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Outcome memory, file, stream;
    bool memory_opened = true, file_opened = true, stream_opened = true;
    const int fd = make_memfd(data, size);
    const std::string path = "/proc/self/fd/" + std::to_string(fd);
    read_with([&] { return StreamReader(std::vector<uint8_t>(data, data + size), "fuzz"); }, true,
              memory_opened, memory);
    read_with([&] { return StreamReader(path); }, true, file_opened, file);
    if (::lseek(fd, 0, SEEK_SET) != 0) finding("lseek on memfd failed");
    read_with([&] { return StreamReader(fd, "fuzz-fd"); }, false, stream_opened, stream);
    ::close(fd);
    agree(memory, memory_opened, file, file_opened, "memory vs path");
    agree(memory, memory_opened, stream, stream_opened, "memory vs fd");
    return 0;
}
