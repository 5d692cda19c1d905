// Display: an SDL2 window showing the controller's framebuffer as a 1989 monitor would,
// with fb89's own text beside it (status lines under the image, the key panel over it when
// asked for), laid out by hud_layout.h so that all of it fits the window.
//
// Reusable by any owner of a Controller: `fb89 view` plays a recorded stream through it,
// and `fb89 controller --view` can show a live one the same way:
//
//     Display display("fb89 controller", 1);
//     Recorder writers;
//     writers.attach(controller);  // its observer: every command, depth-tested pixels too
//     ... every 1/60 s: display.poll(0); display.show(controller.framebuffer(), &writers, hud);
//
// SDL stays inside display.cpp; this header names none of its types.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "controller_sim/hud_layout.h"

namespace fb89::controller {

class Framebuffer;
class Recorder;

// No window can be opened (no DISPLAY, SDL video initialisation failed, or SDL found only
// a driver with no screen): fb89 exits 2. The message is one line; the constructor's starts
// "no display to open a window on".
class DisplayUnavailable : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// Keys other than printable ASCII, as InputEvent::key.
enum DisplayKey : int {
    kKeyEscape = 27,
    kKeyHome = 0x10000,
    kKeyEnd,
    kKeyLeft,
    kKeyRight,
    kKeyUp,
    kKeyDown,
};

struct InputEvent {
    enum class Kind { Quit, Key, MouseMove, MouseLeave };
    Kind kind = Kind::Quit;
    int key = 0;       // Key: printable ASCII or a DisplayKey
    int x = 0, y = 0;  // MouseMove: window coordinates
};

// The window would not fit the screen at the scale asked: the scale used instead
// (fit_scale, hud_layout.h), told once for each framebuffer size that needs it.
struct ScaleFitted {
    double asked = 1, used = 1;
    int window_width = 0, window_height = 0;  // the window at the scale asked
    int screen_width = 0, screen_height = 0;  // the usable screen, less the window's borders
};
using ScaleNotice = std::function<void(const ScaleFitted&)>;

class Display {
  public:
    // Opens a window; the framebuffer is drawn `scale` window pixels per pixel, from 1/8 (a
    // large frame on a small screen, every eighth pixel) to 8. The window never grows larger
    // than the screen's usable bounds (SDL_GetDisplayUsableBounds): for a framebuffer whose
    // window would, a smaller scale is used (fit_scale) and `notice` told.
    // Throws DisplayUnavailable when SDL cannot open one: on X11/Wayland systems, when
    // neither DISPLAY nor WAYLAND_DISPLAY is set (before SDL probes anything, so SDL prints
    // nothing of its own), and when SDL would fall back to its offscreen or dummy driver
    // without SDL_VIDEODRIVER asking for it. An SDL_VIDEODRIVER that is set is obeyed.
    Display(const std::string& title, double scale, ScaleNotice notice = {});
    ~Display();
    Display(const Display&) = delete;
    Display& operator=(const Display&) = delete;

    // Input since the last call; waits up to timeout_ms for the first event (0: no wait).
    std::vector<InputEvent> poll(int timeout_ms);

    // Draws the framebuffer (tinted by its writers when `overlay` is given), then the HUD,
    // and presents. Resizes the window when the layout's size changed: the framebuffer's,
    // or the status bar grew (it does not shrink again for the same framebuffer size).
    void show(const Framebuffer& fb, const Recorder* overlay, const Hud& hud);

    // Draws as show() does, reads the whole window back as the renderer drew it -- image,
    // status bar and key panel -- and presents. RGB888 rows, width * 3 bytes each; the size
    // is the window's.
    std::vector<uint8_t> capture_window(const Framebuffer& fb, const Recorder* overlay,
                                        const Hud& hud, uint32_t& width, uint32_t& height);

    // Draws the framebuffer as show() does (tinted by its writers when `overlay` is given)
    // but without the text, reads back the image area as the renderer drew it, and
    // presents. RGB888 rows, width * 3 bytes each; the size is the framebuffer's times the
    // scale.
    std::vector<uint8_t> capture(const Framebuffer& fb, const Recorder* overlay, uint32_t& width,
                                 uint32_t& height);

    // Window pixels per framebuffer pixel now: the scale asked, or the one that fits.
    double scale() const;

    // The framebuffer pixel under window point (x, y) of the last frame shown, if any.
    std::optional<std::pair<uint32_t, uint32_t>> pixel_at(int x, int y) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> m;
};

}  // namespace fb89::controller
