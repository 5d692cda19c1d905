// StreamWriter: encodes commands as an fb89 stream -- version 4, in checksummed batches, or
// without checksums version 1, 2 or 3 -- into a file, stdout or memory, and closes it with the
// trailing frame index and footer (docs/PROTOCOL.md). Files are written with POSIX write() from
// our own buffer, so every error (bad path, disk full, closed pipe) surfaces here with the
// path and the system's reason.
#include "protocol/stream_writer.h"

#include <algorithm>

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "protocol/output_file.h"

namespace fb89::protocol {

namespace {
constexpr std::size_t kFlushThreshold = 64 * 1024;
constexpr const char* kMemoryName = "<memory>";
}  // namespace

StreamWriter::StreamWriter(const std::string& path, const Properties& properties, Timing timing,
                           Commands commands, Checksums checksums)
    : m_path(path),
      m_timed(timing == Timing::Timed),
      m_depth(commands == Commands::Depth),
      m_checksums(checksums == Checksums::On) {
    // encode the header first: bad properties must not leave an empty file behind
    encode_header(m_buffer, properties, version(), header_flags());
    m_byte_count = m_buffer.size();
    OutputKind kind;
    try {
        kind = output_kind(path);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(fmt::format("cannot open stream {}", e.what()));
    }
    switch (kind) {
        case OutputKind::Descriptor:  // "-", /dev/stdout: the descriptor, left open
            m_path = output_name(path);
            m_fd = named_descriptor(path);
            break;
        case OutputKind::InPlace:  // a device, FIFO or socket: written where it is
            try {
                m_fd = open_in_place(path);
            } catch (const std::runtime_error& e) {
                throw std::runtime_error(fmt::format("cannot open stream {}", e.what()));
            }
            m_owns_fd = true;
            break;
        case OutputKind::Replace:  // a regular file, written live; an old one kept aside
            m_live = std::make_unique<LiveFile>(path);  // throws "PATH: cannot open for writing: …"
            m_fd = m_live->fd();
            m_owns_fd = true;
            break;
    }
    struct stat st {};
    m_is_socket = ::fstat(m_fd, &st) == 0 && S_ISSOCK(st.st_mode);
}

StreamWriter::StreamWriter(int fd, std::string name, const Properties& properties, Timing timing,
                           Commands commands, Checksums checksums)
    : m_path(std::move(name)),
      m_fd(fd),
      m_timed(timing == Timing::Timed),
      m_depth(commands == Commands::Depth),
      m_checksums(checksums == Checksums::On) {
    encode_header(m_buffer, properties, version(), header_flags());
    m_byte_count = m_buffer.size();
    struct stat st {};
    m_is_socket = ::fstat(fd, &st) == 0 && S_ISSOCK(st.st_mode);
}

StreamWriter::StreamWriter(const Properties& properties, Timing timing, Commands commands,
                           Checksums checksums)
    : m_path(kMemoryName),
      m_timed(timing == Timing::Timed),
      m_depth(commands == Commands::Depth),
      m_checksums(checksums == Checksums::On) {
    encode_header(m_buffer, properties, version(), header_flags());
    m_byte_count = m_buffer.size();
}

StreamWriter::~StreamWriter() {
    if (m_closed || m_fd < 0) return;
    // abandoned without close(): keep what was written, as a stream cut after it (in version
    // 4 after its last batch, sealed here)
    if (m_error.empty()) {
        try {
            end_batch();
            flush_buffer();
        } catch (const std::exception&) {  // nothing to report to from a destructor
        }
    }
    close_file();
}

void StreamWriter::discard() noexcept {
    close_file();
    m_closed = true;
    if (m_live) m_live->abandon();  // the old file back, or none (protocol/output_file.h)
    m_live.reset();
}

void StreamWriter::frame_end(const FrameEnd& c) {
    write_command(c);
    if (m_fd >= 0) flush_buffer();  // a reader at the other end of a pipe gets the frame
}

void StreamWriter::write_command(const Command& c) {
    if (!m_error.empty()) throw std::runtime_error(m_error);
    if (m_closed) {
        throw std::logic_error(
            fmt::format("stream {}: {} after close()", m_path, to_string(opcode_of(c))));
    }
    if (auto problem = check_command(c)) {
        throw std::invalid_argument(fmt::format("stream {}: refusing to write command {}: {}",
                                                m_path, m_command_count, *problem));
    }
    if (!depth() && is_depth_opcode(opcode_of(c)))
        throw std::invalid_argument(fmt::format(
            "stream {}: refusing to write command {}: {} needs format version {} "
            "(a writer with Commands::Depth, or checksums); this stream is version {}",
            m_path, m_command_count, to_string(opcode_of(c)), kDepthVersion, version()));
    const auto* begin = std::get_if<FrameBegin>(&c);
    const bool end = std::holds_alternative<FrameEnd>(c);
    before_record(begin != nullptr);
    if (begin) {
        m_index.push_back(FrameIndexEntry{begin->frame, m_command_count, m_byte_count});
        m_times.begin_frame();
    } else if (end) {
        m_times.end_frame();
    }
    const std::size_t before = m_buffer.size();
    encode_command(m_buffer, c);
    m_byte_count += m_buffer.size() - before;
    ++m_command_count;
    after_record(true, end);
    if (m_fd >= 0 && !m_batch_open && m_buffer.size() >= kFlushThreshold) flush_buffer();
}

void StreamWriter::before_record(bool frame_begin) {
    if (!m_checksums) return;
    if (m_batch_open && frame_begin) end_batch();  // a frame starts a batch: seek() finds it
    if (m_batch_open) return;
    m_batch_at = m_buffer.size();
    m_buffer.resize(m_buffer.size() + kBatchRecordSize);  // filled in by end_batch()
    m_byte_count += kBatchRecordSize;
    m_batch = BatchRecord{0, m_batches, m_command_count, 0, 0};
    m_batch_records = 0;
    m_batch_open = true;
}

void StreamWriter::after_record(bool command, bool frame_end) {
    if (!m_batch_open) return;
    ++m_batch_records;
    if (command) ++m_batch.commands;
    if (frame_end || m_batch_records == kMaxBatchRecords) end_batch();
}

void StreamWriter::end_batch() {
    if (!m_batch_open) return;
    m_batch.length = static_cast<uint32_t>(m_buffer.size() - m_batch_at - kBatchRecordSize);
    seal_batch(m_buffer.data() + m_batch_at, m_batch);
    ++m_batches;
    m_batch_open = false;
}

void StreamWriter::send_time(int64_t ns) {
    write_time(kSendTimeOpcode, ns);
}

void StreamWriter::host_end(int64_t ns) {
    write_time(kHostEndOpcode, ns);
}

void StreamWriter::write_time(uint8_t opcode, int64_t ns) {
    const char* name = time_record_name(opcode);
    if (!m_error.empty()) throw std::runtime_error(m_error);
    if (m_closed) throw std::logic_error(fmt::format("stream {}: {} after close()", m_path, name));
    if (!m_timed)
        throw std::logic_error(
            fmt::format("stream {}: {} in a stream without send times (a writer without "
                        "Timing::Timed)",
                        m_path, name));
    if (auto problem = m_times.check(ns))
        throw std::invalid_argument(
            fmt::format("stream {}: refusing to write {} after command {}: {}", m_path, name,
                        m_command_count, *problem));
    if (opcode == kSendTimeOpcode && ns == m_times.send_ns) return;  // no change
    m_times.take(opcode, ns);
    before_record(false);
    const std::size_t before = m_buffer.size();
    encode_time(m_buffer, opcode, ns);
    m_byte_count += m_buffer.size() - before;
    after_record(false, false);
}

void StreamWriter::close() {
    if (!m_error.empty()) throw std::runtime_error(m_error);
    if (m_closed) return;
    // version 4: the open batch sealed, and the frame index in a batch of its own
    end_batch();
    before_record(false);
    const std::size_t before = m_buffer.size();
    encode_index(m_buffer, m_index, Footer{m_byte_count, m_command_count});
    m_byte_count += m_buffer.size() - before;
    end_batch();
    if (m_fd < 0) {
        m_closed = true;
        return;
    }
    flush_buffer();
    m_closed = true;
    if (m_owns_fd) {
        const int fd = m_fd;
        m_fd = -1;
        if (::close(fd) != 0) fail("close failed");
    }
    if (m_live) m_live->keep();  // whole: it stands (with the command, under a batch)
    m_live.reset();
}

void StreamWriter::flush_buffer() {
    std::size_t done = 0;
    while (done < m_buffer.size()) {
        const std::size_t left = m_buffer.size() - done;
        const ssize_t n = m_is_socket ? ::send(m_fd, m_buffer.data() + done, left, MSG_NOSIGNAL)
                                      : ::write(m_fd, m_buffer.data() + done, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) fail(n < 0 ? std::strerror(errno) : "write made no progress");
        done += static_cast<std::size_t>(n);
    }
    m_buffer.clear();
    m_commands_flushed = m_command_count;
}

void StreamWriter::close_file() noexcept {
    if (m_owns_fd && m_fd >= 0) ::close(m_fd);
    m_fd = -1;
}

void StreamWriter::fail(const std::string& what) {
    m_error = fmt::format("cannot write stream {}: {}", m_path, what);
    close_file();
    m_closed = true;
    throw std::runtime_error(m_error);
}

std::vector<uint8_t> encode_stream(const std::vector<Command>& commands,
                                   const Properties& properties, bool with_index,
                                   Checksums checksums) {
    const bool depth = std::any_of(commands.begin(), commands.end(),
                                   [](const Command& c) { return is_depth_opcode(opcode_of(c)); });
    StreamWriter writer(properties, Timing::Untimed, depth ? Commands::Depth : Commands::Tiling,
                        checksums);
    for (const Command& c : commands)
        writer.submit(c);
    if (with_index) writer.close();
    return writer.take_bytes();
}

}  // namespace fb89::protocol
