// The hybrid beam-ray tracer of the paper's §4 (the `beam` method). Warnock-style window
// subdivision with beams for area samples and the ray tracer for point samples:
//   - a window whose beam is a hit (beam_tracer.h) is filled with its path's colour by one
//     FILL_RECT;
//   - a partial or blocked hit is split into four (as evenly as integers allow; no empty
//     window), unless Expr. 2.7, F (16 F_w − D) / (E_w² D), the cost per pixel of going on
//     with beams, exceeds the threshold: then the ray tracer takes every pixel of the
//     window, and ray-traced pixels leave at the end of the frame as DRAW_SPAN runs.
// F is the scene's face count, F_w the faces meeting the window's first beam segment (a
// query of its own), D the scene's depth complexity (measured at set-up), E_w² the window's
// area in pixels (non-square windows). Threshold infinity is beam subdivision down to single
// pixels; 0 hands every window that is not a hit to the ray tracer at once.
//
// Corner rays are shared: a sub-window reuses the corner it shares with its parent, and a
// window given to the ray tracer does not trace its corners again; every ray traced is
// counted. Every pixel shows what the ray tracer alone would show (tests/host/trace).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "host/raster/renderer.h"
#include "host/trace/beam_tracer.h"
#include "host/trace/ray_tracer.h"

namespace fb89::host {

// The Expr. 2.7 threshold `fb89 calibrate --method beam` chooses on G, H, I and the mirrored
// Cornell box with the 8-wide BVH, now that a window of at most 4x4 pixels whose beam fails
// goes to rays at once: infinity, the ramp's last point (docs/RESULTS.md §4; the test
// CalibrateBeam.TheDefaultThresholdIsAPointOfTheRamp keeps it one): Expr. 2.7's F_w query
// costs more than the windows it sends to rays save. The default until a machine is
// calibrated.
inline constexpr double kDefaultBeamThreshold = std::numeric_limits<double>::infinity();

struct BeamOptions {
    double threshold = kDefaultBeamThreshold;   // Expr. 2.7 threshold (inf: down to pixels)
    double grid_density = kDefaultGridDensity;  // Accel::Grid: the grid's top-level cells per piece
};

class BeamRayHybrid final : public Renderer {
  public:
    explicit BeamRayHybrid(BeamOptions options = {}, TraceOptions trace = {})
        : m_options(options), m_trace_options(trace) {}
    std::string_view name() const override { return "beam"; }
    void setup(const ScreenScene& scene) override;
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;

    // After render: per pixel, 1 when a beam decided it, 0 when the ray tracer did (made
    // from the frame's beam windows when asked for).
    const std::vector<uint8_t>& beam_mask() const;
    double depth_complexity() const { return m_depth; }

  private:
    struct Frame;
    void window(Frame& frame, const PixelRect& w, const RayTrace* const corners[4]);
    void rays_for_window(Frame& frame, const PixelRect& w, const RayTrace* const corners[4]);
    // The faces the corners' primary rays hit first, each counted once.
    uint32_t distinct_first_faces(const RayTrace* const corners[4]) const;

    BeamOptions m_options;
    TraceOptions m_trace_options;
    TraceSetup m_trace;
    std::unique_ptr<BeamTracer> m_beams;
    double m_depth = 1;
    int m_width = 0, m_height = 0;
    // Ray-traced pixels, packed_pixel(); 0 elsewhere, and 0 everywhere between frames: only
    // the columns [m_row_from[y], m_row_to[y]) of row y were written this frame, so only
    // they are sent and cleared (beams decide most pixels of a coherent scene).
    std::vector<uint32_t> m_pixels;
    std::vector<int> m_row_from, m_row_to;
    bool m_pixels_clean = true;                // false while a frame is being made
    std::vector<PixelRect> m_beam_windows;     // the frame's windows decided by beams
    mutable std::vector<uint8_t> m_beam_mask;  // beam_mask(), made on demand
};

}  // namespace fb89::host
