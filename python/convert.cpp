#include "python/convert.h"

#include <array>
#include <cstring>
#include <optional>
#include <utility>
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

using protocol::CommandInfo;
using protocol::RowColumn;

template <class C>
constexpr bool has_column(RowColumn column) {
    bool found = false;
    std::apply([&](const auto&... f) { ((found = found || f.row == column), ...); },
               CommandInfo<C>::fields);
    return found;
}

// A command's row, each field in the column its row in protocol/command.h names.
template <class C>
CommandRow row_of(const C& c) {
    CommandRow row{};
    row.opcode = static_cast<uint8_t>(CommandInfo<C>::opcode);
    int64_t span_end = 0;
    protocol::for_each_field(c, [&](const auto& value, const auto& field) {
        if constexpr (std::is_same_v<std::decay_t<decltype(value)>, protocol::Rgb>) {
            row.r = value.r;
            row.g = value.g;
            row.b = value.b;
        } else {
            switch (field.row) {
                case RowColumn::X:
                    row.x = static_cast<int32_t>(value);
                    break;
                case RowColumn::Y:
                    row.y = static_cast<int32_t>(value);
                    break;
                case RowColumn::W:
                    row.w = static_cast<uint32_t>(value);
                    break;
                case RowColumn::H:
                    row.h = static_cast<uint32_t>(value);
                    break;
                case RowColumn::Frame:
                    row.frame = static_cast<uint32_t>(value);
                    break;
                case RowColumn::SpanEnd:
                    span_end = value;
                    break;
                default:  // the depth, beside the row
                    break;
            }
        }
    });
    if constexpr (has_column<C>(RowColumn::SpanEnd)) {
        row.w = static_cast<uint32_t>(span_end - row.x + 1);
        row.h = 1;
    }
    if constexpr (CommandInfo<C>::tail == protocol::Tail::Points)
        row.w = static_cast<uint32_t>(c.points.size());
    return row;
}

// One comparison an alternative, no visitor: rows are made by the million.
CommandRow row_of(const protocol::Command& c) {
    CommandRow row;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((c.index() == I ? (row = row_of(*std::get_if<I>(&c)), true) : false) || ...);
    }
    (std::make_index_sequence<protocol::kOpcodeCount>{});
    return row;
}

// What a depth command carries beside its row.
template <class C>
void add_beside(CommandRows& rows, std::size_t row, const C& c) {
    if constexpr (has_column<C>(RowColumn::Z)) {
        DepthFields d;
        protocol::for_each_field(c, [&](const auto& value, const auto& field) {
            if constexpr (!std::is_same_v<std::decay_t<decltype(value)>, protocol::Rgb>) {
                if (field.row == RowColumn::Z) d.z = static_cast<uint32_t>(value);
                if (field.row == RowColumn::Dzdx) d.dzdx = static_cast<int32_t>(value);
                if (field.row == RowColumn::Dzdy) d.dzdy = static_cast<int32_t>(value);
            }
        });
        rows.depth.emplace_back(row, d);
    }
    if constexpr (CommandInfo<C>::tail == protocol::Tail::Points)
        rows.faces.emplace_back(row, c.points);
    if constexpr (CommandInfo<C>::tail == protocol::Tail::Text)
        rows.markers.emplace_back(row, c.text);
}

void add_beside(CommandRows& rows, std::size_t row, const protocol::Command& c) {
    std::visit([&](const auto& command) { add_beside(rows, row, command); }, c);
}

// What a row's opcode says of the command it is.
struct RowKind {
    const protocol::CommandRow* row = nullptr;  // nullptr: none
    bool depth = false;                         // its z, dzdx and dzdy are beside it
    bool dzdy = false;                          // it steps in y as well
};
// Each opcode byte's kind, made once: replay_into() and check() ask it of every row.
constexpr auto kKinds = [] {
    std::array<RowKind, 256> out{};
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((out[static_cast<uint8_t>(
              CommandInfo<std::variant_alternative_t<I, protocol::Command>>::opcode)] =
              RowKind{
                  &protocol::kCommandRows[I],
                  has_column<std::variant_alternative_t<I, protocol::Command>>(RowColumn::Z),
                  has_column<std::variant_alternative_t<I, protocol::Command>>(RowColumn::Dzdy)}),
         ...);
    }
    (std::make_index_sequence<protocol::kOpcodeCount>{});
    return out;
}();
const RowKind& kind_of(uint8_t opcode) {
    return kKinds[opcode];
}

