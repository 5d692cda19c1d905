// StreamWriter: a CommandSink that encodes the commands it receives as an fb89 stream
// (docs/PROTOCOL.md) into a file, stdout ("-") or memory: version 4, which carries every
// command, with Timing::Timed the host's send times (send_time(), host_end()), and checksums
// over batches of records, so that readers refuse a damaged stream. With Checksums::Off, the
// oldest version without checksums that carries the stream, for readers older than version 4:
// version 1, or with Timing::Timed version 2, or with Commands::Depth version 3.
//
// The header (with its properties) is written on construction, each command as it
// arrives. close() appends the trailing frame index and footer and flushes. Bytes reach
// the file at least at every FRAME_END, so a reader on the other end of a pipe, or a
// viewer following a file, sees whole frames as they are finished.
//
// A writer destroyed without close() flushes what it has but writes no index, so the
// stream reads as one cut after its last command; so does a file whose writer was killed.
// protocol/output_file.h decides how the target is opened: a regular file is replaced at
// once and written in place (live, for a viewer or a reader that follows it); a device,
// FIFO, socket or stdout (`-`, /dev/stdout) is written where it is, never replaced. A
// regular file is a LiveFile: an old file at its path waits aside and is put back if the
// stream is discarded, or if the command fails while an OutputBatch exists (every fb89
// command): a failed command leaves the old stream as it was, or none where there was none
// (docs/RELIABILITY.md, "Outputs").
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "protocol/command_sink.h"
#include "protocol/output_file.h"
#include "protocol/stream_format.h"

namespace fb89::protocol {

// Whether a stream carries the host's send times (format version 2) or not (version 1).
enum class Timing : bool { Untimed, Timed };
// Whether a stream may carry the depth commands (format version 3) or only the tiling ones.
enum class Commands : bool { Tiling, Depth };
// Whether a stream carries checksums (format version 4, what fb89 writes) or not.
enum class Checksums : bool { Off, On };
// The version a stream of these contents is written in: 4 with checksums; without, the oldest
// that carries them.
inline uint16_t format_version(Timing timing, Commands commands,
                               Checksums checksums = Checksums::On) {
    if (checksums == Checksums::On) return kChecksumVersion;
    if (commands == Commands::Depth) return kDepthVersion;
    return timing == Timing::Timed ? kTimedVersion : kUntimedVersion;
}

class StreamWriter final : public CommandSink {
  public:
    // Writes to path ("-" is stdout; a regular file is replaced, a device, FIFO or socket
    // written in place). Throws std::runtime_error naming the path if it cannot be opened
    // or written, std::invalid_argument for properties the format cannot carry.
    StreamWriter(const std::string& path, const Properties& properties,
                 Timing timing = Timing::Untimed, Commands commands = Commands::Tiling,
                 Checksums checksums = Checksums::On);
    // Encodes into memory; read the bytes with bytes() or take_bytes().
    explicit StreamWriter(const Properties& properties, Timing timing = Timing::Untimed,
                          Commands commands = Commands::Tiling,
                          Checksums checksums = Checksums::On);
    // Writes to an open descriptor it does not own (e.g. a connected socket; close() then
    // leaves it open); name stands for it in messages. On a socket, writes never raise
    // SIGPIPE: a vanished reader is a std::runtime_error ("Broken pipe").
    StreamWriter(int fd, std::string name, const Properties& properties,
                 Timing timing = Timing::Untimed, Commands commands = Commands::Tiling,
                 Checksums checksums = Checksums::On);
    ~StreamWriter() override;
    StreamWriter(const StreamWriter&) = delete;
    StreamWriter& operator=(const StreamWriter&) = delete;

    // Each throws std::invalid_argument for a command the format cannot carry (e.g. a span
    // with x1 < x0, or a depth command in a version-1 or -2 writer: Checksums::Off without
    // Commands::Depth),
    // std::runtime_error naming the path on a write error (disk full...), std::logic_error
    // after close().
    void take(const Command& c) override { write_command(c); }
    void frame_end(const FrameEnd& c) override;

