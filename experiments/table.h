// An experiment's result: rows of named columns, printed aligned for people and as CSV for
// charts (scripts/plot_figures.py reads the CSV by column name).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace fb89::experiments {

class Table {
  public:
    explicit Table(std::vector<std::string> columns = {}) : m_columns(std::move(columns)) {}
    void add(std::vector<std::string> row) { m_rows.push_back(std::move(row)); }
    std::string csv() const;
    std::string text() const;
    const std::vector<std::string>& columns() const { return m_columns; }
    const std::vector<std::vector<std::string>>& rows() const { return m_rows; }
    // Rewrites every value of `column` (if the table has one) through `f`: how a command
    // shows, say, scene files.
    void map_column(const std::string& column,
                    const std::function<std::string(const std::string&)>& f);

  private:
    std::vector<std::string> m_columns;
    std::vector<std::vector<std::string>> m_rows;
};

// v with `digits` decimals, the tables' number format.
std::string fixed(double v, int digits);

}  // namespace fb89::experiments