// By alternative: whether the command carries anything beside its row.
constexpr auto kBeside = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<bool, sizeof...(I)>{
        (has_column<std::variant_alternative_t<I, protocol::Command>>(RowColumn::Z) ||
         CommandInfo<std::variant_alternative_t<I, protocol::Command>>::tail !=
             protocol::Tail::None)...};
}
(std::make_index_sequence<protocol::kOpcodeCount>{});

}  // namespace

void CommandRows::add(const protocol::Command& c) {
    add_beside(*this, rows.size(), c);
    rows.push_back(row_of(c));
}

void CommandRows::add(std::span<const protocol::Command> commands) {
    const std::size_t at = rows.size();
    rows.resize(at + commands.size());
    CommandRow* out = rows.data() + at;
    for (std::size_t i = 0; i < commands.size(); ++i) {
        out[i] = row_of(commands[i]);
        if (kBeside[commands[i].index()]) add_beside(*this, at + i, commands[i]);
    }
}

namespace {

// The opcodes a row may have, for its error: "1 (FRAME_BEGIN), 2 (FILL_RECT), ...".
std::string opcode_list() {
    std::string out;
    for (const protocol::CommandRow& r : protocol::kCommandRows)
        out += (out.empty() ? "" : ", ") + std::to_string(static_cast<int>(r.opcode)) + " (" +
               r.name + ")";
    return out;
}

template <class C>
C command_of(const CommandRow& row, std::size_t i, std::string& text, const DepthFields& d,
             const std::vector<protocol::SnappedPoint>* points) {
    using I = CommandInfo<C>;
    C c{};
    protocol::for_each_field(c, [&](auto& value, const auto& field) {
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, protocol::Rgb>) {
            value = protocol::Rgb{row.r, row.g, row.b};
        } else {
            switch (field.row) {
                case RowColumn::X:
                    value = static_cast<T>(row.x);
                    break;
                case RowColumn::Y:
                    value = static_cast<T>(row.y);
                    break;
                case RowColumn::W:
                    value = static_cast<T>(row.w);
                    break;
                case RowColumn::H:
                    value = static_cast<T>(row.h);
                    break;
                case RowColumn::Frame:
                    value = static_cast<T>(row.frame);
                    break;
                case RowColumn::SpanEnd:
                    if (row.w == 0)
                        throw std::invalid_argument("commands: row " + std::to_string(i) + ": " +
                                                    I::name +
                                                    " of width 0 (w is x1 - x0 + 1, at least 1)");
                    value = static_cast<T>(static_cast<uint32_t>(row.x) + row.w - 1u);
                    break;
                case RowColumn::Z:
                    value = static_cast<T>(d.z);
                    break;
                case RowColumn::Dzdx:
                    value = static_cast<T>(d.dzdx);
                    break;
                case RowColumn::Dzdy:
                    value = static_cast<T>(d.dzdy);
                    break;
                case RowColumn::Colour:  // (an Rgb, above)
                    break;
            }
        }
    });
    if constexpr (I::tail == protocol::Tail::Text) c.text = std::move(text);
    if constexpr (I::tail == protocol::Tail::Points) {
        if (points) c.points = *points;
        if (c.points.size() != row.w)
            throw std::invalid_argument("commands: row " + std::to_string(i) + ": " + I::name +
                                        " of " + std::to_string(row.w) + " points has " +
                                        std::to_string(c.points.size()) + " in face_points");
    }
    return c;
}

