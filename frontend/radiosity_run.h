// `fb89 radiosity SCENE` as a library the command line (cli/radiosity_command.cpp) and the
// Python module (fb89.radiosity, python/radiosity.cpp) both call: the options and their
// checks (the ranges of each number, which options go with which --ff), the paper's §5
// pipeline (host/radiosity/pipeline.h) with every stage timed, the patches through the
// Z-buffer into the in-memory buffer, and what the command prints and writes of it: the
// summary, the notes, the --stats JSON, the id buffer and the stream.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "controller_sim/controller.h"
#include "controller_sim/framebuffer.h"
#include "frontend/option_limits.h"
#include "host/radiosity/pipeline.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene.h"
#include "host/stats.h"
#include "protocol/memory_buffer.h"
#include "protocol/stream_format.h"

namespace fb89::frontend {

namespace limits {
inline constexpr OptionLimit kEpsilon{"--epsilon", "epsilon", 0, 1e6, false};
inline constexpr OptionLimit kLinkRays{"--link-rays", "link_rays", 1, 4096};
inline constexpr OptionLimit kMinArea{"--min-area", "min_area", 1e-12, 1e12, false};
inline constexpr OptionLimit kMaxLinks{"--max-links", "max_links", 1, 200'000'000};
inline constexpr OptionLimit kRadiosityPatches{"--patches", "patches", 1, host::kMaxPatches};
inline constexpr OptionLimit kHemicubeRes{"--hemicube-res", "hemicube_res", 4, 4096};
inline constexpr OptionLimit kSolverTolerance{"--tolerance", "tolerance", 1e-15, 1.0, false};
inline constexpr OptionLimit kMaxIterations{"--max-iterations", "max_iterations", 1, 1000000};
inline constexpr OptionLimit kAdaptive{"--adaptive", "adaptive", 1e-6, 1e6, false};
inline constexpr OptionLimit kAdaptivePasses{"--adaptive-passes", "adaptive_passes", 1, 8};
inline constexpr OptionLimit kExposure{"--exposure", "exposure", 1e-12, 1e12, false};
}  // namespace limits

// What a radiosity run is asked: the command's options (numbers already checked against
// the limits above).
struct RadiosityRequest {
    std::string scene;  // the scene file (frontend::resolve_scene)
    std::string ff = std::string(host::to_string(host::RadiosityOptions{}.form_factors));
    std::string solver = std::string(host::to_string(host::RadiosityOptions{}.solver));
    host::RadiosityOptions options;  // form_factors and solver set by prepare()
    std::string size;                // "WxH", or "" for the scene's own
    std::string profile = std::string(controller::kDefaultProfile);
    bool progress = false;  // the progress line on stderr
    Spelling spelling = Spelling::Option;
};

// Which of the options that only some --ff read were given.
struct RadiosityGiven {
    bool hemicube_res = false, epsilon = false, link_rays = false, min_area = false,
         max_links = false, shaft_culling = false, solver = false, adaptive = false,
         adaptive_passes = false;
};

// Checks the --ff and --solver names and which options go with them, as the command does,
// naming each as `r.spelling` says, and sets r.options.form_factors and .solver. Throws
// UsageError.
void prepare_radiosity(RadiosityRequest& r, const RadiosityGiven& given);

struct RadiosityStages {
    host::Timing load, rendering, end_to_end;
};

struct RadiosityRun {
    host::Scene world;
    host::RadiosityResult result;
    RadiosityStages times;
    host::Counters counters;
    host::ScreenScene screen;
    protocol::MemoryBuffer commands;  // the patches' frame
    host::HostStats render_stats;
};

// The paper's pipeline up to the solution, then the patches through the Z-buffer. Throws
// UsageError for a scene radiosity cannot take (orthographic, no emitting face).
RadiosityRun run_radiosity(const RadiosityRequest& r);

// The notes the command prints on stderr: the solver's and the scene's, and why the solver
// stopped short, if it did.
std::vector<std::string> radiosity_notes(const RadiosityRequest& r, const RadiosityRun& run);
// What the command prints before the controller's summary.
std::string radiosity_summary(const RadiosityRequest& r, const RadiosityRun& run);
// What --stats writes, `ctl` having replayed the run's commands.
nlohmann::json radiosity_stats(const RadiosityRequest& r, const RadiosityRun& run,
                               const controller::Controller& ctl);
// The patch scene's face-id buffer (id + 1 as 24-bit RGB, 0 = background), as --ids writes.
controller::Framebuffer radiosity_id_buffer(const RadiosityRun& run);
// The header --stream writes.
protocol::Properties radiosity_stream_header(const RadiosityRequest& r, const RadiosityRun& run);
// --stream PATH ("-" for stdout).
void write_radiosity_stream(const RadiosityRequest& r, const RadiosityRun& run,
                            const std::string& path);

}  // namespace fb89::frontend
