// How the module runs fb89's work: without the GIL, its progress told to a Python callback or
// shown as the command line shows it, and stopped by Ctrl-C or by a callback that raises.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>

namespace fb89::python {

// `progress`: None (the command line's line on stderr when stderr is a terminal), True (the
// line), False (nothing) or a callable progress(what: str, done: int, total: int, unit: str),
// called with the GIL as each piece of work starts (done = total = 0) and as it steps, from
// whichever thread steps it. Runs `work(line_on)` without the GIL; a KeyboardInterrupt (Ctrl-C
// on the main thread) or an exception raised by the callback stops it between rounds, or
// within 50 ms in an emulated run, and is raised once it has stopped.
void run_work(const pybind11::object& progress, const std::function<void(bool line_on)>& work);

}  // namespace fb89::python
