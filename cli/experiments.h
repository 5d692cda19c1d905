// The paper's experiments as functions that return tables; cli/experiment_command.cpp
// only parses options and writes the tables out.
#pragma once

#include <string>
#include <vector>

#include "cli/common.h"

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

Table experiment_fig2_1(const ExperimentSettings& settings);
Table experiment_fig2_4(const ExperimentSettings& settings);

}  // namespace fb89::cli
