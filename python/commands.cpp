// fb89.radiosity(), fb89.model(), fb89.host_validate() and fb89.controller_validate(): the
// commands `fb89 radiosity`, `model`, `host-validate` and `controller-validate` through the
// libraries they run on (frontend/radiosity_run.h, frontend/model_tables.h,
// frontend/validations.h), each keyword checked against the option's own limit and named
// as Python spells it. What radiosity() writes goes through an OutputBatch of its own.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"
#include "controller_sim/png_io.h"
#include "experiments/id_view.h"
#include "frontend/common.h"
#include "frontend/data_dir.h"
#include "frontend/model_tables.h"
#include "frontend/names.h"
#include "frontend/radiosity_run.h"
#include "frontend/validations.h"
#include "python/convert.h"
#include "python/options.h"
#include "python/outputs.h"
#include "python/stream_file.h"
#include "python/work.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

namespace limits = frontend::limits;

// One radiosity run, kept whole: the arrays handed out are views of its buffers.
struct RadiosityOutcome {
    frontend::RadiosityRequest request;
    frontend::RadiosityRun run;
    controller::Framebuffer image, ids;
    std::vector<int32_t> face_ids;  // -1 for the background
    nlohmann::json stats;
    std::string summary, controller_summary;
    std::vector<std::string> notes;
    std::shared_ptr<StreamFile> stream;
};

// The patch ids from the id buffer's 24-bit id + 1 (0: background -> -1).
std::vector<int32_t> ids_of(const controller::Framebuffer& frame) {
    std::vector<int32_t> out(std::size_t{frame.width()} * frame.height());
    const auto p = frame.pixels();
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<int32_t>((uint32_t{p[3 * i]} << 16) | (uint32_t{p[3 * i + 1]} << 8) |
                                      p[3 * i + 2]) -
                 1;
    return out;
}

// The keywords as the request and the options given (None: not given, the command's default).
frontend::RadiosityRequest radiosity_request(const std::string& scene, const py::kwargs& kw,
                                             frontend::RadiosityGiven& given) {
    frontend::RadiosityRequest r;
    r.spelling = frontend::Spelling::Keyword;
    r.scene = frontend::resolve_scene(scene);
    r.ff = text(kw["ff"], "ff");
    host::RadiosityOptions& o = r.options;
    const auto whole = [&](const char* key, const frontend::OptionLimit& limit, auto& out) {
        const py::handle v = kw[key];
        if (v.is_none()) return false;
        out = static_cast<std::remove_reference_t<decltype(out)>>(whole_number(v, limit));
        return true;
    };
    const auto real = [&](const char* key, const frontend::OptionLimit& limit, double& out) {
        const py::handle v = kw[key];
        if (v.is_none()) return false;
        out = real_number(v, limit);
        return true;
    };
    whole("patches", limits::kRadiosityPatches, o.patches);
    given.epsilon = real("epsilon", limits::kEpsilon, o.hierarchical.epsilon);
    given.link_rays = whole("link_rays", limits::kLinkRays, o.hierarchical.link_rays);
    given.min_area = real("min_area", limits::kMinArea, o.hierarchical.min_area);
    given.max_links = whole("max_links", limits::kMaxLinks, o.hierarchical.max_links);
    given.shaft_culling = flag(kw["shaft_culling"], "shaft_culling");
    o.hierarchical.shaft_culling = given.shaft_culling;
    given.hemicube_res = whole("hemicube_res", limits::kHemicubeRes, o.hemicube_res);
    if (!kw["solver"].is_none()) {
        r.solver = text(kw["solver"], "solver");
        given.solver = true;
    }
    real("tolerance", limits::kSolverTolerance, o.tolerance);
    whole("max_iterations", limits::kMaxIterations, o.max_iterations);
    given.adaptive = real("adaptive", limits::kAdaptive, o.adaptive);
    given.adaptive_passes = whole("adaptive_passes", limits::kAdaptivePasses, o.adaptive_passes);
    real("exposure", limits::kExposure, o.exposure);
    r.size = size_text(kw["size"]);
    r.profile = text(kw["profile"], "profile");
    try {
        frontend::check_profile_name(r.profile);
    } catch (const frontend::UsageError& e) {
        throw frontend::UsageError(std::string("profile: ") + e.what());
    }
    frontend::prepare_radiosity(r, given);
    return r;
}

// The outputs radiosity() was asked to write, as the command's --png ... --stats.
struct RadiosityFiles {
    std::string png, ids, ids_view, stream, stats;
};

