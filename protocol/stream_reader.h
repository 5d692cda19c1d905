// StreamReader: reads an fb89 stream (any version up to kFormatVersion, docs/PROTOCOL.md)
// from a file, stdin ("-") or a byte buffer, one command at a time, with its send time in a
// timed stream.
//
// The header is read on construction. next() then returns the commands in order with
// their command numbers and byte offsets, without loading the stream into memory. A
// stream may end after any complete command (cut, or piped and stopped): that is a clean
// end without a frame index. A stream closed by a writer ends with the trailing frame
// index, which the reader checks against the frames it saw and then exposes. Anything
// else -- bad magic, a newer version, an unknown opcode, a field out of range, a record
// cut short, an inconsistent index -- throws StreamError naming the stream, the byte
// offset and the command number, after every complete command before it was delivered.
//
// A version-4 stream carries checksums: the header's is checked on construction, and each
// batch of records is read whole and checked before any command of it is delivered, so a
// damaged batch delivers nothing; its StreamError names the batch, its byte offset and its
// commands, and says damaged().
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/command_sink.h"
#include "protocol/stream_format.h"
#include "protocol/xxhash64.h"

namespace fb89::protocol {

class StreamReader {
  public:
    // Opens path ("-" is stdin) and reads the header. Throws std::runtime_error naming the
    // path if it cannot be opened, StreamError if the header is corrupt, cut short or of a
    // newer version.
    explicit StreamReader(const std::string& path);
    // Reads a stream held in memory; name stands for it in messages.
    explicit StreamReader(std::vector<uint8_t> bytes, std::string name = "<memory>");
    // Reads from an open descriptor it does not own (e.g. a connected socket), as it
    // arrives; name stands for it in messages. With idle_timeout >= 0, a wait of longer
    // than that for the next bytes throws StreamError ("idle"), as a truncation would.
    StreamReader(int fd, std::string name,
                 std::chrono::milliseconds idle_timeout = std::chrono::milliseconds(-1));
    ~StreamReader();
    StreamReader(const StreamReader&) = delete;
    StreamReader& operator=(const StreamReader&) = delete;

    const std::string& name() const { return m_name; }  // path, "<stdin>" or the buffer's
    uint16_t version() const { return m_version; }
    // Version 4: the header and every batch carry checksums (docs/PROTOCOL.md, "Version 4:
    // checksums"); batches_checked() counts the batches read and found whole so far, the
    // frame index's included.
    bool checksummed() const { return m_checked; }
    uint64_t batches_checked() const { return m_batches_checked; }
    const Properties& properties() const { return m_properties; }
    uint64_t header_size() const { return m_header_size; }  // byte offset of the first record

    // Reads the next command into out. Returns false at the end of the stream (after the
    // frame index, or where a cut stream stops at a record boundary). Throws StreamError on
    // corrupt or truncated input, and again on every call after that.
    bool next(Command& out);
    // Reads up to out.size() commands into out's first elements, in order, and returns how
    // many; a batch ends after a FRAME_END, so that the caller sees each frame as it ends.
    // 0 at the end of the stream. A StreamError is thrown only when no command precedes it
    // in the batch: a batch stops short of the error, and the next call throws it. With
    // send_ns (at least as long as out), each command's send time goes beside it.
    std::size_t read_batch(std::span<Command> out, std::span<int64_t> send_ns = {});

    // The send times of a timed stream (docs/PROTOCOL.md, "Version 2"), read with the
    // commands: the last command's send time in nanoseconds from the start of its frame's
    // set-up (0 before a frame's first SEND_TIME, and always in an untimed stream), and the
    // HOST_END of the last command's frame once read (nullopt before it, or without one).
    bool timed() const { return m_timed; }
    int64_t send_time_ns() const { return m_times.send_ns; }
    std::optional<int64_t> host_end_ns() const { return m_times.host_end_ns; }
    // When the host's work on the last command's frame ended, as the pipeline takes it: its
    // HOST_END, or without one its last send time so far.
    int64_t frame_host_end_ns() const { return m_times.host_end_ns.value_or(m_times.send_ns); }

    uint64_t command_number() const { return m_last_number; }  // of the last command read
    uint64_t command_offset() const { return m_last_offset; }  // byte offset of its record
    uint64_t next_command_number() const { return m_next_command; }

