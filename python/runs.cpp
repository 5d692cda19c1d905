// The long-running commands from Python: experiment, sweep threshold, compare and calibrate
// through the same requests as the command line (frontend/runs.h), their keywords checked
// as the command line checks its options (python/options.h) and their errors naming the
// keywords, their tables handed over as columns and rows for fb89.Table (fb89/_table.py).
// What they write goes through an OutputBatch of the call's own (python/outputs.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "controller_sim/png_io.h"
#include "frontend/common.h"
#include "frontend/data_dir.h"
#include "frontend/runs.h"
#include "python/convert.h"
#include "python/options.h"
#include "python/outputs.h"
#include "python/work.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

namespace limits = frontend::limits;

py::dict table_parts(const experiments::Table& t) {
    py::dict out;
    out["columns"] = t.columns();
    out["rows"] = t.rows();
    out["text"] = t.text();
    out["csv"] = t.csv();
    return out;
}

// What the requests share, from the keyword arguments the Python functions pass on
// (`scenes`: paths the Python layer resolved from names, files, dicts and fb89.Scenes).
void fill(frontend::RunRequest& r, const std::vector<std::string>& scenes, const py::object& size,
          const py::object& repeat, const py::object& controller, const py::object& host,
          const py::object& jobs, const py::object& results) {
    r.spelling = frontend::Spelling::Keyword;
    for (const std::string& scene : scenes)
        r.scenes.push_back(frontend::resolve_scene(scene));
    r.size = size_text(size);
    r.repeat = static_cast<int>(whole_number(repeat, limits::kRepeat));
    r.profile = text(controller, "profile");
    r.host.host = text(host, "host");
    r.host.jobs = static_cast<int>(whole_number(jobs, limits::kJobs));
    r.host.results = path_text(results, "results", true);
}

// Runs a request through `run` (frontend/runs.h) as run_work() runs work: without the GIL, its
// progress line on or off as `progress` says; with `writes`, under an OutputBatch of its own.
template <class Request, class Run>
auto run_request(const py::object& progress, Request& request, Run run, bool writes) {
    decltype(run(request)) out;
    run_work(progress, [&](bool line) {
        request.progress = line;
        if (writes)
            with_outputs([&] { out = run(request); });
        else
            out = run(request);
    });
    return out;
}

py::array image_copy(const controller::Framebuffer& frame) {
    py::array_t<uint8_t> out({static_cast<py::ssize_t>(frame.height()),
                              static_cast<py::ssize_t>(frame.width()), py::ssize_t{3}});
    std::copy(frame.pixels().begin(), frame.pixels().end(), out.mutable_data());
    return out;
}

py::dict compare(const std::vector<std::string>& scene, const py::kwargs& kw) {
    frontend::CompareRequest r;
    fill(r, scene, kw["size"], kw["repeat"], kw["controller"], kw["host"], kw["jobs"],
         kw["results"]);
    r.threshold = threshold_text(kw["threshold"], "threshold").value_or("calibrated");
    r.beam_threshold =
        threshold_text(kw["beam_threshold"], "beam_threshold").value_or("calibrated");
    const std::string sheet = path_text(kw["sheet"], "sheet", true);
    const std::string csv = path_text(kw["csv"], "csv", true);
    const std::string json = path_text(kw["json"], "json", true);
    frontend::CompareOutcome out;
    run_work(kw["progress"], [&](bool line) {
        r.progress = line;
        with_outputs([&] {
            out = frontend::run_compare(r);
            file_work([&] {  // in the command's order: sheet, CSV, JSON
                if (!sheet.empty()) {
                    frontend::make_parent_dirs(sheet);
                    controller::write_png(sheet, out.comparison.sheet);
                }
                if (!csv.empty()) frontend::write_text(csv, out.table.csv());
                if (!json.empty()) frontend::write_json(json, out.rows);
            });
        });
    });
    py::dict d = table_parts(out.table);
    d["rows_json"] = to_python(out.rows);
    d["thresholds"] = out.thresholds;
    d["sheet"] = image_copy(out.comparison.sheet);
    py::dict frames;
    for (std::size_t i = 0; i < out.comparison.rows.size(); ++i)
        frames[py::str(out.comparison.rows[i].method)] = image_copy(out.comparison.frames[i]);
    d["frames"] = frames;
    return d;
}

}  // namespace

