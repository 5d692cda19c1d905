// What the module does with streams, as the stream tools do it: replay (into a controller,
// with the pipeline in time and its timeline as `fb89 replay --buffer --timeline` has
// them, frontend/pipelines.h), trim and diff (frontend/stream_edit.h). Whatever they write
// is written under an OutputBatch of the call's own (python/outputs.h).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "controller_sim/controller.h"
#include "frontend/common.h"
#include "frontend/pipelines.h"
#include "frontend/stream_edit.h"
#include "frontend/stream_tools.h"
#include "python/convert.h"
#include "python/options.h"
#include "python/outputs.h"
#include "python/stream_file.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

// The rows into the controller, one command at a time, each (within a frame) through the
// frame's pipeline at its send time with what the controller said it cost.
class PipelineRows final : public protocol::CommandSink {
  public:
    PipelineRows(const StreamFile& s, controller::Controller& ctl,
                 frontend::FramePipelines& pipelines)
        : m_s(s), m_ctl(ctl), m_pipelines(pipelines) {}
    void take(const protocol::Command& c) override { step(c); }

  private:
    void step(const protocol::Command& c) {
        m_ctl.execute(c);
        const int64_t send = m_s.send_ns.empty() ? 0 : m_s.send_ns.at(m_row);
        int64_t host_end = send;  // a frame without a HOST_END: its last send time
        if (std::holds_alternative<protocol::FrameEnd>(c)) {
            while (m_end != m_s.host_ends.end() && m_end->first < m_row)
                ++m_end;
            if (m_end != m_s.host_ends.end() && m_end->first == m_row) host_end = m_end->second;
        }
        m_pipelines.follow(c, send, m_ctl.last_cost(), host_end);
        ++m_row;
    }
    const StreamFile& m_s;
    controller::Controller& m_ctl;
    frontend::FramePipelines& m_pipelines;
    std::size_t m_row = 0;
    std::vector<std::pair<std::size_t, int64_t>>::const_iterator m_end = m_s.host_ends.begin();
};

py::dict replay(const StreamFile& s, const py::object& controller_arg, const py::object& buffer_arg,
                const py::object& timeline_arg) {
    const std::string profile_name = text(controller_arg, "controller");
    const std::string buffer_given = buffer_text(buffer_arg);
    const std::string timeline = path_text(timeline_arg, "timeline", true);
    const controller::CostProfile profile = frontend::profile_option(profile_name, "controller");
    std::optional<uint64_t> buffer =
        frontend::parse_buffer_option(buffer_given, profile_name, frontend::Spelling::Keyword);
    if (!buffer && !timeline.empty()) buffer = profile.command_buffer_bytes;

    auto ctl = std::make_unique<controller::Controller>(profile);
    std::optional<frontend::FramePipelines> pipelines;
    {
        py::gil_scoped_release unlocked;
        if (!buffer) {
            s.commands.replay_into(*ctl);
        } else {
            pipelines.emplace(*buffer, !timeline.empty());
            PipelineRows rows(s, *ctl, *pipelines);
            s.commands.replay_into(rows);
        }
        if (!timeline.empty()) {
            const std::string name = s.path.empty() ? "<memory>" : s.path;
            const std::string sends = frontend::send_times_of(s.header, !s.send_ns.empty());
            with_outputs([&] {
                file_work([&] {
                    frontend::write_text(
                        timeline, pipelines->last_frame_timeline(name, timeline, sends, profile));
                });
            });
        }
    }
    auto* frame = new controller::Framebuffer(ctl->framebuffer());
    py::capsule owner(frame, [](void* p) { delete static_cast<controller::Framebuffer*>(p); });
    py::dict out;
    out["image"] = rgb_view(*frame, owner);
    out["checksum"] = frame->checksum();
    out["stats"] = to_python(ctl->stats().to_json());
    py::object frames = py::none();
    if (pipelines) {
        py::list each;
        for (const controller::PipelineFigures& p : pipelines->frames())
            each.append(to_python(frontend::pipeline_figures_json(p)));
        frames = each;
    }
    out["pipelines"] = frames;
    return out;
}

py::dict trim(const py::object& input_arg, const py::object& output_arg, const py::object& calls,
              const py::object& frames, const py::object& salvage) {
    frontend::TrimRequest r;
    r.input = path_text(input_arg, "stream");
    r.output = path_text(output_arg, "output");
    r.calls = optional_text(calls, "calls").value_or("");
    r.frames = optional_text(frames, "frames").value_or("");
    r.salvage = flag(salvage, "salvage");
    frontend::TrimOutcome out;
    {
        py::gil_scoped_release unlocked;
        with_outputs([&] {
            out = file_work([&] { return frontend::trim_stream(r); });
            using Result = frontend::TrimOutcome::Result;
            const std::string said = out.error ? std::string("; ") + out.error->what() : "";
            if (out.result == Result::NothingMatched)
                throw frontend::UsageError("trim: the selection matched no command of " + r.input +
                                           "; " + out.output + " not written" + said);
            if (out.result == Result::Damaged)
                throw protocol::StreamError(std::string(out.error->what()) + "; " + out.output +
                                                " not written (salvage=True keeps what was read "
                                                "before the error)",
                                            out.error->offset(), out.error->command(),
                                            out.error->damaged(), out.error->batch());
        });
    }
    py::dict d;
    d["path"] = out.output;
    d["commands"] = out.commands_kept;
    d["frames"] = out.frames_kept;
    d["salvaged"] = out.error ? py::object(py::str(out.error->what())) : py::object(py::none());
    return d;
}

py::dict diff(const py::object& a_arg, const py::object& b_arg, const py::object& image_arg) {
    const std::string a = path_text(a_arg, "a"), b = path_text(b_arg, "b");
    const std::string image = path_text(image_arg, "image", true);
    frontend::DiffOutcome out;
    {
        py::gil_scoped_release unlocked;
        with_outputs([&] {
            out = file_work([&] { return frontend::diff_streams(a, b, image); });
            if (out.error)  // nothing written: the image of a frame before it goes too
                throw protocol::StreamError(std::string(out.error->what()) + "; compared " +
                                                std::to_string(out.frames.size()) +
                                                " frame(s) before the error",
                                            out.error->offset(), out.error->command(),
                                            out.error->damaged(), out.error->batch());
        });
    }
    py::list frames;
    for (const frontend::FrameDiff& f : out.frames) {
        py::dict d;
        d["frame"] = f.frame;
        d["size_a"] = f.size_a.empty() ? py::object(py::none()) : py::str(f.size_a);
        d["size_b"] = f.size_b.empty() ? py::object(py::none()) : py::str(f.size_b);
        d["differing"] = f.differing;
        d["compared"] = f.compared;
        frames.append(d);
    }
    py::dict d;
    d["frames"] = frames;
    d["differing_frames"] = out.differing_frames;
    d["image_frame"] =
        out.image_frame ? py::object(py::int_(*out.image_frame)) : py::object(py::none());
    return d;
}

}  // namespace

void register_stream_calls(py::module_& m) {
    m.def("_replay", &replay, py::arg("stream"), py::arg("controller"), py::arg("buffer"),
          py::arg("timeline"));
    m.def("_trim", &trim);
    m.def("_diff", &diff);
}

}  // namespace fb89::python
