// The Warnock/Z-buffer hybrid of the paper's §3. The looker counts the faces of its window
// F_w, estimates the window's depth complexity D and evaluates Expr. 3.1,
//     (F_w log4(F_w / D) + F_w) / E_w^2,
// a cost per pixel of carrying on with window sampling; when it exceeds the threshold (the
// Z-buffer's cost per pixel, found by calibration) the window goes to the Z-buffer,
// restricted to that window and to the window's faces, and leaves as DRAW_SPANs; otherwise
// the thinker goes on and filled windows leave as FILL_RECTs. Threshold 0 is the pure
// Z-buffer, infinity pure Warnock; every threshold gives the Z-buffer's face-id buffer.
//
// How ours handles what the paper leaves open:
// - non-square windows: E_w^2 is the window's area w*h;
// - F_w <= D (at most one visible face left): log4(F_w / D) is taken as 0, leaving the
//   splitting-phase cost F_w / E_w^2 (the sorting phase is over);
// - D: by default the window's own, estimated as the faces' screen area inside the window
//   over the window's area (each face's area scaled by the share of its bounding box that
//   lies in the window), at least 1; or the scene's (the paper's wording), the same
//   estimate over the whole screen, fixed for the frame.
#pragma once

#include "host/raster/warnock.h"
#include "host/raster/zbuffer.h"

namespace fb89::host {

enum class DepthEstimate { Window, Scene };

// The paper's calibrated threshold for Expr. 3.1 (§3).
inline constexpr double kPaperThreshold = 0.04;

struct HybridOptions {
    double threshold = kPaperThreshold;
    DepthEstimate depth = DepthEstimate::Window;
};

// Expr. 3.1 (host/model) for a window of `faces` faces, depth complexity `depth` and `area`
// pixels, with the conventions above.
double expr_3_1_cost(double faces, double depth, double area);

class Hybrid final : public Renderer, private WindowHandoff {
  public:
    explicit Hybrid(HybridOptions options = {}, WarnockOptions warnock = {});
    std::string_view name() const override { return "hybrid"; }
    void setup(const ScreenScene& scene) override;
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;
    const HybridOptions& options() const { return m_options; }

  private:
    bool take(const ScreenScene& scene, const PixelRect& window, std::span<const uint32_t> faces,
              protocol::CommandSink& sink) override;
    double window_depth(const PixelRect& window, std::span<const uint32_t> faces) const;

    struct FaceArea {
        double area;            // on screen, in pixels
        double x0, y0, x1, y1;  // bounding box, in pixels
    };
    HybridOptions m_options;
    Warnock m_warnock;
    ZBuffer m_zbuffer;
    std::vector<FaceArea> m_areas;
    std::vector<uint32_t> m_all;  // every face, for the first window
    double m_scene_depth = 1;
    const ScreenScene* m_setup_for = nullptr;
    ZBufferCounts m_zcounts;
    uint64_t m_zbuffer_pixels = 0;
};

}  // namespace fb89::host
