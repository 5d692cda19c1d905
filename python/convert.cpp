#include "python/convert.h"

#include <cstring>
#include <variant>

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

// One switch on the alternative, no visitor: rows are made by the million.
CommandRow row_of(const protocol::Command& c) {
    switch (c.index()) {
        case 0: {
            const auto& f = *std::get_if<protocol::FrameBegin>(&c);
            return {1,      0, 0, f.width, f.height, f.background.r, f.background.g, f.background.b,
                    f.frame};
        }
        case 1: {
            const auto& f = *std::get_if<protocol::FillRect>(&c);
            return {2, f.x, f.y, f.w, f.h, f.color.r, f.color.g, f.color.b, 0};
        }
        case 2: {
            const auto& s = *std::get_if<protocol::DrawSpan>(&c);
            return {3,         s.x0,      s.y, static_cast<uint32_t>(s.x1 - s.x0 + 1), 1, s.color.r,
                    s.color.g, s.color.b, 0};
        }
        case 3:
            return {4, 0, 0, 0, 0, 0, 0, 0, 0};
        case 4:
            return {5, 0, 0, 0, 0, 0, 0, 0, 0};
        case 5:
            return {8, 0, 0, 0, 0, 0, 0, 0, 0};
        case 6: {
            const auto& s = *std::get_if<protocol::DepthSpan>(&c);
            return {9,         s.x0,      s.y, static_cast<uint32_t>(s.x1 - s.x0 + 1), 1, s.color.r,
                    s.color.g, s.color.b, 0};
        }
        default: {
            const auto& f = *std::get_if<protocol::Face>(&c);
            return {10, f.x_ref,   f.y_ref,   static_cast<uint32_t>(f.points.size()),
                    0,  f.color.r, f.color.g, f.color.b,
                    0};
        }
    }
}

// What a depth command carries beside its row.
void add_beside(CommandRows& rows, std::size_t row, const protocol::Command& c) {
    if (const auto* s = std::get_if<protocol::DepthSpan>(&c)) {
        rows.depth.emplace_back(row, DepthFields{s->z, s->dz, 0});
    } else if (const auto* f = std::get_if<protocol::Face>(&c)) {
        rows.depth.emplace_back(row, DepthFields{f->z, f->dzdx, f->dzdy});
        rows.faces.emplace_back(row, f->points);
    }
}

}  // namespace

void CommandRows::add(const protocol::Command& c) {
    if (const auto* m = std::get_if<protocol::Marker>(&c))
        markers.emplace_back(rows.size(), m->text);
    add_beside(*this, rows.size(), c);
    rows.push_back(row_of(c));
}

void CommandRows::add(std::span<const protocol::Command> commands) {
    const std::size_t at = rows.size();
    rows.resize(at + commands.size());
    CommandRow* out = rows.data() + at;
    for (std::size_t i = 0; i < commands.size(); ++i) {
        out[i] = row_of(commands[i]);
        if (out[i].opcode == 4)
            markers.emplace_back(at + i, std::get_if<protocol::Marker>(&commands[i])->text);
        if (out[i].opcode >= 9) add_beside(*this, at + i, commands[i]);
    }
}

namespace {

// Row `i` as its command (a MARKER with `text`); std::invalid_argument naming the row for one
// that is no command the stream format can carry (protocol::check_command's rules).
protocol::Command row_command(const CommandRow& row, std::size_t i, std::string text,
                              const DepthFields& d,
                              const std::vector<protocol::SnappedPoint>* points) {
    const protocol::Rgb colour{row.r, row.g, row.b};
    protocol::Command c;
    switch (row.opcode) {
        case 1:
            c = protocol::FrameBegin{row.frame, row.w, row.h, colour};
            break;
        case 2:
            c = protocol::FillRect{row.x, row.y, row.w, row.h, colour};
            break;
        case 3:
            if (row.w == 0) {
                throw std::invalid_argument(
                    "commands: row " + std::to_string(i) +
                    ": DRAW_SPAN of width 0 (w is x1 - x0 + 1, at least 1)");
            }
            c = protocol::DrawSpan{row.y, row.x,
                                   static_cast<int32_t>(static_cast<uint32_t>(row.x) + row.w - 1u),
                                   colour};
            break;
        case 4:
            c = protocol::Marker{std::move(text)};
            break;
        case 5:
            c = protocol::FrameEnd{};
            break;
        case 8:
            c = protocol::DepthClear{};
            break;
        case 9:
            if (row.w == 0) {
                throw std::invalid_argument(
                    "commands: row " + std::to_string(i) +
                    ": DEPTH_SPAN of width 0 (w is x1 - x0 + 1, at least 1)");
            }
            c = protocol::DepthSpan{
                row.y, row.x,  static_cast<int32_t>(static_cast<uint32_t>(row.x) + row.w - 1u),
                d.z,   d.dzdx, colour};
            break;
        case 10: {
            protocol::Face f{colour, row.x, row.y, d.z, d.dzdx, d.dzdy, {}};
            if (points) f.points = *points;
            if (f.points.size() != row.w)
                throw std::invalid_argument("commands: row " + std::to_string(i) + ": FACE of " +
                                            std::to_string(row.w) + " points has " +
                                            std::to_string(f.points.size()) + " in face_points");
            c = std::move(f);
            break;
        }
        default:
            throw std::invalid_argument(
                "commands: row " + std::to_string(i) + ": opcode " + std::to_string(row.opcode) +
                " is none of 1 (FRAME_BEGIN) to 5 (FRAME_END), 8 (DEPTH_CLEAR), 9 (DEPTH_SPAN) "
                "and 10 (FACE) (docs/PROTOCOL.md)");
    }
    if (const auto problem = protocol::check_command(c))
        throw std::invalid_argument("commands: row " + std::to_string(i) + " (" +
                                    protocol::to_string(protocol::opcode_of(c)) + "): " + *problem);
    return c;
}

}  // namespace

