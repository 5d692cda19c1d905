// The controller's framebuffer: RGB888 pixels, row-major, row 0 at the top, no padding.
//
// Colours travel as RGB888 and are stored as RGB888, whatever bpp the cost profile models
// (see the "not modelled" list in controller.cpp). Drawing calls take rectangles already
// clipped to the framebuffer (clip_fill_rect / clip_span); nothing here writes outside it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "controller_sim/pixel_fill.h"
#include "protocol/command.h"

namespace fb89::controller {

inline constexpr uint32_t kDefaultWidth = 1024;
inline constexpr uint32_t kDefaultHeight = 780;
// The largest width or height FRAME_BEGIN may set; larger frames are refused, never allocated.
inline constexpr uint32_t kMaxFrameSide = 16384;

// A non-empty rectangle of pixels inside a framebuffer.
struct PixelRect {
    uint32_t x = 0, y = 0, w = 0, h = 0;
    uint64_t pixels() const { return uint64_t{w} * h; }
    friend bool operator==(const PixelRect&, const PixelRect&) = default;
};

// The part of a command inside a width x height framebuffer; `clipped` tells whether
// anything was cut off. No value when nothing is left (wholly outside, or empty).
struct Clipped {
    PixelRect rect;
    bool clipped = false;
};
inline std::optional<Clipped> clip_fill_rect(const protocol::FillRect& c, uint32_t width,
                                             uint32_t height);
// A span is a one-row rectangle; x1 < x0 is empty.
inline std::optional<Clipped> clip_span(const protocol::DrawSpan& c, uint32_t width,
                                        uint32_t height);

class Framebuffer {
  public:
    Framebuffer() : Framebuffer(kDefaultWidth, kDefaultHeight) {}
    // Throws std::invalid_argument when a side exceeds kMaxFrameSide. Pixels start black.
    Framebuffer(uint32_t width, uint32_t height);

    // Sets the size (contents unspecified until clear). Same limits as the constructor.
    void resize(uint32_t width, uint32_t height);

    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }
    bool contains(int64_t x, int64_t y) const {
        return x >= 0 && y >= 0 && x < int64_t{m_width} && y < int64_t{m_height};
    }

    void clear(protocol::Rgb c);
    // `r` must lie inside the framebuffer (as clip_fill_rect returns it).
    void fill_rect(const PixelRect& r, protocol::Rgb c);
    // Pixels x .. x+n-1 of row y, which must lie inside the framebuffer.
    void draw_span(uint32_t y, uint32_t x, uint32_t n, protocol::Rgb c) {
        fill_run(m_pixels.data() + row_offset(y) + std::size_t{x} * 3, n, rgb_pattern(c));
    }

    // Pixels x + i of row y for each i < n whose flags[i] is 1 (every flag 0 or 1), the
    // runs of them each filled at once; the n pixels must lie inside the framebuffer.
    void draw_flagged(uint32_t y, uint32_t x, uint32_t n, const uint8_t* flags, protocol::Rgb c);

    protocol::Rgb pixel(uint32_t x, uint32_t y) const;  // (x, y) must be inside
    void set_pixel(uint32_t x, uint32_t y, protocol::Rgb c);

    // All pixels, RGB888, width * 3 bytes per row.
    std::span<const uint8_t> pixels() const { return m_pixels; }
    const uint8_t* row(uint32_t y) const { return m_pixels.data() + row_offset(y); }

    // XXH64 (seed 0, xxhash64.h) of width and height (each 4 bytes, little-endian) and then
    // the pixels.
    uint64_t checksum() const;

  private:
    std::size_t row_offset(uint32_t y) const { return std::size_t{y} * m_width * 3; }

    uint32_t m_width = 0;
    uint32_t m_height = 0;
    std::vector<uint8_t> m_pixels;
};

namespace detail {

// Intersects [lo, lo + len) with [0, limit); returns false when nothing is left.
inline bool clip_interval(int64_t lo, int64_t len, uint32_t limit, uint32_t& out_lo,
                          uint32_t& out_len) {
    const int64_t a = lo > 0 ? lo : 0;
    const int64_t b = lo + len < int64_t{limit} ? lo + len : int64_t{limit};
    if (b <= a) return false;
    out_lo = static_cast<uint32_t>(a);
    out_len = static_cast<uint32_t>(b - a);
    return true;
}

}  // namespace detail

inline std::optional<Clipped> clip_fill_rect(const protocol::FillRect& c, uint32_t width,
                                             uint32_t height) {
    Clipped out;
    if (!detail::clip_interval(c.x, c.w, width, out.rect.x, out.rect.w)) return std::nullopt;
    if (!detail::clip_interval(c.y, c.h, height, out.rect.y, out.rect.h)) return std::nullopt;
    out.clipped = out.rect.w != c.w || out.rect.h != c.h;
    return out;
}

inline std::optional<Clipped> clip_span(const protocol::DrawSpan& c, uint32_t width,
                                        uint32_t height) {
    if (c.x1 < c.x0) return std::nullopt;
    const int64_t n = int64_t{c.x1} - c.x0 + 1;
    Clipped out;
    if (!detail::clip_interval(c.x0, n, width, out.rect.x, out.rect.w)) return std::nullopt;
    if (!detail::clip_interval(c.y, 1, height, out.rect.y, out.rect.h)) return std::nullopt;
    out.clipped = out.rect.w != n;
    return out;
}

// Fills n RGB888 pixels starting at p (fill_run with the colour's pattern).
void fill_pixels(uint8_t* p, std::size_t n, protocol::Rgb c);

}  // namespace fb89::controller
