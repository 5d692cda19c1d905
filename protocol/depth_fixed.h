// Depth as the version-3 commands carry it and the controller holds it (docs/PROTOCOL.md,
// "Depth commands"): Z, unsigned 32-bit fixed point, window depth z in [0, 1] times
// kDepthOne, and slopes as Z per pixel in signed 32 bits -- what the GSP's 32-bit registers
// step along a span. kDepthOne sits just under 2^28 so that the far plane, stored in a 16-bit
// word as Z >> 12, stays below the cleared value 0xFFFF and is drawn.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

namespace fb89::protocol {

inline constexpr int kDepthFractionBits = 28;
inline constexpr uint32_t kDepthOne = (uint32_t{1} << kDepthFractionBits) - (uint32_t{1} << 13);
// The shift from Z to a 16-bit depth word.
inline constexpr int kDepth16Shift = kDepthFractionBits - 16;

// The depth buffer's word sizes.
inline constexpr bool valid_depth_bits(uint32_t bits) {
    return bits == 16 || bits == 32;
}
// The value a cleared word holds: farther than any depth.
inline constexpr uint32_t depth_clear_value(uint32_t bits) {
    return bits == 16 ? 0xFFFFu : 0xFFFFFFFFu;
}

// Z of window depth z, rounded, held to [0, kDepthOne].
inline uint32_t depth_fixed(double z) {
    const double v = std::nearbyint(z * kDepthOne);
    if (!(v > 0)) return 0;
    return v >= kDepthOne ? kDepthOne : static_cast<uint32_t>(v);
}

// A slope (window depth per pixel) as Z per pixel, rounded; nullopt where it does not fit in
// 32 signed bits (|slope| over 8 a pixel: a face almost edge-on).
inline std::optional<int32_t> slope_fixed(double dz_per_pixel) {
    const double v = std::nearbyint(dz_per_pixel * kDepthOne);
    if (!(v >= -2147483648.0 && v <= 2147483647.0)) return std::nullopt;
    return static_cast<int32_t>(v);
}

// The word a depth of Z (exact, in 64 bits) is stored as: Z held to [0, kDepthOne], then
// all 32 bits of it, or its top 16 (Z >> 12).
inline uint32_t stored_depth(int64_t z, uint32_t bits) {
    const int64_t held = z < 0 ? 0 : (z > kDepthOne ? int64_t{kDepthOne} : z);
    return bits == 16 ? static_cast<uint32_t>(held >> kDepth16Shift) : static_cast<uint32_t>(held);
}

// The smallest difference in window depth a word of `bits` tells apart.
inline constexpr double depth_step(uint32_t bits) {
    return (bits == 16 ? double(1 << kDepth16Shift) : 1.0) / kDepthOne;
}

}  // namespace fb89::protocol
