// The fb89 Python module (import fb89): a thin layer over the libraries the command line uses
// -- the render job (experiments/render_job.h), the id pass, the controller, the stream reader
// -- and the front end's own rules for scene names and thresholds (frontend/data_dir.h,
// frontend/calibration.h), so that a call reads its arguments and does its work exactly as the
// matching command does. Arrays are numpy views of fb89's buffers that keep their owner
// alive; the GIL is released while fb89 works. docs/PYTHON.md is the tour.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"
#include "controller_sim/profile.h"
#include "experiments/catalog.h"
#include "experiments/id_pass.h"
#include "experiments/period_runs.h"
#include "experiments/render_job.h"
#include "frontend/calibration.h"
#include "frontend/common.h"
#include "frontend/data_dir.h"
#include "frontend/names.h"
#include "frontend/period_host.h"
#include "frontend/pipelines.h"
#include "host/methods.h"
#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"
#include "period/emulator.h"
#include "period/host_profile.h"
#include "protocol/stream_format.h"
#include "python/convert.h"
#include "python/options.h"
#include "python/outputs.h"
#include "python/stream_file.h"
#include "python/work.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

// One render, kept whole: the numpy arrays handed out are views of its buffers.
struct RenderOutcome {
    std::string scene, method, host, controller;
    controller::CostProfile profile;
    experiments::RenderResult result;
    controller::Framebuffer image, ids;
    std::vector<int32_t> face_ids;       // ids as face ids, -1 for the background
    std::shared_ptr<StreamFile> stream;  // the frame's commands
    nlohmann::json host_times, counters, controller_figures, split, period, pipeline;
};

// The face-id buffer as ids (-1 for the background) from the id pass's 24-bit id + 1.
std::vector<int32_t> face_ids(const controller::Framebuffer& frame) {
    std::vector<int32_t> out(std::size_t{frame.width()} * frame.height());
    const auto p = frame.pixels();
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<int32_t>((uint32_t{p[3 * i]} << 16) | (uint32_t{p[3 * i + 1]} << 8) |
                                      p[3 * i + 2]) -
                 1;
    return out;
}

// An option given to a method that does not read it is refused, as the command line does.
void check_applies(const host::MethodInfo& info, host::OptionGroup group, const char* option,
                   bool given) {
    if (!given || info.uses(group)) return;
    std::string users;
    for (const auto& m : host::methods())
        if (m.uses(group)) users += (users.empty() ? "" : " and ") + std::string(m.name);
    throw frontend::UsageError(std::string(option) + ": the " + std::string(info.name) +
                               " method does not use it (only " + users + " do)");
}

// What render() takes, as the Python keywords gave it (python/options.h checked each).
struct RenderArgs {
    std::string scene, method = "zbuffer", size, host = "native";
    std::string controller = std::string(controller::kDefaultProfile);
    int repeat = 1;
    std::optional<std::string> threshold, beam_threshold;
    std::optional<int> reflections;
    std::string buffer;  // "": the profile's command buffer
};

RenderArgs render_args(const std::string& scene, const py::object& method, const py::object& size,
                       const py::object& host, const py::object& controller,
                       const py::object& repeat, const py::object& threshold,
                       const py::object& beam_threshold, const py::object& reflections,
                       const py::object& buffer) {
    RenderArgs a;
    a.scene = scene;
    a.method = text(method, "method");
    a.size = size_text(size);
    a.host = text(host, "host");
    a.controller = text(controller, "profile");
    a.repeat = static_cast<int>(whole_number(repeat, frontend::limits::kRenderRepeat));
    a.threshold = threshold_text(threshold, "threshold");
    a.beam_threshold = threshold_text(beam_threshold, "beam_threshold");
    if (!reflections.is_none())
        a.reflections = static_cast<int>(whole_number(reflections, frontend::limits::kReflections));
    a.buffer = buffer_text(buffer);
    return a;
}

