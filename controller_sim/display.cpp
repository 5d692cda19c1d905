// Display: the SDL2 window of fb89's viewer (see display.h).
//
// The framebuffer is uploaded each frame to a streaming RGB24 texture and drawn with
// nearest-neighbour scaling by SDL's software renderer, so what the window shows is the
// controller's pixels exactly (the screenshot test compares them byte for byte). Text uses
// the 5x7 font of bitmap_font.h, baked once into a glyph atlas texture, and goes where
// layout_hud() (hud_layout.h) puts it: status rows wrapped to the window under the image,
// the key panel over the image only when it is shown.
//
// NOT SHOWN / NOT MODELLED:
//  - The monitor: no CRT gamma, no interlace, no overscan, no pixel aspect ratio (the
//    TMS34010 boards' pixels were not square; ours are), no colour palette or video DAC.
//  - Screen refresh: the window shows the framebuffer as it is when the viewer draws, about
//    60 times a second of wall time; the 1989 board scanned its VRAM out continuously, so
//    a real screen could show a fill half done. We never show a command half executed.
//  - VRAM shift-register transfers and the time they steal: not in the cost model either.
//  - The host's screen: the window is sized to the framebuffer (never less than 640 pixels
//    wide) and its text, at --scale (1/8 to 8) or, where that window would not fit the
//    screen's usable bounds, the largest scale that fits (fit_scale); no zoom or pan.
#include "controller_sim/display.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "controller_sim/bitmap_font.h"
#include "controller_sim/framebuffer.h"
#include "controller_sim/recorder.h"

namespace fb89::controller {

namespace {

constexpr const char* kNoDisplay = "no display to open a window on";

bool set_in_environment(const char* name) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0';
}

// SDL's message on one line, for DisplayUnavailable.
std::string one_line(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

int translate_key(const SDL_Keysym& k) {
    switch (k.sym) {
        case SDLK_HOME:
            return kKeyHome;
        case SDLK_END:
            return kKeyEnd;
        case SDLK_LEFT:
            return kKeyLeft;
        case SDLK_RIGHT:
            return kKeyRight;
        case SDLK_UP:
            return kKeyUp;
        case SDLK_DOWN:
            return kKeyDown;
        case SDLK_ESCAPE:
            return kKeyEscape;
        case SDLK_KP_PLUS:
            return '+';
        case SDLK_KP_MINUS:
            return '-';
        case SDLK_KP_PERIOD:
            return '.';
        default:
            break;
    }
    const bool shift = (k.mod & KMOD_SHIFT) != 0;
    if (k.sym == SDLK_EQUALS && shift) return '+';
    if (k.sym >= 32 && k.sym <= 126) return static_cast<int>(k.sym);
    return 0;
}

}  // namespace

struct Display::Impl {
    SDL_Window* window = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* image = nullptr;
    SDL_Texture* font = nullptr;
    double asked = 1;  // the scale asked for
    double scale = 1;  // window pixels per framebuffer pixel: 1/8 to 8
    ScaleNotice notice;
    uint32_t fb_width = 0, fb_height = 0;  // of the texture
    int status_rows = 0;                   // the most the bar has held at this size
    int win_width = 0, win_height = 0;
    HudLayout layout;  // of the last frame drawn
    std::vector<uint8_t> rgb;