void write_radiosity_files(const RadiosityFiles& f, const RadiosityOutcome& out) {
    file_work([&] {  // in the command's order
        if (!f.png.empty()) {
            frontend::make_parent_dirs(f.png);
            controller::write_png(f.png, out.image);
        }
        if (!f.ids.empty() || !f.ids_view.empty())
            experiments::write_id_pngs(out.ids, f.ids, f.ids_view);
        if (!f.stream.empty()) frontend::write_radiosity_stream(out.request, out.run, f.stream);
        if (!f.stats.empty()) frontend::write_json(f.stats, out.stats);
    });
}

std::shared_ptr<RadiosityOutcome> radiosity(const std::string& scene, const py::kwargs& kw) {
    auto out = std::make_shared<RadiosityOutcome>();
    frontend::RadiosityGiven given;
    out->request = radiosity_request(scene, kw, given);
    RadiosityFiles files{path_text(kw["png"], "png", true), path_text(kw["ids"], "ids", true),
                         path_text(kw["ids_view"], "ids_view", true),
                         path_text(kw["stream"], "stream", true),
                         path_text(kw["stats"], "stats", true)};
    const bool writes = !files.png.empty() || !files.ids.empty() || !files.ids_view.empty() ||
                        !files.stream.empty() || !files.stats.empty();
    const controller::CostProfile profile =
        frontend::profile_option(out->request.profile, "profile");
    run_work(kw["progress"], [&](bool line) {
        out->request.progress = line;
        out->run = frontend::run_radiosity(out->request);
        controller::Controller ctl(profile);
        out->run.commands.replay_into(ctl);
        out->image = ctl.framebuffer();
        out->ids = frontend::radiosity_id_buffer(out->run);
        out->face_ids = ids_of(out->ids);
        out->stats = frontend::radiosity_stats(out->request, out->run, ctl);
        out->summary = frontend::radiosity_summary(out->request, out->run);
        out->controller_summary = ctl.stats().summary();
        out->notes = frontend::radiosity_notes(out->request, out->run);
        if (writes) with_outputs([&] { write_radiosity_files(files, *out); });
    });
    out->stream = std::make_shared<StreamFile>();
    out->stream->header = frontend::radiosity_stream_header(out->request, out->run);
    out->stream->header["scene"] = frontend::scene_display_name(out->request.scene);
    out->run.commands.replay_into(out->stream->commands);
    return out;
}

py::dict table_parts(const std::vector<std::string>& columns,
                     const std::vector<std::vector<std::string>>& rows, const std::string& text,
                     const std::string& csv) {
    py::dict d;
    d["columns"] = columns;
    d["rows"] = rows;
    d["text"] = text;
    d["csv"] = csv;
    return d;
}

// A value list as the option takes it: a number, a str ("16,32,64", "1..16384*4") or a list
// or tuple of them.
std::vector<std::string> values_text(const py::handle& value, const char* keyword) {
    std::vector<std::string> out;
    if (value.is_none()) return out;
    const auto one = [&](const py::handle& v) {
        if (PyUnicode_Check(v.ptr())) return v.cast<std::string>();
        return py::repr(py::float_(real_number(v, keyword))).cast<std::string>();
    };
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        for (const py::handle v : value)
            out.push_back(one(v));
    } else {
        out.push_back(one(value));
    }
    return out;
}

py::list model(const py::kwargs& kw) {
    frontend::ModelRequest r;
    r.spelling = frontend::Spelling::Keyword;
    r.es = values_text(kw["es"], "es");
    r.fv = values_text(kw["fv"], "fv");
    r.d = values_text(kw["d"], "d");
    r.fw = values_text(kw["fw"], "fw");
    r.ew = values_text(kw["ew"], "ew");
    r.faces = values_text(kw["faces"], "faces");
    std::vector<frontend::ModelTable> tables;
    {
        py::gil_scoped_release unlocked;
        tables = frontend::model_tables(r);
    }
    py::list out;
    for (const frontend::ModelTable& t : tables) {
        std::vector<std::vector<std::string>> rows;
        for (std::size_t i = 0; i < t.rows.size(); ++i)
            rows.push_back(frontend::model_row(t, i));
        py::dict d = table_parts(frontend::model_keys(t), rows, frontend::model_text(t),
                                 frontend::model_csv(t));
        d["name"] = t.json_name;
        out.append(d);
    }
    return out;
}

py::dict report_parts(const frontend::ValidationReport& report) {
    py::dict d;
    d["text"] = report.text;
    d["csv"] = report.csv;
    d["listing"] = report.listing;
    d["all_pass"] = report.all_pass;
    return d;
}

}  // namespace

