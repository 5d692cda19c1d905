// The ray peer: Intel Embree 3 (REFERENCES.md "Ray peer: Embree 3"), tracing the primary
// rays of a world scene so that its face-id buffer can be compared with our ray tracer's and
// its time with our `raytrace` and `beam` methods.
//
// Set-up: one device made with "threads=1"; one scene holding one triangle geometry; every
// face piece of the host::Scene is fan-triangulated (v0, vi, vi+1) with its vertices
// rounded to float, and each triangle's primID maps back to the piece's face id. Build
// quality and the scene flags (robust, compact) are options; the build is set-up, untimed.
//
// Rays: exactly host::TraceScene::pixel_ray(x, y) (gluLookAt + gluPerspective through pixel
// centres, or along +z for a screen-space scene), each component rounded to float, with
// tnear 0 and tfar infinity; they are generated inside the traced loop, as ours generates
// its own. A frame fills a buffer of ids + 1 per pixel (0 = miss), row 0 at the top; nothing
// is shaded and no command is emitted. Two ways of tracing a frame:
//   - `trace_single`: rtcIntersect1 per pixel, row by row;
//   - `trace_packets`: 4x4-pixel tiles as one rtcIntersect16 packet each, with the context
//     flag RTC_INTERSECT_CONTEXT_FLAG_COHERENT (lanes outside the image are masked off).
// Differences from ours: Embree intersects in single precision, and in its default mode a
// ray may slip through an edge two triangles share; RTC_SCENE_FLAG_ROBUST makes the test
// watertight. Equal hit distances go to whichever triangle Embree meets first; ours gives
// them to the lower piece.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "host/scene/scene.h"
#include "host/trace/trace_scene.h"

namespace fb89::peers {

enum class EmbreeQuality { Low, Medium, High };  // RTC_BUILD_QUALITY_*

struct EmbreeOptions {
    EmbreeQuality quality = EmbreeQuality::High;
    bool robust = false;   // RTC_SCENE_FLAG_ROBUST
    bool compact = false;  // RTC_SCENE_FLAG_COMPACT
};

// "low", "medium", "high"; throws std::invalid_argument otherwise.
EmbreeQuality parse_embree_quality(const std::string& name);
std::string to_string(EmbreeQuality quality);

class EmbreeTracer {
  public:
    // Throws std::runtime_error when Embree reports an error. `scene` need not outlive this.
    explicit EmbreeTracer(const host::Scene& scene, EmbreeOptions options = {});
    ~EmbreeTracer();
    EmbreeTracer(const EmbreeTracer&) = delete;
    EmbreeTracer& operator=(const EmbreeTracer&) = delete;

    // One frame of primary rays into `ids` (resized to width x height): ids + 1, 0 = miss.
    void trace_single(std::vector<uint32_t>& ids) const;
    void trace_packets(std::vector<uint32_t>& ids) const;

    int width() const { return m_rays.width(); }
    int height() const { return m_rays.height(); }
    uint64_t triangles() const { return m_face_of_triangle.size(); }
    const EmbreeOptions& options() const { return m_options; }
    std::string description() const;  // Embree's version, build quality and flags

  private:
    void check(const char* what) const;

    EmbreeOptions m_options;
    host::TraceScene m_rays;                   // for pixel_ray(); its faces are not used
    std::vector<uint32_t> m_face_of_triangle;  // primID -> face id
    void* m_device = nullptr;                  // RTCDevice
    void* m_scene = nullptr;                   // RTCScene
};

}  // namespace fb89::peers
