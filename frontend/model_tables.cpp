// The paper's analytic model as tables (frontend/model_tables.h): the value lists, the two
// grids, and the table as text, CSV and JSON.
#include "frontend/model_tables.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <type_traits>

#include <fmt/format.h>

#include "frontend/common.h"
#include "host/model/analytic_model.h"

namespace fb89::frontend {

namespace {

namespace model = host::model;

constexpr size_t kMaxValuesPerOption = 10000;
constexpr size_t kMaxRows = 100000;

struct ModelArgs {
    std::vector<std::string> es, fv, d{"1"}, fw, ew, faces;
    bool json = false;
    std::string csv;  // a file, or '-' for stdout, as --csv is everywhere
};

// --- value lists: "16,32,64", "1..16384*4", "1..10+0.5", repeated options ------------------

double parse_number(const std::string& option, const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    double v = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size() || !std::isfinite(v))
        throw UsageError(fmt::format("{}: expected a number, got '{}'", option, text));
    if (!(v > 0))
        throw UsageError(fmt::format("{}: expected a positive number, got '{}'", option, text));
    return v;
}

// FIRST..LAST, FIRST..LAST+STEP or FIRST..LAST*FACTOR, LAST included (to 1e-9 relative).
void expand_range(const std::string& option, const std::string& item, size_t dots,
                  std::vector<double>& out) {
    std::string first_text = item.substr(0, dots), rest = item.substr(dots + 2);
    size_t op = rest.find_first_of("+*");
    std::string last_text = rest.substr(0, op);
    double first = parse_number(option, first_text), last = parse_number(option, last_text);
    bool geometric = op != std::string::npos && rest[op] == '*';
    double step = op == std::string::npos ? 1 : parse_number(option, rest.substr(op + 1));
    if (last < first)
        throw UsageError(fmt::format("{}: range '{}' ends before it starts", option, item));
    if (geometric && step <= 1)
        throw UsageError(fmt::format("{}: range '{}' needs a factor above 1", option, item));
    const double limit = last * (1 + 1e-9);
    for (size_t i = 0;; ++i) {
        double v = geometric ? first * std::pow(step, static_cast<double>(i))
                             : first + step * static_cast<double>(i);
        if (v > limit) break;
        if (out.size() >= kMaxValuesPerOption)
            throw UsageError(fmt::format("{}: more than {} values", option, kMaxValuesPerOption));
        out.push_back(v);
    }
}

std::vector<double> parse_values(const std::string& option, const std::vector<std::string>& args) {
    std::vector<double> out;
    for (const std::string& arg : args) {
        size_t start = 0;
        while (start <= arg.size()) {
            size_t comma = arg.find(',', start);
            std::string item =
                arg.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            size_t dots = item.find("..");
            if (dots != std::string::npos)
                expand_range(option, item, dots, out);
            else if (out.size() >= kMaxValuesPerOption)
                throw UsageError(
                    fmt::format("{}: more than {} values", option, kMaxValuesPerOption));
            else
                out.push_back(parse_number(option, item));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    return out;
}

// --- one table, printed for humans, as CSV or as JSON --------------------------------------

std::string human_number(double v) {
    if (!std::isfinite(v)) return fmt::format("{}", v);
    if (std::floor(v) == v && std::fabs(v) < 1e15) return fmt::format("{:.0f}", v);
    if (std::fabs(v) >= 1e5) return fmt::format("{:.1f}", v);
    return fmt::format("{:.6g}", v);
}

std::string cell_text(const ModelCell& c, bool human) {
    if (const double* d = std::get_if<double>(&c))
        return human ? human_number(*d) : fmt::format("{}", *d);
    if (const bool* b = std::get_if<bool>(&c)) return *b ? "true" : "false";
    return std::get<std::string>(c);
}

// Keys in column order (ordered_json), so the JSON reads like the table.
nlohmann::ordered_json table_json(const ModelTable& t) {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& row : t.rows) {
        nlohmann::ordered_json j = nlohmann::ordered_json::object();
        for (size_t i = 0; i < t.columns.size(); ++i) {
            if (t.columns[i].key.empty()) continue;
            std::visit(
                [&](const auto& v) {
                    using T = std::decay_t<decltype(v)>;
                    if constexpr (std::is_same_v<T, double>)
                        j[t.columns[i].key] =
                            std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr;
                    else
                        j[t.columns[i].key] = v;
                },
                row[i]);
        }
        rows.push_back(j);
    }
    return rows;
}

// --- the two tables -------------------------------------------------------------------------

void check_grid_size(size_t rows) {
    if (rows > kMaxRows)
        throw UsageError(
            fmt::format("the grid has {} rows; at most {} (fewer values)", rows, kMaxRows));
}

ModelTable samples_table(const std::vector<double>& es, const std::vector<double>& fv,
                         const std::vector<double>& ds) {
    check_grid_size(es.size() * fv.size() * ds.size());
    ModelTable t;
    t.title = "Window samples of the ideal scene (Eqs. 2.1-2.4) and sorting face computations";
    t.json_name = "samples";
    t.columns = {{"E_s", "e_s"},
                 {"F_v", "f_v"},
                 {"D", "d"},
                 {"E_f", "e_f"},
                 {"S_sort 2.1", "s_sort_2_1"},
                 {"S_split(E_f) 2.3", "s_split_2_3"},
                 {"S(F_v) 2.4", "s_2_4"},
                 {"F=D*F_v", "f"},
                 {"F log4 F_v", "c_sort"},
                 {"", "valid"},
                 {"", "ideal"},
                 {"", "note"},
                 {"domain", ""}};
    for (double e_s : es)
        for (double f_v : fv)
            for (double d : ds) {
                model::SamplePrediction p = model::predict_samples(e_s, f_v, d);
                std::string domain = !p.valid ? p.note : p.ideal ? "ideal scene (exact)" : "ok";
                t.rows.push_back({p.e_s, p.f_v, p.d, p.e_f, p.sort_samples, p.split_samples,
                                  p.window_samples, p.faces, p.sort_face_computations, p.valid,
                                  p.ideal, p.note, domain});
            }
    return t;
}

ModelTable window_table(const std::vector<double>& fw, const std::vector<double>& ew,
                        const std::vector<double>& ds, const std::vector<double>& faces) {
    const bool with_f = !faces.empty();
    check_grid_size(fw.size() * ew.size() * ds.size() * (with_f ? faces.size() : 1));
    ModelTable t;
    t.title = "Cost per pixel of the cheapest window derived from a window (Exprs. 2.5-2.7, 3.1)";
    t.json_name = "window_costs";
    t.columns = {{"F_w", "f_w"},   {"D", "d"},          {"E_w", "e_w"},      {"F_vw", "f_vw"},
                 {"E_fw", "e_fw"}, {"2.5", "expr_2_5"}, {"2.6", "expr_2_6"}, {"3.1", "expr_3_1"}};
    if (with_f) {
        t.columns.insert(t.columns.begin() + 3, ModelColumn{"F", "f"});
        t.columns.push_back({"2.7", "expr_2_7"});
    }
    t.columns.insert(t.columns.end(), {{"", "valid"}, {"", "note"}, {"domain", ""}});
    std::vector<std::optional<double>> fs;
    for (double f : faces)
        fs.emplace_back(f);
    if (!with_f) fs.emplace_back(std::nullopt);
    for (double f_w : fw)
        for (double e_w : ew)
            for (double d : ds)
                for (const auto& f : fs) {
                    model::WindowCostPrediction p = model::predict_window_cost(f_w, d, e_w, f);
                    std::vector<ModelCell> row{p.f_w, p.d, p.e_w};
                    if (with_f) row.emplace_back(*p.f);
                    row.insert(row.end(), {p.f_vw, p.e_fw, p.expr_2_5, p.expr_2_6, p.expr_3_1});
                    if (with_f) row.emplace_back(*p.expr_2_7);
                    row.insert(row.end(), {p.valid, p.note, p.valid ? "ok" : p.note});
                    t.rows.push_back(std::move(row));
                }
    return t;
}

// --es or es, as the front end spells it
std::string named(const ModelRequest& r, const char* option) {
    return r.spelling == Spelling::Option ? std::string(option) : std::string(option + 2);
}

}  // namespace

std::string model_text(const ModelTable& t) {
    std::string out;
    std::vector<size_t> shown;
    for (size_t i = 0; i < t.columns.size(); ++i)
        if (!t.columns[i].label.empty()) shown.push_back(i);
    std::vector<size_t> width(t.columns.size(), 0);
    for (size_t i : shown) {
        width[i] = t.columns[i].label.size();
        for (const auto& row : t.rows)
            width[i] = std::max(width[i], cell_text(row[i], true).size());
    }
    out += t.title + "\n";
    auto print_line = [&](auto text_of) {
        std::string line;
        for (size_t k = 0; k < shown.size(); ++k) {
            size_t i = shown[k];
            bool last = k + 1 == shown.size();  // the domain column, left-aligned
            line += last ? fmt::format("  {}", text_of(i))
                         : fmt::format("{}{:>{}}", k ? "  " : "", text_of(i), width[i]);
        }
        out += line + "\n";
    };
    print_line([&](size_t i) { return t.columns[i].label; });
    for (const auto& row : t.rows)
        print_line([&](size_t i) { return cell_text(row[i], true); });
    return out;
}

std::string model_csv(const ModelTable& t) {
    std::string out;
    std::vector<size_t> keyed;
    for (size_t i = 0; i < t.columns.size(); ++i)
        if (!t.columns[i].key.empty()) keyed.push_back(i);
    auto print_line = [&](auto text_of) {
        std::string line;
        for (size_t k = 0; k < keyed.size(); ++k) {
            if (k) line += ',';
            line += csv_field(text_of(keyed[k]));
        }
        out += line + "\n";
    };
    print_line([&](size_t i) { return t.columns[i].key; });
    for (const auto& row : t.rows)
        print_line([&](size_t i) { return cell_text(row[i], false); });
    return out;
}

std::vector<std::string> model_row(const ModelTable& t, std::size_t row) {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < t.columns.size(); ++i)
        if (!t.columns[i].key.empty()) out.push_back(cell_text(t.rows[row][i], false));
    return out;
}

