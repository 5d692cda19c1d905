// fb89's errors as Python exceptions carrying the command line's messages: fb89.Error, and
// subclasses that are also ValueError (a bad scene or option), OSError (a file: missing,
// unreadable, unwritable, or a corrupt stream) and RuntimeError (an emulated 1989 host
// failed). A value of the wrong type is Python's own TypeError naming the keyword
// (python/options.h).
#include <pybind11/pybind11.h>

#include <filesystem>
#include <stdexcept>

#include "frontend/common.h"
#include "host/scene/scene_error.h"
#include "period/emulator.h"
#include "protocol/stream_format.h"
#include "python/convert.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

// A new exception class of the module, deriving from `bases` (a tuple), with a docstring.
// The class is kept for the life of the process (a handle: no destructor runs after the
// interpreter has gone).
py::handle exception_class(py::module_& m, const char* name, py::tuple bases, const char* doc) {
    const std::string qualified = std::string("fb89.") + name;
    py::object cls = py::reinterpret_steal<py::object>(
        PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr));
    if (!cls) throw py::error_already_set();
    m.attr(name) = cls;
    return cls.release();
}

}  // namespace

void register_errors(py::module_& m) {
    static py::handle error = exception_class(
        m, "Error", py::make_tuple(py::handle(PyExc_Exception)),
        "Every error fb89 raises: its message is the command line's for the same mistake.");
    static py::handle scene_error =
        exception_class(m, "SceneError", py::make_tuple(error, py::handle(PyExc_ValueError)),
                        "A scene that cannot be found or read, naming the file and the field.");
    static py::handle option_error =
        exception_class(m, "OptionError", py::make_tuple(error, py::handle(PyExc_ValueError)),
                        "An option out of range or unknown: a method, a size, a threshold, a "
                        "profile or host.");
    static py::handle file_error =
        exception_class(m, "FileError", py::make_tuple(error, py::handle(PyExc_OSError)),
                        "A file that cannot be opened or written, or a stream that is corrupt "
                        "(naming the byte offset and the command).");
    static py::handle emulator_error =
        exception_class(m, "EmulatorError", py::make_tuple(error, py::handle(PyExc_RuntimeError)),
                        "A 1989 host's emulated run failed, or its emulator or guest is missing.");

    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const py::builtin_exception& e) {
            e.set_error();  // pybind11's own (TypeError, ...) as they are
        } catch (const host::SceneError& e) {
            PyErr_SetString(scene_error.ptr(), e.what());
        } catch (const FileProblem& e) {
            PyErr_SetString(file_error.ptr(), e.what());
        } catch (const protocol::StreamError& e) {
            PyErr_SetString(file_error.ptr(), e.what());
        } catch (const period::EmulatorError& e) {
            PyErr_SetString(emulator_error.ptr(), e.what());
        } catch (const frontend::UsageError& e) {
            PyErr_SetString(option_error.ptr(), e.what());
        } catch (const std::invalid_argument& e) {
            PyErr_SetString(option_error.ptr(), e.what());
        } catch (const std::filesystem::filesystem_error& e) {
            PyErr_SetString(file_error.ptr(), e.what());
        } catch (const std::runtime_error& e) {
            PyErr_SetString(error.ptr(), e.what());
        } catch (const std::logic_error& e) {
            PyErr_SetString(error.ptr(), e.what());
        }
    });
}

}  // namespace fb89::python
