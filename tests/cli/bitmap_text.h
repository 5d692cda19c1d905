// Reads text back from a picture as a person reads it: the rows of characters drawn in fb89's
// bitmap font (controller_sim/bitmap_font.h) in one colour inside an area of an RGB image.
// For checking that a window's or a sheet's text is there whole, not where the code meant
// to put it: the reader finds the character grid itself, from the pixels alone.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "controller_sim/bitmap_font.h"
#include "controller_sim/png_io.h"
#include "protocol/command.h"

namespace fb89::testing {

struct PixelArea {
    uint32_t x = 0, y = 0, width = 0, height = 0;
};

// The rows of text in `area`, top to bottom, trailing spaces dropped and empty rows
// skipped; `scale` window pixels per font pixel. Empty when no character grid explains
// every pixel of colour `ink` in the area (text cut, overlapping, or in another font).
inline std::vector<std::string> read_bitmap_text(const controller::PngImage& img, PixelArea area,
                                                 protocol::Rgb ink, int scale) {
    using controller::kCellHeight;
    using controller::kCellWidth;
    using controller::kGlyphHeight;
    using controller::kGlyphWidth;
    std::map<uint64_t, char> glyphs;  // a glyph's rows as one number -> its character
    for (int c = 126; c >= 32; --c) {
        uint64_t key = 0;
        for (uint8_t row : controller::glyph(static_cast<char>(c)))
            key = key << 8 | row;
        glyphs[key] = static_cast<char>(c);
    }
    const auto lit = [&](uint32_t x, uint32_t y) {
        if (x < area.x || y < area.y || x >= area.x + area.width || y >= area.y + area.height ||
            x >= img.width || y >= img.height)
            return false;
        const std::size_t i = (std::size_t{y} * img.width + x) * 3;
        return img.pixels[i] == ink.r && img.pixels[i + 1] == ink.g && img.pixels[i + 2] == ink.b;
    };
    const auto s = static_cast<uint32_t>(scale);
    const uint32_t cell_w = kCellWidth * s, cell_h = kCellHeight * s;
    // every phase of the grid: the one where each cell is a glyph and nothing lies between
    for (uint32_t oy = 0; oy < cell_h; ++oy)
        for (uint32_t ox = 0; ox < cell_w; ++ox) {
            std::vector<std::string> rows;
            std::size_t explained = 0, total = 0;
            bool ok = true;
            for (uint32_t y = area.y + oy; ok && y + kGlyphHeight * s <= area.y + area.height;
                 y += cell_h) {
                std::string text;
                for (uint32_t x = area.x + ox; ok && x + kGlyphWidth * s <= area.x + area.width;
                     x += cell_w) {
                    uint64_t key = 0;
                    for (int r = 0; r < kGlyphHeight; ++r) {
                        uint8_t bits = 0;
                        for (int c = 0; c < kGlyphWidth; ++c) {
                            const bool on = lit(x + c * s, y + r * s);
                            for (uint32_t dy = 0; dy < s; ++dy)  // a font pixel is s x s
                                for (uint32_t dx = 0; dx < s; ++dx)
                                    ok = ok && lit(x + c * s + dx, y + r * s + dy) == on;
                            bits = static_cast<uint8_t>(bits << 1 | on);
                            explained += on ? s * s : 0;
                        }
                        key = key << 8 | bits;
                    }
                    const auto g = glyphs.find(key);
                    ok = ok && g != glyphs.end();
                    if (ok) text += g->second;
                }
                while (!text.empty() && text.back() == ' ')
                    text.pop_back();
                if (!text.empty()) rows.push_back(text);
            }
            if (!ok || rows.empty()) continue;
            for (uint32_t y = area.y; y < area.y + area.height; ++y)
                for (uint32_t x = area.x; x < area.x + area.width; ++x)
                    total += lit(x, y);
            if (explained == total) return rows;
        }
    return {};
}

// The rows joined into one line, without their spaces: what wrapping must keep.
inline std::string ink_of(const std::vector<std::string>& rows) {
    std::string out;
    for (const std::string& row : rows)
        for (char c : row)
            if (c != ' ') out += c;
    return out;
}

// The smallest area holding every pixel of colour `ink` inside `area`, if any.
inline std::optional<PixelArea> ink_extent(const controller::PngImage& img, PixelArea area,
                                           protocol::Rgb ink) {
    uint32_t x0 = UINT32_MAX, y0 = UINT32_MAX, x1 = 0, y1 = 0;
    for (uint32_t y = area.y; y < area.y + area.height && y < img.height; ++y)
        for (uint32_t x = area.x; x < area.x + area.width && x < img.width; ++x) {
            const std::size_t i = (std::size_t{y} * img.width + x) * 3;
            if (img.pixels[i] != ink.r || img.pixels[i + 1] != ink.g || img.pixels[i + 2] != ink.b)
                continue;
            x0 = std::min(x0, x), y0 = std::min(y0, y);
            x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
    if (x0 == UINT32_MAX) return std::nullopt;
    return PixelArea{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

}  // namespace fb89::testing
