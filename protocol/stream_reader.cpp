// StreamReader: incremental decoder of fb89 streams (docs/PROTOCOL.md). Files and stdin
// are read with POSIX read() into a bounded buffer that grows only to the largest record
// or header property the format allows, or in version 4 to the largest batch, so a corrupt
// length field can never make it allocate more; a pipe delivers commands as soon as they
// arrive (in version 4, batch by batch: a batch is checked whole before it is decoded).
// FILL_RECT, DRAW_SPAN and FRAME_END records already in the buffer are decoded by a fast
// path (decode_buffered); the general path reads every other record, opens each batch and
// reports every error.
#include "protocol/stream_reader.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace fb89::protocol {

constexpr std::size_t kReadChunk = 64 * 1024;

StreamReader::StreamReader(const std::string& path) : m_name(path) {
    if (path == "-") {
        m_name = "<stdin>";
        m_fd = STDIN_FILENO;  // never seekable, even when redirected from a file
    } else {
        m_fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (m_fd < 0) {
            throw std::runtime_error(
                fmt::format("cannot open stream {}: {}", path, std::strerror(errno)));
        }
        m_owns_fd = true;
        struct stat st {};
        if (::fstat(m_fd, &st) == 0 && S_ISREG(st.st_mode)) {
            m_size = static_cast<uint64_t>(st.st_size);
        }
    }
    m_buf.resize(kReadChunk);
    try {
        read_header();
    } catch (...) {
        if (m_owns_fd) ::close(m_fd);
        throw;
    }
}

StreamReader::StreamReader(std::vector<uint8_t> bytes, std::string name)
    : m_name(std::move(name)), m_size(bytes.size()), m_buf(std::move(bytes)) {
    m_end = m_buf.size();
    m_eof = true;
    read_header();
}

StreamReader::StreamReader(int fd, std::string name, std::chrono::milliseconds idle_timeout)
    : m_name(std::move(name)), m_fd(fd), m_idle_timeout(idle_timeout) {
    m_buf.resize(kReadChunk);
    read_header();
}

StreamReader::~StreamReader() {
    if (m_owns_fd) ::close(m_fd);
}

// --- byte source ---------------------------------------------------------------------

// Makes n unread bytes available at m_buf[m_pos]; false if the stream ends first.
bool StreamReader::fill(std::size_t n) {
    if (m_end - m_pos >= n) return true;
    if (m_fd < 0 || m_eof) return false;
    if (m_pos > 0) {
        std::memmove(m_buf.data(), m_buf.data() + m_pos, m_end - m_pos);
        m_buf_offset += m_pos;
        m_end -= m_pos;
        m_pos = 0;
    }
    if (m_buf.size() < n) m_buf.resize(n);  // n is bounded by the format's limits
    while (m_end < n && !m_eof) {
        if (m_idle_timeout.count() >= 0) wait_for_data();
        const ssize_t got = ::read(m_fd, m_buf.data() + m_end, m_buf.size() - m_end);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) fail("read error", stream_end(), "", std::strerror(errno));
        if (got == 0) m_eof = true;
        m_end += static_cast<std::size_t>(got);
    }
    return m_end - m_pos >= n;
}

// With an idle time-out: waits for the next bytes at most that long.
void StreamReader::wait_for_data() {
    pollfd p{m_fd, POLLIN, 0};
    int n = 0;
    while ((n = ::poll(&p, 1, static_cast<int>(m_idle_timeout.count()))) < 0 && errno == EINTR) {
    }
    if (n == 0) {
        fail("idle time-out", stream_end(), "",
             fmt::format("nothing arrived for {:.3g} s",
                         static_cast<double>(m_idle_timeout.count()) / 1e3));
    }
}

bool StreamReader::read_at(uint64_t at, uint8_t* dst, std::size_t n) {
    if (!m_size || at > *m_size || n > *m_size - at) return false;
    if (m_fd < 0) {
        std::memcpy(dst, m_buf.data() + at, n);
        return true;
    }
    std::size_t done = 0;
    while (done < n) {
        const ssize_t got = ::pread(m_fd, dst + done, n - done, static_cast<off_t>(at + done));
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        done += static_cast<std::size_t>(got);
    }
    return true;
}

