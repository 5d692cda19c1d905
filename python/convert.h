// What the Python module's parts share: JSON figures as Python objects, commands as rows of a
// numpy structured array (and back), and framebuffers as numpy views.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/framebuffer.h"
#include "protocol/command.h"
#include "protocol/command_sink.h"
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
// 5 FRAME_END, 8 DEPTH_CLEAR, 9 DEPTH_SPAN, 10 FACE, docs/PROTOCOL.md), x, y, w, h, r, g, b,
// frame. A span is y, x = x0, w = x1 - x0 + 1, h = 1; FRAME_BEGIN's w and h are the frame's
// size and r, g, b its background; a FACE is x = x_ref, y = y_ref, w = its point count. What
// does not fit a row is beside the rows, by row: a marker's text (Stream.markers), a depth
// command's z, dzdx and dzdy (Stream.depth: a DEPTH_SPAN's dz is its dzdx) and a FACE's
// points (Stream.face_points).
pybind11::dtype command_dtype();

// One row of that array, packed as command_dtype() describes it.
#pragma pack(push, 1)
struct CommandRow {
    uint8_t opcode;
    int32_t x, y;
    uint32_t w, h;
    uint8_t r, g, b;
    uint32_t frame;
};
#pragma pack(pop)
static_assert(sizeof(CommandRow) == 24);

// A depth command's depth: z, and its steps a column and a row.
struct DepthFields {
    uint32_t z = 0;
    int32_t dzdx = 0, dzdy = 0;
};

// Commands as rows, with the markers' text beside them: what fb89.Stream holds. Rows and
// commands convert both ways without loss.
struct CommandRows final : protocol::CommandSink {
    std::vector<CommandRow> rows;
    std::vector<std::pair<std::size_t, std::string>> markers;  // (row, text), in row order
    // (row, depth) of each DEPTH_SPAN and FACE, and (row, points) of each FACE, in row order
    std::vector<std::pair<std::size_t, DepthFields>> depth;
    std::vector<std::pair<std::size_t, std::vector<protocol::SnappedPoint>>> faces;

    void add(const protocol::Command& c);
    void add(std::span<const protocol::Command> commands);
    void take(const protocol::Command& c) override { add(c); }
    // Sends every row as its command, in order. Throws std::invalid_argument naming the row
    // ("commands: row 3: opcode 9 is none of ...") of one the stream format cannot carry: an
    // opcode that is none, a span of width 0, a frame of size 0 or over 16384 (what
    // protocol::check_command refuses).
    void replay_into(protocol::CommandSink& sink) const;
    // Checks every row as replay_into() would, and the markers (each on a MARKER row, no
    // longer than the format allows), throwing the same errors; sends nothing.
    void check() const;
};

// A view of an RGB framebuffer, H x W x 3 uint8, that keeps `owner` (what holds the
// framebuffer) alive.
pybind11::array rgb_view(const controller::Framebuffer& frame, pybind11::object owner);

}  // namespace fb89::python
