#include "frontend/data_dir.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <mutex>
#include <vector>

#include "frontend/common.h"
#include "frontend/names.h"
#include "host/scene/scene_error.h"
#include "period/isa.h"

namespace fb89::frontend {

namespace fs = std::filesystem;

fs::path executable_dir() {
    char self[4096];
    const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return fs::current_path();
    return fs::path(std::string(self, static_cast<size_t>(n))).parent_path();
}

namespace {
fs::path& given_prefix() {
    static fs::path prefix;
    return prefix;
}
}  // namespace

fs::path install_prefix() {
    return given_prefix().empty() ? executable_dir().parent_path() : given_prefix();
}

void set_install_prefix(const fs::path& prefix) {
    given_prefix() = prefix;
}

fs::path data_dir() {
    if (const char* given = std::getenv("FB89_DATA_DIR"); given && *given) return given;
    const fs::path installed = install_prefix() / "share" / "fb89";
    if (fs::exists(installed / "scenes")) return installed;
    return FB89_SOURCE_DIR;
}

std::string bundled_scene(const std::string& name) {
    return (data_dir() / "scenes" / name).string();
}

namespace {

// The bundled scenes' folder, canonical, or empty when there is none.
fs::path scenes_dir() {
    std::error_code ec;
    const fs::path dir = fs::canonical(data_dir() / "scenes", ec);
    return ec ? fs::path() : dir;
}

}  // namespace

bool is_scene_path(const std::string& argument) {
    const std::string extension = fs::path(argument).extension().string();
    return argument.find('/') != std::string::npos || extension == ".json" || extension == ".obj" ||
           extension == ".tri";
}

std::string resolve_scene(const std::string& argument) {
    std::error_code ec;
    if (argument.empty()) return argument;
    const std::vector<std::string> bundled = scene_names();
    // a path: from the current folder only
    if (is_scene_path(argument)) {
        if (fs::exists(argument, ec)) return argument;
        const std::string stem = fs::path(argument).stem().string();
        const bool named = std::find(bundled.begin(), bundled.end(), stem) != bundled.end();
        throw host::SceneError(
            argument + ": cannot open the scene file: no such file" +
            (fs::path(argument).is_relative()
                 ? " (a relative path is read from the current folder, " +
                       fs::current_path(ec).string() + ")"
                 : std::string()) +
            (named ? "; " + stem + " is a bundled scene: give its name alone, " + stem : ""));
    }
    // a name: a file of that name here, else the bundled scene
    if (fs::is_regular_file(argument, ec)) return argument;
    const fs::path dir = scenes_dir();
    if (!dir.empty())
        for (const char* extension : {".json", ".tri"})
            if (fs::is_regular_file(dir / (argument + extension), ec))
                return (dir / (argument + extension)).string();
    throw host::SceneError(
        argument +
        ": cannot open the scene file: no bundled scene of that name, nor a file in the current "
        "folder" +
        nearest_hint(argument, bundled) + " (the bundled scenes: " +
        (bundled.empty() ? "none in " + (data_dir() / "scenes").string() : name_list(bundled)) +
        "; fb89 list scenes)");
}

namespace {
std::mutex g_names_mutex;
std::map<std::string, std::string>& given_scene_names() {
    static std::map<std::string, std::string> names;
    return names;
}
}  // namespace

void name_scene_file(const std::string& path, const std::string& name) {
    std::lock_guard lock(g_names_mutex);
    given_scene_names()[path] = name;
}

void forget_scene_file(const std::string& path) {
    std::lock_guard lock(g_names_mutex);
    given_scene_names().erase(path);
}

std::string scene_display_name(const std::string& path) {
    {
        std::lock_guard lock(g_names_mutex);
        if (const auto named = given_scene_names().find(path); named != given_scene_names().end())
            return named->second;
    }
    std::error_code ec;
    const fs::path dir = scenes_dir();
    const fs::path file = fs::canonical(path, ec);
    if (ec || dir.empty() || file.parent_path() != dir) return path;
    return file.stem().string();
}

void use_installed_period_parts() {
    const fs::path libexec = install_prefix() / "libexec" / "fb89";
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

}  // namespace fb89::frontend
