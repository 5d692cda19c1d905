// Every experiment `fb89 experiment` runs, by name, with a one-line description and the
// bundled scenes it runs on by default (file names under the data folder's scenes/).
#pragma once

#include <span>
#include <string_view>
#include <vector>

namespace fb89::experiments {

struct ExperimentInfo {
    std::string_view name;
    std::string_view description;
    std::vector<std::string_view> scenes;
};

std::span<const ExperimentInfo> experiment_catalog();
const ExperimentInfo* find_experiment(std::string_view name);  // null when unknown

}  // namespace fb89::experiments
