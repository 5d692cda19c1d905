#include "bench/growth/growth_run.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "bench/growth/child_process.h"
#include "bench/growth/ladder.h"
#include "host/raster/screen_setup.h"
#include "host/scene/scene_loader.h"
#include "protocol/memory_buffer.h"

namespace fb89::growth {

namespace {

nlohmann::json timing_json(const host::Timing& t) {
    return {{"wall_ms", t.wall_ms}, {"cpu_ms", t.cpu_ms}};
}
host::Timing timing_of(const nlohmann::json& j) {
    return {j.at("wall_ms").get<double>(), j.at("cpu_ms").get<double>()};
}

// In the child: the whole pipeline on the host side, as `fb89 render` runs it.
std::string render_in_child(const std::filesystem::path& scene_file, host::Method method) {
    host::Stopwatch watch;
    const host::Scene scene = host::load_scene(scene_file);
    const host::Timing load = watch.elapsed();

    // set-up: projection, screen set-up, the method's own (buffers, grid)
    watch.restart();
    host::Counters counters;
    const host::ScreenScene screen = host::project_scene(scene, host::ColorMode::Shaded, counters);
    std::unique_ptr<host::Renderer> renderer = host::make_renderer(method);
    renderer->setup(screen);
    const host::Timing setup = watch.elapsed();

    protocol::MemoryBuffer buffer;
    host::HostStats stats;
    const host::Timing hidden_surface = host::render_frame(*renderer, screen, buffer, stats);
    return nlohmann::json{{"loaded_faces", scene.face_count},
                          {"scene_bytes", scene_bytes(scene)},
                          {"load", timing_json(load)},
                          {"setup", timing_json(setup)},
                          {"hidden_surface", timing_json(hidden_surface)},
                          {"pieces", screen.faces.size()},
                          {"commands", buffer.size()}}
        .dump();
}

std::string seconds(const host::Timing& t) {
    return fmt::format("{:.2f} s", t.cpu_ms / 1e3);
}

void report(const Measurement& m) {
    if (!m.ok) {
        std::cerr << fmt::format("  {:>9} {:<9} {:<8} failed: {}\n", m.faces, m.source, m.method,
                                 m.failure);
        return;
    }
    std::cerr << fmt::format(
        "  {:>9} {:<9} {:<8} load {}, set-up {}, hidden-surface {}, peak {:.1f} MiB\n", m.faces,
        m.source, m.method, seconds(m.load), seconds(m.setup), seconds(m.hidden_surface),
        static_cast<double>(m.peak_rss) / (1 << 20));
}

}  // namespace

uint64_t scene_bytes(const host::Scene& scene) {
    uint64_t bytes =
        sizeof(host::Scene) + scene.faces.capacity() * sizeof(host::Face) + scene.source.capacity();
    for (const host::Face& f : scene.faces)
        bytes += f.vertices.capacity() * sizeof(glm::dvec3);
    for (const std::string& note : scene.notes)
        bytes += sizeof(std::string) + note.capacity();
    return bytes;
}

Measurement measure(const std::filesystem::path& scene_file, host::Method method,
                    unsigned timeout_s) {
    Measurement m;
    m.method = std::string(host::method_info(method).name);
    const ChildOutcome child =
        run_in_child([&] { return render_in_child(scene_file, method); }, timeout_s);
    m.peak_rss = child.peak_rss;
    m.ok = child.ok;
    if (!child.ok) {
        m.failure = child.failure + (child.output.empty() ? "" : ": " + child.output);
        return m;
    }
    const nlohmann::json j = nlohmann::json::parse(child.output);
    m.loaded_faces = j.at("loaded_faces").get<uint64_t>();
    m.scene_bytes = j.at("scene_bytes").get<uint64_t>();
    m.load = timing_of(j.at("load"));
    m.setup = timing_of(j.at("setup"));
    m.hidden_surface = timing_of(j.at("hidden_surface"));
    m.pieces = j.at("pieces").get<uint64_t>();
    m.commands = j.at("commands").get<uint64_t>();
    return m;
}

Measurement combine(const std::vector<Measurement>& runs) {
    for (const Measurement& m : runs)
        if (!m.ok) return m;
    Measurement out = runs.front();
    std::vector<host::Timing> load, setup, hidden_surface;
    for (const Measurement& m : runs) {
        load.push_back(m.load);
        setup.push_back(m.setup);
        hidden_surface.push_back(m.hidden_surface);
        out.peak_rss = std::max(out.peak_rss, m.peak_rss);
    }
    out.load = host::median(load);
    out.setup = host::median(setup);
    out.hidden_surface = host::median(hidden_surface);
    return out;
}

std::vector<Measurement> run_ladder(const GrowthOptions& o) {
    const std::filesystem::path& dir = o.scenes;
    std::filesystem::create_directories(dir);
    const std::vector<Rung> rungs = ladder(o.min_faces, o.max_faces);
    if (rungs.empty())
        throw std::invalid_argument(fmt::format(
            "no rung between {} and {} faces (rungs have 4^k faces)", o.min_faces, o.max_faces));
    std::vector<Measurement> all;
    auto run = [&](const Rung& rung, const std::filesystem::path& file, const char* source,
                   uint64_t file_bytes) {
        for (host::Method method : o.methods) {
            std::vector<Measurement> tries;
            for (int r = 0; r < std::max(1, o.repeat); ++r)
                tries.push_back(measure(file, method, o.timeout_s));
            Measurement m = combine(tries);
            m.source = source;
            m.faces = rung.faces();
            m.file_bytes = file_bytes;
            if (o.progress) report(m);
            all.push_back(std::move(m));
        }
    };
    for (const Rung& rung : rungs) {
        run(rung, write_scene(rung, dir), "generator", 0);
        const bool top = &rung == &rungs.back();
        if (o.obj == GrowthOptions::Obj::None || (o.obj == GrowthOptions::Obj::Top && !top))
            continue;
        // the OBJ file is written in a child too, so this process stays small
        const std::string obj = fmt::format("terrain_{}.obj", rung.faces());
        const ChildOutcome written =
            run_in_child([&] { return std::to_string(write_obj(rung, dir / obj)); }, o.timeout_s);
        if (!written.ok)
            throw std::runtime_error(fmt::format("writing {}: {} {}", (dir / obj).string(),
                                                 written.failure, written.output));
        run(rung, write_scene(rung, dir, obj), "obj", std::stoull(written.output));
        if (!o.keep_obj) std::filesystem::remove(dir / obj);
    }
    return all;
}

}  // namespace fb89::growth
