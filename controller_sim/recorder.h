// Recorder: the last command that wrote each pixel of the current frame, and the opcode
// overlay built from it (the paper's Fig. 4.7 idea, §4: there the pixels that needed ray
// tracing are blacked out to show where the beam-ray hybrid found coherence; here every
// pixel is tinted by the opcode that wrote it: FILL_RECT for Warnock windows and beam hits,
// DRAW_SPAN for spans and ray-traced runs, DEPTH_SPAN and FACE for the controller's own
// depth test, FRAME_BEGIN for background nothing covered).
//
// Fed the same commands as the controller, in the same order (record() after each, or
// attach() it to the controller). It mirrors the controller's clipping and framing rules: a
// FRAME_BEGIN sizes and claims every pixel, drawing commands outside a frame write nothing.
// A DEPTH_SPAN or FACE claims exactly the pixels its depth test drew, as the controller
// reports them (Controller::keep_depth_drawn / depth_drawn): a farther one leaves the
// nearer writer in place. DEPTH_CLEAR writes no pixel. It keeps only the current frame's
// commands that wrote a pixel, never the whole stream.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/command.h"

namespace fb89::controller {

class Controller;
class Framebuffer;
struct PixelRect;

// The command that last wrote a pixel: its stream number, the command itself, and how many
// pixels it wrote when it executed (some may have been overwritten since).
struct PixelWriter {
    uint64_t number = 0;
    const protocol::Command* command = nullptr;
    uint64_t pixels = 0;
    protocol::Opcode opcode() const { return protocol::opcode_of(*command); }
};

// A writer for the inspector: "#12 FILL_RECT x=0 y=0 w=4 h=4 #ff0000"; a depth command with
// the pixels its test drew, a FACE by its colour, points and pixel bounds (the stream names
// no face): "#123 FACE #bdbdb1, 4 points in (384,306)-(444,316), drew 310 pixels".
std::string describe(const PixelWriter& w);

class Recorder {
  public:
    // Takes one executed command numbered `number` in the stream; for a DEPTH_SPAN or FACE,
    // `depth_drawn` holds the runs its depth test drew (Controller::depth_drawn()).
    void record(uint64_t number, const protocol::Command& c,
                std::span<const PixelRect> depth_drawn = {});
    // Records every command `controller` executes from now on, numbered as it counts them
    // (its observer), depth commands included (it keeps their drawn pixels for this). The
    // recorder must stay where it is while the controller runs.
    void attach(Controller& controller);
    // Forgets everything, as before the first command (after a seek).
    void reset();

    uint32_t width() const { return m_width; }
    uint32_t height() const { return m_height; }
    // The last writer of (x, y); nullopt outside the frame or before any FRAME_BEGIN.
    std::optional<PixelWriter> writer(uint32_t x, uint32_t y) const;
    // Commands of the current frame that wrote at least one pixel.
    std::size_t writers() const { return m_commands.size(); }

  private:
    struct Entry {
        uint64_t number = 0;
        protocol::Command command;
        uint64_t pixels = 0;
    };
    void claim(uint32_t x, uint32_t y, uint32_t w, uint32_t h, uint32_t slot);
    void claim_runs(uint64_t number, const protocol::Command& c, std::span<const PixelRect> runs);

    uint32_t m_width = 0, m_height = 0;
    bool m_in_frame = false;
    std::vector<uint32_t> m_slot;  // per pixel: index into m_commands
    std::vector<Entry> m_commands;
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