    // Reads every remaining command into sink; returns how many were delivered. Throws
    // StreamError as next() does, after delivering every complete command before it.
    uint64_t replay_into(CommandSink& sink);

    // The trailing frame index, once next() has reached and checked it; nullopt before, and
    // for a stream without one.
    const std::optional<FrameIndex>& frame_index() const { return m_index; }

    // For files and buffers (not stdin): reads the frame index through the footer without
    // reading the commands. nullopt if the source cannot seek or the stream ends in no
    // well-formed index (cut streams have none). The position of next() does not change.
    // Version 4: an index in its batch that fails its checksum throws StreamError (damaged).
    std::optional<FrameIndex> read_trailing_index();
    // For files and buffers: continues reading at an index entry, so that next() returns
    // its FRAME_BEGIN numbered entry.command. Throws StreamError if the entry does not point
    // at that frame's FRAME_BEGIN, std::logic_error if the source cannot seek.
    void seek(const FrameIndexEntry& entry);

  private:
    bool fill(std::size_t n);
    void wait_for_data();
    uint64_t offset() const { return m_buf_offset + m_pos; }
    uint64_t stream_end() const { return m_buf_offset + m_end; }
    bool read_at(uint64_t at, uint8_t* dst, std::size_t n);
    void reposition(uint64_t at);
    void read_header();
    void read_property(uint32_t i, Xxh64& hash);
    std::size_t decode_buffered(std::span<Command> out, int64_t* send_ns = nullptr);
    Command read_record(uint8_t opcode, uint64_t at);
    void read_time(uint8_t opcode, uint64_t at);
    void read_index(uint64_t at);
    // version 4: the batch at a batch boundary, read whole and checked (false at the end)
    bool open_batch();
    void check_within_batch(const char* what, uint64_t at, std::size_t n);
    std::string batch_where(const std::optional<BatchRecord>& b, bool index) const;
    bool trailing_index_checked(const Footer& footer);
    [[noreturn]] void fail(const std::string& what, uint64_t at, const std::string& where,
                           const std::string& detail, bool damaged = false,
                           std::optional<uint32_t> batch = std::nullopt);
    [[noreturn]] void fail_header(const std::string& what, uint64_t at, const std::string& detail);
    [[noreturn]] void fail_command(const std::string& what, uint64_t at, const std::string& detail);
    [[noreturn]] void fail_index(const std::string& what, uint64_t at, const std::string& detail);

    std::string m_name;
    int m_fd = -1;  // -1: the stream is m_buf
    bool m_owns_fd = false;
    std::chrono::milliseconds m_idle_timeout{-1};  // < 0: wait as long as it takes
    std::optional<uint64_t> m_size;  // known for buffers and regular files: they can seek

    std::vector<uint8_t> m_buf;
    std::size_t m_pos = 0, m_end = 0;  // unread bytes are m_buf[m_pos, m_end)
    uint64_t m_buf_offset = 0;         // stream offset of m_buf[0]
    bool m_eof = false;

    uint16_t m_version = 0;
    bool m_timed = false;  // version 2, or version 3 with kFlagTimed
    Properties m_properties;
    uint64_t m_header_size = 0;

    uint64_t m_next_command = 0;
    uint64_t m_last_number = 0;
    uint64_t m_last_offset = 0;
    FrameIndex m_seen;       // FRAME_BEGINs read, to check the trailing index against
    bool m_seen_all = true;  // false after seek(): m_seen misses frames
    bool m_done = false;
    std::optional<StreamError> m_error;
    std::optional<FrameIndex> m_index;
    FrameTimes m_times;  // the time records of the frame being read (version 2)

    // version 4: the batch being read, whole in m_buf and checked, from its BATCH record at
    // m_batch_at to m_batch_end (at a batch boundary, m_batch_end is where the next starts)
    bool m_checked = false;
    bool m_in_batch = false;  // m_batch is the batch being read
    BatchRecord m_batch;
    uint64_t m_batch_at = 0, m_batch_end = 0;
    std::optional<uint32_t> m_next_batch = 0;  // unknown after seek()
    uint64_t m_batches_checked = 0;
};

}  // namespace fb89::protocol
