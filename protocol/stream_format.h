// Wire encoding of the fb89 command stream, versions 1 to 4 (normative spec:
// docs/PROTOCOL.md; version 2 adds the send-time records, version 3 the depth commands,
// version 4 the checksums).
//
// Little-endian throughout. A stream is a header (magic "FB89", u16 version, u16 flags,
// u32 property count, properties; in version 4 its checksum), then one record per command (u8
// opcode + a fixed payload; MARKER carries a u16 length and its text, FACE a point count and
// its points), then optionally a trailing frame index record (opcode 0xFE) ending in a
// fixed-size footer. Version 4 groups the records in batches, each opened by a BATCH record
// that carries the batch's checksum. This file holds the constants, the byte-exact helpers and
// the per-record encoders/decoders that StreamWriter and StreamReader share; it does no I/O.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "protocol/command.h"

namespace fb89::protocol {

// --- header --------------------------------------------------------------------------
inline constexpr std::array<uint8_t, 4> kMagic = {'F', 'B', '8', '9'};
inline constexpr std::size_t kFixedHeaderSize = 12;  // magic, version, flags, property count
inline constexpr uint32_t kMaxPropertyCount = 1024;
inline constexpr std::size_t kMaxPropertyKeyLength = 256;      // bytes, at least 1
inline constexpr std::size_t kMaxPropertyValueLength = 65536;  // bytes, may be 0

// Header properties, written in ascending key order; keys are unique.
using Properties = std::map<std::string, std::string>;

// Conventional property keys (writers may add others).
inline constexpr const char* kPropertyTool = "tool";  // e.g. "fb89 0.1.0"
inline constexpr const char* kPropertyScene = "scene";
inline constexpr const char* kPropertyMethod = "method";
inline constexpr const char* kPropertyThreshold = "threshold";
inline constexpr const char* kPropertyResolution = "resolution";  // e.g. "1024x780"
// Version 2: where the send times come from -- "measured" (this machine's clock) or
// "counted" (a 1989 host's instructions) -- and the host ("native", "sun4-260", ...).
inline constexpr const char* kPropertySendTimes = "send_times";
inline constexpr const char* kPropertyHost = "host";

// --- records -------------------------------------------------------------------------
inline constexpr uint8_t kIndexOpcode = 0xFE;  // trailing frame index; not a command

// The bytes of a field on the wire, and of a command's payload: after the opcode byte, the
// tail's count (MARKER's u16, FACE's u8) and the fields; a MARKER's text and a FACE's points
// follow.
template <class T>
inline constexpr std::size_t kWireSize = std::is_same_v<T, Rgb> ? 3 : sizeof(T);
template <class C>
constexpr std::size_t fixed_payload_size() {
    using I = CommandInfo<C>;
    std::size_t n = I::tail == Tail::Text ? 2 : I::tail == Tail::Points ? 1 : 0;
    std::apply(
        [&](const auto&... f) {
            ((n += kWireSize<std::remove_cvref_t<decltype(C{}.*f.member)>>), ...);
        },
        I::fields);
    return n;
}
namespace detail {
template <std::size_t... I>
constexpr std::array<std::size_t, sizeof...(I)> payload_sizes(std::index_sequence<I...>) {
    return {fixed_payload_size<std::variant_alternative_t<I, Command>>()...};
}
}  // namespace detail
inline constexpr std::array<std::size_t, kOpcodeCount> kPayloadSizes =
    detail::payload_sizes(std::make_index_sequence<kOpcodeCount>{});

// Bytes after the opcode byte of each command record (for MARKER the u16 length only).
std::optional<std::size_t> payload_size(uint8_t opcode);  // nullopt: not a command opcode
inline constexpr std::size_t kFrameBeginRecordSize = 1 + fixed_payload_size<FrameBegin>();
inline constexpr std::size_t kFillRectRecordSize = 1 + fixed_payload_size<FillRect>();
inline constexpr std::size_t kDrawSpanRecordSize = 1 + fixed_payload_size<DrawSpan>();
inline constexpr std::size_t kDepthSpanRecordSize = 1 + fixed_payload_size<DepthSpan>();
// FACE: opcode, its fixed part (u8 count first), then 8 bytes a point.
inline constexpr std::size_t kFaceFixedSize = fixed_payload_size<Face>();
inline constexpr std::size_t kFacePointSize = 8;
inline constexpr std::size_t kMaxRecordSize = 1 + 2 + kMaxMarkerLength;
// The sizes docs/PROTOCOL.md gives.
static_assert(kFrameBeginRecordSize == 16 && kFillRectRecordSize == 20 &&
              kDrawSpanRecordSize == 16 && kDepthSpanRecordSize == 24 && kFaceFixedSize == 24);
static_assert(1 + kFaceFixedSize + kMaxFacePoints * kFacePointSize <= kMaxRecordSize);

// Version 3's header flags: bit 0, the stream carries send-time records (as version 2 does).
// Versions 1 and 2 keep the flags 0.
inline constexpr uint16_t kFlagTimed = 0x0001;

// Version 2's time records: not commands (they get no command number). SEND_TIME: the
// frame's commands after it were sent this many nanoseconds after the start of the host's
// set-up; HOST_END: the host's own work on the frame ended then.
inline constexpr uint8_t kSendTimeOpcode = 0x06;
inline constexpr uint8_t kHostEndOpcode = 0x07;
inline constexpr std::size_t kTimeRecordSize = 9;  // opcode, i64 nanoseconds
inline bool is_time_opcode(uint8_t opcode) {
    return opcode == kSendTimeOpcode || opcode == kHostEndOpcode;
}
const char* time_record_name(uint8_t opcode);  // "SEND_TIME" or "HOST_END"

// The time records of the frame being read or written, and the rules they keep (the writer
// refuses, and the reader rejects, the same records with the same reasons).
struct FrameTimes {
    bool in_frame = false;
    int64_t send_ns = 0;  // the commands' since the frame's last SEND_TIME (0 before one)
    std::optional<int64_t> host_end_ns;

