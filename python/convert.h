// What the Python module's parts share: JSON figures as Python objects, a frame's commands as
// a numpy structured array (one row a command), and a frame written as an fb89 stream.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/framebuffer.h"
#include "protocol/command.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_format.h"

namespace fb89::python {

// A file that cannot be opened or written: fb89.FileError (an OSError) in Python.
class FileProblem : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

// null -> None, objects -> dict, arrays -> list, numbers and strings as themselves.
pybind11::object to_python(const nlohmann::json& j);

// The dtype of a command row: opcode (1 FRAME_BEGIN, 2 FILL_RECT, 3 DRAW_SPAN, 4 MARKER,
// 5 FRAME_END, docs/PROTOCOL.md), x, y, w, h, r, g, b, frame. A span is y, x = x0, w = x1 -
// x0 + 1, h = 1; FRAME_BEGIN's w and h are the frame's size and r, g, b its background; a
// marker's text is not in the row (Stream.markers has it).
pybind11::dtype command_dtype();
pybind11::array commands_array(const std::vector<protocol::Command>& commands);

// A view of an RGB framebuffer, H x W x 3 uint8, that keeps `owner` (what holds the
// framebuffer) alive.
pybind11::array rgb_view(const controller::Framebuffer& frame, pybind11::object owner);

void save_stream(const protocol::MemoryBuffer& commands, const std::string& path,
                 const protocol::Properties& properties);

}  // namespace fb89::python