void StreamReader::reposition(uint64_t at) {
    if (m_fd < 0) {
        m_pos = static_cast<std::size_t>(at);
        return;
    }
    if (::lseek(m_fd, static_cast<off_t>(at), SEEK_SET) < 0) {
        fail("cannot seek", at, "", std::strerror(errno));
    }
    m_buf_offset = at;
    m_pos = m_end = 0;
    m_eof = false;
}

// --- errors --------------------------------------------------------------------------

void StreamReader::fail(const std::string& what, uint64_t at, const std::string& where,
                        const std::string& detail, bool damaged, std::optional<uint32_t> batch) {
    std::string message = fmt::format("{}: {} at byte {}", m_name, what, at);
    if (!where.empty()) message += fmt::format(" ({})", where);
    if (!detail.empty()) message += ": " + detail;
    m_error.emplace(message, at, m_next_command, damaged, batch);
    m_done = true;
    throw *m_error;
}

void StreamReader::fail_header(const std::string& what, uint64_t at, const std::string& detail) {
    fail(what, at, "header, before command 0", detail);
}

void StreamReader::fail_command(const std::string& what, uint64_t at, const std::string& detail) {
    fail(what, at, fmt::format("command {}", m_next_command), detail);
}

void StreamReader::fail_index(const std::string& what, uint64_t at, const std::string& detail) {
    fail(what, at, fmt::format("frame index, after {} commands", m_next_command), detail);
}

// --- header --------------------------------------------------------------------------

void StreamReader::read_header() {
    // magic and version first: a newer version may lay out the rest differently
    fill(6);
    const std::size_t present = std::min(m_end - m_pos, kMagic.size());
    if (!std::equal(m_buf.begin() + m_pos, m_buf.begin() + m_pos + present, kMagic.begin())) {
        fail_header(
            "bad magic", 0,
            fmt::format("expected \"FB89\", found {:02x}; not an fb89 stream",
                        fmt::join(m_buf.begin() + m_pos, m_buf.begin() + m_pos + present, " ")));
    }
    const auto ends = [&] { return fmt::format("the stream ends at byte {}", stream_end()); };
    if (!fill(6)) fail_header("truncated header", 0, ends());
    m_version = get_u16(&m_buf[m_pos + 4]);
    if (m_version > kFormatVersion) {
        m_error.emplace(fmt::format("{}: stream is format version {}; this fb89 reads versions "
                                    "up to {}",
                                    m_name, m_version, kFormatVersion),
                        4, 0);
        throw *m_error;
    }
    if (m_version == 0) fail_header("format version 0", 4, "no fb89 writes version 0");
    if (!fill(kFixedHeaderSize)) fail_header("truncated header", 0, ends());
    const uint16_t flags = get_u16(&m_buf[m_pos + 6]);
    if (m_version >= kDepthVersion) {
        if ((flags & ~kFlagTimed) != 0)
            fail_header(
                "header flags", 6,
                fmt::format("{:#06x} has bits other than {:#06x} (timed)", flags, kFlagTimed));
        m_timed = (flags & kFlagTimed) != 0;
    } else {
        if (flags != 0) fail_header("header flags", 6, fmt::format("{:#06x} is not 0", flags));
        m_timed = m_version >= kTimedVersion;
    }
    const uint32_t count = get_u32(&m_buf[m_pos + 8]);
    if (count > kMaxPropertyCount) {
        fail_header("property count", 8,
                    fmt::format("{} is more than {}", count, kMaxPropertyCount));
    }
    // version 4: the header's checksum follows it; the bytes are hashed as they are read
    Xxh64 hash;
    hash.update(&m_buf[m_pos], kFixedHeaderSize);
    m_pos += kFixedHeaderSize;
    for (uint32_t i = 0; i < count; ++i)
        read_property(i, hash);
    m_checked = m_version >= kChecksumVersion;
    if (m_checked) {
        const uint64_t at = offset();
        if (!fill(kHeaderChecksumSize)) fail_header("truncated header checksum", at, ends());
        const uint64_t stored = get_u64(&m_buf[m_pos]), computed = hash.digest();
        if (stored != computed)
            fail("header fails its checksum", at, "header, before command 0",
                 fmt::format("stored {:#018x}, computed {:#018x}: the stream is damaged", stored,
                             computed),
                 true);
        m_pos += kHeaderChecksumSize;
    }
    m_header_size = offset();
    m_batch_end = m_header_size;  // version 4: the first batch starts here
}

