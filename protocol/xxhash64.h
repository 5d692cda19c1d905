// XXH64: Yann Collet's 64-bit xxHash: the framebuffer checksum (Framebuffer::checksum) and
// the checksums of stream format version 4 (docs/PROTOCOL.md, "Version 4: checksums").
//
// Implements the XXH64 algorithm as its specification (xxHash's doc/xxhash_spec.md,
// "XXH64 algorithm description") gives it: four accumulators, each taking every fourth
// 64-bit little-endian word of 32-byte stripes (round: acc += lane * PRIME64_2,
// rotate left 31, acc *= PRIME64_1), merged, then the last 0-31 bytes as 8-, 4- and 1-byte
// lanes and the final avalanche. Ours differs only in being fed piece by piece (update),
// so that a header and the pixels need not be contiguous; the digest equals XXH64 of the
// concatenated bytes. The four lanes run independently, which is what makes it run at
// memory speed where byte-wise FNV-1a waits on one multiply per byte.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace fb89::protocol {

class Xxh64 {
  public:
    explicit Xxh64(uint64_t seed = 0);

    // Appends n bytes to the input.
    void update(const uint8_t* p, std::size_t n);
    // XXH64 of every byte given so far; the state is unchanged, so more may follow.
    uint64_t digest() const;

  private:
    void consume_stripes(const uint8_t* p, std::size_t stripes);

    uint64_t m_seed;
    std::array<uint64_t, 4> m_acc;
    std::array<uint8_t, 32> m_pending{};  // a stripe's first bytes, until it is complete
    std::size_t m_pending_size = 0;
    uint64_t m_total = 0;  // bytes given
};

// XXH64 of n bytes at p.
uint64_t xxh64(const uint8_t* p, std::size_t n, uint64_t seed = 0);

}  // namespace fb89::protocol
