// The controller's framebuffer (the clipping every drawing command goes through is inline
// in framebuffer.h, on the controller's per-command path).
//
// Hot path: every row is written by fill_run (pixel_fill.h) from the colour's pattern, made
// once per command; clear fills the whole framebuffer as one run, as its rows touch.
#include "controller_sim/framebuffer.h"

#include <bit>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "controller_sim/xxhash64.h"

namespace fb89::controller {

namespace {

void check_size(uint32_t width, uint32_t height) {
    if (width > kMaxFrameSide || height > kMaxFrameSide)
        throw std::invalid_argument(fmt::format("framebuffer {}x{} exceeds the maximum {}x{}",
                                                width, height, kMaxFrameSide, kMaxFrameSide));
}

}  // namespace

void fill_pixels(uint8_t* p, std::size_t n, protocol::Rgb c) {
    fill_run(p, n, rgb_pattern(c));
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
    // rows are contiguous: one run over the whole framebuffer
    fill_run(m_pixels.data(), std::size_t{m_width} * m_height, rgb_pattern(c));
}

namespace {

// The first i in [from, n) whose flag is not `flag` (0 or 1), or n: eight flags a load.
uint32_t next_change(const uint8_t* flags, uint32_t from, uint32_t n, uint8_t flag) {
    const uint64_t same = flag ? 0x0101010101010101ULL : 0;
    uint32_t i = from;
    for (; i + 8 <= n; i += 8) {
        uint64_t v;
        std::memcpy(&v, flags + i, 8);
        if (const uint64_t d = v ^ same; d != 0) {
            const int byte = std::endian::native == std::endian::little ? std::countr_zero(d) / 8
                                                                        : std::countl_zero(d) / 8;
            return i + static_cast<uint32_t>(byte);
        }
    }
    while (i < n && flags[i] == flag)
        ++i;
    return i;
}

}  // namespace

void Framebuffer::draw_flagged(uint32_t y, uint32_t x, uint32_t n, const uint8_t* flags,
                               protocol::Rgb c) {
    uint8_t* const row = m_pixels.data() + row_offset(y) + std::size_t{x} * 3;
    const RgbPattern pattern = rgb_pattern(c);
    for (uint32_t i = next_change(flags, 0, n, 0); i < n;) {
        const uint32_t end = next_change(flags, i, n, 1);
        fill_run(row + std::size_t{i} * 3, end - i, pattern);
        i = next_change(flags, end, n, 0);
    }
}

void Framebuffer::fill_rect(const PixelRect& r, protocol::Rgb c) {
    const RgbPattern pattern = rgb_pattern(c);
    const std::size_t stride = std::size_t{m_width} * 3;
    uint8_t* p = m_pixels.data() + row_offset(r.y) + std::size_t{r.x} * 3;
    for (uint32_t i = 0; i < r.h; ++i, p += stride)
        fill_run(p, r.w, pattern);
}

protocol::Rgb Framebuffer::pixel(uint32_t x, uint32_t y) const {
    const uint8_t* p = row(y) + std::size_t{x} * 3;
    return protocol::Rgb{p[0], p[1], p[2]};
}

void Framebuffer::set_pixel(uint32_t x, uint32_t y, protocol::Rgb c) {
    draw_span(y, x, 1, c);
}

uint64_t Framebuffer::checksum() const {
    uint8_t size[8];
    for (int i = 0; i < 4; ++i) {
        size[i] = static_cast<uint8_t>(m_width >> (8 * i));
        size[4 + i] = static_cast<uint8_t>(m_height >> (8 * i));
    }
    Xxh64 h;
    h.update(size, sizeof size);
    h.update(m_pixels.data(), m_pixels.size());
    return h.digest();
}

}  // namespace fb89::controller