void StreamReader::read_property(uint32_t i, Xxh64& hash) {
    const uint64_t at = offset();
    const std::string what = fmt::format("property {}", i);
    const auto need = [&](std::size_t n) {
        if (!fill(n)) {
            fail_header("truncated " + what, at,
                        fmt::format("the stream ends at byte {}", stream_end()));
        }
    };
    need(2);
    const std::size_t key_length = get_u16(&m_buf[m_pos]);
    if (key_length == 0 || key_length > kMaxPropertyKeyLength) {
        fail_header(
            what, at,
            fmt::format("key length {} is outside 1..{}", key_length, kMaxPropertyKeyLength));
    }
    need(2 + key_length + 4);
    const std::size_t value_length = get_u32(&m_buf[m_pos + 2 + key_length]);
    if (value_length > kMaxPropertyValueLength) {
        fail_header(
            what, at,
            fmt::format("value length {} is more than {}", value_length, kMaxPropertyValueLength));
    }
    need(2 + key_length + 4 + value_length);
    const char* key = reinterpret_cast<const char*>(&m_buf[m_pos + 2]);
    const char* value = key + key_length + 4;
    std::string key_text(key, key_length);
    if (!m_properties.emplace(key_text, std::string(value, value_length)).second) {
        fail_header(what, at, fmt::format("key \"{}\" appears twice", key_text));
    }
    hash.update(&m_buf[m_pos], 2 + key_length + 4 + value_length);
    m_pos += 2 + key_length + 4 + value_length;
}

// --- commands ------------------------------------------------------------------------

bool StreamReader::next(Command& out) {
    for (;;) {
        // (an error also sets m_done: decode_buffered reads nothing then)
        if (decode_buffered({&out, 1}) == 1) return true;
        if (m_error) throw *m_error;
        if (m_done) return false;
        const uint64_t at = offset();
        if (m_checked && at == m_batch_end) {  // version 4: between batches
            if (open_batch()) continue;
            m_done = true;  // a clean cut after a whole batch: no index
            return false;
        }
        if (!fill(1)) {  // a clean cut after a complete record: no index
            m_done = true;
            return false;
        }
        const uint8_t opcode = m_buf[m_pos];
        if (opcode == kIndexOpcode) {
            read_index(at);
            m_done = true;
            return false;
        }
        if (is_time_opcode(opcode) && timed()) {  // not a command: on to the next record
            read_time(opcode, at);
            continue;
        }
        Command c = read_record(opcode, at);
        if (auto problem = check_command(c)) fail_command(to_string(opcode_of(c)), at, *problem);
        if (m_checked && std::holds_alternative<FrameBegin>(c) &&
            at != m_batch_at + kBatchRecordSize)  // (seek() needs a frame to start a batch)
            fail_command("FRAME_BEGIN", at,
                         fmt::format("not the first record of its batch (batch {} at byte {})",
                                     m_batch.batch, m_batch_at));
        if (const auto* begin = std::get_if<FrameBegin>(&c)) {
            if (m_seen_all) m_seen.push_back(FrameIndexEntry{begin->frame, m_next_command, at});
            m_times.begin_frame();
        } else if (std::holds_alternative<FrameEnd>(c)) {
            m_times.end_frame();
        }
        out = std::move(c);
        m_last_offset = at;
        m_last_number = m_next_command++;
        return true;
    }
}

