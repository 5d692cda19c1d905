// Wire encoding of the fb89 command stream, versions 1 to 4: byte-exact little-endian helpers,
// record encoders and decoders, and the field checks shared by the writer and the reader.
// The layout implemented here is the one docs/PROTOCOL.md specifies, field for field.
#include "protocol/stream_format.h"

#include <fmt/format.h>

#include <algorithm>

#include "protocol/xxhash64.h"

namespace fb89::protocol {

std::optional<std::size_t> payload_size(uint8_t opcode) {
    const int i = opcode_index(static_cast<Opcode>(opcode));
    if (i < 0) return std::nullopt;
    return kPayloadSizes[i];
}

// --- little-endian helpers -----------------------------------------------------------

void put_u8(std::vector<uint8_t>& out, uint8_t v) {
    out.push_back(v);
}

void put_u16(std::vector<uint8_t>& out, uint16_t v) {
    out.push_back(static_cast<uint8_t>(v));
    out.push_back(static_cast<uint8_t>(v >> 8));
}

void put_u32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

void put_u64(std::vector<uint8_t>& out, uint64_t v) {
    for (int i = 0; i < 8; ++i)
        out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

void put_i32(std::vector<uint8_t>& out, int32_t v) {
    put_u32(out, static_cast<uint32_t>(v));
}

void put_i64(std::vector<uint8_t>& out, int64_t v) {
    put_u64(out, static_cast<uint64_t>(v));
}

const char* time_record_name(uint8_t opcode) {
    return opcode == kSendTimeOpcode ? "SEND_TIME" : "HOST_END";
}

std::optional<std::string> FrameTimes::check(int64_t ns) const {
    if (!in_frame) return "outside a frame";
    if (ns < 0) return fmt::format("{} ns is before the frame's set-up", ns);
    if (ns < send_ns)
        return fmt::format("{} ns goes back from the frame's send time {} ns", ns, send_ns);
    if (host_end_ns) return fmt::format("after the frame's HOST_END ({} ns)", *host_end_ns);
    return std::nullopt;
}

// --- encoders ------------------------------------------------------------------------

namespace {

void put_field(std::vector<uint8_t>& out, int32_t v) {
    put_i32(out, v);
}
void put_field(std::vector<uint8_t>& out, uint32_t v) {
    put_u32(out, v);
}
void put_field(std::vector<uint8_t>& out, Rgb c) {
    out.push_back(c.r);
    out.push_back(c.g);
    out.push_back(c.b);
}

// The tail's count, the fields in the row's order, the tail.
struct EncodePayload {
    std::vector<uint8_t>& out;
    template <class C>
    void operator()(const C& c) const {
        if constexpr (CommandInfo<C>::tail == Tail::Text)
            put_u16(out, static_cast<uint16_t>(c.text.size()));
        else if constexpr (CommandInfo<C>::tail == Tail::Points)
            put_u8(out, static_cast<uint8_t>(c.points.size()));
        for_each_field(c, [&](const auto& value, const auto&) { put_field(out, value); });
        if constexpr (CommandInfo<C>::tail == Tail::Text) {
            out.insert(out.end(), c.text.begin(), c.text.end());
        } else if constexpr (CommandInfo<C>::tail == Tail::Points) {
            for (const SnappedPoint& p : c.points) {
                put_i32(out, static_cast<int32_t>(p.x));
                put_i32(out, static_cast<int32_t>(p.y));
            }
        }
    }
};

}  // namespace

void encode_header(std::vector<uint8_t>& out, const Properties& properties, uint16_t version,
                   uint16_t flags) {
    if (auto problem = check_properties(properties)) throw std::invalid_argument(*problem);
    if (version < kUntimedVersion || version > kChecksumVersion)
        throw std::invalid_argument(fmt::format("no stream format version {}", version));
    if (flags != 0 && (version < kDepthVersion || flags != kFlagTimed))
        throw std::invalid_argument(
            fmt::format("format version {} has no header flags {:#06x}", version, flags));
    const std::size_t start = out.size();
    out.insert(out.end(), kMagic.begin(), kMagic.end());
    put_u16(out, version);
    put_u16(out, flags);  // zero in versions 1 and 2; kFlagTimed or not in versions 3 and 4
    put_u32(out, static_cast<uint32_t>(properties.size()));
    for (const auto& [key, value] : properties) {  // std::map: ascending key order
        put_u16(out, static_cast<uint16_t>(key.size()));
        out.insert(out.end(), key.begin(), key.end());
        put_u32(out, static_cast<uint32_t>(value.size()));
        out.insert(out.end(), value.begin(), value.end());
    }
    if (version >= kChecksumVersion) put_u64(out, xxh64(out.data() + start, out.size() - start));
}

void encode_command(std::vector<uint8_t>& out, const Command& c) {
    if (auto problem = check_command(c)) {
        throw std::invalid_argument(
            fmt::format("cannot encode {}: {}", to_string(opcode_of(c)), *problem));
    }
    put_u8(out, static_cast<uint8_t>(opcode_of(c)));
    std::visit(EncodePayload{out}, c);
}

void encode_index(std::vector<uint8_t>& out, const FrameIndex& index, const Footer& footer) {
    put_u8(out, kIndexOpcode);
    put_u32(out, static_cast<uint32_t>(index.size()));
    for (const FrameIndexEntry& e : index) {
        put_u32(out, e.frame);
        put_u64(out, e.command);
        put_u64(out, e.offset);
    }
    put_u64(out, footer.index_offset);
    put_u64(out, footer.command_count);
    out.insert(out.end(), kFooterMagic.begin(), kFooterMagic.end());
}

void encode_time(std::vector<uint8_t>& out, uint8_t opcode, int64_t ns) {
    put_u8(out, opcode);
    put_i64(out, ns);
}

namespace {

// Stores v little-endian at p (the BATCH record is filled in place, after its batch).
void store_le(uint8_t* p, uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i)
        p[i] = static_cast<uint8_t>(v >> (8 * i));
}

}  // namespace

uint64_t seal_batch(uint8_t* record, const BatchRecord& b) {
    record[0] = kBatchOpcode;
    store_le(record + 9, b.batch, 4);
    store_le(record + 13, b.first_command, 8);
    store_le(record + 21, b.commands, 2);
    store_le(record + 23, b.length, 4);
    const uint64_t checksum = batch_checksum(record, b.length);
    store_le(record + 1, checksum, 8);
    return checksum;
}

// --- decoders ------------------------------------------------------------------------

Command decode_fixed_payload(Opcode op, const uint8_t* p) {
    const int i = opcode_index(op);
    if (i < 0 || kCommandRows[i].tail != Tail::None)
        throw std::logic_error(fmt::format("decode_fixed_payload: opcode {} has no fixed payload",
                                           static_cast<int>(op)));
    Command out;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((I == static_cast<std::size_t>(i)
              ? decode_fields(p, out.emplace<std::variant_alternative_t<I, Command>>())
              : void()),
         ...);
    }
    (std::make_index_sequence<kOpcodeCount>{});
    return out;
}

