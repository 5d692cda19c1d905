// The paper's analytic model (Marks et al. 1990, Eqs. 2.1-2.4 for the window samples of the
// ideal scene, Exprs. 2.5-2.7 and 3.1 for the cost per pixel of a window) tabulated over a
// grid of values, as `fb89 model` prints it and fb89.model() returns it: the value lists
// ("16,32,64", "1..16384*4", "1..10+0.5"), the two tables, and each as text, CSV and JSON.
// The maths is in host/model/analytic_model.h.
#pragma once

#include <cstddef>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "frontend/option_limits.h"

namespace fb89::frontend {

using ModelCell = std::variant<double, bool, std::string>;

struct ModelColumn {
    std::string label;  // for humans; empty: machine output only
    std::string key;    // CSV header and JSON key; empty: human output only
};

struct ModelTable {
    std::string title, json_name;
    std::vector<ModelColumn> columns;
    std::vector<std::vector<ModelCell>> rows;
};

// The options' value lists, each item a number, a comma list or a range; an option may
// repeat. d defaults to 1.
struct ModelRequest {
    std::vector<std::string> es, fv, d{"1"}, fw, ew, faces;
    Spelling spelling = Spelling::Option;
};

// The samples table (es and fv given), the window-cost table (fw and ew), or both in that
// order. Throws UsageError naming the option of a value or a combination that is wrong.
std::vector<ModelTable> model_tables(const ModelRequest& r);

// The table for humans (its title, then aligned columns), as `fb89 model` prints it.
std::string model_text(const ModelTable& t);
// The table as CSV with a header row, as --csv writes it.
std::string model_csv(const ModelTable& t);
// The tables as --json prints them.
nlohmann::ordered_json model_json(const std::vector<ModelTable>& tables);
// The CSV's column names, and a row's fields as the CSV has them.
std::vector<std::string> model_keys(const ModelTable& t);
std::vector<std::string> model_row(const ModelTable& t, std::size_t row);

}  // namespace fb89::frontend