std::shared_ptr<RenderOutcome> render(const RenderArgs& a) {
    auto out = std::make_shared<RenderOutcome>();
    out->scene = frontend::resolve_scene(a.scene);
    out->method = a.method;
    out->host = a.host;
    out->controller = a.controller;
    host::MethodOptions options;
    // a method, host or profile that is not one: the command line's check, with the nearest
    // known name (frontend/names.h), under the keyword's name
    const auto named = [](const char* keyword, const auto& check) {
        try {
            return check();
        } catch (const frontend::UsageError& e) {
            throw frontend::UsageError(std::string(keyword) + ": " + e.what());
        }
    };
    options.method = named("method", [&] { return frontend::find_method(a.method); });
    named("host", [&] {
        frontend::check_host_name(a.host);
        return 0;
    });
    named("profile", [&] {
        frontend::check_profile_name(a.controller);
        return 0;
    });
    const host::MethodInfo& info = host::method_info(options.method);
    check_applies(info, host::kHybridOptions, "threshold", a.threshold.has_value());
    check_applies(info, host::kBeamOptions, "beam_threshold", a.beam_threshold.has_value());
    check_applies(info, host::kTraceOptions, "reflections", a.reflections.has_value());
    options.hybrid.threshold =
        frontend::resolve_threshold(a.threshold.value_or("calibrated"), nullptr, a.host);
    options.beam.threshold =
        frontend::resolve_beam_threshold(a.beam_threshold.value_or("calibrated"), nullptr, a.host);
    if (a.reflections) options.trace.max_reflections = *a.reflections;
    host::validate(options);

    // a profile or host that is not one is a usage mistake, as on the command line
    out->profile = frontend::profile_option(a.controller, "profile");
    const std::string& controller_profile = a.controller;
    const std::string& host = a.host;
    const std::string& method = a.method;
    experiments::RenderJob job;
    job.scene = out->scene;
    job.methods = {options};
    if (!a.size.empty()) job.size = frontend::parse_size(a.size, frontend::Spelling::Keyword);
    job.repeat = a.repeat;
    job.controller = controller_profile;
    job.buffer_bytes =
        frontend::parse_buffer_option(a.buffer, controller_profile, frontend::Spelling::Keyword);
    if (host != "native") {
        try {
            job.period = std::make_shared<experiments::PeriodRuns>(host, 1, "", "", "");
        } catch (const period::EmulatorError&) {
            throw;
        } catch (const std::runtime_error& e) {
            throw frontend::UsageError(std::string("host: ") + e.what());
        }
    }
    job.check_frames = host != "native";
    out->result = experiments::run_render_job(job);
    const experiments::MethodRun& run = out->result.runs.front();

    // the controller tiles what the host decided: its framebuffer is the image
    controller::Controller ctl(out->profile);
    run.commands.replay_into(ctl);
    out->image = ctl.framebuffer();
    out->ids =
        experiments::id_framebuffer(out->result.scene, *run.renderer, ctl.profile().depth_bits);
    out->face_ids = face_ids(out->ids);
    out->stream = std::make_shared<StreamFile>();
    out->stream->header = {{"scene", frontend::scene_display_name(out->scene)},
                           {"method", method},
                           {"resolution", std::to_string(out->result.screen.width) + "x" +
                                              std::to_string(out->result.screen.height)},
                           {"tool", std::string("fb89 ") + FB89_VERSION}};
    run.commands.replay_into(out->stream->commands);

    const nlohmann::json stats = run.stats.to_json();
    out->host_times = stats["times"];
    out->counters = stats["counters"];
    out->controller_figures = ctl.stats().to_json();
    out->split = {{"host_ms", run.host_frame_ms},
                  {"controller_ms", run.controller.frame_ms},
                  {"frame_ms", run.split.frame_ms},
                  {"bound_by", run.split.host_bounds ? "host" : "controller"},
                  {"ratio", run.split.ratio}};
    if (run.pipeline)
        out->pipeline = frontend::pipeline_json(
            *run.pipeline, frontend::send_times_source(run.period.has_value()));
    if (run.period) {
        const auto& p = *run.period;
        out->period = {{"profile", p.cost.profile},
                       {"cpu", p.cpu},
                       {"fpu", p.fpu},
                       {"instructions", p.guest_instructions},
                       {"end_to_end_ms", p.cost.end_to_end_ms()},
                       {"same_frame", p.same_frame}};
    }
    return out;
}

// The render's frame as render --timeline writes it; a UsageError naming `what` when the
// frame has no send times.
std::string timeline_of(const RenderOutcome& r, const std::string& what) {
    try {
        return frontend::render_timeline(r.result.runs.front(), r.scene, r.method, r.host,
                                         r.profile, what);
    } catch (const std::runtime_error& e) {
        throw frontend::UsageError(e.what());
    }
}

}  // namespace

void register_errors(py::module_& m);
void register_stream_calls(py::module_& m);
void register_streams(py::module_& m);
void register_runs(py::module_& m);
void register_commands(py::module_& m);
void register_info(py::module_& m);

