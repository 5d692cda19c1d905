// The host-vs-controller split, the study fb89 exists for: every method on every scene,
// the host's time per frame (set-up + hidden-surface) beside the controller's modelled
// frame time, the frame time of the two-stage pipeline (host makes frame n + 1 while the
// controller tiles frame n: the larger of the two) and the side that bounds it. With a
// 1989 --host both sides are of one era. Beside it, the frame through the pipeline in time
// from the commands' send times (docs/COST_MODEL.md): its frame time, the overlap it
// achieves, the host's stalls and both sides' utilization; and the band those frame times
// and the host's ratio to the controller lie in when the controller's estimated figures
// range over their bands (the profile's "bands": docs/COST_MODEL.md). Every ratio is one
// way round, host over controller, as its column says: host_over_controller at the
// estimate, _low with the controller at its dear end, _high at its cheap end (above 1: the
// host bounds the frame).
#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "experiments/experiments.h"
#include "experiments/measure.h"
#include "experiments/period_runs.h"
#include "experiments/render_job.h"

namespace fb89::experiments {

Table experiment_split(const ExperimentSettings& s) {
    Table table({"scene",
                 "method",
                 "host",
                 "host_setup_ms",
                 "host_hs_ms",
                 "host_frame_ms",
                 "controller_ms",
                 "frame_ms",
                 "bound_by",
                 "host_over_controller",
                 "commands",
                 "sum_ms",
                 "pipeline_ms",
                 "overlap",
                 "host_stalled_ms",
                 "host_util",
                 "controller_util",
                 "controller_ms_low",
                 "controller_ms_high",
                 "pipeline_ms_low",
                 "pipeline_ms_high",
                 "host_over_controller_low",
                 "host_over_controller_high",
                 "bus_bytes"});
    const controller::CostProfile profile = controller::load_profile(s.profile);
    // the controller's estimated figures at the ends of their bands (the profile's "bands")
    const controller::CostProfile cheap = controller::band_end(profile, false);
    const controller::CostProfile dear = controller::band_end(profile, true);
    const std::string host = s.period ? s.period->profile().name : "native";
    std::vector<host::MethodOptions> settings = every_method();
    if (!s.methods.empty())
        std::erase_if(settings, [&](const host::MethodOptions& o) {
            return std::find(s.methods.begin(), s.methods.end(), o.method) == s.methods.end();
        });
    for (host::MethodOptions& o : settings)
        o.trace.accel = s.accel;
    for (const auto& file : s.scenes) {
        host::Scene scene;
        const host::ScreenScene screen = load_screen(file, s, scene);
        const std::vector<Measured> r = measure_settings(file, screen, settings, s);
        for (size_t m = 0; m < settings.size(); ++m) {
            const Measured& run = r[m];
            const double setup_ms = run.setup.cpu_ms;
            const double host_ms = setup_ms + run.median.cpu_ms;
            // the frame under a profile: the controller's figures and, with send times, the
            // pipeline in time, from one pass (none: a 1989 host's counts from before send
            // marks, or an untimed run)
            const auto frame_under = [&](const controller::CostProfile& p,
                                         ControllerFigures& ctl) -> std::optional<FramePipeline> {
                if (run.send_us.empty()) {
                    ctl = controller_figures(run.commands, p);
                    return std::nullopt;
                }
                return pipeline_figures(run.commands, run.send_us, host_ms * 1e3, p,
                                        p.command_buffer_bytes, &ctl);
            };
            ControllerFigures ctl, low, high;
            const auto pipe = frame_under(profile, ctl);
            const auto pipe_low = frame_under(cheap, low);
            const auto pipe_high = frame_under(dear, high);
            const FrameSplit split = frame_split(host_ms, ctl.frame_ms);
            // host over controller, to three significant figures at least (a face method's
            // host is a few hundredths of the controller's frame)
            const auto over_controller = [&](double controller_ms) -> std::string {
                if (!(controller_ms > 0)) return "";
                const double v = host_ms / controller_ms;
                const int digits = v > 0 ? 2 - static_cast<int>(std::floor(std::log10(v))) : 2;
                return fixed(v, std::max(2, digits));
            };
            std::vector<std::string> row = {file,
                                            std::string(host::method_info(settings[m].method).name),
                                            host,
                                            fixed(setup_ms, 3),
                                            fixed(run.median.cpu_ms, 3),
                                            fixed(host_ms, 3),
                                            fixed(ctl.frame_ms, 3),
                                            fixed(split.frame_ms, 3),
                                            split.host_bounds ? "host" : "controller",
                                            over_controller(ctl.frame_ms),
                                            std::to_string(ctl.commands),
                                            fixed(host_ms + ctl.frame_ms, 3)};
            if (pipe) {
                const double frame = pipe->frame_us / 1e3;
                row.insert(row.end(), {fixed(frame, 3), fixed(pipe->overlap(), 4),
                                       fixed(pipe->host_stalled_us / 1e3, 3),
                                       fixed(pipe->host_utilization(), 4),
                                       fixed(pipe->controller_utilization(), 4)});
            } else {
                row.resize(row.size() + 5);
            }
            // the band: the controller's frame and the pipeline's at the two ends, and the
            // host over the controller at them (the dear end gives the low ratio)
            row.insert(row.end(), {fixed(low.frame_ms, 3), fixed(high.frame_ms, 3)});
            for (const auto* end : {&pipe_low, &pipe_high})
                row.push_back(*end ? fixed((*end)->frame_us / 1e3, 3) : "");
            row.insert(row.end(), {over_controller(high.frame_ms), over_controller(low.frame_ms),
                                   std::to_string(ctl.bus_bytes)});
            table.add(std::move(row));
        }
    }
    return table;
}

}  // namespace fb89::experiments
