// fb89 model: tabulates the paper's analytic model (Marks et al. 1990, Eqs. 2.1-2.4 for the
// window samples of the ideal scene, Exprs. 2.5-2.7 and 3.1 for the cost per pixel of a
// window) over a grid of E_s, F_v, D or F_w, E_w, D, F, as a table, JSON or CSV.
// The maths is in host/model/analytic_model.h; this file parses lists and prints.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "host/model/analytic_model.h"

namespace fb89::cli {

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

using Cell = std::variant<double, bool, std::string>;

struct Column {
    std::string label;  // for humans; empty: machine output only
    std::string key;    // CSV header and JSON key; empty: human output only
};

struct Table {
    std::string title, json_name;
    std::vector<Column> columns;
    std::vector<std::vector<Cell>> rows;
};

std::string human_number(double v) {
    if (!std::isfinite(v)) return fmt::format("{}", v);
    if (std::floor(v) == v && std::fabs(v) < 1e15) return fmt::format("{:.0f}", v);
    if (std::fabs(v) >= 1e5) return fmt::format("{:.1f}", v);
    return fmt::format("{:.6g}", v);
}

std::string cell_text(const Cell& c, bool human) {
    if (const double* d = std::get_if<double>(&c))
        return human ? human_number(*d) : fmt::format("{}", *d);
    if (const bool* b = std::get_if<bool>(&c)) return *b ? "true" : "false";
    return std::get<std::string>(c);
}

void print_human(const Table& t) {
    std::vector<size_t> shown;
    for (size_t i = 0; i < t.columns.size(); ++i)
        if (!t.columns[i].label.empty()) shown.push_back(i);
    std::vector<size_t> width(t.columns.size(), 0);
    for (size_t i : shown) {
        width[i] = t.columns[i].label.size();
        for (const auto& row : t.rows)
            width[i] = std::max(width[i], cell_text(row[i], true).size());
    }
    fmt::print("{}\n", t.title);
    auto print_line = [&](auto text_of) {
        std::string line;
        for (size_t k = 0; k < shown.size(); ++k) {
            size_t i = shown[k];
            bool last = k + 1 == shown.size();  // the domain column, left-aligned
            line += last ? fmt::format("  {}", text_of(i))
                         : fmt::format("{}{:>{}}", k ? "  " : "", text_of(i), width[i]);
        }
        fmt::print("{}\n", line);
    };
    print_line([&](size_t i) { return t.columns[i].label; });
    for (const auto& row : t.rows)
        print_line([&](size_t i) { return cell_text(row[i], true); });
}

std::string csv_text(const Table& t) {
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

// Keys in column order (ordered_json), so the JSON reads like the table.
nlohmann::ordered_json table_json(const Table& t) {
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

Table samples_table(const std::vector<double>& es, const std::vector<double>& fv,
                    const std::vector<double>& ds) {
    check_grid_size(es.size() * fv.size() * ds.size());
    Table t;
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

Table window_table(const std::vector<double>& fw, const std::vector<double>& ew,
                   const std::vector<double>& ds, const std::vector<double>& faces) {
    const bool with_f = !faces.empty();
    check_grid_size(fw.size() * ew.size() * ds.size() * (with_f ? faces.size() : 1));
    Table t;
    t.title = "Cost per pixel of the cheapest window derived from a window (Exprs. 2.5-2.7, 3.1)";
    t.json_name = "window_costs";
    t.columns = {{"F_w", "f_w"},   {"D", "d"},          {"E_w", "e_w"},      {"F_vw", "f_vw"},
                 {"E_fw", "e_fw"}, {"2.5", "expr_2_5"}, {"2.6", "expr_2_6"}, {"3.1", "expr_3_1"}};
    if (with_f) {
        t.columns.insert(t.columns.begin() + 3, Column{"F", "f"});
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
                    std::vector<Cell> row{p.f_w, p.d, p.e_w};
                    if (with_f) row.emplace_back(*p.f);
                    row.insert(row.end(), {p.f_vw, p.e_fw, p.expr_2_5, p.expr_2_6, p.expr_3_1});
                    if (with_f) row.emplace_back(*p.expr_2_7);
                    row.insert(row.end(), {p.valid, p.note, p.valid ? "ok" : p.note});
                    t.rows.push_back(std::move(row));
                }
    return t;
}

int run_model(const ModelArgs& args) {
    const bool samples = !args.es.empty() || !args.fv.empty();
    const bool windows = !args.fw.empty() || !args.ew.empty() || !args.faces.empty();
    if (!samples && !windows)
        throw UsageError(
            "model: give --es and --fv (Eqs. 2.1-2.4), or --fw and --ew (Exprs. 2.5-2.7, 3.1)");
    if (samples && (args.es.empty() || args.fv.empty()))
        throw UsageError(
            fmt::format("{}: Eq. 2.4 needs both --es and --fv", args.es.empty() ? "--es" : "--fv"));
    if (windows && (args.fw.empty() || args.ew.empty()))
        throw UsageError(fmt::format("{}: Exprs. 2.5-2.7 and 3.1 need both --fw and --ew",
                                     args.fw.empty() ? "--fw" : "--ew"));
    if (!args.csv.empty() && samples && windows)
        throw UsageError("--csv: prints one table; ask for --es/--fv or --fw/--ew, not both");

    std::vector<double> ds = parse_values("--d", args.d);
    std::vector<Table> tables;
    if (samples)
        tables.push_back(
            samples_table(parse_values("--es", args.es), parse_values("--fv", args.fv), ds));
    if (windows)
        tables.push_back(window_table(parse_values("--fw", args.fw), parse_values("--ew", args.ew),
                                      ds, parse_values("--faces", args.faces)));

    if (args.json) {
        nlohmann::ordered_json j;
        j["model"] = "Marks, Walsh, Christensen & Friedell 1990, Eqs. 2.1-2.7 and Expr. 3.1";
        for (const Table& t : tables)
            j[t.json_name] = table_json(t);
        fmt::print("{}\n", j.dump(2));
    } else if (!args.csv.empty()) {
        write_text(args.csv, csv_text(tables.front()));
    } else {
        for (size_t i = 0; i < tables.size(); ++i) {
            if (i) fmt::print("\n");
            print_human(tables[i]);
        }
    }
    return kSuccess;
}

constexpr const char* kEquations =
    R"(Equations (Marks, Walsh, Christensen & Friedell 1990; docs/MODEL.md):
  Eq. 2.1      S_sort(F_v) = (F_v - 1) / 3
               window samples of the sorting phase, until each window holds one visible face
  Eqs. 2.2-2.3 S_split(E_f) = 8 E_f - 4 log2 E_f - 7, with S_split_1edge(n) = 4n - 3
               samples splitting a window that holds one face of edge E_f = sqrt(E_s^2 / F_v)
  Eq. 2.4      S(F_v) = (F_v - 1)/3 + 8 E_s sqrt(F_v) - 4 F_v log2 sqrt(E_s^2/F_v) - 7 F_v
               all window samples of an E_s x E_s ideal scene with F_v visible faces
  F log4 F_v   face computations of the sorting phase, F = D F_v faces in D layers
  Expr. 2.5    (F_w log4(F_w/D) / F_vw + D) / (E_fw^2 / 4)
               face computations per pixel of the cheapest window derived from a window
  Expr. 2.6    (4 F_w log4(F_w/D) + 4 F_w) / E_w^2
               Expr. 2.5 with F_vw = F_w / D and E_fw^2 = E_w^2 D / F_w substituted
  Expr. 2.7    F (16 F_w - D) / (E_w^2 D)
               cost per pixel when every sample costs time proportional to F (needs --faces)
  Expr. 3.1    (F_w log4(F_w/D) + F_w) / E_w^2
               the hybrid Warnock/Z-buffer's estimate, Expr. 2.6 / 4 (paper's threshold 0.04)
Values: lists 16,32,64; ranges FIRST..LAST (step 1), FIRST..LAST+STEP, FIRST..LAST*FACTOR
(e.g. --es 16..1024*2 --fv 1..16384*4); options may repeat. Rows outside the model's domain
(F_v < 1, F_v > E_s^2, F_w < D, E_fw < 1) are printed with the reason.)";

}  // namespace

void register_model(CLI::App& app, int& exit_code) {
    auto args = std::make_shared<ModelArgs>();
    CLI::App* sub = app.add_subcommand(
        "model", "Tabulate the paper's analytic model of window sampling (Eqs. 2.1-2.7, 3.1)");
    sub->add_option("--es", args->es, "Screen edge E_s in pixels (Eqs. 2.1-2.4); list or range");
    sub->add_option("--fv", args->fv, "Visible faces F_v (Eqs. 2.1-2.4); list or range");
    sub->add_option("--d", args->d, "Depth complexity D (sorting face computations, 2.5-2.7, 3.1)")
        ->capture_default_str();
    sub->add_option("--fw", args->fw, "Faces in the window F_w (Exprs. 2.5-2.7, 3.1)");
    sub->add_option("--ew", args->ew, "Window edge E_w in pixels (Exprs. 2.5-2.7, 3.1)");
    sub->add_option("--faces", args->faces, "Faces in the whole scene F (Expr. 2.7)");
    CLI::Option* json = sub->add_flag("--json", args->json, "Print JSON instead of a table");
    sub->add_option("--csv", args->csv,
                    "Write CSV with a header row instead of printing a table ('-' for stdout)")
        ->excludes(json);
    sub->footer(kEquations);
    sub->callback([args, &exit_code] { exit_code = run_model(*args); });
}

}  // namespace fb89::cli
