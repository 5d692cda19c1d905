// fb89 streams from Python: a stream file read through the stream reader in batches into rows
// (one a command, viewed as a numpy structured array), with its header and markers; a stream
// built from such an array; saved, replayed into a controller, trimmed and compared.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <algorithm>

#include <array>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "controller_sim/controller.h"
#include "controller_sim/profile.h"
#include "frontend/common.h"
#include "frontend/stream_edit.h"
#include "frontend/stream_tools.h"
#include "protocol/call_set.h"
#include "protocol/stream_reader.h"
#include "protocol/stream_writer.h"
#include "python/convert.h"
#include "python/options.h"
#include "python/outputs.h"
#include "python/stream_file.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

std::shared_ptr<StreamFile> open_stream(const std::string& path,
                                        const std::optional<std::string>& calls) {
    std::optional<protocol::CallSet> selection;
    if (calls) selection = frontend::parse_call_set_option("calls", *calls);
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
    // rows for the whole file at once (a record is at least 16 bytes but for FRAME_END's
    // one): growing the array as it goes would copy it a dozen times
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    if (!ec && !selection) out->commands.rows.reserve(bytes / protocol::kDrawSpanRecordSize + 1024);
    std::array<protocol::Command, 4096> batch;
    std::vector<int64_t> send_ns(reader.timed() ? batch.size() : 0);
    if (selection) out->numbers.emplace();
    uint64_t number = 0;
    // a batch ends at a FRAME_END: the frame's HOST_END, if any, has been read by then
    const auto keep_host_end = [&](const protocol::Command& last) {
        if (reader.timed() && std::holds_alternative<protocol::FrameEnd>(last) &&
            reader.host_end_ns())
            out->host_ends.emplace_back(out->commands.rows.size() - 1, *reader.host_end_ns());
    };
    for (std::size_t n; (n = reader.read_batch(batch, send_ns)) > 0;) {
        if (!selection) {
            out->commands.add(std::span<const protocol::Command>(batch.data(), n));
            out->send_ns.insert(
                out->send_ns.end(), send_ns.begin(),
                send_ns.begin() + static_cast<std::ptrdiff_t>(reader.timed() ? n : 0));
            keep_host_end(batch[n - 1]);
            continue;
        }
        for (std::size_t i = 0; i < n; ++i, ++number) {
            if (number > selection->last()) return out;
            if (!selection->contains(number, batch[i])) continue;
            out->numbers->push_back(number);
            out->commands.add(batch[i]);
            if (reader.timed()) out->send_ns.push_back(send_ns[i]);
            if (i + 1 == n) keep_host_end(batch[i]);
        }
    }
    return out;
}

// Rows from a structured array of fb89.COMMAND_DTYPE (or what numpy reads as one, field by
// field), checked as the stream format checks commands: a row it cannot carry is an
// fb89.OptionError naming the row, here rather than when the stream is saved.
py::array rows_of(const py::handle& commands) {
    const py::dtype want = command_dtype();
    py::array rows;
    try {
        const py::module_ numpy = py::module_::import("numpy");
        if (py::isinstance<py::array>(commands)) {
            rows = py::reinterpret_borrow<py::array>(commands);
            if (!rows.dtype().equal(want)) rows = rows.attr("astype")(want);
        } else {
            rows = numpy.attr("asarray")(commands, want);
        }
    } catch (const py::error_already_set& e) {
        throw py::type_error(std::string("commands: not rows of fb89.COMMAND_DTYPE (") + e.what() +
                             ")");
    }
    if (rows.ndim() != 1)
        throw py::type_error("commands: a 1-D structured array of fb89.COMMAND_DTYPE");
    return py::array::ensure(rows, py::array::c_style);
}

protocol::Properties header_of(const py::handle& header) {
    protocol::Properties out;
    if (header.is_none()) return out;
    if (!py::isinstance<py::dict>(header)) throw py::type_error("header: expected a dict of str");
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(header)) {
        const std::string k = text(key, "header");
        out[k] = text(value, "header['" + k + "']");
    }
    if (const auto problem = protocol::check_properties(out))
        throw std::invalid_argument("header: " + *problem);
    return out;
}

