// XXH64, step by step as in its specification (see xxhash64.h): stripe accumulation,
// convergence of the four accumulators, the tail, the avalanche.
#include "protocol/xxhash64.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace fb89::protocol {

namespace {

constexpr uint64_t kPrime1 = 0x9E3779B185EBCA87ULL;
constexpr uint64_t kPrime2 = 0xC2B2AE3D27D4EB4FULL;
constexpr uint64_t kPrime3 = 0x165667B19E3779F9ULL;
constexpr uint64_t kPrime4 = 0x85EBCA77C2B2AE63ULL;
constexpr uint64_t kPrime5 = 0x27D4EB2F165667C5ULL;
constexpr std::size_t kStripe = 32;

uint64_t read_u64(const uint8_t* p) {
    uint64_t v;
    std::memcpy(&v, p, sizeof v);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap64(v);
    return v;
}

uint32_t read_u32(const uint8_t* p) {
    uint32_t v;
    std::memcpy(&v, p, sizeof v);
    if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
    return v;
}

uint64_t round(uint64_t acc, uint64_t lane) {
    acc += lane * kPrime2;
    acc = std::rotl(acc, 31);
    return acc * kPrime1;
}

uint64_t merge(uint64_t acc, uint64_t lane_acc) {
    acc ^= round(0, lane_acc);
    return acc * kPrime1 + kPrime4;
}

}  // namespace

Xxh64::Xxh64(uint64_t seed)
    : m_seed(seed), m_acc{seed + kPrime1 + kPrime2, seed + kPrime2, seed, seed - kPrime1} {}

void Xxh64::consume_stripes(const uint8_t* p, std::size_t stripes) {
    // stripe accumulation: lane i of each stripe goes to accumulator i
    uint64_t a0 = m_acc[0], a1 = m_acc[1], a2 = m_acc[2], a3 = m_acc[3];
    for (std::size_t s = 0; s < stripes; ++s, p += kStripe) {
        a0 = round(a0, read_u64(p));
        a1 = round(a1, read_u64(p + 8));
        a2 = round(a2, read_u64(p + 16));
        a3 = round(a3, read_u64(p + 24));
    }
    m_acc = {a0, a1, a2, a3};
}

void Xxh64::update(const uint8_t* p, std::size_t n) {
    m_total += n;
    // complete a pending stripe first
    if (m_pending_size > 0) {
        const std::size_t take = std::min(n, kStripe - m_pending_size);
        std::memcpy(m_pending.data() + m_pending_size, p, take);
        m_pending_size += take;
        p += take;
        n -= take;
        if (m_pending_size < kStripe) return;
        consume_stripes(m_pending.data(), 1);
        m_pending_size = 0;
    }
    consume_stripes(p, n / kStripe);
    const std::size_t rest = n % kStripe;
    std::memcpy(m_pending.data(), p + (n - rest), rest);
    m_pending_size = rest;
}

uint64_t Xxh64::digest() const {
    // convergence of the accumulators (inputs of 32 bytes or more)
    uint64_t acc;
    if (m_total >= kStripe) {
        acc = std::rotl(m_acc[0], 1) + std::rotl(m_acc[1], 7) + std::rotl(m_acc[2], 12) +
              std::rotl(m_acc[3], 18);
        for (uint64_t a : m_acc)
            acc = merge(acc, a);
    } else {
        acc = m_seed + kPrime5;
    }
    acc += m_total;

    // the last 0-31 bytes: 8-byte lanes, one 4-byte lane, single bytes
    const uint8_t* p = m_pending.data();
    std::size_t left = m_pending_size;
    for (; left >= 8; left -= 8, p += 8)
        acc = std::rotl(acc ^ round(0, read_u64(p)), 27) * kPrime1 + kPrime4;
    if (left >= 4) {
        acc = std::rotl(acc ^ (uint64_t{read_u32(p)} * kPrime1), 23) * kPrime2 + kPrime3;
        left -= 4;
        p += 4;
    }
    for (; left > 0; --left, ++p)
        acc = std::rotl(acc ^ (uint64_t{*p} * kPrime5), 11) * kPrime1;

    // avalanche
    acc ^= acc >> 33;
    acc *= kPrime2;
    acc ^= acc >> 29;
    acc *= kPrime3;
    acc ^= acc >> 32;
    return acc;
}

uint64_t xxh64(const uint8_t* p, std::size_t n, uint64_t seed) {
    Xxh64 h(seed);
    h.update(p, n);
    return h.digest();
}

}  // namespace fb89::protocol