    // Timed streams only, inside a frame (after its FRAME_BEGIN, before its FRAME_END): the
    // frame's commands from here on were sent `ns` nanoseconds after the start of the
    // host's set-up (a SEND_TIME record, written only when the time changes); the host's own
    // work on the frame ended at `ns` (HOST_END, once a frame, after its last send time).
    // Throw std::logic_error on an untimed writer, std::invalid_argument for a time outside a
    // frame, negative, going back, or after the frame's HOST_END.
    void send_time(int64_t ns);
    void host_end(int64_t ns);
    bool timed() const { return m_timed; }
    bool depth() const { return version() >= kDepthVersion; }  // takes the depth commands
    bool checksums() const { return m_checksums; }
    uint16_t version() const {
        return format_version(m_timed ? Timing::Timed : Timing::Untimed,
                              m_depth ? Commands::Depth : Commands::Tiling,
                              m_checksums ? Checksums::On : Checksums::Off);
    }

    // Writes the frame index and footer, flushes and closes the file. Does nothing if
    // already closed. Throws std::runtime_error naming the path on a write error.
    void close();

    // Abandons the stream before close(): a regular file of its own is closed and removed,
    // and the file it replaced put back;
    // a descriptor, device or pipe is closed as it stands (bytes already sent cannot be
    // taken back). What a command calls when it decides it has failed.
    void discard() noexcept;

    // The path, "<stdout>" for "-", "<memory>" in memory: the name used in messages.
    const std::string& path() const { return m_path; }
    uint64_t command_count() const { return m_command_count; }
    uint64_t byte_count() const { return m_byte_count; }  // bytes encoded so far
    // Commands whose bytes were all handed to the file or socket (at the last flush).
    uint64_t commands_flushed() const { return m_commands_flushed; }
    const FrameIndex& frame_index() const { return m_index; }
    // Version 4: the batches sealed so far (each with its checksum).
    uint32_t batch_count() const { return m_batches; }

    // The encoded stream, in-memory writers only (empty for a file). In version 4, a batch is
    // sealed at a FRAME_END, after 256 records and by close(): bytes() before that ends in a
    // batch whose BATCH record is not yet filled in; take_bytes() seals it first.
    const std::vector<uint8_t>& bytes() const { return m_buffer; }
    std::vector<uint8_t> take_bytes() {
        end_batch();
        return std::move(m_buffer);
    }

  private:
    uint16_t header_flags() const { return version() >= kDepthVersion && m_timed ? kFlagTimed : 0; }
    void write_command(const Command& c);
    void write_time(uint8_t opcode, int64_t ns);
    // Version 4: a batch opened before a record (a FRAME_BEGIN ends the open one), counted after
    // it, and sealed after a FRAME_END or its 256th record.
    void before_record(bool frame_begin);
    void after_record(bool command, bool frame_end);
    void end_batch();
    void flush_buffer();
    void close_file() noexcept;
    [[noreturn]] void fail(const std::string& what);

    std::string m_path;
    int m_fd = -1;                     // -1: in memory
    std::unique_ptr<LiveFile> m_live;  // a regular file of its own until close() keeps it
    bool m_owns_fd = false;
    bool m_is_socket = false;  // write with send(MSG_NOSIGNAL)
    bool m_closed = false;
    std::string m_error;            // set after a write error; later calls repeat it
    std::vector<uint8_t> m_buffer;  // bytes not yet written (all of them in memory)
    uint64_t m_byte_count = 0;
    uint64_t m_command_count = 0;
    uint64_t m_commands_flushed = 0;
    FrameIndex m_index;
    bool m_timed = false;
    bool m_depth = false;
    bool m_checksums = true;
    FrameTimes m_times;  // the time records of the frame being written
    // version 4: the open batch (its BATCH record at m_buffer[m_batch_at], filled in when it
    // ends: the buffer is written out only between batches), and the batches sealed
    bool m_batch_open = false;
    std::size_t m_batch_at = 0;
    BatchRecord m_batch;
    std::size_t m_batch_records = 0;
    uint32_t m_batches = 0;
};

// Encodes a whole untimed stream in memory (version 4; with Checksums::Off version 1, or 3
// when a command needs it): header, commands, and (if with_index) the trailing frame index
// and footer.
std::vector<uint8_t> encode_stream(const std::vector<Command>& commands,
                                   const Properties& properties = {}, bool with_index = true,
                                   Checksums checksums = Checksums::On);

}  // namespace fb89::protocol