// The entries of `list` (None, or a list or tuple of tuples or lists of `lo` to `hi` items),
// each made by `make` from its items as a (row, value) pair, in row order (a row's entries in
// their given order). `what` names the keyword and `shape` an entry in the TypeErrors;
// `size_note` follows the one for an entry of the wrong length.
template <class T, class Make>
std::vector<std::pair<std::size_t, T>> row_entries(const py::handle& list, const std::string& what,
                                                   const std::string& shape, std::size_t lo,
                                                   std::size_t hi, const std::string& size_note,
                                                   Make make) {
    std::vector<std::pair<std::size_t, T>> out;
    if (list.is_none()) return out;
    const auto sequence = [](const py::handle& h) {
        return py::isinstance<py::list>(h) || py::isinstance<py::tuple>(h);
    };
    if (!sequence(list)) throw py::type_error(what + ": expected a list of " + shape);
    for (const py::handle entry : list) {
        if (!sequence(entry)) throw py::type_error(what + ": expected " + shape);
        const py::sequence e = py::reinterpret_borrow<py::sequence>(entry);
        if (e.size() < lo || e.size() > hi)
            throw py::type_error(what + ": expected " + shape + size_note);
        out.push_back(make(e));
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    return out;
}

std::vector<std::pair<std::size_t, std::string>> markers_of(const py::handle& markers) {
    static constexpr frontend::OptionLimit kRow{"", "markers: row", 0, 1e15};
    return row_entries<std::string>(
        markers, "markers", "(row, text) pairs", 2, 2, "", [](const py::sequence& p) {
            return std::pair{static_cast<std::size_t>(whole_number(p[0], kRow)),
                             text(p[1], "markers: text")};
        });
}

// (row, z, dzdx[, dzdy]) entries, as Stream.depth gives them, in row order.
std::vector<std::pair<std::size_t, DepthFields>> depth_of(const py::handle& depth) {
    static constexpr frontend::OptionLimit kRow{"", "depth: row", 0, 1e15};
    static constexpr frontend::OptionLimit kZ{"", "depth: z", 0, 4294967295.0};
    static constexpr frontend::OptionLimit kSlope{"", "depth: slope", -2147483648.0, 2147483647.0};
    return row_entries<DepthFields>(
        depth, "depth", "(row, z, dzdx, dzdy) tuples", 3, 4,
        " (dzdy may be left out for a DEPTH_SPAN)", [](const py::sequence& e) {
            DepthFields d;
            d.z = static_cast<uint32_t>(whole_number(e[1], kZ));
            d.dzdx = static_cast<int32_t>(whole_number(e[2], kSlope));
            if (e.size() == 4) d.dzdy = static_cast<int32_t>(whole_number(e[3], kSlope));
            return std::pair{static_cast<std::size_t>(whole_number(e[0], kRow)), d};
        });
}

// (row, points) pairs, points an n x 2 array of integers in 1/256 pixel, as Stream.face_points
// gives them, in row order.
std::vector<std::pair<std::size_t, std::vector<protocol::SnappedPoint>>> face_points_of(
    const py::handle& faces) {
    static constexpr frontend::OptionLimit kRow{"", "face_points: row", 0, 1e15};
    return row_entries<std::vector<protocol::SnappedPoint>>(
        faces, "face_points", "(row, points) pairs", 2, 2, "", [](const py::sequence& p) {
            const std::size_t row = static_cast<std::size_t>(whole_number(p[0], kRow));
            py::array_t<int64_t> a;
            try {
                a = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(p[1]);
            } catch (const py::error_already_set&) {
                a = {};
            }
            if (!a || a.ndim() != 2 || a.shape(1) != 2)
                throw py::type_error("face_points: row " + std::to_string(row) +
                                     ": expected an n x 2 array of integers (x, y in 1/256 pixel)");
            if (py::isinstance<py::array>(p[1]) &&
                py::reinterpret_borrow<py::array>(p[1]).dtype().kind() == 'f')
                throw py::type_error("face_points: row " + std::to_string(row) +
                                     ": points are integers in 1/256 pixel, not floats");
            const auto v = a.unchecked<2>();
            std::vector<protocol::SnappedPoint> points(static_cast<std::size_t>(a.shape(0)));
            for (py::ssize_t i = 0; i < a.shape(0); ++i)
                points[static_cast<std::size_t>(i)] = {v(i, 0), v(i, 1)};
            return std::pair{row, std::move(points)};
        });
}

std::shared_ptr<StreamFile> stream_from(const py::handle& commands, const py::handle& header,
                                        const py::handle& markers, const py::handle& depth,
                                        const py::handle& face_points) {
    const py::array rows = rows_of(commands);
    auto out = std::make_shared<StreamFile>();
    out->header = header_of(header);
    const auto* first = static_cast<const CommandRow*>(rows.data());
    out->commands.rows.assign(first, first + rows.shape(0));
    out->commands.markers = markers_of(markers);
    out->commands.depth = depth_of(depth);
    out->commands.faces = face_points_of(face_points);
    out->commands.check();
    return out;
}

py::array rows_view(const py::object& self) {
    const StreamFile& s = self.cast<const StreamFile&>();
    return py::array(command_dtype(), {static_cast<py::ssize_t>(s.commands.rows.size())},
                     {static_cast<py::ssize_t>(sizeof(CommandRow))}, s.commands.rows.data(), self);
}

}  // namespace

