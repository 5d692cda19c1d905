// How the module's functions write files: as fb89's main does around each command, under an
// OutputBatch of their own (protocol/output_file.h), put in place only when the work
// succeeds. A call that fails anywhere -- bad input found late, a later output that cannot
// be written, a selection that matches nothing -- leaves every old file byte for byte as it
// was and no new file, hidden temporary or partial stream behind.
#pragma once

#include <functional>
#include <stdexcept>
#include <typeinfo>

#include "python/convert.h"

namespace fb89::python {

// Runs `work` with every file it writes in an OutputBatch, published when it returns; called
// without the GIL. The batch is the process's (the library's worker threads write into it),
// so calls that write files take turns: one waits while another's batch is open. One made
// on the thread that holds the batch (from a progress callback) is refused: a std::logic_error.
// A target that cannot be put in place at the end is a FileProblem naming it.
void with_outputs(const std::function<void()>& work);

// Runs `work`, a file's reading or writing: a plain std::runtime_error from it (what
// protocol/, controller_sim/ and frontend/ throw when a file cannot be opened, read or
// written) becomes a FileProblem, fb89.FileError. Errors of their own type (a corrupt
// stream, a bad option) pass as they are.
template <class Work>
auto file_work(Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const std::runtime_error& e) {
        if (typeid(e) == typeid(std::runtime_error)) throw FileProblem(e.what());
        throw;
    }
}

}  // namespace fb89::python