// Takes the time record at `record` (its opcode byte) into the frame's times, or says why
// the frame cannot take it (and takes nothing): the general path and the fast one alike.
namespace {
std::optional<std::string> take_time(FrameTimes& times, const uint8_t* record) {
    const int64_t ns = get_i64(record + 1);
    auto problem = times.check(ns);
    if (!problem) times.take(record[0], ns);
    return problem;
}
}  // namespace

// A SEND_TIME or HOST_END record at m_pos (version 2): checked against the frame's times so
// far and kept for the commands after it.
void StreamReader::read_time(uint8_t opcode, uint64_t at) {
    const char* name = time_record_name(opcode);
    check_within_batch(name, at, kTimeRecordSize);
    if (!fill(kTimeRecordSize)) {
        fail_command(fmt::format("truncated {}", name), at,
                     fmt::format("the stream ends at byte {}", stream_end()));
    }
    if (auto problem = take_time(m_times, &m_buf[m_pos])) fail_command(name, at, *problem);
    m_pos += kTimeRecordSize;
}

// The fast path of next() and read_batch(), for the records that make up almost every
// stream: decodes FILL_RECT, DRAW_SPAN, FRAME_END and DEPTH_SPAN records wholly in the buffer
// straight into out[0], out[1], ..., with the read position and command numbers kept in locals.
// Stops at out's end, after a FRAME_END, where fewer than kDepthSpanRecordSize bytes are
// buffered, and before any other record -- FRAME_BEGIN, MARKER, the index, an unknown
// opcode, a span with x1 < x0, a time record the frame refuses -- which the general path
// then reads or reports, so both accept and refuse exactly the same records. A version-2
// time record the frame allows is taken on the way; with `send_ns`, send_ns[i] is out[i]'s
// send time. Returns how many commands it decoded.
std::size_t StreamReader::decode_buffered(std::span<Command> out, int64_t* send_ns) {
    if (m_done) return 0;
    const uint8_t* const buf = m_buf.data();
    std::size_t pos = m_pos, last = m_pos, n = 0;
    const bool depth = m_version >= kDepthVersion;
    // version 4: only the checked batch, wholly buffered (a BATCH record is the general path's)
    const std::size_t end =
        m_checked ? static_cast<std::size_t>(m_batch_end - m_buf_offset) : m_end;
    while (n < out.size() && end - pos >= kDepthSpanRecordSize) {
        const std::size_t size = decode_common_record(buf + pos, out[n], depth);
        if (size == 0) {
            // a version-2 time record the frame allows is taken here too (one every packet
            // of commands: leaving each to the general path cost a fifth of the replay);
            // anything else, or a time the frame refuses, is the general path's to read and
            // report
            if (!timed() || !is_time_opcode(buf[pos]) || take_time(m_times, buf + pos)) break;
            pos += kTimeRecordSize;
            continue;
        }
        if (send_ns) send_ns[n] = m_times.send_ns;
        last = pos;
        pos += size;
        ++n;
        if (size == 1) {  // FRAME_END
            m_times.end_frame();
            break;
        }
    }
    if (n > 0) {
        m_last_offset = m_buf_offset + last;
        m_last_number = m_next_command + n - 1;
        m_next_command += n;
    }
    m_pos = pos;  // past the commands and the time records taken
    return n;
}

std::size_t StreamReader::read_batch(std::span<Command> out, std::span<int64_t> send_ns) {
    if (!send_ns.empty() && send_ns.size() < out.size())
        throw std::logic_error("read_batch: fewer send times than commands");
    std::size_t n = 0;
    try {
        while (n < out.size()) {
            const std::size_t fast =
                decode_buffered(out.subspan(n), send_ns.empty() ? nullptr : send_ns.data() + n);
            n += fast;
            if (fast > 0 && std::holds_alternative<FrameEnd>(out[n - 1])) break;
            if (n == out.size() || !next(out[n])) break;
            if (!send_ns.empty()) send_ns[n] = m_times.send_ns;
            if (std::holds_alternative<FrameEnd>(out[n++])) break;
        }
    } catch (const StreamError&) {
        if (n == 0) throw;  // else kept in m_error for the next call
    }
    return n;
}

