// Z-buffer kernels at 1024x780: hidden-surface time only (projection is set-up, done once;
// the controller is not in the loop). For scale, REFERENCES.md measures Mesa's llvmpipe at
// ~3.0 ms per frame for 1,000 random triangles of ~700 px on one thread. Each scene runs
// with the widest depth kernel the CPU has (wide:1, AVX2 where there) and with the
// baseline one (wide:0, SSE2 on x86-64), which give the same frame.
#include <benchmark/benchmark.h>

#include "host/raster/screen_setup.h"
#include "host/raster/zbuffer.h"
#include "host/scene/generators.h"
#include "protocol/memory_buffer.h"

namespace {

using namespace fb89;

host::ScreenScene random_triangles(int count, double area) {
    host::Scene scene;
    scene.projection = host::Projection::Screen;
    for (auto& t : host::generate_random_triangles(1024, 780, count, area, 1989)) {
        host::Face f;
        f.vertices = std::move(t.vertices);
        f.material.color = *t.color;
        f.id = scene.face_count++;
        scene.faces.push_back(std::move(f));
    }
    host::Counters counters;
    return host::project_scene(scene, host::ColorMode::Shaded, counters);
}

void run_zbuffer(benchmark::State& state, const host::ScreenScene& scene) {
    host::ZBuffer zbuffer;
    zbuffer.allow_avx2(state.range(0) != 0);
    protocol::MemoryBuffer buffer;
    host::HostStats stats;
    for (auto _ : state) {
        buffer.clear();
        host::render_frame(zbuffer, scene, buffer, stats);
        benchmark::DoNotOptimize(buffer.commands().data());
    }
    const double frames = static_cast<double>(state.iterations());
    state.counters["spans"] = static_cast<double>(buffer.size() - 3);  // less FRAME_*, MARKER
    state.counters["depth_tests"] = static_cast<double>(stats.counters.get("depth_tests")) / frames;
}

void BM_ZBuffer_1000Triangles700px(benchmark::State& state) {
    static const host::ScreenScene scene = random_triangles(1000, 700);
    run_zbuffer(state, scene);
}
BENCHMARK(BM_ZBuffer_1000Triangles700px)
    ->ArgName("wide")
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

void BM_ZBuffer_10000Triangles270px(benchmark::State& state) {
    static const host::ScreenScene scene = random_triangles(10000, 270);
    run_zbuffer(state, scene);
}
BENCHMARK(BM_ZBuffer_10000Triangles270px)
    ->ArgName("wide")
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

void BM_ZBuffer_100000Triangles8px(benchmark::State& state) {
    static const host::ScreenScene scene = random_triangles(100000, 8);
    run_zbuffer(state, scene);
}
BENCHMARK(BM_ZBuffer_100000Triangles8px)
    ->ArgName("wide")
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
