// Recorder: the last writer of each pixel, and the opcode overlay (see recorder.h).
//
// Clipping uses the controller's own clip_fill_rect / clip_span, so the recorder claims
// exactly the pixels the controller wrote. Commands that wrote nothing (wholly outside,
// empty, outside any frame, MARKER, FRAME_END) leave the map as it was.
#include "controller_sim/recorder.h"

#include <algorithm>
#include <variant>

#include "controller_sim/framebuffer.h"

namespace fb89::controller {

using protocol::Command;
using protocol::Opcode;
using protocol::Rgb;

void Recorder::reset() {
    *this = Recorder{};
}

void Recorder::claim(uint32_t x, uint32_t y, uint32_t w, uint32_t h, uint32_t slot) {
    for (uint32_t row = y; row < y + h; ++row) {
        auto first = m_slot.begin() + static_cast<std::ptrdiff_t>(std::size_t{row} * m_width + x);
        std::fill(first, first + w, slot);
    }
}

void Recorder::record(uint64_t number, const Command& c) {
    // a new frame: resize, and FRAME_BEGIN's clear is every pixel's writer
    if (const auto* f = std::get_if<protocol::FrameBegin>(&c)) {
        if (f->width > kMaxFrameSide || f->height > kMaxFrameSide) return;  // refused
        m_width = f->width;
        m_height = f->height;
        m_in_frame = true;
        m_commands.clear();
        m_commands.emplace_back(number, c);
        m_slot.assign(std::size_t{m_width} * m_height, 0);
        return;
    }
    if (std::holds_alternative<protocol::FrameEnd>(c)) {
        m_in_frame = false;
        return;
    }
    if (!m_in_frame) return;

    // drawing commands: claim what the controller wrote
    std::optional<Clipped> clip;
    if (const auto* r = std::get_if<protocol::FillRect>(&c))
        clip = clip_fill_rect(*r, m_width, m_height);
    else if (const auto* s = std::get_if<protocol::DrawSpan>(&c))
        clip = clip_span(*s, m_width, m_height);
    if (!clip) return;
    const auto slot = static_cast<uint32_t>(m_commands.size());
    m_commands.emplace_back(number, c);
    claim(clip->rect.x, clip->rect.y, clip->rect.w, clip->rect.h, slot);
}

std::optional<PixelWriter> Recorder::writer(uint32_t x, uint32_t y) const {
    if (x >= m_width || y >= m_height || m_commands.empty()) return std::nullopt;
    const auto& [number, command] = m_commands[m_slot[std::size_t{y} * m_width + x]];
    return PixelWriter{number, &command};
}

Rgb opcode_tint(Opcode op) {
    switch (op) {
        case Opcode::FrameBegin:
            return Rgb{40, 40, 140};  // background: blue-grey
        case Opcode::FillRect:
            return Rgb{40, 220, 60};  // windows, beams: green
        case Opcode::DrawSpan:
            return Rgb{240, 40, 40};  // spans, rays: red
        case Opcode::Marker:
        case Opcode::FrameEnd:
        case Opcode::DepthClear:  // the depth commands are not recorded as writers
        case Opcode::DepthSpan:
        case Opcode::Face:
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