// Decodes the record at m_pos (its opcode byte) and moves past it.
Command StreamReader::read_record(uint8_t opcode, uint64_t at) {
    const std::optional<std::size_t> payload = payload_size(opcode);
    if (!payload) fail_command(fmt::format("unknown opcode {:#04x}", opcode), at, "");
    const auto op = static_cast<Opcode>(opcode);
    if (is_depth_opcode(op) && m_version < kDepthVersion)
        fail_command(fmt::format("opcode {:#04x} ({})", opcode, to_string(op)), at,
                     fmt::format("a depth command needs format version {}; this stream is "
                                 "version {}",
                                 kDepthVersion, m_version));
    const auto need = [&](std::size_t n) {
        check_within_batch(to_string(op), at, n);
        if (!fill(n)) {
            fail_command("truncated " + std::string(to_string(op)), at,
                         fmt::format("the stream ends at byte {}", stream_end()));
        }
    };
    need(1 + *payload);
    if (op == Opcode::Face) {
        Face f = decode_face_fixed(&m_buf[m_pos + 1]);
        const std::size_t count = f.points.size();
        if (count < 3 || count > kMaxFacePoints)
            fail_command("FACE", at,
                         fmt::format("{} points, outside 3..{}", count, kMaxFacePoints));
        need(1 + kFaceFixedSize + count * kFacePointSize);
        const uint8_t* p = &m_buf[m_pos + 1 + kFaceFixedSize];
        for (std::size_t i = 0; i < count; ++i)
            f.points[i] = decode_face_point(p + i * kFacePointSize);
        m_pos += 1 + kFaceFixedSize + count * kFacePointSize;
        return f;
    }
    if (op != Opcode::Marker) {
        Command c = decode_fixed_payload(op, &m_buf[m_pos + 1]);
        m_pos += 1 + *payload;
        return c;
    }
    const std::size_t length = get_u16(&m_buf[m_pos + 1]);
    if (length > kMaxMarkerLength) {
        fail_command("MARKER", at,
                     fmt::format("length {} is longer than {}", length, kMaxMarkerLength));
    }
    need(3 + length);
    Marker m{std::string(reinterpret_cast<const char*>(&m_buf[m_pos + 3]), length)};
    m_pos += 3 + length;
    return m;
}

// --- version 4: batches ---------------------------------------------------------------

// Where a batch is, for messages: "commands 1792-2047", "the frame index, after 2048
// commands", "no commands, after 12 commands"; with its number when the record is not known.
std::string StreamReader::batch_where(const std::optional<BatchRecord>& b, bool index) const {
    if (index) return fmt::format("the frame index, after {} commands", m_next_command);
    if (!b) return fmt::format("after {} commands", m_next_command);
    if (b->commands == 0 || b->commands > kMaxBatchRecords)
        return fmt::format("{} commands, after {} commands", b->commands, m_next_command);
    return fmt::format("commands {}-{}", m_next_command, m_next_command + b->commands - 1);
}

