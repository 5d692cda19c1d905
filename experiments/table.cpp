#include "experiments/table.h"

#include <cstdlib>

#include <algorithm>

#include <fmt/format.h>

namespace fb89::experiments {

void Table::map_column(const std::string& column,
                       const std::function<std::string(const std::string&)>& f) {
    for (size_t c = 0; c < m_columns.size(); ++c)
        if (m_columns[c] == column)
            for (auto& row : m_rows)
                if (c < row.size()) row[c] = f(row[c]);
}

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

namespace {

// Display width in code points (a header or a scene name may hold "§").
size_t width_of(const std::string& s) {
    size_t n = 0;
    for (const char c : s)
        n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
}

bool numeric(const std::string& s) {
    if (s.empty()) return true;
    char* end = nullptr;
    std::strtod(s.c_str(), &end);
    return end && *end == '\0';
}

}  // namespace

std::string Table::text() const {
    const size_t n = m_columns.size();
    std::vector<size_t> width(n);
    std::vector<bool> right(n, true);  // numbers line up on the right, words on the left
    for (size_t i = 0; i < n; ++i)
        width[i] = width_of(m_columns[i]);
    for (const auto& r : m_rows)
        for (size_t i = 0; i < r.size() && i < n; ++i) {
            width[i] = std::max(width[i], width_of(r[i]));
            right[i] = right[i] && numeric(r[i]);
        }
    std::string out;
    auto line = [&](const std::vector<std::string>& cells) {
        std::string text;
        for (size_t i = 0; i < cells.size() && i < n; ++i) {
            const std::string pad(width[i] - width_of(cells[i]), ' ');
            text += (i ? "  " : "") + (right[i] ? pad + cells[i] : cells[i] + pad);
        }
        text.erase(text.find_last_not_of(' ') + 1);
        out += text + "\n";
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
