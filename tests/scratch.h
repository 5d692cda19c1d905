// A folder of this test process's own under the system's temporary folder, removed when
// the process exits. ctest runs tests in parallel processes, and two checkouts' suites
// may run on one machine at once: a fixed name there lets them read each other's files.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace fb89::testing {

inline std::filesystem::path scratch_dir_of(pid_t pid) {
    return std::filesystem::temp_directory_path() / ("fb89_test." + std::to_string(pid));
}

inline const std::filesystem::path& scratch_dir() {
    static const std::filesystem::path dir = [] {
        std::filesystem::path d = scratch_dir_of(::getpid());
        std::filesystem::create_directories(d);
        // names the folder afresh: `dir` itself is destroyed before this runs
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(scratch_dir_of(::getpid()), ec);
        });
        return d;
    }();
    return dir;
}

// `name` inside scratch_dir().
inline std::filesystem::path scratch_path(const std::string& name) {
    return scratch_dir() / name;
}

// Whether `program` is an executable on $PATH (what `command -v` says, without a shell whose
// output would have to go somewhere).
inline bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    for (std::size_t start = 0; start <= dirs.size();) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::string dir = dirs.substr(start, end - start);
        const std::filesystem::path candidate = (dir.empty() ? "." : dir) + ("/" + program);
        if (::access(candidate.c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

}  // namespace fb89::testing
