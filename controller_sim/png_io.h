// PNG output of frames and PNG input for golden tests, through libpng.
//
// Writing: 8-bit RGB, no interlace, default compression, whole or not at all
// (protocol/output_file.h). Reading: 8-bit RGB or RGBA only,
// bytes exactly as stored (no gamma or colour conversion), so face-id buffers compare
// exactly. Errors are std::runtime_error naming the path and what is wrong.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "protocol/output_file.h"

namespace fb89::controller {

class Framebuffer;

struct PngImage {
    uint32_t width = 0;
    uint32_t height = 0;
    uint32_t channels = 3;        // 3 = RGB, 4 = RGBA
    std::vector<uint8_t> pixels;  // row-major, width * channels bytes per row
};

// `rgb` holds width * height * 3 bytes, row 0 at the top.
void write_png(const std::filesystem::path& path, uint32_t width, uint32_t height,
               std::span<const uint8_t> rgb,
               protocol::Publish publish = protocol::Publish::WithCommand);
void write_png(const std::filesystem::path& path, const Framebuffer& fb,
               protocol::Publish publish = protocol::Publish::WithCommand);

PngImage read_png(const std::filesystem::path& path);

}  // namespace fb89::controller