    void begin_frame() {
        in_frame = true;
        send_ns = 0;
        host_end_ns.reset();
    }
    void end_frame() { in_frame = false; }
    // Why a SEND_TIME or HOST_END of `ns` cannot come now: outside a frame, negative, going
    // back, or after the frame's HOST_END; nullopt when it can.
    std::optional<std::string> check(int64_t ns) const;
    // Takes a record check() allowed.
    void take(uint8_t opcode, int64_t ns) {
        if (opcode == kSendTimeOpcode)
            send_ns = ns;
        else
            host_end_ns = ns;
    }
};

// --- trailing index ------------------------------------------------------------------
struct FrameIndexEntry {
    uint32_t frame = 0;    // frame number of the FRAME_BEGIN
    uint64_t command = 0;  // command number of the FRAME_BEGIN
    uint64_t offset = 0;   // byte offset of the FRAME_BEGIN record's opcode byte
    friend bool operator==(const FrameIndexEntry&, const FrameIndexEntry&) = default;
};
using FrameIndex = std::vector<FrameIndexEntry>;

inline constexpr std::size_t kIndexEntrySize = 20;  // u32 frame, u64 command, u64 offset
inline constexpr std::size_t kIndexPrefixSize = 5;  // opcode 0xFE, u32 entry count
inline constexpr std::size_t kFooterSize = 20;      // u64 index offset, u64 commands, magic
inline constexpr std::array<uint8_t, 4> kFooterMagic = {'F', 'B', 'I', 'X'};

struct Footer {
    uint64_t index_offset = 0;   // byte offset of the 0xFE opcode byte
    uint64_t command_count = 0;  // commands in the stream
};

// --- version 4: checksums (docs/PROTOCOL.md, "Version 4: checksums") -------------------
// The header ends in the XXH64 (seed 0) of every header byte before it. Then every record --
// command, time record, frame index -- belongs to a batch: a BATCH record, then `length` bytes
// of records, at most kMaxBatchRecords of them. The BATCH record's checksum is the XXH64 of
// the bytes from its batch field to the batch's end, so a reader checks a batch whole before
// it decodes any of it. A batch starts at every FRAME_BEGIN and ends after every FRAME_END;
// the frame index is a batch of its own.
inline constexpr std::size_t kHeaderChecksumSize = 8;  // u64 after the properties
inline constexpr uint8_t kBatchOpcode = 0x0B;          // not a command
// opcode, u64 checksum, u32 batch, u64 first command, u16 commands, u32 length
inline constexpr std::size_t kBatchRecordSize = 27;
inline constexpr std::size_t kBatchHashedFrom = 9;  // the checksum covers the record from here
inline constexpr std::size_t kMaxBatchRecords = 256;
inline constexpr std::size_t kMaxBatchBytes = kMaxBatchRecords * kMaxRecordSize;  // 262,912

struct BatchRecord {
    uint64_t checksum = 0;       // XXH64 of the record from byte 9 to the batch's end
    uint32_t batch = 0;          // batches are numbered from 0 in stream order
    uint64_t first_command = 0;  // command number of its first command (or of the next one)
    uint16_t commands = 0;       // commands in the batch (its time records are not commands)
    uint32_t length = 0;         // bytes of records after the BATCH record
    friend bool operator==(const BatchRecord&, const BatchRecord&) = default;
};

// --- errors --------------------------------------------------------------------------
// A truncated or corrupt stream. The message names the stream, the byte offset and the
// command number; offset() and command() give them to programs. command() is the number
// of commands delivered before the error. damaged(): the bytes are not what the writer wrote
// (version 4: a header or batch failing its checksum, or a batch record that is not one),
// beyond a stream merely cut short or refused; batch() names the batch, when one is at fault.
class StreamError : public std::runtime_error {
  public:
    StreamError(const std::string& message, uint64_t offset, uint64_t command, bool damaged = false,
                std::optional<uint32_t> batch = std::nullopt)
        : std::runtime_error(message),
          m_offset(offset),
          m_command(command),
          m_damaged(damaged),
          m_batch(batch) {}
    uint64_t offset() const { return m_offset; }
    uint64_t command() const { return m_command; }
    bool damaged() const { return m_damaged; }
    std::optional<uint32_t> batch() const { return m_batch; }