namespace {

// The rows into a timed writer, each with its send time, a FRAME_END with its frame's HOST_END.
class TimedRows final : public protocol::CommandSink {
  public:
    TimedRows(const StreamFile& s, protocol::StreamWriter& writer) : m_s(s), m_writer(writer) {}
    void frame_begin(const protocol::FrameBegin& c) override {
        m_writer.frame_begin(c);  // at 0: the frame's origin
        m_in_frame = true;
        ++m_row;
    }
    void take(const protocol::Command& c) override { timed(c); }
    void frame_end(const protocol::FrameEnd& c) override {
        if (m_in_frame) {
            m_writer.send_time(m_s.send_ns.at(m_row));
            while (m_end != m_s.host_ends.end() && m_end->first < m_row)
                ++m_end;
            if (m_end != m_s.host_ends.end() && m_end->first == m_row)
                m_writer.host_end(m_end->second);
        }
        m_writer.frame_end(c);
        m_in_frame = false;
        ++m_row;
    }

  private:
    template <class C>
    void timed(const C& c) {  // (a command outside a frame, of a selection, has no time)
        if (m_in_frame) m_writer.send_time(m_s.send_ns.at(m_row));
        ++m_row;
        m_writer.submit(c);
    }
    const StreamFile& m_s;
    protocol::StreamWriter& m_writer;
    std::size_t m_row = 0;
    bool m_in_frame = false;
    std::vector<std::pair<std::size_t, int64_t>>::const_iterator m_end = m_s.host_ends.begin();
};

}  // namespace

std::vector<uint8_t> encode_rows(const StreamFile& s) {
    if (!s.send_ns.empty() && s.send_ns.size() != s.commands.rows.size())
        throw std::invalid_argument("send times: " + std::to_string(s.send_ns.size()) + " for " +
                                    std::to_string(s.commands.rows.size()) + " commands");
    if (const auto problem = protocol::check_properties(s.header))
        throw std::invalid_argument("header: " + *problem);
    s.commands.check();  // the rows may have changed since: they are a writable view
    const bool timed = !s.send_ns.empty();
    const bool depth =
        std::any_of(s.commands.rows.begin(), s.commands.rows.end(), [](const CommandRow& r) {
            const protocol::CommandRow* c = protocol::command_row(r.opcode);
            return c && c->since >= protocol::kDepthVersion;
        });
    protocol::StreamWriter writer(s.header,
                                  timed ? protocol::Timing::Timed : protocol::Timing::Untimed,
                                  depth ? protocol::Commands::Depth : protocol::Commands::Tiling);
    if (timed) {
        TimedRows rows(s, writer);
        s.commands.replay_into(rows);
    } else {
        s.commands.replay_into(writer);
    }
    writer.close();
    return writer.take_bytes();
}

