// Filling runs of RGB888 pixels with whole-word stores: the inner loop of every fill, clear
// and span of the controller's framebuffer.
//
// A run of n pixels is 3n bytes of the colour's 3-byte period, which 64-bit words repeat
// every 24 bytes: the words at bytes 0, 8 and 16 of a run start at phases 0, 2 and 1 of
// the period, and an 8- or 16-byte store at byte offset o of the run takes the word(s) of
// phase o mod 3. As 3n is a multiple of 3, a store that ends exactly at the run's end
// starts at a fixed phase (8 bytes before the end: phase 1; 16: phase 2; 48: phase 0), so
// short runs take two or three overlapping stores and long ones 48-byte blocks plus one
// block flush with the end. Stores overlap one another, never the bytes outside the run:
// the same bytes as a byte-by-byte loop, in a handful of stores instead of 3n.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "protocol/command.h"

namespace fb89::controller {

// 16 bytes, stored with one unaligned vector move where SSE2 has one (a memcpy of 16 bytes
// would be compiled as two 8-byte moves; an under-aligned vector type is not honoured by
// every compiler: clang's UBSan found the store misaligned).
using Bytes16 = uint64_t __attribute__((vector_size(16)));
inline void store16(uint8_t* at, Bytes16 v) {
#if defined(__SSE2__)
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at), reinterpret_cast<__m128i>(v));
#else
    std::memcpy(at, &v, 16);
#endif
}

// The first 48 bytes of a run of the colour (16 pixels), as three 16-byte blocks of two
// 64-bit words each, holding the bytes in memory order. Every store below copies from
// these: block 0 starts at phase 0, block 1 at phase 1, block 2 at phase 2, and the words
// are phase 0 (block[0][0]), 2 (block[0][1]) and 1 (block[1][0]).
struct RgbPattern {
    Bytes16 block[3];
    uint8_t r, g, b;  // for runs of fewer than 3 pixels
};

inline RgbPattern rgb_pattern(protocol::Rgb c) {
    // v * (1 + 2^24 + 2^48) lays 24-bit v at bytes 0, 3 and 6 (the third copy cut at 64 bits)
    constexpr uint64_t kSpread = 0x0001000001000001ULL;
    const auto word = [](uint8_t a, uint8_t b, uint8_t d) {
        uint64_t w = (uint64_t{a} | uint64_t{b} << 8 | uint64_t{d} << 16) * kSpread;
        if constexpr (std::endian::native == std::endian::big) w = __builtin_bswap64(w);
        return w;
    };
    const uint64_t phase0 = word(c.r, c.g, c.b);  // r g b r g b r g
    const uint64_t phase2 = word(c.b, c.r, c.g);  // b r g b r g b r
    const uint64_t phase1 = word(c.g, c.b, c.r);  // g b r g b r g b
    return RgbPattern{{{phase0, phase2}, {phase1, phase0}, {phase2, phase1}}, c.r, c.g, c.b};
}

// Writes n pixels of the pattern's colour at p (3n bytes); n may be 0.
inline void fill_run(uint8_t* p, std::size_t n, const RgbPattern& c) {
    const std::size_t bytes = 3 * n;
    const auto store8 = [](uint8_t* at, uint64_t v) { std::memcpy(at, &v, 8); };
    // fewer than 3 pixels: byte stores
    if (n < 3) {
        for (std::size_t i = 0; i < n; ++i, p += 3) {
            p[0] = c.r;
            p[1] = c.g;
            p[2] = c.b;
        }
        return;
    }
    // 9 to 45 bytes: two 8-byte stores or two to three 16-byte ones, the last flush with the end
    if (bytes < 16) {
        store8(p, c.block[0][0]);
        store8(p + bytes - 8, c.block[1][0]);
        return;
    }
    if (bytes < 48) {
        store16(p, c.block[0]);
        if (bytes > 32) store16(p + 16, c.block[1]);
        store16(p + bytes - 16, c.block[2]);
        return;
    }
    // 48 bytes and more: 48-byte blocks, then one block flush with the end
    const Bytes16 b0 = c.block[0], b1 = c.block[1], b2 = c.block[2];
    std::size_t o = 0;
    for (; o + 48 <= bytes; o += 48) {
        store16(p + o, b0);
        store16(p + o + 16, b1);
        store16(p + o + 32, b2);
    }
    if (o < bytes) {
        uint8_t* last = p + bytes - 48;
        store16(last, b0);
        store16(last + 16, b1);
        store16(last + 32, b2);
    }
}

}  // namespace fb89::controller