    // n framebuffer pixels in window pixels (at least 1 for n > 0)
    int scaled(uint32_t n) const { return scaled_size(n, scale); }
    void make_font();
    void choose_scale(uint32_t width, uint32_t height, const Hud& hud);
    void fit(uint32_t width, uint32_t height, const Hud& hud);
    void resize_window(int w, int h);
    void draw_image(const Framebuffer& fb, const Recorder* overlay);
    void draw_text(const TextRow& row, SDL_Color color);
    void draw_hud();
    std::vector<uint8_t> read_pixels(int w, int h);
};

// glyph atlas: 95 cells in a row, white where a glyph pixel is set, transparent elsewhere
void Display::Impl::make_font() {
    const int w = 95 * kCellWidth, h = kGlyphHeight;
    std::vector<uint32_t> argb(static_cast<std::size_t>(w * h), 0);
    for (int g = 0; g < 95; ++g)
        for (int row = 0; row < kGlyphHeight; ++row)
            for (int col = 0; col < kGlyphWidth; ++col)
                if (glyph_pixel(kFont[static_cast<std::size_t>(g)], col, row))
                    argb[static_cast<std::size_t>(row * w + g * kCellWidth + col)] = 0xffffffffu;
    font = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_ARGB8888, SDL_TEXTUREACCESS_STATIC, w, h);
    if (!font) throw DisplayUnavailable(std::string("SDL_CreateTexture: ") + SDL_GetError());
    SDL_UpdateTexture(font, nullptr, argb.data(), w * 4);
    SDL_SetTextureBlendMode(font, SDL_BLENDMODE_BLEND);
}

// the scale for a width x height framebuffer: the one asked, unless its window would not
// fit the screen (kept 2 status rows more than `hud` has, for the lines to grow)
void Display::Impl::choose_scale(uint32_t width, uint32_t height, const Hud& hud) {
    scale = asked;
    SDL_Rect screen{0, 0, 0, 0};
    const int index = SDL_GetWindowDisplayIndex(window);
    if (SDL_GetDisplayUsableBounds(std::max(index, 0), &screen) != 0) return;  // unknown
    int top = 0, left = 0, bottom = 0, right = 0;
    if (SDL_GetWindowBordersSize(window, &top, &left, &bottom, &right) != 0)
        top = left = bottom = right = 0;  // not known before the window is mapped
    const int rows = static_cast<int>(hud.status.size()) + 2;
    const int screen_w = screen.w - left - right, screen_h = screen.h - top - bottom;
    scale = fit_scale(width, height, hud, rows, asked, screen_w, screen_h);
    if (scale == asked || !notice) return;
    const HudLayout l = layout_hud(scaled_size(width, asked), scaled_size(height, asked), hud);
    notice(ScaleFitted{asked, scale, l.window_width, l.window_height, screen_w, screen_h});
}

// texture sized for a width x height framebuffer, the layout made for `hud`, and the
// window sized to the layout
void Display::Impl::fit(uint32_t width, uint32_t height, const Hud& hud) {
    if (width != fb_width || height != fb_height || !image) {
        if (image) SDL_DestroyTexture(image);
        image = SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING,
                                  static_cast<int>(std::max(width, 1u)),
                                  static_cast<int>(std::max(height, 1u)));
        if (!image) throw DisplayUnavailable(std::string("SDL_CreateTexture: ") + SDL_GetError());
        fb_width = width;
        fb_height = height;
        status_rows = 0;
        choose_scale(width, height, hud);
    }
    layout = layout_hud(scaled(width), scaled(height), hud, status_rows);
    status_rows = std::max(status_rows, static_cast<int>(layout.status.size()));
    resize_window(layout.window_width, layout.window_height);
}

void Display::Impl::resize_window(int w, int h) {
    if (w == win_width && h == win_height) return;
    SDL_SetWindowSize(window, w, h);
    // centre the window when it is first shown, or when it grew off the screen
    int x = 0, y = 0;
    SDL_Rect screen{0, 0, 0, 0};
    SDL_GetWindowPosition(window, &x, &y);
    const bool fits = SDL_GetDisplayUsableBounds(SDL_GetWindowDisplayIndex(window), &screen) != 0 ||
                      (x + w <= screen.x + screen.w && y + h <= screen.y + screen.h);
    if (win_width == 0 || !fits)
        SDL_SetWindowPosition(window, SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED);
    if (win_width == 0) SDL_ShowWindow(window);
    SDL_PumpEvents();  // let the renderer see the new size before drawing
    win_width = w;
    win_height = h;
}