// At a batch boundary: checks that the batch read held the commands its record says, then
// reads the next BATCH record and its whole batch into the buffer and checks its checksum,
// so that no record of a damaged batch is decoded. False at the end of the stream.
bool StreamReader::open_batch() {
    if (m_in_batch && m_next_command != m_batch.first_command + m_batch.commands)
        fail(fmt::format("batch {}", m_batch.batch), m_batch_at,
             fmt::format("from command {}", m_batch.first_command),
             fmt::format("holds {} commands; its BATCH record says {}",
                         m_next_command - m_batch.first_command, m_batch.commands),
             false, m_batch.batch);
    const uint64_t at = offset();
    if (!fill(1)) return false;
    const std::string number = m_next_batch ? fmt::format("batch {}", *m_next_batch) : "batch";
    if (m_buf[m_pos] != kBatchOpcode)
        fail(fmt::format("no BATCH record for {}", number), at, batch_where(std::nullopt, false),
             fmt::format("found {:#04x} where a batch must start: the stream is damaged",
                         m_buf[m_pos]),
             true, m_next_batch);
    const auto ends = [&] { return fmt::format("the stream ends at byte {}", stream_end()); };
    if (!fill(kBatchRecordSize))
        fail("truncated BATCH record of " + number, at, batch_where(std::nullopt, false), ends(),
             false, m_next_batch);
    const BatchRecord b = decode_batch(&m_buf[m_pos]);
    // (after a seek(), the batch's number is the one its record gives)
    const uint32_t batch = m_next_batch.value_or(b.batch);
    const std::string named = fmt::format("batch {}", batch);
    // a batch holds at most kMaxBatchBytes; the frame index's, as many as its entries take
    // (as many as the frames read, or after a seek() as the stream has left)
    const bool index = b.length > 0 && fill(kBatchRecordSize + 1) &&
                       m_buf[m_pos + kBatchRecordSize] == kIndexOpcode;
    uint64_t most = kMaxBatchBytes;
    if (index && m_seen_all)
        most = std::max<uint64_t>(
            most, kIndexPrefixSize + kFooterSize + uint64_t{m_seen.size()} * kIndexEntrySize);
    else if (index && m_size && *m_size >= at + kBatchRecordSize)
        most = std::max<uint64_t>(most, *m_size - at - kBatchRecordSize);
    if (b.length > most)
        fail(named, at, batch_where(b, index),
             fmt::format("its length {} is more than the {} bytes a batch may take: the stream is "
                         "damaged",
                         b.length, most),
             true, batch);
    if (!fill(kBatchRecordSize + b.length))
        fail("truncated " + named, at, batch_where(b, index), ends(), false, batch);
    const uint64_t computed = batch_checksum(&m_buf[m_pos], b.length);
    if (computed != b.checksum)
        fail(named + " fails its checksum", at, batch_where(b, index),
             fmt::format("stored {:#018x}, computed {:#018x}: the stream is damaged", b.checksum,
                         computed),
             true, batch);
    // whole as written: what it says of itself must be so
    if ((m_next_batch && b.batch != *m_next_batch) || b.first_command != m_next_command ||
        b.commands > kMaxBatchRecords)
        fail("BATCH record", at, batch_where(b, index),
             fmt::format("says batch {}, {} commands from command {}; expected {} from command "
                         "{}, at most {} commands",
                         b.batch, b.commands, b.first_command, number, m_next_command,
                         kMaxBatchRecords),
             false, b.batch);
    m_batch = b;
    m_in_batch = true;
    m_batch_at = at;
    m_batch_end = at + kBatchRecordSize + b.length;
    m_next_batch = b.batch + 1;
    ++m_batches_checked;
    m_pos += kBatchRecordSize;
    return true;
}

// Version 4: a record of n bytes at `at` must end within its batch.
void StreamReader::check_within_batch(const char* what, uint64_t at, std::size_t n) {
    if (m_checked && at + n > m_batch_end)
        fail_command(fmt::format("{} runs past its batch", what), at,
                     fmt::format("batch {} ends at byte {}", m_batch.batch, m_batch_end));
}

uint64_t StreamReader::replay_into(CommandSink& sink) {
    uint64_t delivered = 0;
    Command c;
    while (next(c)) {
        sink.submit(c);
        ++delivered;
    }
    return delivered;
}

// --- frame index ---------------------------------------------------------------------