std::vector<std::string> model_keys(const ModelTable& t) {
    std::vector<std::string> out;
    for (const ModelColumn& c : t.columns)
        if (!c.key.empty()) out.push_back(c.key);
    return out;
}

nlohmann::ordered_json model_json(const std::vector<ModelTable>& tables) {
    nlohmann::ordered_json j;
    j["model"] = "Marks, Walsh, Christensen & Friedell 1990, Eqs. 2.1-2.7 and Expr. 3.1";
    for (const ModelTable& t : tables)
        j[t.json_name] = table_json(t);
    return j;
}

std::vector<ModelTable> model_tables(const ModelRequest& r) {
    const bool samples = !r.es.empty() || !r.fv.empty();
    const bool windows = !r.fw.empty() || !r.ew.empty() || !r.faces.empty();
    const std::string es = named(r, "--es"), fv = named(r, "--fv"), fw = named(r, "--fw"),
                      ew = named(r, "--ew");
    if (!samples && !windows)
        throw UsageError(
            fmt::format("model: give {} and {} (Eqs. 2.1-2.4), or {} and {} (Exprs. "
                        "2.5-2.7, 3.1)",
                        es, fv, fw, ew));
    if (samples && (r.es.empty() || r.fv.empty()))
        throw UsageError(
            fmt::format("{}: Eq. 2.4 needs both {} and {}", r.es.empty() ? es : fv, es, fv));
    if (windows && (r.fw.empty() || r.ew.empty()))
        throw UsageError(fmt::format("{}: Exprs. 2.5-2.7 and 3.1 need both {} and {}",
                                     r.fw.empty() ? fw : ew, fw, ew));
    const std::vector<double> ds = parse_values(named(r, "--d"), r.d);
    std::vector<ModelTable> tables;
    if (samples)
        tables.push_back(samples_table(parse_values(es, r.es), parse_values(fv, r.fv), ds));
    if (windows)
        tables.push_back(window_table(parse_values(fw, r.fw), parse_values(ew, r.ew), ds,
                                      parse_values(named(r, "--faces"), r.faces)));
    return tables;
}

}  // namespace fb89::frontend
