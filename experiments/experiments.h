// The paper's experiments as functions that return tables: the library fb89_experiments,
// which `fb89 experiment`, `sweep` and `calibrate` and the tests link. The commands only
// parse options and write the tables out.
#pragma once

#include <string>
#include <vector>

#include "experiments/settings.h"
#include "experiments/table.h"
#include "host/methods.h"

namespace fb89::experiments {

// §2 (raster_experiments.cpp). Fig. 2.1: hidden-surface time of the Z-buffer, scan-line
// and Warnock (both window tests), interleaved, with counts and the controller's figures.
Table experiment_fig2_1(const ExperimentSettings& settings);
// Fig. 2.4: Eq. 2.4's window samples against the counts, on the scenes and ideal scenes.
Table experiment_fig2_4(const ExperimentSettings& settings);

// §3. `steps` thresholds from `from` to `to`, evenly spaced on a log scale.
std::vector<double> threshold_ramp(double from, double to, int steps);
// The hybrid (options `base`, method and threshold replaced) at each threshold, on each
// scene, timed interleaved: one row per scene and threshold.
Table sweep_threshold(const ExperimentSettings& settings, const std::vector<double>& thresholds,
                      const host::MethodOptions& base);
// Exact and approximate Warnock and hybrid (at `threshold`) against the Z-buffer: time,
// commands and pixels wrong.
Table experiment_accuracy(const ExperimentSettings& settings, double threshold);

// Fig. 3.1: the threshold sweep on each scene, including `chosen` and the paper's 0.04.
Table experiment_fig3_1(const ExperimentSettings& settings, double chosen);
// The hybrid at `chosen` and at the paper's 0.04 against the Z-buffer, per scene.
Table experiment_hybrid(const ExperimentSettings& settings, double chosen);

// After the paper (successor_experiments.cpp): the hierarchical Z-buffer beside the Z-buffer
// and the §3 hybrid at the paper's 0.04, on each scene and on the ideal scene at depth
// complexities 1 to 64; natively, or on a 1989 host (each run emulated once, counted).
Table experiment_successors(const ExperimentSettings& settings);
// The same for §4 (successor_experiments.cpp): multi-level ray tracing beside the ray tracer
// (on its BVH and on the kd-tree) and the beam-ray hybrid at `beam_threshold`, per scene at
// each size; natively or on a 1989 host.
Table experiment_successors_rays(const ExperimentSettings& settings,
                                 const std::vector<ImageSize>& sizes, double beam_threshold);

// The split (split_experiment.cpp): every method on every scene, host time per frame beside
// the controller's, the pipeline's frame time and the side that bounds it.
Table experiment_split(const ExperimentSettings& settings);

// §4 (trace_experiments.cpp). Figs. 4.8, 4.11: the ray tracer alone and the beam-ray
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

// §5 (radiosity_experiments.cpp). The paper's table: rays, volume queries and
// form-factor time of flux tracing and the decahedral hybrid per room, interleaved; about
// `patches` patches per room (0: the paper's count for the bundled rooms, else 800).
Table experiment_radiosity(const ExperimentSettings& settings, int patches);
// Form-factor error against time per method (flux, hybrid, disk, hemicubes), against a
// reference of exact form factors times fractional visibility from reference_n^4 rays per
// pair; with `solve`, also the radiosity error of each method's solution.
Table experiment_form_factor_error(const ExperimentSettings& settings, int patches, int reference_n,
                                   bool solve);

}  // namespace fb89::experiments
