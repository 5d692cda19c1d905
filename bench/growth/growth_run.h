// The growth benchmark's runs: every rung of the ladder (bench/growth/ladder.h) rendered by
// each method in a child process of its own (child_process.h), measuring the stages as
// docs/ARCHITECTURE.md times them (load, set-up, hidden-surface), the child's peak resident
// set and the size of its input, the loaded scene.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "host/methods.h"
#include "host/stats.h"

namespace fb89::growth {

// One render of one scene by one method, in one child.
struct Measurement {
    std::string source;  // "generator" or "obj": how the scene's faces were made
    std::string method;
    uint64_t faces = 0;         // the rung's face count
    uint64_t loaded_faces = 0;  // faces the loader made (ids), to check the rung
    uint64_t scene_bytes = 0;   // the loaded scene in memory: the input's own size
    uint64_t file_bytes = 0;    // the OBJ file read, or 0
    host::Timing load, setup, hidden_surface;
    uint64_t peak_rss = 0;  // bytes
    uint64_t pieces = 0;    // face pieces on screen after clipping and snapping
    uint64_t commands = 0;  // in the frame, FRAME_BEGIN and FRAME_END included
    bool ok = false;
    std::string failure;  // why the child failed, when it did
};

// Bytes a loaded scene holds: its faces, their vertex arrays and its notes (allocator
// overheads not counted).
uint64_t scene_bytes(const host::Scene& scene);

// Loads `scene_file`, projects it, sets the method up and renders one frame, all in a child.
Measurement measure(const std::filesystem::path& scene_file, host::Method method,
                    unsigned timeout_s);
// Repeated runs as one: each stage's median time, the largest peak; the first failure.
Measurement combine(const std::vector<Measurement>& runs);

struct GrowthOptions {
    std::filesystem::path scenes = "growth/scenes";  // the rungs' scene files and OBJ files
    uint64_t min_faces = 1024, max_faces = 1 << 20;
    std::vector<host::Method> methods{host::Method::ZBuffer, host::Method::Hybrid,
                                      host::Method::RayTrace, host::Method::Beam};
    enum class Obj { None, Top, All } obj = Obj::Top;  // rungs also read from an OBJ file
    bool keep_obj = false;                             // otherwise removed after their runs
    int repeat = 3;             // runs per rung and method: median times, largest peak
    unsigned timeout_s = 3600;  // per child
    bool progress = true;       // one line per run on stderr
};

// Every rung, then every method on it; OBJ rungs after the generator's.
std::vector<Measurement> run_ladder(const GrowthOptions& options);

}  // namespace fb89::growth