void register_runs(py::module_& m) {
    m.def("_experiment", [](const py::object& name, const std::vector<std::string>& scenes,
                            const py::kwargs& kw) {
        frontend::ExperimentRequest r;
        fill(r, scenes, kw["size"], kw["repeat"], kw["controller"], kw["host"], kw["jobs"],
             kw["results"]);
        r.name = text(name, "name");
        r.threshold = threshold_text(kw["threshold"], "threshold").value_or("calibrated");
        r.beam_threshold =
            threshold_text(kw["beam_threshold"], "beam_threshold").value_or("calibrated");
        r.sizes.clear();
        if (!kw["sizes"].is_none()) {
            if (!py::isinstance<py::list>(kw["sizes"]) && !py::isinstance<py::tuple>(kw["sizes"]))
                throw py::type_error("sizes: expected a list of sizes (\"WxH\" or (W, H))");
            for (const py::handle size : kw["sizes"])
                r.sizes.push_back(size_text(size, "sizes"));
        }
        r.out_dir = path_text(kw["out_dir"], "out_dir");
        r.accel = text(kw["accel"], "accel");
        r.patches = static_cast<int>(whole_number(kw["patches"], limits::kPatches));
        r.reference_rays =
            static_cast<int>(whole_number(kw["reference_rays"], limits::kReferenceRays));
        if (!kw["methods"].is_none()) r.methods = text_list(kw["methods"], "methods");
        const auto out = run_request(kw["progress"], r, frontend::run_experiment, true);
        return table_parts(out.table);
    });
    m.def("_sweep", [](const std::vector<std::string>& scenes, const py::kwargs& kw) {
        frontend::SweepRequest r;
        fill(r, scenes, kw["size"], kw["repeat"], kw["controller"], kw["host"], kw["jobs"],
             kw["results"]);
        r.from = real_number(kw["start"], "start");
        r.to = real_number(kw["stop"], "stop");
        r.steps = static_cast<int>(whole_number(kw["steps"], limits::kSteps));
        r.window_test = text(kw["window_test"], "window_test");
        r.depth_estimate = text(kw["depth_estimate"], "depth_estimate");
        // (it writes only a 1989 host's results folder, which is kept as it goes)
        const auto out = run_request(kw["progress"], r, frontend::run_threshold_sweep, false);
        return table_parts(out.table);
    });
    m.def("_compare", &compare);
    m.def("_calibrate", [](const std::vector<std::string>& scenes, const py::kwargs& kw) {
        frontend::CalibrateRequest r;
        fill(r, scenes, py::none(), kw["repeat"], py::str(r.profile), kw["host"], kw["jobs"],
             kw["results"]);
        r.method = text(kw["method"], "method");
        r.from = real_number(kw["start"], "start");
        r.to = real_number(kw["stop"], "stop");
        r.steps = static_cast<int>(whole_number(kw["steps"], limits::kSteps));
        r.tolerance = real_number(kw["tolerance"], limits::kTolerance);
        r.dry_run = !flag(kw["save"], "save");
        const auto out = run_request(kw["progress"], r, frontend::run_calibration, !r.dry_run);
        const experiments::Calibration& c = out.calibration;
        py::dict d;
        d["chosen"] = c.chosen;
        d["sweep"] = table_parts(c.sweep);
        d["total_ms"] = c.total;
        d["worst"] = c.worst;
        d["reference_ms"] = c.reference_ms;
        d["choices"] = c.choices;
        d["stable"] = c.stable;
        d["details"] = to_python(out.details);
        d["saved_to"] = out.saved_to.empty() ? py::object(py::none()) : py::str(out.saved_to);
        d["warning"] = out.warning.empty() ? py::object(py::none()) : py::str(out.warning);
        return d;
    });
}

}  // namespace fb89::python
