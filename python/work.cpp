#include "python/work.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <optional>

#include "experiments/progress.h"
#include "period/stop.h"

namespace py = pybind11;

namespace fb89::python {

namespace {

// Calls under way: the stop flag is cleared when the last one ends, so that one call's stop
// never outlives it (two threads' calls stop together: Ctrl-C means stop).
std::atomic<int> calls_under_way{0};

void on_sigint(int) {
    period::request_stop();
}

// While alive on the main thread, SIGINT asks fb89's work to stop instead of waiting for
// Python's handler, which cannot run until the call returns; the handler before is put
// back after. Elsewhere, or when SIGINT is ignored, it does nothing.
class InterruptStops {
  public:
    InterruptStops() {
        const py::object threading = py::module_::import("threading");
        if (!threading.attr("current_thread")().is(threading.attr("main_thread")())) return;
        struct sigaction ours {};
        ours.sa_handler = on_sigint;
        sigemptyset(&ours.sa_mask);
        if (::sigaction(SIGINT, nullptr, &m_before) != 0 || m_before.sa_handler == SIG_IGN) return;
        m_installed = ::sigaction(SIGINT, &ours, nullptr) == 0;
    }
    ~InterruptStops() {
        if (m_installed) ::sigaction(SIGINT, &m_before, nullptr);
    }
    InterruptStops(const InterruptStops&) = delete;
    InterruptStops& operator=(const InterruptStops&) = delete;

  private:
    struct sigaction m_before {};
    bool m_installed = false;
};

}  // namespace

void run_work(const py::object& progress, const std::function<void(bool)>& work) {
    bool line_on = false;
    experiments::ProgressObserver observer;
    // what the callback raised. The observer holds only references: it is dropped without the
    // GIL, and nothing of Python's may be
    std::optional<py::error_already_set> raised;
    if (progress.is_none()) {
        line_on = ::isatty(STDERR_FILENO) != 0;
    } else if (py::isinstance<py::bool_>(progress)) {
        line_on = progress.cast<bool>();
    } else if (PyCallable_Check(progress.ptr())) {
        observer = [&progress, &raised](const std::string& what, uint64_t done, uint64_t total,
                                        std::string_view unit) {
            py::gil_scoped_acquire gil;
            try {
                progress(what, done, total, std::string(unit));
            } catch (py::error_already_set& e) {
                if (!raised) raised.emplace(std::move(e));
                throw period::Stopped{};
            }
        };
    } else {
        throw py::type_error("progress: None, True, False or a callable (what, done, total, unit)");
    }

    InterruptStops interrupt_stops;
    if (calls_under_way++ == 0) period::clear_stop();  // a Ctrl-C that came after the last call
    bool stopped = false;
    {
        py::gil_scoped_release unlocked;
        const experiments::ObserveProgress observe(std::move(observer));
        try {
            work(line_on);
        } catch (const period::Stopped&) {
            stopped = true;
        } catch (...) {
            if (--calls_under_way == 0) period::clear_stop();
            throw;
        }
    }
    const bool interrupted = period::stop_requested();
    if (--calls_under_way == 0) period::clear_stop();
    if (raised) throw std::move(*raised);
    if (stopped || interrupted) {
        PyErr_SetNone(PyExc_KeyboardInterrupt);
        throw py::error_already_set();
    }
}

}  // namespace fb89::python
