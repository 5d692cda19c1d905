// `fb89 compare`'s algorithm: every method on one scene, timed, costed and counted against
// the Z-buffer's face ids, and the contact sheet of their frames with captions drawn in
// the bitmap font.
#include "experiments/compare.h"

#include <algorithm>

#include <fmt/format.h>

#include "controller_sim/bitmap_font.h"
#include "controller_sim/controller.h"
#include "controller_sim/hud_layout.h"
#include "experiments/depth_agreement.h"
#include "experiments/id_pass.h"
#include "experiments/period_runs.h"
#include "experiments/render_job.h"
#include "host/raster/screen_setup.h"

namespace fb89::experiments {

namespace {

constexpr uint32_t kMaxColumns = 3, kThumbWidth = 256, kGap = 8, kCaptionLines = 7;
constexpr uint64_t kMaxThumbHeight = 4 * kThumbWidth;  // a frame far taller than wide
constexpr protocol::Rgb kBackground{24, 24, 28}, kBand{44, 44, 52};
constexpr protocol::Rgb kWhite{255, 255, 255}, kGrey{200, 200, 200};

// The frame the controller holds after `commands`: pixels do not depend on the profile but
// for the depth commands' on its depth word, `depth_bits`.
controller::Framebuffer frame_of(const protocol::MemoryBuffer& commands, uint32_t depth_bits) {
    controller::CostProfile ideal = controller::load_profile("ideal");
    ideal.depth_bits = depth_bits;
    controller::Controller ctl(std::move(ideal));
    commands.replay_into(ctl);
    return ctl.framebuffer();
}

controller::Framebuffer ids_of(const host::Scene& scene, const host::MethodOptions& o,
                               uint32_t depth_bits = 32) {
    auto renderer = host::make_renderer(o);
    return id_framebuffer(scene, *renderer, depth_bits);
}

}  // namespace

// Pixels whose face ids differ, split as the tests split them: coverage (one frame has a face
// there, the other the background) apart from the other face (both covered, by different
// faces: a shared edge or a depth tie decided the other way).
IdDifferences id_differences(const controller::Framebuffer& a, const controller::Framebuffer& b) {
    const auto pa = a.pixels(), pb = b.pixels();
    IdDifferences d;
    if (pa.size() != pb.size()) {
        d.coverage = std::max(pa.size(), pb.size()) / 3;
        return d;
    }
    for (size_t i = 0; i + 2 < pa.size(); i += 3) {
        if (pa[i] == pb[i] && pa[i + 1] == pb[i + 1] && pa[i + 2] == pb[i + 2]) continue;
        const bool covered_a = pa[i] || pa[i + 1] || pa[i + 2];  // id + 1; 0 = background
        const bool covered_b = pb[i] || pb[i + 1] || pb[i + 2];
        ++(covered_a && covered_b ? d.other_face : d.coverage);
    }
    return d;
}

namespace {

// `frame` scaled to the thumbnail by point sampling, its top-left corner at (x0, y0).
void draw_thumbnail(controller::Framebuffer& sheet, const controller::Framebuffer& frame,
                    const SheetLayout& l, uint32_t x0, uint32_t y0) {
    if (frame.width() == 0 || frame.height() == 0) return;
    for (uint32_t y = 0; y < l.thumb_height; ++y) {
        const auto sy = static_cast<uint32_t>(uint64_t{y} * frame.height() / l.thumb_height);
        for (uint32_t x = 0; x < l.thumb_width; ++x) {
            const auto sx = static_cast<uint32_t>(uint64_t{x} * frame.width() / l.thumb_width);
            sheet.set_pixel(x0 + x, y0 + y, frame.pixel(sx, sy));
        }
    }
}

std::vector<std::string> caption(const CompareRow& row) {
    return {row.method,
            fmt::format("host {:.3f} ms", row.host_ms),
            fmt::format("controller {:.3f} ms", row.controller.frame_ms),
            fmt::format("frame {:.3f} ms, {}-bound", row.frame_ms,
                        row.host_bound ? "host" : "controller"),
            fmt::format("{} commands", row.controller.commands),
            row.depth
                ? fmt::format("{} faces, {} depth spans", row.controller.faces,
                              row.controller.depth_spans)
                : fmt::format("{} fills, {} spans", row.controller.fills, row.controller.spans),
            row.depth ? fmt::format("{} px differ: {} ties", row.ids.total(), row.depth->ties)
                      : fmt::format("{} px differ from zbuffer", row.ids.total())};
}

controller::Framebuffer draw_sheet(const Comparison& c) {
    const SheetLayout l = sheet_layout(c.width, c.height, c.frames.size(), sheet_title(c));
    controller::Framebuffer sheet(l.width, l.height);
    sheet.clear(kBackground);
    for (size_t k = 0; k < l.title_rows.size(); ++k)
        draw_text(sheet, static_cast<int>(l.gap),
                  static_cast<int>(l.title_y + k * controller::kCellHeight), l.title_rows[k],
                  kWhite);
    for (size_t i = 0; i < c.frames.size(); ++i) {
        const uint32_t x = l.gap + static_cast<uint32_t>(i % l.columns) * (l.thumb_width + l.gap);
        const uint32_t y = l.title_height + static_cast<uint32_t>(i / l.columns) *
                                                (l.thumb_height + l.caption_height + l.gap);
        draw_thumbnail(sheet, c.frames[i], l, x, y);
        sheet.fill_rect({x, y + l.thumb_height, l.thumb_width, l.caption_height}, kBand);
        const std::vector<std::string> lines = caption(c.rows[i]);
        for (size_t k = 0; k < lines.size(); ++k)
            draw_text(sheet, static_cast<int>(x) + 4,
                      static_cast<int>(y + l.thumb_height) + 4 +
                          static_cast<int>(k) * controller::kCellHeight,
                      lines[k], k == 0 ? kWhite : kGrey);
    }
    return sheet;
}

}  // namespace

Comparison compare_methods(const std::string& file,
                           const std::vector<host::MethodOptions>& settings,
                           const ExperimentSettings& s, const std::string& name) {
    Comparison c;
    c.scene = file;
    c.name = name.empty() ? file : name;
    c.host = s.period ? s.period->profile().name : "native";
    c.profile = s.profile;
    RenderJob job;
    job.scene = file;
    job.methods = settings;
    job.size = s.size;
    job.repeat = s.period ? 0 : s.repeat;
    job.controller = s.profile;
    job.progress = s.progress;
    job.period = s.period;
    const RenderResult r = run_render_job(job);
    c.width = static_cast<uint32_t>(r.screen.width);
    c.height = static_cast<uint32_t>(r.screen.height);
    // the frames as the named profile's controller draws them: its depth word decides the
    // depth commands' ties
    const uint32_t depth_bits = controller::load_profile(s.profile).depth_bits;
    c.depth_bits = depth_bits;
    const controller::Framebuffer truth = ids_of(r.scene, host::Method::ZBuffer);
    std::optional<host::ScreenScene> id_screen;  // the scene in id mode, for the ties
    for (const MethodRun& run : r.runs) {
        CompareRow row;
        row.method = std::string(host::method_info(run.options.method).name);
        row.host_ms = run.host_frame_ms;
        row.controller = run.controller;
        row.frame_ms = run.split.frame_ms;
        row.host_bound = run.split.host_bounds;
        const controller::Framebuffer ids = ids_of(r.scene, run.options, depth_bits);
        row.ids = id_differences(truth, ids);
        if (host::method_info(run.options.method).depth_commands) {
            if (!id_screen) {
                host::Counters counters;
                id_screen = host::project_scene(r.scene, host::ColorMode::FaceId, counters);
            }
            row.depth = depth_agreement(*id_screen, truth, ids, depth_bits);
        }
        row.pipeline = run.pipeline;
        c.rows.push_back(row);
        c.frames.push_back(frame_of(run.commands, depth_bits));
    }
    c.sheet = draw_sheet(c);
    return c;
}

Table comparison_table(const Comparison& c) {
    Table table({"scene",
                 "method",
                 "host",
                 "host_ms",
                 "commands",
                 "fills",
                 "spans",
                 "controller_ms",
                 "frame_ms",
                 "bound_by",
                 "pixels_differing",
                 "px_coverage",
                 "px_other_face",
                 "pipeline_ms",
                 "overlap",
                 "host_stalled_ms",
                 "host_util",
                 "controller_util",
                 "px_ties",
                 "depth_bits",
                 "depth_spans",
                 "faces"});
    for (const CompareRow& r : c.rows) {
        std::vector<std::string> row = {c.name,
                                        r.method,
                                        c.host,
                                        fixed(r.host_ms, 3),
                                        std::to_string(r.controller.commands),
                                        std::to_string(r.controller.fills),
                                        std::to_string(r.controller.spans),
                                        fixed(r.controller.frame_ms, 3),
                                        fixed(r.frame_ms, 3),
                                        r.host_bound ? "host" : "controller",
                                        std::to_string(r.ids.total()),
                                        std::to_string(r.ids.coverage),
                                        std::to_string(r.ids.other_face)};
        if (r.pipeline) {
            const double frame = r.pipeline->frame_us / 1e3;
            row.insert(row.end(), {fixed(frame, 3), fixed(r.pipeline->overlap(), 4),
                                   fixed(r.pipeline->host_stalled_us / 1e3, 3),
                                   fixed(r.pipeline->host_utilization(), 4),
                                   fixed(r.pipeline->controller_utilization(), 4)});
        } else {
            row.resize(row.size() + 5);
        }
        // the depth commands' ties of the depth word (empty for the other methods)
        row.insert(row.end(),
                   {r.depth ? std::to_string(r.depth->ties) : "",
                    r.depth ? std::to_string(c.depth_bits) : "",
                    std::to_string(r.controller.depth_spans), std::to_string(r.controller.faces)});
        table.add(std::move(row));
    }
    return table;
}

SheetLayout sheet_layout(uint32_t width, uint32_t height, size_t tiles, const std::string& title) {
    SheetLayout l;
    const auto n = static_cast<uint32_t>(std::max<size_t>(tiles, 1));
    l.columns = std::min(n, kMaxColumns);
    l.rows = (n + l.columns - 1) / l.columns;
    l.gap = kGap;
    l.thumb_width = kThumbWidth;
    const uint64_t scaled = width > 0 ? (uint64_t{height} * kThumbWidth + width / 2) / width : 1;
    l.thumb_height = static_cast<uint32_t>(std::clamp<uint64_t>(scaled, 1, kMaxThumbHeight));
    l.caption_height = kCaptionLines * controller::kCellHeight + 6;
    l.width = l.columns * l.thumb_width + (l.columns + 1) * l.gap;
    const auto title_columns = static_cast<int>((l.width - 2 * l.gap) / controller::kCellWidth);
    l.title_rows = controller::wrap_line(title, title_columns);
    l.title_height =
        static_cast<uint32_t>(l.title_rows.size()) * controller::kCellHeight + 2 * kGap;
    l.title_y = kGap + (controller::kCellHeight - controller::kGlyphHeight) / 2;
    l.height = l.title_height + l.rows * (l.thumb_height + l.caption_height + l.gap);
    return l;
}

std::string sheet_title(const Comparison& c) {
    return fmt::format("{}  {}x{}  host {}  controller {}", c.name, c.width, c.height, c.host,
                       c.profile);
}

void draw_text(controller::Framebuffer& fb, int x, int y, const std::string& text,
               protocol::Rgb color) {
    for (size_t i = 0; i < text.size(); ++i) {
        const controller::Glyph& g = controller::glyph(text[i]);
        const int left = x + static_cast<int>(i) * controller::kCellWidth;
        for (int row = 0; row < controller::kGlyphHeight; ++row)
            for (int col = 0; col < controller::kGlyphWidth; ++col)
                if (controller::glyph_pixel(g, col, row) && fb.contains(left + col, y + row))
                    fb.set_pixel(static_cast<uint32_t>(left + col), static_cast<uint32_t>(y + row),
                                 color);
    }
}

}  // namespace fb89::experiments
