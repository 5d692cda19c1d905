// fb89 model: tabulates the paper's analytic model (Marks et al. 1990, Eqs. 2.1-2.4 for the
// window samples of the ideal scene, Exprs. 2.5-2.7 and 3.1 for the cost per pixel of a
// window) over a grid of E_s, F_v, D or F_w, E_w, D, F, as a table, JSON or CSV.
// The maths is in host/model/analytic_model.h, the tables in frontend/model_tables.h (shared
// with fb89.model() in Python); this file reads the options and prints.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.h"
#include "frontend/model_tables.h"

namespace fb89::cli {

namespace {

struct ModelArgs {
    frontend::ModelRequest request;
    bool json = false;
    std::string csv;  // a file, or '-' for stdout, as --csv is everywhere
};

int run_model(const ModelArgs& args) {
    const frontend::ModelRequest& r = args.request;
    const bool samples = !r.es.empty() || !r.fv.empty();
    const bool windows = !r.fw.empty() || !r.ew.empty() || !r.faces.empty();
    if (!args.csv.empty() && samples && windows)
        throw UsageError("--csv: prints one table; ask for --es/--fv or --fw/--ew, not both");
    const std::vector<frontend::ModelTable> tables = frontend::model_tables(r);
    if (args.json) {
        fmt::print("{}\n", frontend::model_json(tables).dump(2));
    } else if (!args.csv.empty()) {
        write_text(args.csv, frontend::model_csv(tables.front()));
    } else {
        for (size_t i = 0; i < tables.size(); ++i)
            fmt::print("{}{}", i ? "\n" : "", frontend::model_text(tables[i]));
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
    sub->add_option("--es", args->request.es,
                    "Screen edge E_s in pixels (Eqs. 2.1-2.4); list or range");
    sub->add_option("--fv", args->request.fv, "Visible faces F_v (Eqs. 2.1-2.4); list or range");
    sub->add_option("--d", args->request.d,
                    "Depth complexity D (sorting face computations, 2.5-2.7, 3.1)")
        ->capture_default_str();
    sub->add_option("--fw", args->request.fw, "Faces in the window F_w (Exprs. 2.5-2.7, 3.1)");
    sub->add_option("--ew", args->request.ew, "Window edge E_w in pixels (Exprs. 2.5-2.7, 3.1)");
    sub->add_option("--faces", args->request.faces, "Faces in the whole scene F (Expr. 2.7)");
    CLI::Option* json = sub->add_flag("--json", args->json, "Print JSON instead of a table");
    sub->add_option("--csv", args->csv,
                    "Write CSV with a header row instead of printing a table ('-' for stdout)")
        ->excludes(json);
    sub->footer(kEquations);
    sub->callback([args, &exit_code] { exit_code = run_model(*args); });
}

}  // namespace fb89::cli