void register_commands(py::module_& m) {
    py::class_<RadiosityOutcome, std::shared_ptr<RadiosityOutcome>>(
        m, "Radiosity",
        "One radiosity run (fb89 radiosity): the controller's image, the patch id buffer, the "
        "counts and times --stats writes, and the summary the command prints.")
        .def_property_readonly("scene", [](const RadiosityOutcome& r) { return r.request.scene; })
        .def_property_readonly("ff", [](const RadiosityOutcome& r) { return r.request.ff; })
        .def_property_readonly("profile",
                               [](const RadiosityOutcome& r) { return r.request.profile; })
        .def_property_readonly(
            "image",
            [](py::object self) { return rgb_view(self.cast<RadiosityOutcome&>().image, self); },
            "The controller's framebuffer, H x W x 3 uint8 (a view: no copy), what --png writes.")
        .def_property_readonly(
            "ids",
            [](py::object self) {
                const RadiosityOutcome& r = self.cast<const RadiosityOutcome&>();
                return py::array_t<int32_t>({static_cast<py::ssize_t>(r.ids.height()),
                                             static_cast<py::ssize_t>(r.ids.width())},
                                            r.face_ids.data(), self);
            },
            "The patch id buffer, H x W int32: each pixel's patch, -1 for the background (what "
            "--ids writes as a PNG).")
        .def_property_readonly(
            "stats", [](const RadiosityOutcome& r) { return to_python(r.stats); },
            "Everything --stats writes: scene, radiosity, host (times, counters), render, "
            "controller.")
        .def_property_readonly(
            "counts",
            [](const RadiosityOutcome& r) {
                nlohmann::json c = r.stats["radiosity"];
                c["counters"] = r.stats["host"]["counters"];
                return to_python(c);
            },
            "The run's figures: patches, elements, iterations, residual, converged, "
            "max_row_sum, exposure, the hierarchy's counts (under 'hierarchical') and the "
            "counted operations (under 'counters': facing pairs, form factors, queries, rays).")
        .def_property_readonly(
            "times", [](const RadiosityOutcome& r) { return to_python(r.stats["host"]["times"]); },
            "Each stage's wall and CPU ms: load, meshing, visibility, form factors, solving, "
            "rendering, end to end.")
        .def_property_readonly(
            "controller_figures",
            [](const RadiosityOutcome& r) { return to_python(r.stats["controller"]); },
            "The controller's figures for the patches' frame (checksums as hex text).")
        .def_readonly("summary", &RadiosityOutcome::summary,
                      "What `fb89 radiosity` prints before the controller's summary.")
        .def_readonly("controller_summary", &RadiosityOutcome::controller_summary,
                      "The controller's summary the command prints after it.")
        .def_readonly("notes", &RadiosityOutcome::notes, "The notes the command prints on stderr.")
        .def_readonly("stream", &RadiosityOutcome::stream,
                      "The patches' frame as an fb89.Stream (what --stream writes).")
        .def("__repr__", [](const RadiosityOutcome& r) {
            return "<fb89.Radiosity " + frontend::scene_display_name(r.request.scene) + " " +
                   r.request.ff + ": " + std::to_string(r.run.result.mesh.patches.size()) +
                   " patches, " + std::to_string(r.run.screen.width) + "x" +
                   std::to_string(r.run.screen.height) + ">";
        });
    m.def("_radiosity", &radiosity);
    // A controller profile that is none, refused as the commands refuse --profile, under
    // Python's name for it.
    m.def("_check_profile", [](const py::object& name) {
        frontend::profile_option(text(name, "profile"), "profile");
    });
    m.def("_model", &model);
    m.def("_host_validate", [](const py::kwargs& kw) {
        frontend::HostValidationRequest r;
        r.spelling = frontend::Spelling::Keyword;
        if (!kw["profiles"].is_none()) r.profiles = text_list(kw["profiles"], "profile");
        if (!kw["classes"].is_none())
            r.classes = static_cast<int>(whole_number(kw["classes"], limits::kClasses));
        frontend::ValidationReport report;
        run_work(kw["progress"], [&](bool) { report = frontend::host_validation(r); });
        return report_parts(report);
    });
    m.def("_controller_validate", [](const py::kwargs& kw) {
        frontend::ControllerValidationRequest r;
        r.spelling = frontend::Spelling::Keyword;
        r.profile = text(kw["profile"], "profile");
        r.listing = flag(kw["listing"], "listing");
        frontend::ValidationReport report;
        run_work(py::bool_(false), [&](bool) { report = frontend::controller_validation(r); });
        return report_parts(report);
    });
}

}  // namespace fb89::python
