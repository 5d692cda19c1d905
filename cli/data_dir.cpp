#include "cli/data_dir.h"

#include <unistd.h>

#include <cstdlib>

#include "period/isa.h"

namespace fb89::cli {

namespace fs = std::filesystem;

fs::path executable_dir() {
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return fs::current_path();
    return fs::path(std::string(self, static_cast<size_t>(n))).parent_path();
}

fs::path data_dir() {
    if (const char* given = std::getenv("FB89_DATA_DIR"); given && *given) return given;
    const fs::path installed = executable_dir().parent_path() / "share" / "fb89";
    if (fs::exists(installed / "scenes")) return installed;
    return FB89_SOURCE_DIR;
}

std::string bundled_scene(const std::string& name) {
    return (data_dir() / "scenes" / name).string();
}

void use_installed_period_parts() {
    const fs::path libexec = executable_dir().parent_path() / "libexec" / "fb89";
    if (!fs::exists(libexec / "libfb89_count.so")) return;
    ::setenv("FB89_COUNT_PLUGIN", (libexec / "libfb89_count.so").c_str(), 0);
    for (const period::InstructionSet& isa : period::instruction_sets()) {
        const fs::path dir = libexec / std::string(isa.name);
        if (!fs::exists(dir / "fb89_guest")) continue;
        const std::string prefix = "FB89_" + std::string(isa.env) + "_";
        ::setenv((prefix + "GUEST").c_str(), (dir / "fb89_guest").c_str(), 0);
        ::setenv((prefix + "KERNELS_DIR").c_str(), dir.c_str(), 0);
    }
}

}  // namespace fb89::cli
