#include "bench/soak/soak_plan.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

namespace fb89::soak {

namespace fs = std::filesystem;

std::string Pair::label() const {
    return scene.filename().string() + " " + method;
}

std::string Pair::stem() const {
    return scene.stem().string() + "-" + method;
}

Pair pair_of(const SoakOptions& options, int cycle) {
    const std::size_t methods = options.methods.size();
    const std::size_t i = static_cast<std::size_t>(cycle) % (options.scenes.size() * methods);
    return {options.scenes[i / methods], options.methods[i % methods]};
}

std::vector<fs::path> scene_files(const fs::path& dir, const std::vector<std::string>& names) {
    std::vector<fs::path> files;
    if (names.empty()) {
        for (const fs::directory_entry& e : fs::directory_iterator(dir))
            if (e.path().extension() == ".json") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        if (files.empty())
            throw std::invalid_argument(fmt::format("no scene files in {}", dir.string()));
        return files;
    }
    for (const std::string& name : names) {
        fs::path file = dir / name;
        if (file.extension() != ".json") file += ".json";
        if (!fs::is_regular_file(file))
            throw std::invalid_argument(fmt::format("no scene {} ({})", name, file.string()));
        files.push_back(file);
    }
    return files;
}

WorkDir::WorkDir(const SoakOptions& options) {
    if (!options.work.empty()) {
        m_path = fs::absolute(options.work);
        fs::create_directories(m_path);
        return;
    }
    // short, for the controller's socket path (108 bytes at most)
    std::string base = (fs::temp_directory_path() / "fb89-soak-XXXXXX").string();
    if (base.size() > 60) base = "/tmp/fb89-soak-XXXXXX";
    if (::mkdtemp(base.data()) == nullptr)
        throw std::runtime_error(fmt::format("cannot make a folder {}", base));
    m_path = base;
    m_remove = !options.keep_work;
}

WorkDir::~WorkDir() {
    std::error_code ignored;
    if (m_remove) fs::remove_all(m_path, ignored);
}

}  // namespace fb89::soak