void Display::Impl::draw_image(const Framebuffer& fb, const Recorder* overlay) {
    SDL_SetRenderDrawColor(renderer, 24, 24, 24, 255);
    SDL_RenderClear(renderer);
    if (fb.width() == 0 || fb.height() == 0) return;
    compose_image(fb, overlay, rgb);
    SDL_UpdateTexture(image, nullptr, rgb.data(), static_cast<int>(fb.width() * 3));
    const SDL_Rect dst{0, 0, scaled(fb.width()), scaled(fb.height())};
    SDL_RenderCopy(renderer, image, nullptr, &dst);
}

void Display::Impl::draw_text(const TextRow& row, SDL_Color color) {
    const int ts = layout.text_scale;
    SDL_SetTextureColorMod(font, color.r, color.g, color.b);
    int x = row.box.x;
    for (char c : row.text) {
        const auto u = static_cast<unsigned char>(c);
        const int g = (u >= 32 && u <= 126) ? u - 32 : '?' - 32;
        const SDL_Rect src{g * kCellWidth, 0, kGlyphWidth, kGlyphHeight};
        const SDL_Rect dst{x, row.box.y, kGlyphWidth * ts, kGlyphHeight * ts};
        SDL_RenderCopy(renderer, font, &src, &dst);
        x += kCellWidth * ts;
    }
}

void Display::Impl::draw_hud() {
    for (const TextRow& row : layout.status)
        draw_text(row, SDL_Color{230, 230, 230, 255});
    if (layout.panel_rows.empty()) return;

    // the key panel, over the image
    const SDL_Rect box{layout.panel.x, layout.panel.y, layout.panel.width, layout.panel.height};
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);
    SDL_SetRenderDrawColor(renderer, 0, 0, 0, 200);
    SDL_RenderFillRect(renderer, &box);
    SDL_SetRenderDrawColor(renderer, 255, 210, 80, 255);
    SDL_RenderDrawRect(renderer, &box);
    for (const TextRow& row : layout.panel_rows)
        draw_text(row, SDL_Color{255, 230, 140, 255});
}

// The top-left w x h of what the renderer drew, as RGB888 rows.
std::vector<uint8_t> Display::Impl::read_pixels(int w, int h) {
    std::vector<uint8_t> out(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
    const SDL_Rect area{0, 0, w, h};
    if (w > 0 && h > 0 &&
        SDL_RenderReadPixels(renderer, &area, SDL_PIXELFORMAT_RGB24, out.data(), w * 3) != 0)
        throw std::runtime_error(std::string("SDL_RenderReadPixels: ") + SDL_GetError());
    return out;
}

Display::Display(const std::string& title, double scale, ScaleNotice notice)
    : m(std::make_unique<Impl>()) {
    m->asked = m->scale = std::clamp(scale, 0.125, 8.0);
    m->notice = std::move(notice);
    const bool driver_asked = set_in_environment("SDL_VIDEODRIVER");
#if defined(__unix__) && !defined(__APPLE__)
    // X11 or Wayland: without either there is no screen. Say so before SDL probes its
    // drivers (the Wayland probe prints its own complaint, and SDL would then settle on its
    // offscreen driver: a window nobody sees).
    if (!driver_asked && !set_in_environment("DISPLAY") && !set_in_environment("WAYLAND_DISPLAY"))
        throw DisplayUnavailable(std::string(kNoDisplay) + " (DISPLAY is not set)");
#endif
    SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "0");  // nearest: pixels stay pixels
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0)
        throw DisplayUnavailable(std::string(kNoDisplay) + " (SDL: " + one_line(SDL_GetError()) +
                                 ")");
    const char* driver = SDL_GetCurrentVideoDriver();
    const std::string driver_name = driver ? driver : "";
    if (!driver_asked && (driver_name == "offscreen" || driver_name == "dummy")) {
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
        throw DisplayUnavailable(std::string(kNoDisplay) + " (SDL found only its '" + driver_name +
                                 "' driver)");
    }
    m->window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                 kMinWindowWidth, 480, SDL_WINDOW_HIDDEN);
    if (m->window) m->renderer = SDL_CreateRenderer(m->window, -1, SDL_RENDERER_SOFTWARE);
    if (!m->window || !m->renderer) {
        const std::string why = SDL_GetError();
        if (m->window) SDL_DestroyWindow(m->window);
        SDL_QuitSubSystem(SDL_INIT_VIDEO);
        throw DisplayUnavailable(std::string(kNoDisplay) + " (SDL: " + one_line(why) + ")");
    }
    m->make_font();
}

