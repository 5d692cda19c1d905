// The method registry: every hidden-surface method fb89 knows, by name, with a one-line
// description and the typed options it reads. It sits above host/raster and host/trace,
// which never include it; the CLI, the experiments and the tests build renderers here.
//
// Each option has one default, in the struct that owns it (WarnockOptions in
// raster/warnock.h, HybridOptions in raster/hybrid.h, TraceOptions in trace/ray_tracer.h,
// BeamOptions in trace/beam_ray_hybrid.h), and one check, validate() below.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "host/raster/hybrid.h"
#include "host/raster/renderer.h"
#include "host/raster/warnock.h"
#include "host/trace/beam_ray_hybrid.h"
#include "host/trace/ray_tracer.h"

namespace fb89::host {

enum class Method {
    ZBuffer,
    ScanLine,
    Warnock,
    Hybrid,
    RayTrace,
    Beam,
    DepthSpans,
    Faces,
    Hzb,
    Mlrta
};

// Which option groups a method reads; any other group's options do not apply to it.
enum OptionGroup : unsigned {
    kWindowOptions = 1u << 0,  // WarnockOptions: window test, approximate fills
    kHybridOptions = 1u << 1,  // HybridOptions: Expr. 3.1 threshold, depth estimate
    kTraceOptions = 1u << 2,   // TraceOptions: reflections, grid density
    kBeamOptions = 1u << 3,    // BeamOptions: Expr. 2.7 threshold
};

struct MethodInfo {
    Method method;
    std::string_view name;
    std::string_view description;
    unsigned options;  // OptionGroup bits
    // Whether it sends depth commands (stream format version 3): the controller tests depth.
    bool depth_commands = false;
    bool uses(OptionGroup group) const { return (options & group) != 0; }
};

// Every method, in the order the paper introduces them; then the two that move the split; then
// the successors that came after the paper.
std::span<const MethodInfo> methods();
const MethodInfo& method_info(Method method);
// Throws std::invalid_argument naming the known methods when `name` is not one.
Method method_named(std::string_view name);
std::vector<std::string> renderer_names();

struct MethodOptions {
    Method method = Method::ZBuffer;
    WarnockOptions warnock;  // warnock, hybrid
    HybridOptions hybrid;    // hybrid
    TraceOptions trace;      // raytrace, beam
    BeamOptions beam;        // beam

    MethodOptions() = default;
    MethodOptions(Method m) : method(m) {}  // NOLINT: a method alone is a complete choice
};

// Throws std::invalid_argument naming the option when a value the method reads is out of
// range. make_renderer() calls it; the CLI calls it to report usage errors early.
void validate(const MethodOptions& options);

std::unique_ptr<Renderer> make_renderer(const MethodOptions& options);

}  // namespace fb89::host
