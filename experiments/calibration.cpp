#include "experiments/calibration.h"

#include <algorithm>
#include <string>

#include "experiments/experiments.h"
#include "host/raster/hybrid.h"

namespace fb89::experiments {

namespace {

// The sweep's numbers, read back from its table by column name.
double cell(const Table& t, const std::vector<std::string>& row, const std::string& column) {
    const auto& columns = t.columns();
    const size_t i =
        static_cast<size_t>(std::find(columns.begin(), columns.end(), column) - columns.begin());
    return row.at(i).empty() ? 1.0 : std::stod(row.at(i));
}

}  // namespace

Calibration calibrate_hybrid(const ExperimentSettings& s, const std::vector<double>& ramp,
                             double tolerance) {
    std::vector<double> thresholds{0.0, host::kPaperThreshold};
    thresholds.insert(thresholds.end(), ramp.begin(), ramp.end());
    std::sort(thresholds.begin(), thresholds.end());
    thresholds.erase(std::unique(thresholds.begin(), thresholds.end()), thresholds.end());

    Calibration c;
    c.sweep = sweep_threshold(s, thresholds, host::MethodOptions(host::Method::Hybrid));
    // the total of the per-scene medians, and the worst scene against the Z-buffer
    for (const auto& row : c.sweep.rows()) {
        const double t = std::stod(row[1]);
        c.total[t] += cell(c.sweep, row, "hs_cpu_ms");
        c.worst[t] = std::max(c.worst[t], cell(c.sweep, row, "ratio_to_zbuffer"));
    }
    auto best = c.total.find(0.0);
    for (auto it = c.total.begin(); it != c.total.end(); ++it)
        if (c.worst[it->first] <= 1.0 + tolerance && it->second < best->second) best = it;
    c.reference_ms = c.total.at(0.0);
    c.chosen = best->first;
    return c;
}

Calibration calibrate_stably(const ExperimentSettings& s,
                             const std::function<Calibration()>& calibrate, int max_sweeps) {
    Calibration c = calibrate();
    std::vector<double> choices{c.chosen};
    while (!s.period && static_cast<int>(choices.size()) < max_sweeps &&
           (choices.size() < 2 || choices[choices.size() - 1] != choices[choices.size() - 2])) {
        c = calibrate();
        choices.push_back(c.chosen);
    }
    c.choices = choices;
    c.stable = s.period || (choices.size() >= 2 && choices.back() == choices[choices.size() - 2]);
    if (!c.stable) {
        std::map<double, int> votes;
        for (double t : choices)
            ++votes[t];
        int most = 0;
        for (double t : choices)  // in order: the later wins a tie
            if (votes[t] >= most) most = votes[t], c.chosen = t;
    }
    return c;
}

Calibration calibrate_beam(const ExperimentSettings& s) {
    Calibration c;
    c.sweep = experiment_beam_threshold(s, beam_threshold_ramp());
    for (const auto& row : c.sweep.rows()) {
        const double ms = cell(c.sweep, row, "hs_cpu_ms");
        if (row[1] == "raytrace") {
            c.reference_ms += ms;
            continue;
        }
        c.total[std::stod(row[1])] += ms;
    }
    auto best = c.total.begin();
    for (auto it = c.total.begin(); it != c.total.end(); ++it)
        if (it->second < best->second) best = it;
    c.chosen = best->first;
    return c;
}

}  // namespace fb89::experiments