Face decode_face_fixed(const uint8_t* p) {
    Face f;
    f.points.resize(p[0]);
    decode_fields(p + 1, f);
    return f;
}

FrameIndexEntry decode_index_entry(const uint8_t* p) {
    return FrameIndexEntry{get_u32(p), get_u64(p + 4), get_u64(p + 12)};
}

std::optional<Footer> decode_footer(const uint8_t* p) {
    if (!std::equal(kFooterMagic.begin(), kFooterMagic.end(), p + 16)) return std::nullopt;
    return Footer{get_u64(p), get_u64(p + 8)};
}

BatchRecord decode_batch(const uint8_t* p) {
    return BatchRecord{get_u64(p + 1), get_u32(p + 9), get_u64(p + 13), get_u16(p + 21),
                       get_u32(p + 23)};
}

uint64_t batch_checksum(const uint8_t* record, std::size_t length) {
    return xxh64(record + kBatchHashedFrom, kBatchRecordSize - kBatchHashedFrom + length);
}

// --- validation ----------------------------------------------------------------------

std::optional<std::string> check_properties(const Properties& properties) {
    if (properties.size() > kMaxPropertyCount) {
        return fmt::format("{} properties, more than {}", properties.size(), kMaxPropertyCount);
    }
    for (const auto& [key, value] : properties) {
        if (key.empty() || key.size() > kMaxPropertyKeyLength) {
            return fmt::format("property key \"{}\" of {} bytes is outside 1..{}", key, key.size(),
                               kMaxPropertyKeyLength);
        }
        if (value.size() > kMaxPropertyValueLength) {
            return fmt::format("property \"{}\" has a value of {} bytes, more than {}", key,
                               value.size(), kMaxPropertyValueLength);
        }
    }
    return std::nullopt;
}

std::optional<std::string> check_index(const FrameIndex& index, uint64_t first_record,
                                       const Footer& footer) {
    for (std::size_t i = 0; i < index.size(); ++i) {
        const FrameIndexEntry& e = index[i];
        if (e.offset < first_record || e.offset >= footer.index_offset) {
            return fmt::format("entry {} points at byte {}, outside the commands {}..{}", i,
                               e.offset, first_record, footer.index_offset);
        }
        if (e.command >= footer.command_count) {
            return fmt::format("entry {} names command {} of {}", i, e.command,
                               footer.command_count);
        }
        if (i > 0 && (e.offset <= index[i - 1].offset || e.command <= index[i - 1].command)) {
            return fmt::format("entry {} is not after entry {}", i, i - 1);
        }
    }
    return std::nullopt;
}

}  // namespace fb89::protocol
