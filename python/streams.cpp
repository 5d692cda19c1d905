// fb89 streams from Python: a stream file read through the stream reader into a structured
// array of its commands, its header and markers; replayed into a controller.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "controller_sim/controller.h"
#include "controller_sim/profile.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_reader.h"
#include "python/convert.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

struct StreamFile {
    std::string path;
    uint16_t version = 0;
    protocol::Properties header;
    protocol::MemoryBuffer commands;
};

std::shared_ptr<StreamFile> open_stream(const std::string& path) {
    auto out = std::make_shared<StreamFile>();
    out->path = path;
    std::optional<protocol::StreamReader> opened;
    try {
        opened.emplace(path);
    } catch (const protocol::StreamError&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw FileProblem(e.what());  // it cannot be opened
    }
    protocol::StreamReader& reader = *opened;
    out->version = reader.version();
    out->header = reader.properties();
    reader.replay_into(out->commands);
    return out;
}

}  // namespace

void register_streams(py::module_& m) {
    m.attr("COMMAND_DTYPE") = command_dtype();

    py::class_<StreamFile, std::shared_ptr<StreamFile>>(
        m, "Stream",
        "An fb89 command stream read whole (docs/PROTOCOL.md): its header, and its commands "
        "as a numpy structured array (fb89.COMMAND_DTYPE).")
        .def_static(
            "open",
            [](const std::string& path) {
                py::gil_scoped_release unlocked;
                return open_stream(path);
            },
            py::arg("path"),
            "Reads a stream file. Raises fb89.FileError naming the byte offset and command "
            "number of anything corrupt.")
        .def_readonly("path", &StreamFile::path)
        .def_readonly("version", &StreamFile::version, "The stream's format version.")
        .def_readonly("header", &StreamFile::header,
                      "The header's properties (scene, method, resolution, tool ...).")
        .def_property_readonly(
            "commands", [](const StreamFile& s) { return commands_array(s.commands.commands()); },
            "The commands, one row each, in order (row i is command number i).")
        .def_property_readonly(
            "markers",
            [](const StreamFile& s) {
                py::list out;
                const auto& all = s.commands.commands();
                for (std::size_t i = 0; i < all.size(); ++i)
                    if (const auto* mk = std::get_if<protocol::Marker>(&all[i]))
                        out.append(py::make_tuple(i, mk->text));
                return out;
            },
            "The MARKER commands: (command number, text) pairs.")
        .def_property_readonly(
            "frames",
            [](const StreamFile& s) {
                std::size_t n = 0;
                for (const auto& c : s.commands.commands())
                    n += std::holds_alternative<protocol::FrameBegin>(c);
                return n;
            },
            "How many frames the stream begins.")
        .def("__len__", [](const StreamFile& s) { return s.commands.size(); })
        .def(
            "save",
            [](const StreamFile& s, const std::string& path) {
                py::gil_scoped_release unlocked;
                save_stream(s.commands, path, s.header);
            },
            py::arg("path"), "Writes the stream again (version 1), header and all.")
        .def("__repr__", [](const StreamFile& s) {
            return "<fb89.Stream " + s.path + ": " + std::to_string(s.commands.size()) +
                   " commands>";
        });

    m.def(
        "replay",
        [](const StreamFile& s, const std::string& profile) {
            auto ctl = std::make_unique<controller::Controller>(controller::load_profile(profile));
            {
                py::gil_scoped_release unlocked;
                s.commands.replay_into(*ctl);
            }
            auto* frame = new controller::Framebuffer(ctl->framebuffer());
            py::capsule owner(frame,
                              [](void* p) { delete static_cast<controller::Framebuffer*>(p); });
            py::dict out;
            out["image"] = rgb_view(*frame, owner);
            out["checksum"] = frame->checksum();
            out["stats"] = to_python(ctl->stats().to_json());
            return out;
        },
        py::arg("stream"), py::kw_only(),
        py::arg("profile") = std::string(controller::kDefaultProfile),
        "Replays a stream into a controller of the given cost profile (fb89 replay): returns "
        "{'image': H x W x 3 uint8, 'checksum': the last frame's XXH64, 'stats': the controller's "
        "figures per opcode and per frame}.");
}

}  // namespace fb89::python
