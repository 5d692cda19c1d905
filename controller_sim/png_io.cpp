// PNG reading and writing with libpng's low-level API.
//
// libpng reports errors by longjmp. Every setjmp here sits in a small function whose only
// locals are trivial, and which returns false on error, so no C++ object is skipped or left
// indeterminate by the jump; the C++ side then throws with the message libpng gave.
#include "controller_sim/png_io.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "controller_sim/framebuffer.h"
#include "protocol/output_file.h"

namespace fb89::controller {

namespace {

constexpr std::size_t kMessageSize = 256;

void on_png_error(png_structp png, png_const_charp message) {
    auto* buffer = static_cast<char*>(png_get_error_ptr(png));
    std::snprintf(buffer, kMessageSize, "%s", message);
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// libpng's structures, destroyed on every way out (the destroy calls accept null).
struct WriteStructs {
    png_structp png = nullptr;
    png_infop info = nullptr;
    WriteStructs() = default;
    WriteStructs(const WriteStructs&) = delete;
    WriteStructs& operator=(const WriteStructs&) = delete;
    ~WriteStructs() { png_destroy_write_struct(&png, &info); }
};
struct ReadStructs {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ReadStructs() = default;
    ReadStructs(const ReadStructs&) = delete;
    ReadStructs& operator=(const ReadStructs&) = delete;
    ~ReadStructs() { png_destroy_read_struct(&png, &info, nullptr); }
};

[[noreturn]] void fail(const std::filesystem::path& path, std::string_view what) {
    throw std::runtime_error(fmt::format("{}: {}", path.string(), what));
}

bool write_rows(png_structp png, png_infop info, std::FILE* f, uint32_t width, uint32_t height,
                png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, f);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_rows(png, info, rows);
    png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    return true;
}

struct Header {
    png_uint_32 width, height;
    int bit_depth, color_type, interlace;
};

bool read_header(png_structp png, png_infop info, std::FILE* f, Header* h) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    png_get_IHDR(png, info, &h->width, &h->height, &h->bit_depth, &h->color_type, &h->interlace,
                 nullptr, nullptr);
    return true;
}

bool read_rows(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

const char* color_type_name(int t) {
    switch (t) {
        case PNG_COLOR_TYPE_GRAY:
            return "greyscale";
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            return "greyscale with alpha";
        case PNG_COLOR_TYPE_PALETTE:
            return "palette";
        case PNG_COLOR_TYPE_RGB:
            return "RGB";
        case PNG_COLOR_TYPE_RGB_ALPHA:
            return "RGBA";
    }
    return "unknown colour type";
}

template <typename Bytes>
std::vector<png_bytep> row_pointers(Bytes* data, uint32_t height, std::size_t stride) {
    std::vector<png_bytep> rows(height);
    for (uint32_t y = 0; y < height; ++y)
        rows[y] = const_cast<png_bytep>(data + std::size_t{y} * stride);  // libpng takes non-const
    return rows;
}

}  // namespace

void write_png(const std::filesystem::path& path, uint32_t width, uint32_t height,
               std::span<const uint8_t> rgb, protocol::Publish publish) {
    if (width == 0 || height == 0)
        fail(path, fmt::format("cannot write a {}x{} image", width, height));
    if (rgb.size() != std::size_t{width} * height * 3)
        fail(path, fmt::format("{} bytes given for a {}x{} RGB image", rgb.size(), width, height));
    std::vector<png_bytep> rows = row_pointers(rgb.data(), height, std::size_t{width} * 3);
    // whole or not at all: a failed write leaves the old file as it was
    protocol::write_output(
        path,
        [&](std::FILE* f) {
            char message[kMessageSize] = "";
            WriteStructs s;
            s.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, message, on_png_error,
                                            on_png_warning);
            s.info = s.png ? png_create_info_struct(s.png) : nullptr;
            if (!s.info) fail(path, "out of memory in libpng");
            if (write_rows(s.png, s.info, f, width, height, rows.data())) return;
            // a failed fwrite (a full disk, a file size limit) left its cause in errno
            if (std::ferror(f) && errno != 0) fail(path, std::strerror(errno));
            fail(path, fmt::format("PNG write error: {}", message));
        },
        publish);
}

void write_png(const std::filesystem::path& path, const Framebuffer& fb,
               protocol::Publish publish) {
    write_png(path, fb.width(), fb.height(), fb.pixels(), publish);
}

PngImage read_png(const std::filesystem::path& path) {
    File f(std::fopen(path.c_str(), "rb"));
    if (!f) fail(path, fmt::format("cannot open: {}", std::strerror(errno)));
    png_byte signature[8] = {};
    if (std::fread(signature, 1, 8, f.get()) != 8 || png_sig_cmp(signature, 0, 8) != 0)
        fail(path, "not a PNG file (bad signature)");

    char message[kMessageSize] = "";
    ReadStructs s;
    s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, message, on_png_error, on_png_warning);
    s.info = s.png ? png_create_info_struct(s.png) : nullptr;
    if (!s.info) fail(path, "out of memory in libpng");

    Header h{};
    if (!read_header(s.png, s.info, f.get(), &h))
        fail(path, fmt::format("corrupt PNG: {}", message));
    if (h.bit_depth != 8 ||
        (h.color_type != PNG_COLOR_TYPE_RGB && h.color_type != PNG_COLOR_TYPE_RGB_ALPHA))
        fail(path, fmt::format("unsupported PNG: {}-bit {} (expected 8-bit RGB or RGBA)",
                               h.bit_depth, color_type_name(h.color_type)));
    if (h.interlace != PNG_INTERLACE_NONE) fail(path, "unsupported PNG: interlaced");
    if (h.width > kMaxFrameSide || h.height > kMaxFrameSide)
        fail(path, fmt::format("unsupported PNG: {}x{} exceeds the maximum {}x{}", h.width,
                               h.height, kMaxFrameSide, kMaxFrameSide));

    PngImage img;
    img.width = h.width;
    img.height = h.height;
    img.channels = h.color_type == PNG_COLOR_TYPE_RGB ? 3 : 4;
    const std::size_t stride = std::size_t{img.width} * img.channels;
    if (png_get_rowbytes(s.png, s.info) != stride) fail(path, "unexpected row size");
    img.pixels.resize(stride * img.height);
    std::vector<png_bytep> rows = row_pointers(img.pixels.data(), img.height, stride);
    if (!read_rows(s.png, s.info, rows.data())) fail(path, fmt::format("corrupt PNG: {}", message));
    return img;
}

}  // namespace fb89::controller
