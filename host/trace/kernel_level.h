// Which instruction set the tracing kernels run with. The ray tracer's inner loop (the BVH
// walk and the watertight test: RayTracer::closest_hit) is compiled for x86-64 three times,
// for the baseline and for the x86-64-v3 (AVX2, FMA, BMI) and x86-64-v4 (AVX-512) levels,
// and the best level the CPU supports is used, as Embree picks its kernels at start-up.
// Every level computes the same thing to the bit: fb89 builds with -ffp-contract=off and
// no fast-math, so no level fuses or reorders a floating-point operation; the golden tests
// run under each level the machine has and compare ids and counts. Elsewhere (the period
// guests) there is one, portable, level.
//
// The level may be forced, for comparison: set_kernel_level(), `--isa` on the commands that
// trace, or $FB89_ISA (baseline, v3 or v4).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fb89::host {

enum class KernelLevel { Baseline, V3, V4 };

// "baseline", "v3", "v4": the names --isa and $FB89_ISA take.
std::string_view kernel_level_name(KernelLevel level);
// What the level is: "x86-64 (SSE2)", "x86-64-v3 (AVX2)", "x86-64-v4 (AVX-512)", or
// "portable" where there is only one.
std::string_view kernel_level_description(KernelLevel level);
// A name as above; throws std::invalid_argument naming the levels for any other.
KernelLevel parse_kernel_level(std::string_view name);

// The levels this build has and this CPU runs, lowest first (Baseline always).
const std::vector<KernelLevel>& supported_kernel_levels();

// The level in use: the one set, else $FB89_ISA, else the highest supported.
KernelLevel kernel_level();
// Sets it; throws std::invalid_argument when the build or the CPU lacks it.
void set_kernel_level(KernelLevel level);

}  // namespace fb89::host