// Reads the trailing index record at m_pos (its 0xFE byte), checks it against the frames
// seen and the footer against the stream, and requires the stream to end there.
void StreamReader::read_index(uint64_t at) {
    const auto need = [&](std::size_t n) {
        if (!fill(n)) {
            fail_index("truncated frame index", at,
                       fmt::format("the stream ends at byte {}", stream_end()));
        }
    };
    check_within_batch("frame index", at, kIndexPrefixSize);
    need(kIndexPrefixSize);
    const uint32_t count = get_u32(&m_buf[m_pos + 1]);
    const uint64_t index_end = at + kIndexPrefixSize + uint64_t{count} * kIndexEntrySize;
    // version 4: the index is a batch of its own, whole
    if (m_checked && (at != m_batch_at + kBatchRecordSize || m_batch.commands != 0 ||
                      index_end + kFooterSize != m_batch_end)) {
        fail_index("frame index", at,
                   fmt::format("{} entries are not the whole of batch {} (bytes {}-{}, {} "
                               "commands)",
                               count, m_batch.batch, m_batch_at, m_batch_end, m_batch.commands));
    }
    if (m_seen_all && count != m_seen.size()) {
        fail_index("frame index", at,
                   fmt::format("lists {} frames; the stream has {}", count, m_seen.size()));
    }
    if (!m_seen_all && (!m_size || index_end + kFooterSize != *m_size)) {
        fail_index("frame index", at, fmt::format("{} entries do not end the stream", count));
    }
    m_pos += kIndexPrefixSize;
    FrameIndex index;
    index.reserve(count);  // bounded: by the frames seen, or by the stream's size
    for (uint32_t i = 0; i < count; ++i) {
        need(kIndexEntrySize);
        const FrameIndexEntry e = decode_index_entry(&m_buf[m_pos]);
        if (m_seen_all && e != m_seen[i]) {
            const FrameIndexEntry& s = m_seen[i];
            fail_index("frame index", at,
                       fmt::format("entry {} says frame {}, command {}, byte {}; the stream "
                                   "has frame {}, command {}, byte {}",
                                   i, e.frame, e.command, e.offset, s.frame, s.command, s.offset));
        }
        index.push_back(e);
        m_pos += kIndexEntrySize;
    }
    need(kFooterSize);
    const std::optional<Footer> footer = decode_footer(&m_buf[m_pos]);
    if (!footer) fail_index("footer", index_end, "magic \"FBIX\" missing");
    if (footer->index_offset != at || footer->command_count != m_next_command) {
        fail_index("footer", index_end,
                   fmt::format("says the index is at byte {} after {} commands; it is at "
                               "byte {} after {} commands",
                               footer->index_offset, footer->command_count, at, m_next_command));
    }
    if (auto problem = check_index(index, m_header_size, *footer)) {
        fail_index("frame index", at, *problem);
    }
    m_pos += kFooterSize;
    if (fill(1)) fail_index("unexpected data after the footer", offset(), "");
    m_index = std::move(index);
}

std::optional<FrameIndex> StreamReader::read_trailing_index() {
    if (m_index) return m_index;
    const uint64_t tail = kIndexPrefixSize + kFooterSize;
    if (!m_size || *m_size < m_header_size + tail) return std::nullopt;
    uint8_t bytes[kFooterSize];
    if (!read_at(*m_size - kFooterSize, bytes, kFooterSize)) return std::nullopt;
    const std::optional<Footer> footer = decode_footer(bytes);
    if (!footer || footer->index_offset < m_header_size || footer->index_offset > *m_size - tail) {
        return std::nullopt;
    }
    // the entry count must fill the space exactly, and there is at most one frame per
    // FRAME_BEGIN record: both bound what is read and allocated
    const uint64_t space = *m_size - tail - footer->index_offset;
    const uint64_t count = space / kIndexEntrySize;
    const uint64_t most = (footer->index_offset - m_header_size) / kFrameBeginRecordSize;
    if (space % kIndexEntrySize != 0 || count > most || count > footer->command_count) {
        return std::nullopt;
    }
    uint8_t prefix[kIndexPrefixSize];
    if (!read_at(footer->index_offset, prefix, kIndexPrefixSize) || prefix[0] != kIndexOpcode ||
        get_u32(prefix + 1) != count) {
        return std::nullopt;
    }
    if (m_checked && !trailing_index_checked(*footer)) return std::nullopt;
    FrameIndex index(static_cast<std::size_t>(count));
    uint8_t entry[kIndexEntrySize];
    for (uint64_t i = 0; i < count; ++i) {
        if (!read_at(footer->index_offset + kIndexPrefixSize + i * kIndexEntrySize, entry,
                     kIndexEntrySize)) {
            return std::nullopt;
        }
        index[static_cast<size_t>(i)] = decode_index_entry(entry);
    }
    if (check_index(index, m_header_size, *footer)) return std::nullopt;
    return index;
}

