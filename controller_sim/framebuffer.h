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
std::optional<Clipped> clip_fill_rect(const protocol::FillRect& c, uint32_t width, uint32_t height);
// A span is a one-row rectangle; x1 < x0 is empty.
std::optional<Clipped> clip_span(const protocol::DrawSpan& c, uint32_t width, uint32_t height);

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
    void draw_span(uint32_t y, uint32_t x, uint32_t n, protocol::Rgb c);

    protocol::Rgb pixel(uint32_t x, uint32_t y) const;  // (x, y) must be inside
    void set_pixel(uint32_t x, uint32_t y, protocol::Rgb c);

    // All pixels, RGB888, width * 3 bytes per row.
    std::span<const uint8_t> pixels() const { return m_pixels; }
    const uint8_t* row(uint32_t y) const { return m_pixels.data() + row_offset(y); }

    // 64-bit FNV-1a over width and height (each 4 bytes, little-endian) and then the pixels.
    uint64_t checksum() const;

  private:
    std::size_t row_offset(uint32_t y) const { return std::size_t{y} * m_width * 3; }

    uint32_t m_width = 0;
    uint32_t m_height = 0;
    std::vector<uint8_t> m_pixels;
};

// Fills n RGB888 pixels starting at p: the inner loop of every fill, clear and span.
void fill_pixels(uint8_t* p, std::size_t n, protocol::Rgb c);

}  // namespace fb89::controller
