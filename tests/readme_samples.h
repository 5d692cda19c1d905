// The README's sample sessions against what the commands print: a line's shape (its words
// and columns, numbers aside) and its figures (every number but the times a run measures),
// "..." in a sample standing for lines left out. tests/readme_tour_test.cpp runs the
// commands; tests/readme_samples_test.cpp holds the matcher to what it must see.
#pragma once

#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fb89::testing {

inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        out.push_back(l);
    return out;
}

// A line's shape: numbers and checksums as '#', runs of spaces as one.
inline std::string shape(const std::string& line) {
    static const std::regex number(R"([0-9a-f]{16}|[-+]?[0-9][0-9,]*(\.[0-9]+)?(e[-+]?[0-9]+)?)");
    std::string s = std::regex_replace(line, number, "#");
    s = std::regex_replace(s, std::regex(" +"), " ");
    const size_t a = s.find_first_not_of(' ');
    return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(' ') - a + 1);
}

// What a run measures, and so differs from run to run: each pattern's numbers are left out
// of the comparison of figures ("~" in their place).
inline const std::vector<std::regex>& measured() {
    static const std::vector<std::regex> patterns = {
        // render's host times: wall and CPU
        std::regex(R"(^(\s*(?:load|set-up|hidden-surface\*|end to end)\s).*$)"),
        // the host against the controller, and the pipeline the measured send times make
        std::regex(R"((host \S+ )[0-9.]+( ms CPU))"),
        std::regex(R"((\()[0-9.]+(x the host\)))"),
        std::regex(R"(^(pipeline ).*$)"),
        // send times: dump's, info's table of them, diff's host ends
        std::regex(R"((sent )[0-9.]+( us))"),
        std::regex(R"((host end )[0-9.]+( us))"),
        std::regex(R"(^(\s*[0-9]+)\s+[0-9]+\.[0-9]{6}\s+[0-9]+\.[0-9]{6}()$)"),
        std::regex(
            R"(^(\s*[0-9]+\s+[0-9]+x[0-9]+\s+[0-9]+x[0-9]+\s+[0-9,]+\s+)[0-9.]+\s+[0-9.]+(\s+\())"),
        // replay --benchmark's speed
        std::regex(R"(( in )[0-9.]+ s wall: .*()$)"),
    };
    return patterns;
}

// A line's figures: the line with what a run measures as "~", runs of spaces as one.
inline std::string figures(const std::string& line) {
    std::string s = line;
    for (const std::regex& r : measured())
        s = std::regex_replace(s, r, "$1~$2");
    s = std::regex_replace(s, std::regex(" +"), " ");
    const size_t a = s.find_first_not_of(' ');
    return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(' ') - a + 1);
}

// "" when `actual` has the sample's lines in order, in shape, each "..." standing for any
// number of lines, or what differs; with `same_figures`, each line found must also carry the
// sample's figures but for what a run measures.
inline std::string matches(const std::vector<std::string>& sample, const std::string& actual,
                           bool same_figures = false) {
    const std::vector<std::string> printed = lines_of(actual);
    std::vector<std::string> got;
    for (const std::string& l : printed)
        got.push_back(shape(l));
    size_t at = 0;
    bool gap = false;
    for (const std::string& want_line : sample) {
        if (shape(want_line) == "...") {
            gap = true;
            continue;
        }
        const std::string want = shape(want_line);
        size_t k = at;
        if (gap)
            while (k < got.size() && got[k] != want)
                ++k;
        if (k >= got.size() || got[k] != want)
            return "expected, " + std::string(gap ? "somewhere after" : "right after") +
                   " output line " + std::to_string(at) + ": '" + want_line + "'";
        if (same_figures && figures(want_line) != figures(printed[k]))
            return "the sample says '" + want_line + "', the command prints '" + printed[k] + "'";
        at = k + 1;
        gap = false;
    }
    if (!gap && at != got.size())
        return "output goes on after the sample's last line: '" + printed[at] + "'";
    return "";
}

}  // namespace fb89::testing
