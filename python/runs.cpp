// The long-running commands from Python: experiment, sweep threshold and calibrate through
// the same requests as the command line (frontend/runs.h), their tables handed over as columns and
// rows for fb89.Table (fb89/_table.py).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "frontend/data_dir.h"
#include "frontend/runs.h"
#include "python/convert.h"
#include "python/work.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

py::dict table_parts(const experiments::Table& t) {
    py::dict out;
    out["columns"] = t.columns();
    out["rows"] = t.rows();
    out["text"] = t.text();
    out["csv"] = t.csv();
    return out;
}

// What the three requests share, from the keyword arguments the Python functions pass on.
void fill(frontend::RunRequest& r, const std::vector<std::string>& scenes, const std::string& size,
          int repeat, const std::string& controller, const std::string& host, int jobs,
          const std::string& results) {
    for (const std::string& scene : scenes)
        r.scenes.push_back(frontend::resolve_scene(scene));
    r.size = size;
    r.repeat = repeat;
    r.profile = controller;
    r.host.host = host;
    r.host.jobs = jobs;
    r.host.results = results;
}

// Runs a request through `run` (frontend/runs.h) as run_work() runs work: without the GIL, its
// progress line on or off as `progress` says.
template <class Request, class Run>
auto run_request(const py::object& progress, Request& request, Run run) {
    decltype(run(request)) out;
    run_work(progress, [&](bool line) {
        request.progress = line;
        out = run(request);
    });
    return out;
}

}  // namespace

void register_runs(py::module_& m) {
    m.def("_experiment", [](const std::string& name, const std::vector<std::string>& scenes,
                            const std::string& size, int repeat, const std::string& controller,
                            const std::string& threshold, const std::string& beam_threshold,
                            const std::vector<std::string>& sizes, const std::string& out_dir,
                            const std::string& accel, int patches, int reference_rays,
                            const std::vector<std::string>& methods, const std::string& host,
                            int jobs, const std::string& results, const py::object& progress) {
        frontend::ExperimentRequest r;
        fill(r, scenes, size, repeat, controller, host, jobs, results);
        r.name = name;
        r.threshold = threshold;
        r.beam_threshold = beam_threshold;
        r.sizes = sizes;
        r.out_dir = out_dir;
        r.accel = accel;
        r.patches = patches;
        r.reference_rays = reference_rays;
        r.methods = methods;
        const auto out = run_request(progress, r, frontend::run_experiment);
        return table_parts(out.table);
    });
    m.def("_sweep", [](const std::vector<std::string>& scenes, double start, double stop, int steps,
                       const std::string& window_test, const std::string& depth_estimate,
                       const std::string& size, int repeat, const std::string& controller,
                       const std::string& host, int jobs, const std::string& results,
                       const py::object& progress) {
        frontend::SweepRequest r;
        fill(r, scenes, size, repeat, controller, host, jobs, results);
        r.from = start;
        r.to = stop;
        r.steps = steps;
        r.window_test = window_test;
        r.depth_estimate = depth_estimate;
        const auto out = run_request(progress, r, frontend::run_threshold_sweep);
        return table_parts(out.table);
    });
    m.def("_calibrate",
          [](const std::string& method, const std::vector<std::string>& scenes, double start,
             double stop, int steps, int repeat, double tolerance, const std::string& host,
             int jobs, const std::string& results, bool save, const py::object& progress) {
              frontend::CalibrateRequest r;
              fill(r, scenes, "", repeat, r.profile, host, jobs, results);
              r.method = method;
              r.from = start;
              r.to = stop;
              r.steps = steps;
              r.tolerance = tolerance;
              r.dry_run = !save;
              const auto out = run_request(progress, r, frontend::run_calibration);
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