void save_rows(const StreamFile& s, const std::string& path) {
    const std::vector<uint8_t> bytes = encode_rows(s);  // every check before any file
    with_outputs([&] {
        file_work([&] {
            frontend::make_parent_dirs(path);
            protocol::write_output(
                path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        });
    });
}

void register_streams(py::module_& m) {
    m.attr("COMMAND_DTYPE") = command_dtype();
    py::dict opcodes;  // each command's name and opcode, from its row (protocol/command.h)
    for (const protocol::CommandRow& r : protocol::kCommandRows)
        opcodes[py::str(r.name)] = static_cast<int>(r.opcode);
    m.attr("OPCODES") = opcodes;

    py::class_<StreamFile, std::shared_ptr<StreamFile>>(
        m, "Stream",
        R"(A command stream (docs/PROTOCOL.md): its header, and its commands as a numpy structured
array of fb89.COMMAND_DTYPE, one row a command, with the markers' text beside them.

Stream.open(path) reads a file; Stream(commands, header=None, markers=None) makes one from an
array (of fb89.COMMAND_DTYPE, or one that casts to it); a render's is Render.stream.)")
        .def(py::init([](const py::object& commands, const py::object& header,
                         const py::object& markers, const py::object& depth,
                         const py::object& face_points) {
                 return stream_from(commands, header, markers, depth, face_points);
             }),
             py::arg("commands"), py::arg("header") = py::none(), py::arg("markers") = py::none(),
             py::arg("depth") = py::none(), py::arg("face_points") = py::none(),
             "A stream of these commands (copied), its header properties, the MARKER rows' "
             "text as (row, text) pairs, and for format version 3 each DEPTH_SPAN's and FACE's "
             "depth as (row, z, dzdx, dzdy) and each FACE's points as (row, n x 2 integer array "
             "in 1/256 pixel), as Stream.depth and Stream.face_points give them. Every row is "
             "checked as the stream format checks commands: an opcode that is none, a span of "
             "width 0, a frame of size 0, a depth command without its depth, a FACE whose "
             "points are not its w, or a depth out of range is an fb89.OptionError naming the "
             "row.")
        .def_static(
            "open",
            [](const py::object& path, const py::object& calls) {
                const std::string file = path_text(path, "path");
                const std::optional<std::string> selection = optional_text(calls, "calls");
                py::gil_scoped_release unlocked;
                return open_stream(file, selection);
            },
            py::arg("path"), py::arg("calls") = py::none(),
            "Reads a stream file, or with `calls` (a call set as dump --calls takes it, e.g. "
            "'0-1000', '/span', 'frame') only the commands in it (numbers says which). Raises "
            "fb89.FileError naming the byte offset and command number of anything corrupt, "
            "fb89.OptionError for a bad call set.")
        .def_readonly("path", &StreamFile::path, "The file read ('' when not read from one).")
        .def_readonly("version", &StreamFile::version,
                      "The stream's format version (of a stream not read from a file, the "
                      "version save() writes: 4).")
        .def_readonly("header", &StreamFile::header,
                      "The header's properties (scene, method, resolution, tool ...).")
        .def_property_readonly(
            "commands", &rows_view,
            "The commands, one row each, in order: a view (no copy) that keeps the stream alive.")
        .def_property_readonly(
            "numbers",
            [](const py::object& self) -> py::object {
                const StreamFile& s = self.cast<const StreamFile&>();
                if (!s.numbers) return py::none();
                return py::array_t<uint64_t>({static_cast<py::ssize_t>(s.numbers->size())},
                                             s.numbers->data(), self);
            },
            "Opened with a call set: each row's command number in the file (uint64); else None "
            "(row i is command i).")
        .def_property_readonly(
            "markers", [](const StreamFile& s) { return s.commands.markers; },
            "The MARKER commands: (row, text) pairs.")
        .def_property_readonly(
            "depth",
            [](const StreamFile& s) {
                py::list out;
                for (const auto& [row, d] : s.commands.depth)
                    out.append(py::make_tuple(row, d.z, d.dzdx, d.dzdy));
                return out;
            },
            "The depth commands' depth (format version 3): (row, z, dzdx, dzdy) of each "
            "DEPTH_SPAN (its dz as dzdx, dzdy 0) and FACE, z in units of 1/268427264 "
            "(protocol/depth_fixed.h).")
        .def_property_readonly(
            "face_points",
            [](const StreamFile& s) {
                py::list out;
                for (const auto& [row, points] : s.commands.faces) {
                    py::array_t<int64_t> a(
                        {static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
                    auto v = a.mutable_unchecked<2>();
                    for (std::size_t i = 0; i < points.size(); ++i) {
                        v(i, 0) = points[i].x;
                        v(i, 1) = points[i].y;
                    }
                    out.append(py::make_tuple(row, a));
                }
                return out;
            },
            "The FACE commands' points (format version 3): (row, array of n x 2 int64 in 1/256 "
            "pixel) pairs.")
        .def_property_readonly(
            "send_times",
            [](const py::object& self) -> py::object {
                const StreamFile& s = self.cast<const StreamFile&>();
                if (s.send_ns.empty()) return py::none();
                return py::array_t<int64_t>({static_cast<py::ssize_t>(s.send_ns.size())},
                                            s.send_ns.data(), self);
            },
            "A stream with send times (format version 2): each row's send time in nanoseconds "
            "from the start of its frame's set-up (int64, a view); else None.")
        .def_property_readonly(
            "host_ends", [](const StreamFile& s) { return s.host_ends; },
            "A stream with send times: when the host's work on each frame ended, as (row of "
            "the frame's FRAME_END, nanoseconds) pairs; frames without a HOST_END are absent.")
        .def_property_readonly(
            "frames",
            [](const StreamFile& s) {
                std::size_t n = 0;
                for (const CommandRow& r : s.commands.rows)
                    n += r.opcode == static_cast<uint8_t>(protocol::Opcode::FrameBegin);
                return n;
            },
            "How many frames the stream begins.")
        .def("__len__", [](const StreamFile& s) { return s.commands.rows.size(); })
        .def(
            "save",
            [](const StreamFile& s, const py::object& path) {
                const std::string file = path_text(path, "path");
                py::gil_scoped_release unlocked;
                save_rows(s, file);
            },
            py::arg("path"),
            "Writes the stream, header and all: format version 4 (checksummed), with its send "
            "times when it has them. The rows are checked first (fb89.OptionError naming the "
            "row); the file is written whole or not at all (an old one is left as it was on "
            "any failure) and its folder made, as the command line writes its outputs.")
        .def("__repr__", [](const StreamFile& s) {
            return "<fb89.Stream " + (s.path.empty() ? std::string("(in memory)") : s.path) + ": " +
                   std::to_string(s.commands.rows.size()) + " commands>";
        });

    // For bench/python_overhead.py: the stream reader's own speed on a file (every command read
    // in batches, nothing kept), to hold Stream.open to: (commands, seconds).
    m.def("_bench_read", [](const std::string& path) {
        py::gil_scoped_release unlocked;
        const auto start = std::chrono::steady_clock::now();
        protocol::StreamReader reader(path);
        std::array<protocol::Command, 4096> batch;
        uint64_t commands = 0;
        for (std::size_t n; (n = reader.read_batch(batch)) > 0;)
            commands += n;
        return std::make_pair(
            commands,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    });
}

}  // namespace fb89::python