  private:
    uint64_t m_offset;
    uint64_t m_command;
    bool m_damaged;
    std::optional<uint32_t> m_batch;
};

// --- little-endian helpers -----------------------------------------------------------
void put_u8(std::vector<uint8_t>& out, uint8_t v);
void put_u16(std::vector<uint8_t>& out, uint16_t v);
void put_u32(std::vector<uint8_t>& out, uint32_t v);
void put_u64(std::vector<uint8_t>& out, uint64_t v);
void put_i32(std::vector<uint8_t>& out, int32_t v);  // two's complement
void put_i64(std::vector<uint8_t>& out, int64_t v);  // two's complement
// Inline: the reader decodes every record with them. Compilers turn each into one load
// (plus a byte swap on big-endian hosts).
inline uint16_t get_u16(const uint8_t* p) {
    return static_cast<uint16_t>(p[0] | (p[1] << 8));
}
inline uint32_t get_u32(const uint8_t* p) {
    return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
           (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
}
inline uint64_t get_u64(const uint8_t* p) {
    return static_cast<uint64_t>(get_u32(p)) | (static_cast<uint64_t>(get_u32(p + 4)) << 32);
}
inline int32_t get_i32(const uint8_t* p) {
    return static_cast<int32_t>(get_u32(p));
}
inline int64_t get_i64(const uint8_t* p) {
    return static_cast<int64_t>(get_u64(p));
}

// --- encoders (append to out) --------------------------------------------------------
// Throw std::invalid_argument for what the format cannot carry (see check_*).
// The header of a stream of `version` (kUntimedVersion, kTimedVersion, kDepthVersion or
// kChecksumVersion; the flags 0 but for kFlagTimed in versions 3 and 4), in version 4 with
// its checksum.
void encode_header(std::vector<uint8_t>& out, const Properties& properties,
                   uint16_t version = kUntimedVersion, uint16_t flags = 0);
void encode_command(std::vector<uint8_t>& out, const Command& c);
void encode_index(std::vector<uint8_t>& out, const FrameIndex& index, const Footer& footer);
// A SEND_TIME or HOST_END record (version 2).
void encode_time(std::vector<uint8_t>& out, uint8_t opcode, int64_t ns);
// Version 4: fills in the BATCH record at `record` (kBatchRecordSize bytes, followed by the
// batch's b.length bytes of records) from b's batch, first_command, commands and length, and
// its checksum over them; returns the checksum. A writer appends kBatchRecordSize bytes of
// any value where a batch starts, and seals them when the batch ends.
uint64_t seal_batch(uint8_t* record, const BatchRecord& b);

// --- decoders ------------------------------------------------------------------------
// Decodes a fixed-size command record's payload (not MARKER or FACE); p points after the
// opcode and holds payload_size(opcode) bytes.
Command decode_fixed_payload(Opcode op, const uint8_t* p);
// Stores the fields at p, in the row's order, into c one by one (the reader's fast path
// relies on that: detail::held).
inline int32_t get_field(const uint8_t* p, int32_t*) {
    return get_i32(p);
}
inline uint32_t get_field(const uint8_t* p, uint32_t*) {
    return get_u32(p);
}
inline Rgb get_field(const uint8_t* p, Rgb*) {
    return Rgb{p[0], p[1], p[2]};
}
template <class C>
inline void decode_fields(const uint8_t* p, C& c) {
    for_each_field(c, [&](auto& value, const auto&) {
        using T = std::remove_cvref_t<decltype(value)>;
        value = get_field(p, static_cast<T*>(nullptr));
        p += kWireSize<T>;
    });
}
// A FACE's fixed part (p after the opcode, kFaceFixedSize bytes) with its point count as
// the size of points (unfilled); then each point, p at its 8 bytes.
Face decode_face_fixed(const uint8_t* p);
inline SnappedPoint decode_face_point(const uint8_t* p) {
    return SnappedPoint{get_i32(p), get_i32(p + 4)};
}

namespace detail {

// The T that out holds, made one if it holds another alternative: in the common case (runs
// of one opcode) a record's fields are then stored one by one into the command in place.
// Stored as a whole struct, the compiler may write it with overlapping 8-byte moves, which
// the controller's 4-byte loads of the same fields cannot take from the store buffer.
template <class T>
T& held(Command& out) {
    if (T* t = std::get_if<T>(&out)) return *t;
    return out.emplace<T>();
}

template <class T>
void store_fields(const T& from, T& to) {
    std::apply([&](const auto&... f) { ((to.*f.member = from.*f.member), ...); },
               CommandInfo<T>::fields);
}
// A span's record at p decoded into out, or 0 for one check_command refuses (x1 < x0).
template <class T>
std::size_t decode_span(const uint8_t* p, Command& out) {
    T s;
    decode_fields(p + 1, s);
    if (s.x1 < s.x0) return 0;
    store_fields(s, held<T>(out));
    return 1 + fixed_payload_size<T>();
}

}  // namespace detail

// The StreamReader's fast path: decodes the FILL_RECT, DRAW_SPAN, FRAME_END or (with `depth`,
// a version-3 stream) DEPTH_SPAN record at p (which must hold kDepthSpanRecordSize bytes,
// whatever the opcode) into out and returns its size in bytes. Returns 0, leaving out as it
// was, for any other opcode and for a span that check_command refuses (x1 < x0): those take
// the general path.
inline std::size_t decode_common_record(const uint8_t* p, Command& out, bool depth) {
    switch (p[0]) {
        case static_cast<uint8_t>(Opcode::DrawSpan):
            return detail::decode_span<DrawSpan>(p, out);
        case static_cast<uint8_t>(Opcode::FillRect): {
            FillRect f;
            decode_fields(p + 1, f);
            detail::store_fields(f, detail::held<FillRect>(out));
            return kFillRectRecordSize;
        }
        case static_cast<uint8_t>(Opcode::FrameEnd):
            detail::held<FrameEnd>(out);
            return 1;
        case static_cast<uint8_t>(Opcode::DepthSpan):
            return depth ? detail::decode_span<DepthSpan>(p, out) : 0;
        default:
            return 0;
    }
}

FrameIndexEntry decode_index_entry(const uint8_t* p);
// nullopt when the footer magic is absent.
std::optional<Footer> decode_footer(const uint8_t* p);
// The fields of the BATCH record at p (its opcode byte, which is not checked).
BatchRecord decode_batch(const uint8_t* p);
// What the checksum of the BATCH record at `record`, followed by `length` bytes, must be.
uint64_t batch_checksum(const uint8_t* record, std::size_t length);

// --- validation ----------------------------------------------------------------------
// (a command's own check: check_command, protocol/command.h)
std::optional<std::string> check_properties(const Properties& properties);
// Whether entries are in stream order and point inside [first_record, index_offset) at
// command numbers below command_count.
std::optional<std::string> check_index(const FrameIndex& index, uint64_t first_record,
                                       const Footer& footer);

}  // namespace fb89::protocol
