// Recorder: the last command that wrote each pixel of the current frame, and the opcode
// overlay built from it (the paper's Fig. 4.7 idea, §4: there the pixels that needed ray
// tracing are blacked out to show where the beam-ray hybrid found coherence; here every
// pixel is tinted by the opcode that wrote it: FILL_RECT for Warnock windows and beam hits,
// DRAW_SPAN for spans and ray-traced runs, FRAME_BEGIN for background nothing covered).
//
// Fed the same commands as the controller, in the same order (record(), or hook it with
// Controller::set_observer). It mirrors the controller's clipping and framing rules: a
// FRAME_BEGIN sizes and claims every pixel, drawing commands outside a frame write nothing.
// It keeps only the current frame's commands that wrote a pixel, never the whole stream.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "protocol/command.h"

namespace fb89::controller {

class Framebuffer;

// The command that last wrote a pixel: its stream number and the command itself.
struct PixelWriter {
    uint64_t number = 0;
    const protocol::Command* command = nullptr;
    protocol::Opcode opcode() const { return protocol::opcode_of(*command); }
};

class Recorder {
  public:
    // Takes one executed command numbered `number` in the stream.
    void record(uint64_t number, const protocol::Command& c);
    // Forgets everything, as before the first command (after a seek).
    void reset();

    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }
    // The last writer of (x, y); nullopt outside the frame or before any FRAME_BEGIN.
    std::optional<PixelWriter> writer(uint32_t x, uint32_t y) const;
    // Commands of the current frame that wrote at least one pixel.
    std::size_t writers() const { return m_commands.size(); }

  private:
    void claim(uint32_t x, uint32_t y, uint32_t w, uint32_t h, uint32_t slot);

    uint32_t m_width = 0, m_height = 0;
    bool m_in_frame = false;
    std::vector<uint32_t> m_slot;  // per pixel: index into m_commands
    std::vector<std::pair<uint64_t, protocol::Command>> m_commands;
};

// The tint of an opcode in the overlay.
protocol::Rgb opcode_tint(protocol::Opcode op);
// One pixel of the overlay: the pixel's colour mixed 1:2 with its writer's tint, so the
// image stays readable under the tint.
protocol::Rgb tint(protocol::Rgb pixel, protocol::Opcode writer);

// The framebuffer as RGB888 (width * 3 bytes per row), tinted by the last writer of each
// pixel when `overlay` is set and the recorder matches the framebuffer's size; untouched
// pixels otherwise.
void compose_image(const Framebuffer& fb, const Recorder* overlay, std::vector<uint8_t>& rgb);

}  // namespace fb89::controller
