#include "experiments/table.h"

#include <algorithm>

#include <fmt/format.h>

namespace fb89::experiments {

std::string Table::csv() const {
    std::string out;
    auto line = [&out](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i)
            out += (i ? "," : "") + cells[i];
        out += "\n";
    };
    line(m_columns);
    for (const auto& r : m_rows)
        line(r);
    return out;
}

std::string Table::text() const {
    std::vector<size_t> width(m_columns.size());
    for (size_t i = 0; i < m_columns.size(); ++i)
        width[i] = m_columns[i].size();
    for (const auto& r : m_rows)
        for (size_t i = 0; i < r.size() && i < width.size(); ++i)
            width[i] = std::max(width[i], r[i].size());
    std::string out;
    auto line = [&](const std::vector<std::string>& cells) {
        for (size_t i = 0; i < cells.size(); ++i)
            out += fmt::format("{:>{}}  ", cells[i], width[i]);
        out += "\n";
    };
    line(m_columns);
    for (const auto& r : m_rows)
        line(r);
    return out;
}

std::string fixed(double v, int digits) {
    return fmt::format("{:.{}f}", v, digits);
}

}  // namespace fb89::experiments
