// Speed against accuracy for one scene in one go (`fb89 compare`): one render job
// (render_job.h) of every given method, timed as the experiments time them (interleaved
// rounds here, or modelled from emulated runs on a 1989 host), its commands costed by the
// controller, its face-id buffer counted against the Z-buffer's, and its frame laid out on a
// contact sheet with a caption of those figures under it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "controller_sim/framebuffer.h"
#include "controller_sim/timed_pipeline.h"
#include "experiments/depth_agreement.h"
#include "experiments/measure.h"
#include "experiments/settings.h"
#include "experiments/table.h"
#include "host/methods.h"

namespace fb89::experiments {

// Face ids that differ from the Z-buffer's, pixel by pixel.
struct IdDifferences {
    uint64_t coverage = 0;    // one frame has a face there, the other the background
    uint64_t other_face = 0;  // both have a face there, different ones
    uint64_t total() const { return coverage + other_face; }
};
IdDifferences id_differences(const controller::Framebuffer& a, const controller::Framebuffer& b);

// One method's figures. The host's time per frame is set-up (projection and the method's
// own) plus hidden-surface, as in the split; the controller's is its modelled frame time;
// the two-stage pipeline's frame time is the larger of them.
struct CompareRow {
    std::string method;
    double host_ms = 0;
    ControllerFigures controller;  // commands, fills, spans; frame_ms is the controller's time
    double frame_ms = 0;
    bool host_bound = false;  // the host's time bounds the frame, not the controller's
    IdDifferences ids;        // face ids that differ from the Z-buffer's
    // for the methods that send depth commands: of those, the ties of the profile's depth word
    std::optional<DepthAgreement> depth;
    // the frame through the pipeline in time (render_job.h), when it has send times
    std::optional<FramePipeline> pipeline;
};

struct Comparison {
    std::string scene;        // the file as given
    std::string name;         // how the sheet and the table name the scene (default: the file)
    std::string host;         // "native" or the 1989 host profile's name
    std::string profile;      // the controller's cost profile
    uint32_t depth_bits = 0;  // its depth word, which the depth commands' frames are drawn with
    uint32_t width = 0, height = 0;
    std::vector<CompareRow> rows;                 // one per method, in the order given
    std::vector<controller::Framebuffer> frames;  // each method's shaded frame
    controller::Framebuffer sheet;                // the contact sheet of the frames
};

// Renders `file` with each of `settings` (times under `s`; s.scenes is not read) and lays
// out the sheet, naming the scene `name` there and in the table (the file when empty: a
// front end passes a bundled scene's name, or the path as the user gave it). Throws what
// loading the scene or the profile throws.
Comparison compare_methods(const std::string& file,
                           const std::vector<host::MethodOptions>& settings,
                           const ExperimentSettings& s, const std::string& name = "");

// The rows as a table: scene, method, host, host_ms, commands, fills, spans, controller_ms,
// frame_ms, bound_by, pixels_differing (px_coverage + px_other_face), then the pipeline in
// time: pipeline_ms, overlap, host_stalled_ms, host_util, controller_util (empty without
// send times), then px_ties and depth_bits (of pixels_differing, the ties of the profile's
// depth word; the depth-command methods only) and the depth commands sent (depth_spans,
// faces). Every frame is the one the profile's controller draws.
Table comparison_table(const Comparison& c);

// Where things go on the contact sheet: a title band, then `columns` x `rows` tiles, each
// the frame scaled to thumb_width (point sampled) with a caption band under it.
struct SheetLayout {
    uint32_t columns = 0, rows = 0;
    uint32_t thumb_width = 0, thumb_height = 0;
    uint32_t caption_height = 0, title_height = 0, gap = 0;
    uint32_t width = 0, height = 0;  // of the whole sheet
    // the title's rows, wrapped to the sheet's width (controller::wrap_line), each drawn at
    // x = gap, y = title_y + k * kCellHeight
    std::vector<std::string> title_rows;
    uint32_t title_y = 0;
};
// The layout for `tiles` frames of width x height: up to 3 columns, thumbnails 256 px wide,
// the title band as tall as `title` takes.
SheetLayout sheet_layout(uint32_t width, uint32_t height, size_t tiles,
                         const std::string& title = "");

// The sheet's title: the scene's name, the frame's size, the host and the controller's
// profile.
std::string sheet_title(const Comparison& c);

// Draws `text` in the 5x7 bitmap font (controller_sim/bitmap_font.h) with its top-left
// corner at (x, y), one 6x10 cell per character; pixels outside `fb` are skipped.
void draw_text(controller::Framebuffer& fb, int x, int y, const std::string& text,
               protocol::Rgb color);

}  // namespace fb89::experiments
