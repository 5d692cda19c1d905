// Recorder: the last writer of each pixel, and the opcode overlay (see recorder.h).
//
// Clipping uses the controller's own clip_fill_rect / clip_span, and a depth command's
// pixels are the runs the controller's depth test drew (Controller::depth_drawn), so the
// recorder claims exactly the pixels the controller wrote. Commands that wrote nothing
// (wholly outside, empty, farther everywhere, outside any frame, MARKER, FRAME_END,
// DEPTH_CLEAR) leave the map as it was.
#include "controller_sim/recorder.h"

#include <algorithm>
#include <variant>

#include <fmt/format.h>

#include "controller_sim/controller.h"
#include "controller_sim/framebuffer.h"
#include "protocol/coverage.h"

namespace fb89::controller {

// Unnamed, so that in a unity build no enumerator of the same name in a later header
// (ViewGoal::Command) shadows them (-Wshadow).
namespace {
using protocol::Command;
using protocol::Opcode;
using protocol::Rgb;
}  // namespace

void Recorder::reset() {
    *this = Recorder{};
}

void Recorder::claim(uint32_t x, uint32_t y, uint32_t w, uint32_t h, uint32_t slot) {
    for (uint32_t row = y; row < y + h; ++row) {
        auto first = m_slot.begin() + static_cast<std::ptrdiff_t>(std::size_t{row} * m_width + x);
        std::fill(first, first + w, slot);
    }
}

void Recorder::record(uint64_t number, const Command& c, std::span<const PixelRect> depth_drawn) {
    // a new frame: resize, and FRAME_BEGIN's clear is every pixel's writer
    if (const auto* f = std::get_if<protocol::FrameBegin>(&c)) {
        if (f->width > kMaxFrameSide || f->height > kMaxFrameSide) return;  // refused
        m_width = f->width;
        m_height = f->height;
        m_in_frame = true;
        m_commands.clear();
        m_commands.push_back(Entry{number, c, uint64_t{m_width} * m_height});
        m_slot.assign(std::size_t{m_width} * m_height, 0);
        return;
    }
    if (std::holds_alternative<protocol::FrameEnd>(c)) {
        m_in_frame = false;
        return;
    }
    if (!m_in_frame) return;
    if (std::holds_alternative<protocol::DepthSpan>(c) || std::holds_alternative<protocol::Face>(c))
        return claim_runs(number, c, depth_drawn);

    // drawing commands: claim what the controller wrote
    std::optional<Clipped> clip;
    if (const auto* r = std::get_if<protocol::FillRect>(&c))
        clip = clip_fill_rect(*r, m_width, m_height);
    else if (const auto* s = std::get_if<protocol::DrawSpan>(&c))
        clip = clip_span(*s, m_width, m_height);
    if (!clip) return;
    const auto slot = static_cast<uint32_t>(m_commands.size());
    m_commands.push_back(Entry{number, c, clip->rect.pixels()});
    claim(clip->rect.x, clip->rect.y, clip->rect.w, clip->rect.h, slot);
}

// a depth command: the runs its test drew (each inside the frame; any other is ignored)
void Recorder::claim_runs(uint64_t number, const Command& c, std::span<const PixelRect> runs) {
    const auto slot = static_cast<uint32_t>(m_commands.size());
    uint64_t pixels = 0;
    for (const PixelRect& r : runs) {
        if (r.w == 0 || r.h == 0 || r.x >= m_width || r.w > m_width - r.x || r.y >= m_height ||
            r.h > m_height - r.y)
            continue;
        claim(r.x, r.y, r.w, r.h, slot);
        pixels += r.pixels();
    }
    if (pixels > 0) m_commands.push_back(Entry{number, c, pixels});
}

void Recorder::attach(Controller& controller) {
    controller.keep_depth_drawn(true);
    controller.set_observer([this, &controller](uint64_t n, const Command& c) {
        record(n, c, controller.depth_drawn());
    });
}

std::optional<PixelWriter> Recorder::writer(uint32_t x, uint32_t y) const {
    if (x >= m_width || y >= m_height || m_commands.empty()) return std::nullopt;
    const Entry& e = m_commands[m_slot[std::size_t{y} * m_width + x]];
    return PixelWriter{e.number, &e.command, e.pixels};
}

std::string describe(const PixelWriter& w) {
    const Command& c = *w.command;
    if (const auto* f = std::get_if<protocol::Face>(&c)) {
        // the pixels its points span (on the 1/256-pixel grid)
        int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        for (std::size_t i = 0; i < f->points.size(); ++i) {
            const int64_t x = protocol::detail::floor_div(f->points[i].x, protocol::kSubpixel);
            const int64_t y = protocol::detail::floor_div(f->points[i].y, protocol::kSubpixel);
            x0 = i == 0 ? x : std::min(x0, x);
            y0 = i == 0 ? y : std::min(y0, y);
            x1 = i == 0 ? x : std::max(x1, x);
            y1 = i == 0 ? y : std::max(y1, y);
        }
        return fmt::format("#{} FACE {}, {} points in ({},{})-({},{}), drew {} pixels", w.number,
                           protocol::to_string(f->color), f->points.size(), x0, y0, x1, y1,
                           w.pixels);
    }
    std::string text = fmt::format("#{} {}", w.number, protocol::to_string(c));
    if (std::holds_alternative<protocol::DepthSpan>(c))
        text += fmt::format(", drew {} pixels", w.pixels);
    return text;
}

Rgb opcode_tint(Opcode op) {
    switch (op) {
        case Opcode::FrameBegin:
            return Rgb{40, 40, 140};  // background: blue-grey
        case Opcode::FillRect:
            return Rgb{40, 220, 60};  // windows, beams: green
        case Opcode::DrawSpan:
            return Rgb{240, 40, 40};  // spans, rays: red
        case Opcode::DepthSpan:
            return Rgb{250, 190, 20};  // depth-tested spans: amber
        case Opcode::Face:
            return Rgb{200, 60, 230};  // faces the controller scan-converts: magenta
        case Opcode::Marker:
        case Opcode::FrameEnd:
        case Opcode::DepthClear:  // writes no pixel
            break;
    }
    return Rgb{255, 255, 255};
}

Rgb tint(Rgb pixel, Opcode writer) {
    const Rgb t = opcode_tint(writer);
    auto mix = [](uint8_t p, uint8_t q) { return static_cast<uint8_t>((p + 2 * q) / 3); };
    return Rgb{mix(pixel.r, t.r), mix(pixel.g, t.g), mix(pixel.b, t.b)};
}

void compose_image(const Framebuffer& fb, const Recorder* overlay, std::vector<uint8_t>& rgb) {
    const auto src = fb.pixels();
    rgb.assign(src.begin(), src.end());
    if (!overlay || overlay->width() != fb.width() || overlay->height() != fb.height()) return;

    // tint each pixel by its writer's opcode
    for (uint32_t y = 0; y < fb.height(); ++y) {
        uint8_t* p = rgb.data() + std::size_t{y} * fb.width() * 3;
        for (uint32_t x = 0; x < fb.width(); ++x, p += 3) {
            const auto w = overlay->writer(x, y);
            if (!w) continue;
            const Rgb t = tint(Rgb{p[0], p[1], p[2]}, w->opcode());
            p[0] = t.r;
            p[1] = t.g;
            p[2] = t.b;
        }
    }
}

}  // namespace fb89::controller
