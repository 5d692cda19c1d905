// Tests of controller_sim/xxhash64: XXH64 against values computed independently (the
// published test vectors, and the system's libxxhash for the rest), and piecewise input
// against one-shot input at every split.
#include "controller_sim/xxhash64.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace fb89::controller {
namespace {

uint64_t xxh64_of(std::string_view text, uint64_t seed = 0) {
    return xxh64(reinterpret_cast<const uint8_t*>(text.data()), text.size(), seed);
}

TEST(Xxh64, MatchesThePublishedValues) {
    EXPECT_EQ(xxh64_of(""), 0xef46db3751d8e999ULL);
    EXPECT_EQ(xxh64_of("a"), 0xd24ec4f1a98c6e5bULL);
    EXPECT_EQ(xxh64_of("abc"), 0x44bc2cf5ad770999ULL);
    EXPECT_EQ(xxh64_of("Nobody inspects the spammish repetition"), 0xfbcea83c8a378bf1ULL);
}

TEST(Xxh64, MatchesLibxxhashWithASeedOverManyStripes) {
    // XXH64(0, 1, ..., 255 four times, seed 2654435761), from libxxhash 0.8.1
    std::vector<uint8_t> bytes;
    for (int i = 0; i < 1024; ++i)
        bytes.push_back(static_cast<uint8_t>(i));
    EXPECT_EQ(xxh64(bytes.data(), bytes.size(), 2654435761ULL), 0xb05af54d5f68bff7ULL);
}

TEST(Xxh64, PiecewiseInputGivesTheOneShotDigestAtEverySplit) {
    std::vector<uint8_t> bytes(100);
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = static_cast<uint8_t>(i * 37 + 11);
    for (std::size_t n : {0u, 1u, 7u, 31u, 32u, 33u, 64u, 100u}) {
        const uint64_t whole = xxh64(bytes.data(), n);
        for (std::size_t a = 0; a <= n; ++a)
            for (std::size_t b = a; b <= n; ++b) {
                Xxh64 h;
                h.update(bytes.data(), a);
                h.update(bytes.data() + a, b - a);
                h.update(bytes.data() + b, n - b);
                ASSERT_EQ(h.digest(), whole) << "n=" << n << " split at " << a << ", " << b;
            }
    }
}

TEST(Xxh64, DigestLeavesTheStateToContinue) {
    const std::string_view text = "Nobody inspects the spammish repetition";
    Xxh64 h;
    h.update(reinterpret_cast<const uint8_t*>(text.data()), 10);
    EXPECT_EQ(h.digest(), xxh64_of(text.substr(0, 10)));
    h.update(reinterpret_cast<const uint8_t*>(text.data()) + 10, text.size() - 10);
    EXPECT_EQ(h.digest(), 0xfbcea83c8a378bf1ULL);
}

}  // namespace
}  // namespace fb89::controller
