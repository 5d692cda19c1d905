// The three soaks. Each runs options.cycles cycles over the (scene, method) pairs of
// soak_plan.h, samples resources (resource_sampler.h) and returns what it saw; none throws
// for a failed cycle, which is a failure in the result.
//
//   inprocess   the library: render into a stream file, read it back into a controller,
//               and compare with the same render sent straight to a controller
//   cli         the fb89 executable: render --stream --png, replay --png, diff, in a work
//               folder that must hold nothing else afterwards
//   controller  one `fb89 controller` process serving a `fb89 render --connect` per cycle,
//               its resources sampled, its --stats checked frame by frame at the end
#pragma once

#include "bench/soak/soak_plan.h"
#include "bench/soak/soak_report.h"

namespace fb89::soak {

SoakResult run_inprocess(const SoakOptions& options);
SoakResult run_cli(const SoakOptions& options);
SoakResult run_controller(const SoakOptions& options);

// A progress line on stderr after a sampled cycle (when options.progress).
void report_progress(const SoakOptions& options, const SoakResult& r, const ResourceSample& s);

}  // namespace fb89::soak