PYBIND11_MODULE(_fb89, m) {
    m.doc() =
        "fb89: the paper's hidden-surface methods, a 1989 frame-buffer controller and "
        "its command streams, from Python (docs/PYTHON.md)";
    register_errors(m);

    // ---- what fb89 list lists ----
    m.def(
        "scenes",
        [] {
            std::vector<std::string> names;
            for (const auto& e :
                 std::filesystem::directory_iterator(frontend::data_dir() / "scenes"))
                if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
            std::sort(names.begin(), names.end());
            return names;
        },
        "The bundled scenes, by name (fb89 list scenes).");
    m.def(
        "methods",
        [] {
            std::vector<std::string> names;
            for (const auto& info : host::methods())
                names.emplace_back(info.name);
            return names;
        },
        "The hidden-surface methods (fb89 list methods).");
    m.def(
        "hosts",
        [] {
            std::vector<std::string> names{"native"};
            for (const std::string& n : period::builtin_host_profile_names())
                names.push_back(n);
            return names;
        },
        "The hosts a render can be timed on: 'native' and the 1989 host profiles (fb89 list "
        "hosts).");
    m.def("profiles", &controller::list_profiles,
          "The controller cost profiles (fb89 list profiles).");
    m.def(
        "experiments",
        [] {
            std::vector<std::string> names;
            for (const auto& e : experiments::experiment_catalog())
                names.emplace_back(e.name);
            return names;
        },
        "The paper's experiments (fb89 list experiments).");

    // ---- a render ----
    py::class_<RenderOutcome, std::shared_ptr<RenderOutcome>>(
        m, "Render",
        "One render: the controller's image, the face-id buffer, the host's times "
        "and counters, the controller's figures and the split (fb89 render).")
        .def_readonly("scene", &RenderOutcome::scene, "The scene file rendered.")
        .def_readonly("method", &RenderOutcome::method)
        .def_readonly("host", &RenderOutcome::host)
        .def_readonly("profile", &RenderOutcome::controller,
                      "The controller's cost profile (render's --profile).")
        .def_readonly("controller", &RenderOutcome::controller, "The profile's old name.")
        .def_property_readonly(
            "image",
            [](py::object self) { return rgb_view(self.cast<RenderOutcome&>().image, self); },
            "The controller's framebuffer, H x W x 3 uint8 (a view: no copy).")
        .def_property_readonly(
            "ids",
            [](py::object self) {
                const RenderOutcome& r = self.cast<const RenderOutcome&>();
                return py::array_t<int32_t>({static_cast<py::ssize_t>(r.ids.height()),
                                             static_cast<py::ssize_t>(r.ids.width())},
                                            r.face_ids.data(), self);
            },
            "The face-id buffer, H x W int32: each pixel's face id, -1 for the background "
            "(what render --ids writes as a PNG).")
        .def_property_readonly(
            "times", [](const RenderOutcome& r) { return to_python(r.host_times); },
            "The host's times (load, set-up, hidden-surface, end to end: wall and CPU ms) and "
            "counters, as render --stats writes them.")
        .def_property_readonly(
            "counters", [](const RenderOutcome& r) { return to_python(r.counters); },
            "The counted operations of the frame (window samples, depth tests, rays ...).")
        .def_property_readonly(
            "controller_figures",
            [](const RenderOutcome& r) { return to_python(r.controller_figures); },
            "The controller's figures per opcode and per frame (commands, pixels, bytes, cycles, "
            "modelled times), as controller --stats writes them.")
        .def_property_readonly(
            "split", [](const RenderOutcome& r) { return to_python(r.split); },
            "The host against the controller: host_ms, controller_ms, frame_ms, bound_by, "
            "ratio.")
        .def_property_readonly(
            "pipeline", [](const RenderOutcome& r) { return to_python(r.pipeline); },
            "The frame through the pipeline in time from the commands' send times, measured "
            "natively and counted on a 1989 host (docs/COST_MODEL.md): send_times, frame_ms "
            "beside max_ms and sum_ms, overlap, host stalls, bus and controller busy, the "
            "controller alone through the buffer (controller_alone_ms), "
            "utilizations (render --stats' \"pipeline\"); None when there are no send times.")
        .def_property_readonly(
            "period", [](const RenderOutcome& r) { return to_python(r.period); },
            "On a 1989 host: the profile, its chips, the emulated instructions and the modelled "
            "end-to-end time; None natively.")
        .def_readonly("stream", &RenderOutcome::stream,
                      "The frame's command stream (an fb89.Stream: .commands, .save(path)).")
        .def_property_readonly(
            "commands",
            [](const RenderOutcome& r) {
                const py::object stream = py::cast(r.stream);
                return py::object(stream.attr("commands"));
            },
            "The frame's commands as a structured array (fb89.COMMAND_DTYPE), one row a "
            "command: render.stream.commands.")
        .def(
            "timeline",
            [](const RenderOutcome& r) {
                std::string json;
                {
                    py::gil_scoped_release unlocked;
                    json = timeline_of(r, "timeline");
                }
                return py::module_::import("json").attr("loads")(json);
            },
            "The frame through the pipeline in time as Chrome trace-event JSON (a dict; "
            "Perfetto and chrome://tracing open it), what render --timeline writes: host, bus "
            "and controller lanes, host stalls, the buffer's fill. Raises fb89.OptionError "
            "for a frame without send times.")
        .def(
            "save_timeline",
            [](const RenderOutcome& r, const py::object& path) {
                const std::string file = path_text(path, "path");
                py::gil_scoped_release unlocked;
                const std::string json = timeline_of(r, "save_timeline");
                with_outputs([&] { file_work([&] { frontend::write_text(file, json); }); });
            },
            py::arg("path"),
            "Writes timeline() to a file, byte for byte as render --timeline writes it (whole "
            "or not at all, its folder made).")
        .def("__repr__", [](const RenderOutcome& r) {
            return "<fb89.Render " + frontend::scene_display_name(r.scene) + " " + r.method + " " +
                   std::to_string(r.result.screen.width) + "x" +
                   std::to_string(r.result.screen.height) + " on " + r.host + ">";
        });

    m.def("_render",
          [](const std::string& scene, const py::object& method, const py::object& size,
             const py::object& host, const py::object& controller, const py::object& repeat,
             const py::object& threshold, const py::object& beam_threshold,
             const py::object& reflections, const py::object& buffer) {
              const RenderArgs args = render_args(scene, method, size, host, controller, repeat,
                                                  threshold, beam_threshold, reflections, buffer);
              std::shared_ptr<RenderOutcome> out;
              run_work(py::bool_(false), [&](bool) { out = render(args); });
              return out;
          });
    // For bench/python_overhead.py: the same render done from C++, `rounds` times, each timed
    // here; what fb89.render() adds is its time less this.
    m.def("_bench_render", [](const std::string& scene, const std::string& method, int rounds) {
        std::vector<double> seconds;
        py::gil_scoped_release unlocked;
        for (int i = 0; i < rounds; ++i) {
            const auto start = std::chrono::steady_clock::now();
            RenderArgs args;
            args.scene = scene;
            args.method = method;
            render(args);  // made and freed, as in Python
            seconds.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        return seconds;
    });
    m.def(
        "_installed_at",
        [](const std::string& prefix) {
            frontend::set_install_prefix(prefix);
            frontend::use_installed_period_parts();
        },
        "Called by the installed package (fb89/_install.py): the prefix it is installed in, where "
        "the bundled data and the 1989 hosts' parts are, as for the installed fb89 command.");
    // A scene's facts; `name` (a scene given as a dict, in its private file `argument`):
    // read under that name, which its errors and every table, header and repr then show.
    m.def("_scene_info", [](const std::string& argument, const std::string& name) {
        const std::string file = name.empty() ? frontend::resolve_scene(argument) : argument;
        host::Scene scene;
        {
            py::gil_scoped_release unlocked;
            if (name.empty()) {
                scene = host::load_scene(file);
            } else {
                std::ifstream in(file, std::ios::binary);
                const std::string json((std::istreambuf_iterator<char>(in)),
                                       std::istreambuf_iterator<char>());
                scene =
                    host::parse_scene_json(json, name, std::filesystem::path(file).parent_path());
            }
        }
        if (!name.empty()) frontend::name_scene_file(file, name);
        py::dict d;
        d["path"] = file;
        d["name"] = frontend::scene_display_name(file);
        d["width"] = scene.width;
        d["height"] = scene.height;
        d["faces"] = scene.faces.size();
        d["face_ids"] = scene.face_count;
        d["notes"] = scene.notes;
        return d;
    });
    m.def("_forget_scene_file", [](const std::string& file) {
        frontend::forget_scene_file(file);
        std::error_code ec;
        std::filesystem::remove(file, ec);
    });

    register_streams(m);
    register_stream_calls(m);
    register_runs(m);
    register_commands(m);
    register_info(m);
}

}  // namespace fb89::python
