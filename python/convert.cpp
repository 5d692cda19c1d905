#include "python/convert.h"

#include <cstring>
#include <variant>

#include "protocol/stream_writer.h"

namespace py = pybind11;

namespace fb89::python {

py::object to_python(const nlohmann::json& j) {
    switch (j.type()) {
        case nlohmann::json::value_t::null:
            return py::none();
        case nlohmann::json::value_t::boolean:
            return py::bool_(j.get<bool>());
        case nlohmann::json::value_t::number_integer:
            return py::int_(j.get<int64_t>());
        case nlohmann::json::value_t::number_unsigned:
            return py::int_(j.get<uint64_t>());
        case nlohmann::json::value_t::number_float:
            return py::float_(j.get<double>());
        case nlohmann::json::value_t::string:
            return py::str(j.get<std::string>());
        case nlohmann::json::value_t::array: {
            py::list out;
            for (const auto& v : j)
                out.append(to_python(v));
            return out;
        }
        case nlohmann::json::value_t::object: {
            py::dict out;
            for (const auto& [k, v] : j.items())
                out[py::str(k)] = to_python(v);
            return out;
        }
        default:
            return py::none();
    }
}

namespace {

// One row of the command array, packed as command_dtype() describes it.
#pragma pack(push, 1)
struct Row {
    uint8_t opcode;
    int32_t x, y;
    uint32_t w, h;
    uint8_t r, g, b;
    uint32_t frame;
};
#pragma pack(pop)

Row row_of(const protocol::Command& c) {
    Row row{};
    std::visit(
        [&](const auto& cmd) {
            using T = std::decay_t<decltype(cmd)>;
            if constexpr (std::is_same_v<T, protocol::FrameBegin>) {
                row = {1,
                       0,
                       0,
                       cmd.width,
                       cmd.height,
                       cmd.background.r,
                       cmd.background.g,
                       cmd.background.b,
                       cmd.frame};
            } else if constexpr (std::is_same_v<T, protocol::FillRect>) {
                row = {2, cmd.x, cmd.y, cmd.w, cmd.h, cmd.color.r, cmd.color.g, cmd.color.b, 0};
            } else if constexpr (std::is_same_v<T, protocol::DrawSpan>) {
                row = {3, cmd.x0,      cmd.y,       static_cast<uint32_t>(cmd.x1 - cmd.x0 + 1),
                       1, cmd.color.r, cmd.color.g, cmd.color.b,
                       0};
            } else if constexpr (std::is_same_v<T, protocol::Marker>) {
                row.opcode = 4;
            } else {
                row.opcode = 5;
            }
        },
        c);
    return row;
}

}  // namespace

py::dtype command_dtype() {
    py::list fields;
    const auto field = [&](const char* name, const char* format) {
        fields.append(py::make_tuple(name, py::dtype(format)));
    };
    field("opcode", "u1");
    field("x", "<i4");
    field("y", "<i4");
    field("w", "<u4");
    field("h", "<u4");
    field("r", "u1");
    field("g", "u1");
    field("b", "u1");
    field("frame", "<u4");
    return py::dtype::from_args(fields);
}

py::array commands_array(const std::vector<protocol::Command>& commands) {
    py::array out(command_dtype(),
                  std::vector<py::ssize_t>{static_cast<py::ssize_t>(commands.size())});
    static_assert(sizeof(Row) == 24);
    auto* rows = static_cast<Row*>(out.mutable_data());
    for (std::size_t i = 0; i < commands.size(); ++i)
        rows[i] = row_of(commands[i]);
    return out;
}

py::array rgb_view(const controller::Framebuffer& frame, py::object owner) {
    const auto h = static_cast<py::ssize_t>(frame.height()),
               w = static_cast<py::ssize_t>(frame.width());
    return py::array(py::dtype::of<uint8_t>(), {h, w, py::ssize_t{3}},
                     {w * 3, py::ssize_t{3}, py::ssize_t{1}}, frame.pixels().data(), owner);
}

void save_stream(const protocol::MemoryBuffer& commands, const std::string& path,
                 const protocol::Properties& properties) {
    try {
        protocol::StreamWriter writer(path, properties);
        commands.replay_into(writer);
        writer.close();
    } catch (const std::invalid_argument&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw FileProblem(e.what());
    }
}

}  // namespace fb89::python