namespace {

// The entry of (row, value) pairs in row order for row i, moving `at` on; nullptr if none.
template <class T>
const T* beside(const std::vector<std::pair<std::size_t, T>>& pairs,
                typename std::vector<std::pair<std::size_t, T>>::const_iterator& at,
                std::size_t i) {
    while (at != pairs.end() && at->first < i)
        ++at;
    return at != pairs.end() && at->first == i ? &at->second : nullptr;
}

}  // namespace

void CommandRows::replay_into(protocol::CommandSink& sink) const {
    auto marker = markers.begin();
    auto d = depth.begin();
    auto face = faces.begin();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        std::string text;
        if (rows[i].opcode == 4)
            if (const std::string* t = beside(markers, marker, i)) text = *t;
        const DepthFields* fields = rows[i].opcode >= 9 ? beside(depth, d, i) : nullptr;
        const auto* points = rows[i].opcode == 10 ? beside(faces, face, i) : nullptr;
        sink.submit(
            row_command(rows[i], i, std::move(text), fields ? *fields : DepthFields{}, points));
    }
}

void CommandRows::check() const {
    auto d = depth.begin();
    auto face = faces.begin();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const DepthFields* fields = rows[i].opcode >= 9 ? beside(depth, d, i) : nullptr;
        const auto* points = rows[i].opcode == 10 ? beside(faces, face, i) : nullptr;
        if (rows[i].opcode >= 9 && rows[i].opcode <= 10 && !fields)
            throw std::invalid_argument("commands: row " + std::to_string(i) + " (" +
                                        (rows[i].opcode == 9 ? "DEPTH_SPAN" : "FACE") +
                                        ") has no (row, z, dzdx, dzdy) entry in depth");
        if (fields && rows[i].opcode == 9 && fields->dzdy != 0)
            throw std::invalid_argument(
                "depth: row " + std::to_string(i) + " (DEPTH_SPAN) has a dzdy of " +
                std::to_string(fields->dzdy) + "; a span steps in x only (0)");
        row_command(rows[i], i, {}, fields ? *fields : DepthFields{}, points);
    }
    for (std::size_t k = 0; k < depth.size(); ++k) {
        const std::size_t row = depth[k].first;
        if (row >= rows.size() || (rows[row].opcode != 9 && rows[row].opcode != 10))
            throw std::invalid_argument("depth: row " + std::to_string(row) +
                                        " is not a DEPTH_SPAN or FACE");
        if (k > 0 && depth[k - 1].first == row)
            throw std::invalid_argument("depth: row " + std::to_string(row) + " given twice");
    }
    for (std::size_t k = 1; k < faces.size(); ++k)
        if (faces[k - 1].first == faces[k].first)
            throw std::invalid_argument("face_points: row " + std::to_string(faces[k].first) +
                                        " given twice");
    for (const auto& [row, points] : faces)
        if (row >= rows.size() || rows[row].opcode != 10)
            throw std::invalid_argument("face_points: row " + std::to_string(row) +
                                        " is not a FACE");
    for (const auto& [row, text] : markers) {
        if (row >= rows.size() || rows[row].opcode != 4)
            throw std::invalid_argument("markers: row " + std::to_string(row) + " is not a MARKER");
        if (text.size() > protocol::kMaxMarkerLength)
            throw std::invalid_argument("markers: row " + std::to_string(row) + ": longer than " +
                                        std::to_string(protocol::kMaxMarkerLength) + " bytes");
    }
}

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

py::array rgb_view(const controller::Framebuffer& frame, py::object owner) {
    const auto h = static_cast<py::ssize_t>(frame.height()),
               w = static_cast<py::ssize_t>(frame.width());
    return py::array(py::dtype::of<uint8_t>(), {h, w, py::ssize_t{3}},
                     {w * 3, py::ssize_t{3}, py::ssize_t{1}}, frame.pixels().data(), owner);
}

}  // namespace fb89::python
