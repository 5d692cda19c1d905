// fb89.info(stream): what `fb89 info` reports of a stream file (frontend/stream_info.h), as a
// dict -- the JSON `fb89 info --json` prints: header, frame index, and per frame the commands
// by opcode, pixels, bus bytes, file bytes and checksum (16 hex digits, as the command prints
// it). A truncated or corrupt stream gives its complete frames and an "error".
#include <pybind11/pybind11.h>

#include <string>

#include "frontend/common.h"
#include "frontend/stream_info.h"
#include "python/convert.h"
#include "python/options.h"
#include "python/outputs.h"

namespace py = pybind11;

namespace fb89::python {

void register_info(py::module_& m) {
    m.def("_info", [](const py::object& path, const py::object& profile_name) {
        const std::string file = path_text(path, "stream");
        const controller::CostProfile profile =
            frontend::profile_option(text(profile_name, "profile"), "profile");
        frontend::StreamInfoReport report;
        {
            py::gil_scoped_release unlocked;
            report = file_work([&] { return frontend::stream_info(file, profile); });
        }
        return to_python(report.info);
    });
}

}  // namespace fb89::python
