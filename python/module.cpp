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
#include "host/methods.h"
#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"
#include "period/emulator.h"
#include "period/host_profile.h"
#include "protocol/stream_format.h"
#include "python/convert.h"
#include "python/stream_file.h"
#include "python/work.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

// One render, kept whole: the numpy arrays handed out are views of its buffers.
struct RenderOutcome {
    std::string scene, method, host, controller;
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

std::shared_ptr<RenderOutcome> render(const std::string& scene, const std::string& method,
                                      const std::string& size, const std::string& host,
                                      const std::string& controller_profile, int repeat,
                                      const std::optional<std::string>& threshold,
                                      const std::optional<std::string>& beam_threshold,
                                      const std::optional<int>& reflections) {
    auto out = std::make_shared<RenderOutcome>();
    out->scene = frontend::resolve_scene(scene);
    out->method = method;
    out->host = host;
    out->controller = controller_profile;
    // a method, profile or host that is not one is a usage mistake, as on the command line,
    // answered with the nearest known name (frontend/names.h)
    const auto named = [](const char* what, const auto& load) {
        try {
            return load();
        } catch (const period::EmulatorError&) {
            throw;
        } catch (const std::runtime_error& e) {
            throw frontend::UsageError(std::string(what) + ": " + e.what());
        }
    };
    host::MethodOptions options(named("method", [&] { return frontend::find_method(method); }));
    named("host", [&] {
        frontend::check_host_name(host);
        return 0;
    });
    named("controller", [&] {
        frontend::check_profile_name(controller_profile);
        return 0;
    });
    const host::MethodInfo& info = host::method_info(options.method);
    check_applies(info, host::kHybridOptions, "threshold", threshold.has_value());
    check_applies(info, host::kBeamOptions, "beam_threshold", beam_threshold.has_value());
    check_applies(info, host::kTraceOptions, "reflections", reflections.has_value());
    options.hybrid.threshold =
        frontend::resolve_threshold(threshold.value_or("calibrated"), nullptr, host);
    options.beam.threshold =
        frontend::resolve_beam_threshold(beam_threshold.value_or("calibrated"), nullptr, host);
    if (reflections) options.trace.max_reflections = *reflections;
    host::validate(options);

    const controller::CostProfile cost =
        named("controller", [&] { return controller::load_profile(controller_profile); });

    experiments::RenderJob job;
    job.scene = out->scene;
    job.methods = {options};
    if (!size.empty()) job.size = frontend::parse_size(size);
    job.repeat = repeat;
    job.controller = controller_profile;
    if (host != "native")
        job.period = named(
            "host", [&] { return std::make_shared<experiments::PeriodRuns>(host, 1, "", "", ""); });
    job.check_frames = host != "native";
    out->result = experiments::run_render_job(job);
    const experiments::MethodRun& run = out->result.runs.front();

    // the controller tiles what the host decided: its framebuffer is the image
    controller::Controller ctl(cost);
    run.commands.replay_into(ctl);
    out->image = ctl.framebuffer();
    out->ids = experiments::id_framebuffer(out->result.scene, *run.renderer);
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

}  // namespace

void register_errors(py::module_& m);
void register_streams(py::module_& m);
void register_runs(py::module_& m);

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
        .def_readonly("controller", &RenderOutcome::controller)
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
        .def("__repr__", [](const RenderOutcome& r) {
            return "<fb89.Render " + frontend::scene_display_name(r.scene) + " " + r.method + " " +
                   std::to_string(r.result.screen.width) + "x" +
                   std::to_string(r.result.screen.height) + " on " + r.host + ">";
        });

    m.def("_render",
          [](const std::string& scene, const std::string& method, const std::string& size,
             const std::string& host, const std::string& controller, int repeat,
             const std::optional<std::string>& threshold,
             const std::optional<std::string>& beam_threshold,
             const std::optional<int>& reflections) {
              std::shared_ptr<RenderOutcome> out;
              run_work(py::bool_(false), [&](bool) {
                  out = render(scene, method, size, host, controller, repeat, threshold,
                               beam_threshold, reflections);
              });
              return out;
          });
    // For bench/python_overhead.py: the same render done from C++, `rounds` times, each timed
    // here; what fb89.render() adds is its time less this.
    m.def("_bench_render", [](const std::string& scene, const std::string& method, int rounds) {
        std::vector<double> seconds;
        py::gil_scoped_release unlocked;
        for (int i = 0; i < rounds; ++i) {
            const auto start = std::chrono::steady_clock::now();
            render(scene, method, "", "native", std::string(controller::kDefaultProfile), 1,
                   std::nullopt, std::nullopt, std::nullopt);  // made and freed, as in Python
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
    m.def("_scene_info", [](const std::string& argument) {
        const std::string file = frontend::resolve_scene(argument);
        host::Scene scene;
        {
            py::gil_scoped_release unlocked;
            scene = host::load_scene(file);
        }
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

    register_streams(m);
    register_runs(m);
}

}  // namespace fb89::python