// Version 4: whether the frame index that ends the stream (its footer read) is in a batch of its
// own, the last, as a writer puts it (false: not an index, as for any other misfit); throws
// StreamError if that batch fails its checksum.
bool StreamReader::trailing_index_checked(const Footer& footer) {
    if (footer.index_offset < m_header_size + kBatchRecordSize) return false;
    const uint64_t at = footer.index_offset - kBatchRecordSize;
    uint8_t record[kBatchRecordSize];
    if (!read_at(at, record, kBatchRecordSize) || record[0] != kBatchOpcode) return false;
    const BatchRecord b = decode_batch(record);
    if (b.length != *m_size - footer.index_offset || b.commands != 0 ||
        b.first_command != footer.command_count)
        return false;
    Xxh64 hash;
    hash.update(record + kBatchHashedFrom, kBatchRecordSize - kBatchHashedFrom);
    std::vector<uint8_t> chunk(static_cast<std::size_t>(std::min<uint64_t>(b.length, kReadChunk)));
    for (uint64_t done = 0; done < b.length;) {
        const std::size_t n =
            static_cast<std::size_t>(std::min<uint64_t>(chunk.size(), b.length - done));
        if (!read_at(footer.index_offset + done, chunk.data(), n)) return false;
        hash.update(chunk.data(), n);
        done += n;
    }
    if (hash.digest() != b.checksum) {
        m_error.emplace(
            fmt::format("{}: batch {} fails its checksum at byte {} (the frame index, after {} "
                        "commands): stored {:#018x}, computed {:#018x}: the stream is damaged",
                        m_name, b.batch, at, footer.command_count, b.checksum, hash.digest()),
            at, m_next_command, true, b.batch);
        m_done = true;
        throw *m_error;
    }
    return true;
}

void StreamReader::seek(const FrameIndexEntry& entry) {
    if (!m_size) throw std::logic_error(fmt::format("stream {} cannot seek", m_name));
    m_error.reset();
    m_next_command = entry.command;
    // version 4: a frame starts a batch, read and checked from its BATCH record before it
    const uint64_t first = m_header_size + (m_checked ? kBatchRecordSize : 0);
    if (entry.offset < first || entry.offset >= *m_size) {
        fail_command(
            "frame index entry", entry.offset,
            fmt::format("byte {} is outside the commands {}..{}", entry.offset, first, *m_size));
    }
    m_seen.clear();
    m_seen_all = false;
    m_done = false;
    if (m_checked) {
        reposition(entry.offset - kBatchRecordSize);
        m_batch_end = entry.offset - kBatchRecordSize;
        m_in_batch = false;
        m_next_batch.reset();
        if (!open_batch() || m_batch_end - entry.offset < kFrameBeginRecordSize)
            fail_command(
                "frame index entry", entry.offset,
                fmt::format("no batch starting with a FRAME_BEGIN of frame {} there", entry.frame));
    } else {
        reposition(entry.offset);
    }
    if (!fill(kFrameBeginRecordSize) || m_buf[m_pos] != static_cast<uint8_t>(Opcode::FrameBegin) ||
        get_u32(&m_buf[m_pos + 1]) != entry.frame) {
        fail_command("frame index entry", entry.offset,
                     fmt::format("no FRAME_BEGIN of frame {} there", entry.frame));
    }
    m_times.end_frame();
}

}  // namespace fb89::protocol
