// The Z-buffer's depth-test kernels: the vector kernels against the scalar one on every
// run length and offset, the plane exactly as depth_at() gives it, ties kept, and entries
// outside the run left alone.
#include "host/raster/depth_rows.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "host/raster/depth.h"

namespace fb89::host {
namespace {

constexpr int kRowWidth = 40;

// One row of buffers, padded as the Z-buffer pads its band.
struct Row {
    std::vector<double> depth = std::vector<double>(kRowWidth + kDepthRowPad);
    std::vector<uint32_t> face = std::vector<uint32_t>(kRowWidth + kDepthRowPad);
    bool operator==(const Row& o) const {
        // bitwise, so that -0.0 and 0.0 or NaNs would not hide a difference
        return face == o.face &&
               std::memcmp(depth.data(), o.depth.data(), depth.size() * sizeof(double)) == 0;
    }
};

// A row half empty, half holding faces at depths in [0, 1).
Row random_depth_row(std::mt19937& rng) {
    std::uniform_real_distribution<double> z(0.0, 1.0);
    Row row;
    for (size_t x = 0; x < row.depth.size(); ++x) {
        row.depth[x] = z(rng);
        row.face[x] = static_cast<uint32_t>(rng() % 2 ? 0 : 1 + rng() % 50);
    }
    return row;
}

using Kernel = uint64_t (*)(const DepthPlane&, int, int, int, uint32_t, double*, uint32_t*);

std::vector<Kernel> vector_kernels() {
    std::vector<Kernel> kernels;
#if defined(__SSE2__)
    kernels.push_back(&DepthRowSse2::test);
#endif
#if defined(FB89_HAS_AVX2_KERNEL)
    if (has_avx2()) kernels.push_back(&DepthRowAvx2::test);
#endif
    return kernels;
}

TEST(DepthRows, VectorKernelsMatchTheScalarKernelOnEveryRunLengthAndOffset) {
    std::mt19937 rng(1989);
    std::uniform_real_distribution<double> slope(-0.05, 0.05), offset(0.0, 1.0);
    for (Kernel kernel : vector_kernels()) {
        for (int xb = 0; xb < 9; ++xb) {
            for (int xe = xb + 1; xe <= kRowWidth; ++xe) {
                const DepthPlane plane{slope(rng), slope(rng), offset(rng)};
                const int y = static_cast<int>(rng() % 700);
                Row expected = random_depth_row(rng), got = expected;
                const uint64_t won_expected = DepthRowScalar::test(
                    plane, y, xb, xe, 77, expected.depth.data(), expected.face.data());
                const uint64_t won =
                    kernel(plane, y, xb, xe, 77, got.depth.data(), got.face.data());
                ASSERT_EQ(won, won_expected) << "run " << xb << ".." << xe;
                ASSERT_TRUE(got == expected) << "run " << xb << ".." << xe;
            }
        }
    }
}

TEST(DepthRows, EveryKernelStoresThePlaneExactlyAsDepthAtGivesIt) {
    // awkward coefficients, so that any other order of operations would round differently
    const DepthPlane plane{0.1 / 3.0, -0.7 / 9.0, 0.333333333333333};
    const int y = 517;
    std::vector<Kernel> kernels = vector_kernels();
    kernels.push_back(&DepthRowScalar::test);
    for (Kernel kernel : kernels) {
        Row row;  // all empty: every centre is won
        EXPECT_EQ(kernel(plane, y, 3, 37, 5, row.depth.data(), row.face.data()), 34u);
        for (int x = 3; x < 37; ++x) {
            EXPECT_EQ(row.face[static_cast<size_t>(x)], 5u);
            const double want = depth_at(plane, x, y);
            EXPECT_EQ(std::memcmp(&row.depth[static_cast<size_t>(x)], &want, sizeof want), 0)
                << "x " << x;
        }
        EXPECT_EQ(row.face[2], 0u);
        EXPECT_EQ(row.face[37], 0u);
    }
}

TEST(DepthRows, AnEqualDepthKeepsTheStoredFace) {
    const DepthPlane plane{0.0, 0.0, 0.25};
    std::vector<Kernel> kernels = vector_kernels();
    kernels.push_back(&DepthRowScalar::test);
    for (Kernel kernel : kernels) {
        Row row;
        for (size_t x = 0; x < row.face.size(); ++x)
            row.depth[x] = 0.25, row.face[x] = 9;
        EXPECT_EQ(kernel(plane, 0, 0, 11, 12, row.depth.data(), row.face.data()), 0u);
        for (uint32_t f : row.face)
            EXPECT_EQ(f, 9u);
    }
}

}  // namespace
}  // namespace fb89::host
