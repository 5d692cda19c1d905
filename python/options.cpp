#include "python/options.h"

#include <cmath>

#include <fmt/format.h>

#include "frontend/common.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

// "str '3'": the value's type and (a short) repr, for a TypeError.
std::string described(const py::handle& value) {
    std::string shown = py::repr(value).cast<std::string>();
    if (shown.size() > 40) shown = shown.substr(0, 37) + "...";
    return fmt::format("{} {}", Py_TYPE(value.ptr())->tp_name, shown);
}

[[noreturn]] void wrong_type(std::string_view keyword, std::string_view expected,
                             const py::handle& value) {
    throw py::type_error(
        fmt::format("{}: expected {}, got {}", keyword, expected, described(value)));
}

bool is_bool(const py::handle& value) {
    if (PyBool_Check(value.ptr())) return true;
    const std::string_view name = Py_TYPE(value.ptr())->tp_name;
    return name == "numpy.bool_" || name == "numpy.bool";
}

}  // namespace

int64_t whole_number(const py::handle& value, const frontend::OptionLimit& limit) {
    const std::string_view keyword = limit.keyword;
    if (is_bool(value) || !PyNumber_Check(value.ptr())) wrong_type(keyword, "an integer", value);
    const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
    if (!index) {  // a number, but not an integer: 2.5, numpy.float32(2)
        PyErr_Clear();
        throw frontend::UsageError(
            fmt::format("{}: {} is not an integer", keyword, py::repr(value).cast<std::string>()));
    }
    int overflow = 0;
    const long long v = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
    const std::string shown = py::str(index).cast<std::string>();
    if (overflow != 0) {
        frontend::check_limit(limit, overflow > 0 ? HUGE_VAL : -HUGE_VAL,
                              frontend::Spelling::Keyword, shown);
    }
    frontend::check_limit(limit, static_cast<double>(v), frontend::Spelling::Keyword, shown);
    return v;
}

double real_number(const py::handle& value, std::string_view keyword) {
    if (is_bool(value) || !PyNumber_Check(value.ptr())) wrong_type(keyword, "a number", value);
    const double v = PyFloat_AsDouble(value.ptr());
    if (v == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        wrong_type(keyword, "a number", value);
    }
    return v;
}

double real_number(const py::handle& value, const frontend::OptionLimit& limit) {
    const double v = real_number(value, limit.keyword);
    frontend::check_limit(limit, v, frontend::Spelling::Keyword,
                          py::repr(value).cast<std::string>());
    return v;
}

std::string text(const py::handle& value, std::string_view keyword) {
    if (!PyUnicode_Check(value.ptr())) wrong_type(keyword, "a str", value);
    return value.cast<std::string>();
}

std::optional<std::string> optional_text(const py::handle& value, std::string_view keyword) {
    if (value.is_none()) return std::nullopt;
    return text(value, keyword);
}

std::string path_text(const py::handle& value, std::string_view keyword, bool none_allowed) {
    if (none_allowed && value.is_none()) return "";
    const py::object path = py::reinterpret_steal<py::object>(PyOS_FSPath(value.ptr()));
    if (!path || !PyUnicode_Check(path.ptr())) {
        PyErr_Clear();
        wrong_type(keyword, none_allowed ? "a path (str or os.PathLike) or None" : "a path", value);
    }
    return path.cast<std::string>();
}

std::vector<std::string> text_list(const py::handle& value, std::string_view keyword) {
    if (!py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value))
        wrong_type(keyword, "a list of str", value);
    std::vector<std::string> out;
    for (const py::handle item : value)
        out.push_back(text(item, fmt::format("{}[{}]", keyword, out.size())));
    return out;
}

bool flag(const py::handle& value, std::string_view keyword) {
    if (!is_bool(value)) wrong_type(keyword, "True or False", value);
    return value.cast<bool>();
}

std::string size_text(const py::handle& value, std::string_view keyword) {
    if (value.is_none()) return "";
    if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
    if ((!py::isinstance<py::tuple>(value) && !py::isinstance<py::list>(value)) ||
        py::len(value) != 2)
        wrong_type(keyword, "\"WxH\" or (width, height)", value);
    const py::sequence sides = py::reinterpret_borrow<py::sequence>(value);
    const frontend::OptionLimit& side = frontend::limits::kImageSide;
    return fmt::format("{}x{}", whole_number(sides[0], side), whole_number(sides[1], side));
}

std::optional<std::string> threshold_text(const py::handle& value, std::string_view keyword) {
    if (value.is_none()) return std::nullopt;
    if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
    if (is_bool(value) || !PyNumber_Check(value.ptr()))
        wrong_type(keyword, "a number, 'inf', 'paper' or 'calibrated'", value);
    return fmt::format("{}", real_number(value, keyword));
}

std::string buffer_text(const py::handle& value) {
    if (value.is_none()) return "";
    if (PyUnicode_Check(value.ptr())) return value.cast<std::string>();
    return std::to_string(whole_number(value, frontend::limits::kBufferBytes));
}

}  // namespace fb89::python
