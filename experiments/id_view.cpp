// The face-id buffer in false colour (see id_view.h).
#include "experiments/id_view.h"

#include <cmath>
#include <filesystem>

#include "controller_sim/png_io.h"

namespace fb89::experiments {

namespace {

constexpr double kGoldenStep = 0.6180339887498949;   // 1 / golden ratio: the hue walk
constexpr double kPlasticStep = 0.7548776662466927;  // 1 / plastic number: the value walk
constexpr double kSaturation = 0.80;
constexpr double kMinValue = 0.70, kValueRange = 0.30;

double fraction(double x) {
    return x - std::floor(x);
}

uint8_t channel(double c) {
    return static_cast<uint8_t>(std::lround(c * 255));
}

// HSV, each in [0, 1], to 8-bit RGB.
protocol::Rgb from_hsv(double h, double s, double v) {
    const double sector = h * 6;
    const int i = static_cast<int>(sector) % 6;
    const double f = sector - std::floor(sector);
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    switch (i) {
        case 0:
            return {channel(v), channel(t), channel(p)};
        case 1:
            return {channel(q), channel(v), channel(p)};
        case 2:
            return {channel(p), channel(v), channel(t)};
        case 3:
            return {channel(p), channel(q), channel(v)};
        case 4:
            return {channel(t), channel(p), channel(v)};
        default:
            return {channel(v), channel(p), channel(q)};
    }
}

}  // namespace

protocol::Rgb id_view_colour(uint32_t id) {
    const double hue = fraction(id * kGoldenStep);
    const double value = kMinValue + kValueRange * fraction(id * kPlasticStep);
    return from_hsv(hue, kSaturation, value);
}

controller::Framebuffer id_view(const controller::Framebuffer& ids) {
    controller::Framebuffer out(ids.width(), ids.height());
    for (uint32_t y = 0; y < ids.height(); ++y)
        for (uint32_t x = 0; x < ids.width(); ++x) {
            const protocol::Rgb p = ids.pixel(x, y);
            const uint32_t code = uint32_t{p.r} << 16 | uint32_t{p.g} << 8 | p.b;
            out.set_pixel(x, y, code == 0 ? protocol::Rgb{} : id_view_colour(code - 1));
        }
    return out;
}

void write_id_pngs(const controller::Framebuffer& ids, const std::string& ids_png,
                   const std::string& view_png) {
    auto write = [](const std::string& path, const controller::Framebuffer& fb) {
        if (path.empty()) return;
        const std::filesystem::path parent = std::filesystem::path(path).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent);
        controller::write_png(path, fb);
    };
    write(ids_png, ids);
    if (!view_png.empty()) write(view_png, id_view(ids));
}

}  // namespace fb89::experiments
