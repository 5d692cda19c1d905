// Where the viewer's text goes: the window's size and every row of text in it, worked out
// without SDL (display.cpp draws what this lays out; the tests check it fits).
//
// The window holds the framebuffer at its top left, a key panel over the image when it is
// shown, and a bar of status rows under the body. The window is never less than 640 pixels
// wide; text is drawn in the 5x7 font (bitmap_font.h), doubled when the window is 960 or
// more wide. A status line longer than the window wraps onto more rows -- between fields
// (runs of two spaces) where it can, else between words, else anywhere -- each
// continuation indented by two spaces, and the bar grows to hold them: no text is cut, and
// none is drawn outside the window or over the image. The body is tall enough for the key
// panel whether or not it is shown, so that toggling it does not resize the window.
#pragma once

#include <string>
#include <vector>

namespace fb89::controller {

// What is drawn on top of the framebuffer.
struct Hud {
    std::vector<std::string> status;  // lines in the bar under the image
    std::vector<std::string> help;    // the key panel's lines
    bool help_shown = false;          // the key panel is drawn, over the image's top left
};

inline constexpr int kMinWindowWidth = 640;
inline constexpr int kTextPad = 4;  // pixels around the status text and inside the panel

// A rectangle in window pixels.
struct TextRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool contains(const TextRect& r) const {
        return r.x >= x && r.y >= y && r.x + r.width <= x + width && r.y + r.height <= y + height;
    }
    bool overlaps(const TextRect& r) const {
        return r.x < x + width && x < r.x + r.width && r.y < y + height && y < r.y + r.height;
    }
};

// One row of text: its characters and the cells they take, one cell per character.
struct TextRow {
    std::string text;
    TextRect box;
};

struct HudLayout {
    int window_width = 0, window_height = 0;
    int text_scale = 1;  // window pixels per font pixel
    int columns = 0;     // characters that fit on a status row
    TextRect image;      // where the framebuffer is drawn
    TextRect bar;        // the status bar, under the body
    std::vector<TextRow> status;
    TextRect panel;  // the key panel's box (empty when it is not shown)
    std::vector<TextRow> panel_rows;
};

// `line` in rows of at most `columns` characters (see the header comment; a long word
// breaks after a '/' where it can, so a path breaks between folders); a line that fits is
// one row. `columns` below 8 counts as 8. The contact sheet's title wraps the same way.
std::vector<std::string> wrap_line(const std::string& line, int columns);

// The layout for an image of image_width x image_height window pixels under `hud`. The bar
// has at least `min_status_rows` rows (a caller keeps it from shrinking as lines vary).
HudLayout layout_hud(int image_width, int image_height, const Hud& hud, int min_status_rows = 0);

// n framebuffer pixels in window pixels at `scale` (at least 1 for n > 0).
int scaled_size(unsigned n, double scale);

// The scale at which a width x height framebuffer's window (the image under `hud`, with at
// least `min_status_rows` rows, as layout_hud lays it out) fits a screen_width x
// screen_height screen: `asked` when it fits, else the largest that fits of the whole scales
// below it down to 1, then 1/2, 1/4 and 1/8 (whole blocks of pixels, or every 2nd, 4th or
// 8th pixel); 1/8 when none fits (a screen narrower than kMinWindowWidth).
double fit_scale(unsigned width, unsigned height, const Hud& hud, int min_status_rows, double asked,
                 int screen_width, int screen_height);

}  // namespace fb89::controller