// Row `i` as its command (a MARKER with `text`); std::invalid_argument naming the row for one
// that is no command the stream format can carry (protocol::check_command's rules).
protocol::Command row_command(const CommandRow& row, std::size_t i, std::string text,
                              const DepthFields& d,
                              const std::vector<protocol::SnappedPoint>* points) {
    std::optional<protocol::Command> c;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((row.opcode == static_cast<uint8_t>(
                            CommandInfo<std::variant_alternative_t<I, protocol::Command>>::opcode)
              ? void(c = command_of<std::variant_alternative_t<I, protocol::Command>>(row, i, text,
                                                                                      d, points))
              : void()),
         ...);
    }
    (std::make_index_sequence<protocol::kOpcodeCount>{});
    if (!c)
        throw std::invalid_argument("commands: row " + std::to_string(i) + ": opcode " +
                                    std::to_string(row.opcode) + " is none of " + opcode_list() +
                                    " (docs/PROTOCOL.md)");
    if (const auto problem = protocol::check_command(*c))
        throw std::invalid_argument("commands: row " + std::to_string(i) + " (" +
                                    protocol::to_string(protocol::opcode_of(*c)) +
                                    "): " + *problem);
    return *c;
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

namespace {

// The names of the commands whose rows `has` holds, "DEPTH_SPAN or FACE".
template <class Has>
std::string names_where(Has has) {
    std::string out;
    for (const protocol::CommandRow& r : protocol::kCommandRows)
        if (has(kind_of(static_cast<uint8_t>(r.opcode))))
            out += (out.empty() ? "" : " or ") + std::string(r.name);
    return out;
}
bool has_text(const RowKind& k) {
    return k.row && k.row->tail == protocol::Tail::Text;
}
bool has_points(const RowKind& k) {
    return k.row && k.row->tail == protocol::Tail::Points;
}

}  // namespace

void CommandRows::replay_into(protocol::CommandSink& sink) const {
    auto marker = markers.begin();
    auto d = depth.begin();
    auto face = faces.begin();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const RowKind k = kind_of(rows[i].opcode);
        std::string text;
        if (has_text(k))
            if (const std::string* t = beside(markers, marker, i)) text = *t;
        const DepthFields* fields = k.depth ? beside(depth, d, i) : nullptr;
        const auto* points = has_points(k) ? beside(faces, face, i) : nullptr;
        sink.submit(
            row_command(rows[i], i, std::move(text), fields ? *fields : DepthFields{}, points));
    }
}

void CommandRows::check() const {
    auto d = depth.begin();
    auto face = faces.begin();
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const RowKind k = kind_of(rows[i].opcode);
        const DepthFields* fields = k.depth ? beside(depth, d, i) : nullptr;
        const auto* points = has_points(k) ? beside(faces, face, i) : nullptr;
        if (k.depth && !fields)
            throw std::invalid_argument("commands: row " + std::to_string(i) + " (" + k.row->name +
                                        ") has no (row, z, dzdx, dzdy) entry in depth");
        if (fields && !k.dzdy && fields->dzdy != 0)
            throw std::invalid_argument("depth: row " + std::to_string(i) + " (" + k.row->name +
                                        ") has a dzdy of " + std::to_string(fields->dzdy) +
                                        "; it steps in x only (0)");
        row_command(rows[i], i, {}, fields ? *fields : DepthFields{}, points);
    }
    for (std::size_t k = 0; k < depth.size(); ++k) {
        const std::size_t row = depth[k].first;
        if (row >= rows.size() || !kind_of(rows[row].opcode).depth)
            throw std::invalid_argument("depth: row " + std::to_string(row) + " is not a " +
                                        names_where([](const RowKind& r) { return r.depth; }));
        if (k > 0 && depth[k - 1].first == row)
            throw std::invalid_argument("depth: row " + std::to_string(row) + " given twice");
    }
    for (std::size_t k = 1; k < faces.size(); ++k)
        if (faces[k - 1].first == faces[k].first)
            throw std::invalid_argument("face_points: row " + std::to_string(faces[k].first) +
                                        " given twice");
    for (const auto& [row, points] : faces)
        if (row >= rows.size() || !has_points(kind_of(rows[row].opcode)))
            throw std::invalid_argument("face_points: row " + std::to_string(row) + " is not a " +
                                        names_where(has_points));
    for (const auto& [row, text] : markers) {
        if (row >= rows.size() || !has_text(kind_of(rows[row].opcode)))
            throw std::invalid_argument("markers: row " + std::to_string(row) + " is not a " +
                                        names_where(has_text));
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
