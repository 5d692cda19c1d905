// The paper's experiments as functions that return tables; cli/experiment_command.cpp
// only parses options and writes the tables out.
#pragma once

#include <string>
#include <vector>

#include "cli/common.h"
#include "controller_sim/profile.h"
#include "host/raster/renderer.h"
#include "host/scene/scene.h"
#include "protocol/memory_buffer.h"

namespace fb89::cli {

// Rows of named columns, printed aligned for people and as CSV for charts.
class Table {
  public:
    explicit Table(std::vector<std::string> columns = {}) : m_columns(std::move(columns)) {}
    void add(std::vector<std::string> row) { m_rows.push_back(std::move(row)); }
    std::string csv() const;
    std::string text() const;
    const std::vector<std::vector<std::string>>& rows() const { return m_rows; }

  private:
    std::vector<std::string> m_columns;
    std::vector<std::vector<std::string>> m_rows;
};

struct ExperimentSettings {
    std::vector<std::string> scenes;
    ImageSize size;  // 0 x 0: each scene's own
    int repeat = 7;
    std::string profile = "tms34010-50mhz";
    bool progress = false;
};

// One setting's result of interleaved timing: the median time, the counters and commands
// of its last frame (every frame is the same).
struct Measured {
    host::Timing median;
    host::Counters counters;
    protocol::MemoryBuffer commands;
};
std::vector<Measured> measure_interleaved(const host::ScreenScene& screen,
                                          const std::vector<host::RenderOptions>& settings,
                                          int repeat, const std::string& label, bool progress);

// What the controller makes of one frame's commands under a profile.
struct ControllerFigures {
    uint64_t commands = 0, fills = 0, spans = 0;
    double controller_ms = 0, bus_ms = 0, frame_ms = 0;
};
ControllerFigures controller_figures(const protocol::MemoryBuffer& commands,
                                     const controller::CostProfile& profile);

host::ScreenScene load_screen(const std::string& file, const ExperimentSettings& s,
                              host::Scene& scene);
std::string fixed(double v, int digits);

Table experiment_fig2_1(const ExperimentSettings& settings);

// `steps` thresholds from `from` to `to`, evenly spaced on a log scale.
std::vector<double> threshold_ramp(double from, double to, int steps);
// The hybrid (options `base`, method and threshold replaced) at each threshold, on each
// scene, timed interleaved: one row per scene and threshold.
// Exact and approximate Warnock and hybrid (at `threshold`) against the Z-buffer: time,
// commands and pixels wrong.
Table experiment_accuracy(const ExperimentSettings& settings, double threshold);

// Fig. 3.1: the threshold sweep on each scene, including `chosen` and the paper's 0.04.
Table experiment_fig3_1(const ExperimentSettings& settings, double chosen);
// The hybrid at `chosen` and at the paper's 0.04 against the Z-buffer, per scene.
Table experiment_hybrid(const ExperimentSettings& settings, double chosen);

Table sweep_threshold(const ExperimentSettings& settings, const std::vector<double>& thresholds,
                      const host::RenderOptions& base);
Table experiment_fig2_4(const ExperimentSettings& settings);

// §4 (cli/trace_experiments.cpp). Figs. 4.8, 4.11: the ray tracer alone and the beam-ray
// hybrid at `threshold`, whole process timed interleaved, at each size, per scene.
Table experiment_beam_resolution(const ExperimentSettings& settings,
                                 const std::vector<ImageSize>& sizes, double threshold);
// Figs. 4.7, 4.10: each scene's beam-ray frame and its mask, written to `out_dir`.
Table experiment_beam_masks(const ExperimentSettings& settings, double threshold,
                            const std::string& out_dir);
// Hidden-surface time and pixels by beams against the Expr. 2.7 threshold (first row per
// scene: the ray tracer alone); every row says whether its frame equals the ray tracer's.
Table experiment_beam_threshold(const ExperimentSettings& settings,
                                const std::vector<double>& thresholds);
std::vector<double> beam_threshold_ramp();  // 0, 0.01 ... 1000 on a log scale, inf

// §5 (cli/radiosity_experiments.cpp). The paper's table: rays, volume queries and
// form-factor time of flux tracing and the decahedral hybrid per room, interleaved; about
// `patches` patches per room (0: the paper's count for the bundled rooms, else 800).
Table experiment_radiosity(const ExperimentSettings& settings, int patches);
// Form-factor error against time per method (flux, hybrid, disk, hemicubes), against a
// reference of exact form factors times fractional visibility from reference_n^4 rays per
// pair; with `solve`, also the radiosity error of each method's solution.
Table experiment_form_factor_error(const ExperimentSettings& settings, int patches, int reference_n,
                                   bool solve);

}  // namespace fb89::cli
