// The controller's framebuffer and the clipping every drawing command goes through.
//
// Hot path: fill_pixels writes one row with plain stores for short runs and with doubling
// memcpy for long ones; fill_rect and clear fill one row and copy it to the others.
#include "controller_sim/framebuffer.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

namespace fb89::controller {

namespace {

// Intersects [lo, lo + len) with [0, limit); returns false when nothing is left.
bool clip_interval(int64_t lo, int64_t len, uint32_t limit, uint32_t& out_lo, uint32_t& out_len) {
    const int64_t a = std::max<int64_t>(lo, 0);
    const int64_t b = std::min<int64_t>(lo + len, limit);
    if (b <= a) return false;
    out_lo = static_cast<uint32_t>(a);
    out_len = static_cast<uint32_t>(b - a);
    return true;
}

void check_size(uint32_t width, uint32_t height) {
    if (width > kMaxFrameSide || height > kMaxFrameSide)
        throw std::invalid_argument(fmt::format("framebuffer {}x{} exceeds the maximum {}x{}",
                                                width, height, kMaxFrameSide, kMaxFrameSide));
}

}  // namespace

std::optional<Clipped> clip_fill_rect(const protocol::FillRect& c, uint32_t width,
                                      uint32_t height) {
    Clipped out;
    if (!clip_interval(c.x, c.w, width, out.rect.x, out.rect.w)) return std::nullopt;
    if (!clip_interval(c.y, c.h, height, out.rect.y, out.rect.h)) return std::nullopt;
    out.clipped = out.rect.w != c.w || out.rect.h != c.h;
    return out;
}

std::optional<Clipped> clip_span(const protocol::DrawSpan& c, uint32_t width, uint32_t height) {
    if (c.x1 < c.x0) return std::nullopt;
    const int64_t n = int64_t{c.x1} - c.x0 + 1;
    Clipped out;
    if (!clip_interval(c.x0, n, width, out.rect.x, out.rect.w)) return std::nullopt;
    if (!clip_interval(c.y, 1, height, out.rect.y, out.rect.h)) return std::nullopt;
    out.clipped = out.rect.w != n;
    return out;
}

void fill_pixels(uint8_t* p, std::size_t n, protocol::Rgb c) {
    // short runs: plain stores
    const std::size_t head = std::min<std::size_t>(n, 16);
    for (std::size_t i = 0; i < head; ++i) {
        p[3 * i] = c.r;
        p[3 * i + 1] = c.g;
        p[3 * i + 2] = c.b;
    }
    // long runs: copy what is written so far onto the rest, doubling each time
    std::size_t done = head * 3;
    const std::size_t total = n * 3;
    while (done < total) {
        const std::size_t chunk = std::min(done, total - done);
        std::memcpy(p + done, p, chunk);
        done += chunk;
    }
}

Framebuffer::Framebuffer(uint32_t width, uint32_t height) {
    resize(width, height);
    clear(protocol::Rgb{});
}

void Framebuffer::resize(uint32_t width, uint32_t height) {
    check_size(width, height);
    m_width = width;
    m_height = height;
    m_pixels.resize(std::size_t{width} * height * 3);
}

void Framebuffer::clear(protocol::Rgb c) {
    if (m_width == 0 || m_height == 0) return;
    fill_rect(PixelRect{0, 0, m_width, m_height}, c);
}

void Framebuffer::fill_rect(const PixelRect& r, protocol::Rgb c) {
    // first row, then copies of it
    uint8_t* first = m_pixels.data() + row_offset(r.y) + std::size_t{r.x} * 3;
    fill_pixels(first, r.w, c);
    const std::size_t row_bytes = std::size_t{r.w} * 3;
    const std::size_t stride = std::size_t{m_width} * 3;
    uint8_t* p = first;
    for (uint32_t i = 1; i < r.h; ++i) {
        p += stride;
        std::memcpy(p, first, row_bytes);
    }
}

void Framebuffer::draw_span(uint32_t y, uint32_t x, uint32_t n, protocol::Rgb c) {
    fill_pixels(m_pixels.data() + row_offset(y) + std::size_t{x} * 3, n, c);
}

protocol::Rgb Framebuffer::pixel(uint32_t x, uint32_t y) const {
    const uint8_t* p = row(y) + std::size_t{x} * 3;
    return protocol::Rgb{p[0], p[1], p[2]};
}

void Framebuffer::set_pixel(uint32_t x, uint32_t y, protocol::Rgb c) {
    draw_span(y, x, 1, c);
}

uint64_t Framebuffer::checksum() const {
    constexpr uint64_t kOffsetBasis = 0xcbf29ce484222325ULL;
    constexpr uint64_t kPrime = 0x100000001b3ULL;
    uint64_t h = kOffsetBasis;
    auto mix = [&h](uint8_t byte) {
        h ^= byte;
        h *= kPrime;
    };
    for (uint32_t v : {m_width, m_height})
        for (int i = 0; i < 4; ++i)
            mix(static_cast<uint8_t>(v >> (8 * i)));
    for (uint8_t byte : m_pixels)
        mix(byte);
    return h;
}

}  // namespace fb89::controller
