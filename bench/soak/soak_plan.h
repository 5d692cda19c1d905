// What a soak runs: how many cycles, over which scenes and methods, where its files go and
// which fb89 executable it drives. Cycle c takes the pair c modulo (scenes x methods), the
// method changing fastest, so every scene meets every method and 1,000 cycles visit each
// of the 84 bundled pairs 11 or 12 times.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fb89::soak {

struct SoakOptions {
    int cycles = 1000;
    int every = 50;  // resources sampled after cycle 1, every `every` cycles, and at the end
    std::vector<std::filesystem::path> scenes;
    std::vector<std::string> methods;
    std::filesystem::path work;  // empty: a temporary folder of its own, removed at the end
    bool keep_work = false;
    std::filesystem::path fb89;       // the executable (cli and controller modes)
    double max_rss_growth_kib = 256;  // over the second half of the cycles; <= 0: unchecked
    unsigned child_timeout_s = 120;   // one fb89 process
    bool controller_stats = true;     // controller mode: run it with --stats and check them
    bool progress = true;
};

// One cycle's scene and method.
struct Pair {
    std::filesystem::path scene;
    std::string method;
    // "C.json warnock"
    std::string label() const;
    // "C-warnock", for file names
    std::string stem() const;
};

Pair pair_of(const SoakOptions& options, int cycle);

// The bundled scenes in `dir` named by `names` ("A" or "A.json"), or all of them when
// `names` is empty, in name order. Throws std::invalid_argument for a name not there.
std::vector<std::filesystem::path> scene_files(const std::filesystem::path& dir,
                                               const std::vector<std::string>& names);

// The folder a soak works in: options.work (created), or a new one under the temporary
// folder. Removes a folder it made unless keep_work is set.
class WorkDir {
  public:
    explicit WorkDir(const SoakOptions& options);
    ~WorkDir();
    WorkDir(const WorkDir&) = delete;
    WorkDir& operator=(const WorkDir&) = delete;
    const std::filesystem::path& path() const { return m_path; }

  private:
    std::filesystem::path m_path;
    bool m_remove = false;
};

}  // namespace fb89::soak
