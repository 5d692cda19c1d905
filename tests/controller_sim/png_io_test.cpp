// Tests of controller_sim/png_io: lossless round trip, RGBA input, and errors that name
// the path and what is wrong.
#include "controller_sim/png_io.h"

#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "controller_sim/framebuffer.h"
#include "tests/scratch.h"

namespace fb89::controller {
namespace {

namespace fs = std::filesystem;

// A fresh path in the temp directory, removed when the test ends.
class TempPath {
  public:
    explicit TempPath(const std::string& name)
        : m_path(fb89::testing::scratch_path("png_test_" + name)) {}
    ~TempPath() { fs::remove(m_path); }
    const fs::path& path() const { return m_path; }

  private:
    fs::path m_path;
};

// The message `f` throws as std::runtime_error, or "".
template <typename F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

// Writes a PNG of the given format with libpng's simplified API (a writer that is not ours).
void write_with_libpng(const fs::path& path, uint32_t w, uint32_t h, png_uint_32 format,
                       const std::vector<uint8_t>& bytes) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = w;
    image.height = h;
    image.format = format;
    ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, bytes.data(), 0, nullptr))
        << image.message;
}

TEST(PngIo, WriteThenReadGivesTheSameRgbBytes) {
    Framebuffer fb(37, 23);  // odd sizes: no row padding may creep in
    for (uint32_t y = 0; y < fb.height(); ++y)
        for (uint32_t x = 0; x < fb.width(); ++x)
            fb.set_pixel(x, y,
                         protocol::Rgb{static_cast<uint8_t>(x * 7), static_cast<uint8_t>(y * 11),
                                       static_cast<uint8_t>(x ^ y)});
    const TempPath file("round_trip.png");
    write_png(file.path(), fb);
    const PngImage img = read_png(file.path());
    EXPECT_EQ(img.width, 37u);
    EXPECT_EQ(img.height, 23u);
    EXPECT_EQ(img.channels, 3u);
    EXPECT_TRUE(
        std::equal(img.pixels.begin(), img.pixels.end(), fb.pixels().begin(), fb.pixels().end()));
}

TEST(PngIo, ReadsRgbaAsStored) {
    const TempPath file("rgba.png");
    const std::vector<uint8_t> rgba = {1, 2, 3, 255, 4, 5, 6, 128, 7, 8, 9, 0, 10, 11, 12, 1};
    write_with_libpng(file.path(), 2, 2, PNG_FORMAT_RGBA, rgba);
    const PngImage img = read_png(file.path());
    EXPECT_EQ(img.channels, 4u);
    EXPECT_EQ(img.pixels, rgba);
}

TEST(PngIo, GreyscaleIsRefusedSayingWhatItIs) {
    const TempPath file("grey.png");
    write_with_libpng(file.path(), 2, 1, PNG_FORMAT_GRAY, {0, 255});
    const std::string e = error_of([&] { read_png(file.path()); });
    EXPECT_NE(e.find(file.path().string()), std::string::npos) << e;
    EXPECT_NE(e.find("8-bit greyscale (expected 8-bit RGB or RGBA)"), std::string::npos) << e;
}

TEST(PngIo, MissingFileErrorNamesThePath) {
    const std::string e = error_of([] { read_png("/nonexistent/fb89/none.png"); });
    EXPECT_NE(e.find("/nonexistent/fb89/none.png: cannot open"), std::string::npos) << e;
}

TEST(PngIo, NonPngFileIsRefusedByItsSignature) {
    const TempPath file("text.png");
    std::ofstream(file.path()) << "this is not a PNG file at all";
    const std::string e = error_of([&] { read_png(file.path()); });
    EXPECT_NE(e.find(file.path().string() + ": not a PNG file"), std::string::npos) << e;
}

TEST(PngIo, TruncatedPngIsReportedCorrupt) {
    Framebuffer fb(64, 64);
    fb.fill_rect(PixelRect{3, 3, 30, 30}, protocol::Rgb{200, 10, 10});
    const TempPath whole("whole.png");
    write_png(whole.path(), fb);
    std::ifstream in(whole.path(), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const TempPath cut("cut.png");
    std::ofstream(cut.path(), std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    const std::string e = error_of([&] { read_png(cut.path()); });
    EXPECT_NE(e.find(cut.path().string() + ": corrupt PNG"), std::string::npos) << e;
}

TEST(PngIo, UnwritablePathErrorNamesThePath) {
    const Framebuffer fb(2, 2);
    const std::string e = error_of([&] { write_png("/nonexistent/fb89/out.png", fb); });
    EXPECT_NE(e.find("/nonexistent/fb89/out.png: cannot open for writing"), std::string::npos) << e;
}

TEST(PngIo, WrongBufferSizeIsRefused) {
    const std::vector<uint8_t> too_short(5);
    const std::string e = error_of([&] { write_png("/tmp/unused.png", 2, 2, too_short); });
    EXPECT_NE(e.find("5 bytes given for a 2x2 RGB image"), std::string::npos) << e;
}

}  // namespace
}  // namespace fb89::controller
