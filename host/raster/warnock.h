// Warnock's area-subdivision hidden-surface algorithm as the paper's §1 describes it: a
// looker that samples a window and, when the thinker fails, splits it evenly into four;
// a thinker that succeeds on an empty window (background: counted, nothing sent, since
// FRAME_BEGIN cleared the frame) or on a window one face S surrounds and is in front of
// (one FILL_RECT in S's colour). Instrumented as §2 counts it: window samples (thinker
// calls) and face computations (a face sorted whole into one sub-window, or split across
// several), plus windows filled by size and recursion depth.
//
// Two window tests (DESIGN.md), giving the same face-id buffer:
// - area (the paper's, what Eqs. 2.1-2.4 model): a face goes into a sub-window when its
//   interior overlaps the sub-window's; S surrounds when it contains the closed window;
// - centres (sampling-aware): a face goes into a sub-window only if it covers one of its
//   pixel centres; S surrounds when it covers every centre; empty means no centre covered.
// Where ours differs from the paper: coverage and depth come from the shared rule
// (coverage.h, depth.h); "in front" is checked on the planes at the window's corner
// centres with a rounding margin, and a thinker that cannot prove it declines; a 1-pixel
// window is resolved by point sampling at its centre (and filled 1x1); odd windows split
// as evenly as integers allow and no empty sub-window is made.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "host/raster/renderer.h"

namespace fb89::host {

enum class WindowTest { Area, Centres };
const char* to_string(WindowTest t);

// What the looker may hand a window to instead of sampling it: the Warnock/Z-buffer
// hybrid (hybrid.h). `faces` are the window's faces, ascending scene.faces indices.
class WindowHandoff {
  public:
    virtual ~WindowHandoff() = default;
    // Returns true when it took the window (and sent its commands).
    virtual bool take(const ScreenScene& scene, const PixelRect& window,
                      std::span<const uint32_t> faces, protocol::CommandSink& sink) = 0;
};

// Speed against accuracy: let the thinker fill a window whose shorter side is at least
// `min_side` with a face in front that covers all but a fraction `epsilon` of its pixel
// centres. Off (exact) when min_side is 0.
struct Approximation {
    int min_side = 0;
    double epsilon = 0;
};

// Warnock's options, shared by the hybrid, which runs Warnock's looker.
struct WarnockOptions {
    WindowTest window_test = WindowTest::Area;  // the paper's
    Approximation approx;                       // exact
};

struct WarnockCounts {
    uint64_t samples = 0;        // thinker calls (window samples)
    uint64_t face_sorts = 0;     // face computations: a face into exactly one sub-window
    uint64_t face_splits = 0;    // face computations: a face across two or more
    uint64_t face_drops = 0;     // centres test: faces that reached no sub-window's centre
    uint64_t empty_windows = 0;  // background, nothing sent
    uint64_t surrounded = 0;     // windows filled by a surrounder in front
    uint64_t pixel_windows = 0;  // 1-pixel windows resolved by point sampling
    uint64_t fills = 0;          // FILL_RECT commands sent
    uint64_t filled_pixels = 0;
    uint64_t front_tests = 0;        // surrounder-in-front checks of one face pair
    uint64_t max_depth = 0;          // deepest recursion level (the screen is level 0)
    uint64_t handed_over = 0;        // windows the looker handed to a WindowHandoff
    uint64_t approximate_fills = 0;  // windows filled by a face missing some centres
    // Filled windows by the shorter side: [k] counts sides in [2^k, 2^(k+1)).
    std::array<uint64_t, 16> fills_by_side{};

    void publish(Counters& counters) const;
};

class Warnock final : public Renderer {
  public:
    explicit Warnock(WarnockOptions options = {})
        : m_test(options.window_test), m_approx(options.approx) {}
    // The looker offers every window to `handoff` before sampling it (null: never).
    void set_handoff(WindowHandoff* handoff) { m_handoff = handoff; }
    std::string_view name() const override { return "warnock"; }
    void setup(const ScreenScene& scene) override;
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;

    // The counts of the last render.
    const WarnockCounts& counts() const { return m_counts; }

  private:
    struct Box {  // bounding box of a face's snapped vertices, in 1/256 pixel
        int64_t x0, y0, x1, y1;
    };
    void look(const PixelRect& window, size_t begin, size_t end, uint64_t depth);
    bool think(const PixelRect& window, size_t begin, size_t end);
    bool resolve_pixel(const PixelRect& window, size_t begin, size_t end);
    bool in_front(uint32_t s, const PixelRect& window, size_t begin, size_t end);
    bool surrounds(uint32_t face, const PixelRect& window) const;
    bool belongs(uint32_t face, const PixelRect& window) const;
    bool interiors_overlap(uint32_t face, const PixelRect& window) const;
    bool covers_a_centre(uint32_t face, const PixelRect& window) const;
    bool nearly_surrounds(uint32_t face, const PixelRect& window) const;
    void fill(const PixelRect& window, protocol::Rgb color);

    WindowTest m_test;
    Approximation m_approx;
    WindowHandoff* m_handoff = nullptr;
    const ScreenScene* m_scene = nullptr;
    protocol::CommandSink* m_sink = nullptr;
    std::vector<Box> m_boxes;
    std::vector<uint32_t> m_arena;  // face lists of the windows on the recursion path
    WarnockCounts m_counts;
};

}  // namespace fb89::host