Display::~Display() {
    if (m->image) SDL_DestroyTexture(m->image);
    if (m->font) SDL_DestroyTexture(m->font);
    SDL_DestroyRenderer(m->renderer);
    SDL_DestroyWindow(m->window);
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

std::vector<InputEvent> Display::poll(int timeout_ms) {
    std::vector<InputEvent> events;
    SDL_Event e;
    bool got = timeout_ms > 0 ? SDL_WaitEventTimeout(&e, timeout_ms) != 0 : SDL_PollEvent(&e) != 0;
    for (; got; got = SDL_PollEvent(&e) != 0) {
        if (e.type == SDL_QUIT) {
            events.push_back(InputEvent{InputEvent::Kind::Quit, 0, 0, 0});
        } else if (e.type == SDL_KEYDOWN) {
            const int key = translate_key(e.key.keysym);
            if (key != 0) events.push_back(InputEvent{InputEvent::Kind::Key, key, 0, 0});
        } else if (e.type == SDL_MOUSEMOTION) {
            events.push_back(InputEvent{InputEvent::Kind::MouseMove, 0, e.motion.x, e.motion.y});
        } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_LEAVE) {
            events.push_back(InputEvent{InputEvent::Kind::MouseLeave, 0, 0, 0});
        }
    }
    return events;
}

void Display::show(const Framebuffer& fb, const Recorder* overlay, const Hud& hud) {
    m->fit(fb.width(), fb.height(), hud);
    m->draw_image(fb, overlay);
    m->draw_hud();
    SDL_RenderPresent(m->renderer);
}

std::vector<uint8_t> Display::capture(const Framebuffer& fb, const Recorder* overlay,
                                      uint32_t& width, uint32_t& height) {
    if (fb.width() != m->fb_width || fb.height() != m->fb_height || !m->image)
        m->fit(fb.width(), fb.height(), Hud{});
    m->draw_image(fb, overlay);
    width = static_cast<uint32_t>(m->scaled(fb.width()));
    height = static_cast<uint32_t>(m->scaled(fb.height()));
    std::vector<uint8_t> rgb = m->read_pixels(static_cast<int>(width), static_cast<int>(height));
    SDL_RenderPresent(m->renderer);
    return rgb;
}

std::vector<uint8_t> Display::capture_window(const Framebuffer& fb, const Recorder* overlay,
                                             const Hud& hud, uint32_t& width, uint32_t& height) {
    m->fit(fb.width(), fb.height(), hud);
    m->draw_image(fb, overlay);
    m->draw_hud();
    width = static_cast<uint32_t>(m->layout.window_width);
    height = static_cast<uint32_t>(m->layout.window_height);
    std::vector<uint8_t> rgb = m->read_pixels(m->layout.window_width, m->layout.window_height);
    SDL_RenderPresent(m->renderer);
    return rgb;
}

double Display::scale() const {
    return m->scale;
}

std::optional<std::pair<uint32_t, uint32_t>> Display::pixel_at(int x, int y) const {
    if (x < 0 || y < 0) return std::nullopt;
    const auto px = static_cast<uint32_t>(x / m->scale),
               py = static_cast<uint32_t>(y / m->scale);  // floor
    if (px >= m->fb_width || py >= m->fb_height) return std::nullopt;
    return std::pair{px, py};
}

}  // namespace fb89::controller
