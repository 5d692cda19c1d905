// The fb89 commands: one register_* per file in cli/, called by main.cpp. What the
// commands share with the other front ends (the Python module) is in frontend/.
#pragma once

#include <CLI/CLI.hpp>

#include "frontend/common.h"
#include "frontend/names.h"

namespace fb89::cli {

using namespace fb89::frontend;

void register_render(CLI::App& app, int& exit_code);
void register_model(CLI::App& app, int& exit_code);
void register_experiment(CLI::App& app, int& exit_code);
void register_sweep(CLI::App& app, int& exit_code);
void register_compare(CLI::App& app, int& exit_code);
void register_calibrate(CLI::App& app, int& exit_code);
void register_replay(CLI::App& app, int& exit_code);
void register_dump(CLI::App& app, int& exit_code);
void register_info(CLI::App& app, int& exit_code);
void register_trim(CLI::App& app, int& exit_code);
void register_diff(CLI::App& app, int& exit_code);
void register_controller(CLI::App& app, int& exit_code);
void register_view(CLI::App& app, int& exit_code);
void register_radiosity(CLI::App& app, int& exit_code);
void register_host_run(CLI::App& app, int& exit_code);
void register_list(CLI::App& app, int& exit_code);
void register_host_validate(CLI::App& app, int& exit_code);
void register_controller_validate(CLI::App& app, int& exit_code);
void register_help(CLI::App& app, int& exit_code);

}  // namespace fb89::cli
