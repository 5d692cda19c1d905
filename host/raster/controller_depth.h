// The two methods that move the split (docs/RESULTS.md, "Moving the split"): the host does
// less and sends the controller depth commands (stream format version 3), which it tests
// itself (controller_sim/controller.cpp; the pixel loops priced in controller_sim/gsp).
//
// - `zspans`: the host scan-converts. Each face, in id order, row by row through the shared
//   coverage rule (row_span), leaves as a DEPTH_SPAN with its depth at the run's first pixel
//   and its step; the host tests no depth and keeps no buffer.
// - `faces`: the host only projects, clips and snaps (the set-up stage every method shares)
//   and sends each convex piece as a FACE with its depth plane; the controller scan-converts
//   it by the same rule (protocol/coverage.h: one implementation, both sides).
//
// Both open the frame with DEPTH_CLEAR. Depth travels in fixed point (protocol/depth_fixed.h),
// so where two faces' depths lie within its resolution the controller may keep the other
// face than the host Z-buffer's exact rule: those pixels are the ties
// (experiments/depth_agreement.h counts them). A face whose slope does not fit 32 bits (a
// face almost edge-on, a pixel wide) goes as DEPTH_SPANs from `faces` too; one with more than
// kMaxFacePoints points goes as fans of them, whose shared diagonals the top-left rule gives
// to one side.
#pragma once

#include "host/raster/renderer.h"

namespace fb89::host {

class DepthSpans final : public Renderer {
  public:
    std::string_view name() const override { return "zspans"; }
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;
};

class FaceSender final : public Renderer {
  public:
    std::string_view name() const override { return "faces"; }
    void render(const ScreenScene& scene, protocol::CommandSink& sink, HostStats& stats) override;
};

// A face's depth spans, as `zspans` sends them, for rows [bounds.y0, bounds.y1); returns the
// spans sent and adds the pixels they cover to `pixels`.
uint64_t send_depth_spans(const ScreenScene& scene, const ScreenFace& face,
                          protocol::CommandSink& sink, uint64_t& pixels);

}  // namespace fb89::host
