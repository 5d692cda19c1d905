// The viewer's text layout (see hud_layout.h): status lines wrapped to the window's width,
// the bar grown to hold them, the key panel's box kept inside the window.
#include "controller_sim/hud_layout.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "controller_sim/bitmap_font.h"

namespace fb89::controller {

namespace {

constexpr std::size_t kIndent = 2;  // a continuation row's indent, in characters
constexpr int kWideWindow = 960;    // from this width on, text is drawn twice the size

// `line` split at runs of two or more spaces; leading and trailing spaces dropped.
std::vector<std::string> split_fields(const std::string& line) {
    std::vector<std::string> fields;
    std::size_t i = line.find_first_not_of(' ');
    while (i != std::string::npos) {
        std::size_t end = line.find("  ", i);
        fields.push_back(line.substr(i, end == std::string::npos ? std::string::npos : end - i));
        i = end == std::string::npos ? end : line.find_first_not_of(' ', end);
    }
    return fields;
}

std::vector<std::string> split_words(const std::string& field) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < field.size()) {
        const std::size_t end = std::min(field.find(' ', i), field.size());
        words.push_back(field.substr(i, end - i));
        i = end + 1;
    }
    return words;
}

// Fills rows greedily: pieces joined by `glue` while they fit, a piece that fits no row
// alone split into row-sized parts.
class RowFiller {
  public:
    explicit RowFiller(std::size_t width) : m_width(width) {}

    // Room on the row being filled (the first has no indent).
    std::size_t room() const { return m_width - (m_rows.empty() ? 0 : kIndent); }
    bool fits(const std::string& piece, const char* glue) const {
        const std::size_t glued = std::char_traits<char>::length(glue);
        return (m_row.empty() ? piece.size() : m_row.size() + glued + piece.size()) <= room();
    }
    void add(const std::string& piece, const char* glue) {
        m_row = m_row.empty() ? piece : m_row + glue + piece;
    }
    void flush() {
        if (!m_row.empty()) m_rows.push_back(m_row);
        m_row.clear();
    }
    // a word longer than any row: as much as fits on each, after a '/' if there is one (a
    // path breaks between its folders)
    void split_long(std::string word) {
        while (word.size() > room()) {
            std::size_t n = room();
            const std::size_t slash = word.rfind('/', n - 1);
            if (slash != std::string::npos && slash > 0) n = slash + 1;
            m_rows.push_back(word.substr(0, n));
            word.erase(0, n);
        }
        m_row = word;
    }
    std::vector<std::string> rows() {
        flush();
        for (std::size_t i = 1; i < m_rows.size(); ++i)
            m_rows[i].insert(0, kIndent, ' ');
        return m_rows;
    }

  private:
    std::size_t m_width;
    std::vector<std::string> m_rows;
    std::string m_row;
};

}  // namespace

std::vector<std::string> wrap_line(const std::string& line, int columns) {
    const auto width = static_cast<std::size_t>(std::max(columns, 8));
    if (line.size() <= width) return {line};
    RowFiller f(width);
    for (const std::string& field : split_fields(line)) {
        if (f.fits(field, "  ")) {
            f.add(field, "  ");
            continue;
        }
        f.flush();
        if (f.fits(field, "")) {
            f.add(field, "");
            continue;
        }
        // a field longer than a row: between words, else anywhere
        for (const std::string& word : split_words(field)) {
            if (f.fits(word, " ")) {
                f.add(word, " ");
                continue;
            }
            f.flush();
            f.split_long(word);
        }
    }
    return f.rows();
}

HudLayout layout_hud(int image_width, int image_height, const Hud& hud, int min_status_rows) {
    HudLayout l;
    l.image = {0, 0, std::max(image_width, 0), std::max(image_height, 0)};
    l.window_width = std::max(l.image.width, kMinWindowWidth);
    l.text_scale = l.window_width >= kWideWindow ? 2 : 1;
    const int cell_w = kCellWidth * l.text_scale, line_h = kCellHeight * l.text_scale;
    l.columns = (l.window_width - 2 * kTextPad) / cell_w;

    // the key panel: over the image's top left, its text inset by two pads
    const int panel_columns = (l.window_width - 6 * kTextPad) / cell_w;
    std::vector<std::string> panel_lines;
    for (const std::string& line : hud.help)
        for (std::string& row : wrap_line(line, panel_columns))
            panel_lines.push_back(std::move(row));
    std::size_t longest = 0;
    for (const std::string& row : panel_lines)
        longest = std::max(longest, row.size());
    const TextRect panel{kTextPad, kTextPad, static_cast<int>(longest) * cell_w + 4 * kTextPad,
                         static_cast<int>(panel_lines.size()) * line_h + 3 * kTextPad};
    const int body_h =
        std::max(l.image.height, panel_lines.empty() ? 0 : panel.y + panel.height + kTextPad);
    if (hud.help_shown && !panel_lines.empty()) {
        l.panel = panel;
        int y = panel.y + 2 * kTextPad;
        for (std::string& row : panel_lines) {
            const int w = static_cast<int>(row.size()) * cell_w;
            l.panel_rows.push_back({std::move(row), {panel.x + 2 * kTextPad, y, w, line_h}});
            y += line_h;
        }
    }

    // the status bar under the body
    int y = body_h + kTextPad;
    for (const std::string& line : hud.status)
        for (std::string& row : wrap_line(line, l.columns)) {
            const int w = static_cast<int>(row.size()) * cell_w;
            l.status.push_back({std::move(row), {kTextPad, y, w, line_h}});
            y += line_h;
        }
    const int rows = std::max(static_cast<int>(l.status.size()), min_status_rows);
    l.bar = {0, body_h, l.window_width, rows * line_h + 2 * kTextPad};
    l.window_height = body_h + l.bar.height;
    return l;
}

int scaled_size(unsigned n, double scale) {
    return n == 0 ? 0 : std::max(1, static_cast<int>(std::lround(n * scale)));
}

double fit_scale(unsigned width, unsigned height, const Hud& hud, int min_status_rows, double asked,
                 int screen_width, int screen_height) {
    const auto fits = [&](double scale) {
        const HudLayout l =
            layout_hud(scaled_size(width, scale), scaled_size(height, scale), hud, min_status_rows);
        return l.window_width <= screen_width && l.window_height <= screen_height;
    };
    if (fits(asked)) return asked;
    // the whole scales below `asked`, then the halvings below both it and 1
    for (double s = std::min(std::ceil(asked) - 1, std::floor(asked)); s >= 1; --s)
        if (fits(s)) return s;
    for (double s = 0.5; s >= 0.125; s /= 2)
        if (s < asked && fits(s)) return s;
    return 0.125;
}

}  // namespace fb89::controller
