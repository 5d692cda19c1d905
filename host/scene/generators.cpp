#include "host/scene/generators.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <tuple>
#include <utility>

#include <glm/vec2.hpp>
#include <glm/vector_relational.hpp>

#include <fmt/format.h>

#include "host/scene/copies.h"
#include "host/scene/lathe.h"
#include "host/scene/scene_error.h"
#include "host/scene/shell.h"

namespace fb89::host {

namespace {

// No generator makes more faces than this: a typo in a count is an error, not a machine
// brought to its knees.
constexpr long long kMaxGeneratedFaces = 10'000'000;

// A pleasant, deterministic colour for face k of a mosaic.
glm::dvec3 mosaic_color(uint32_t k) {
    uint32_t h = k * 2654435761u;
    double hue = static_cast<double>(h >> 8) / static_cast<double>(1u << 24);
    double r = 0.5 + 0.4 * std::cos(6.2831853 * (hue + 0.0));
    double g = 0.5 + 0.4 * std::cos(6.2831853 * (hue + 0.33));
    double b = 0.5 + 0.4 * std::cos(6.2831853 * (hue + 0.67));
    return {r, g, b};
}

GeneratedPolygons ideal_from_json(const JsonFields& o, const Scene& scene) {
    if (scene.projection != Projection::Screen)
        throw SceneError(o.where("generator") +
                         ": the ideal scene is built in screen space; set "
                         "\"camera\": {\"projection\": \"screen\"}");
    int layers = o.integer_in("layers", 1, 64);
    double gap = o.number_or("gap", 0.5, 0, 1e6);
    double cell_w = 0, cell_h = 0;
    if (o.has("faces_per_layer")) {
        int fv = o.integer_in("faces_per_layer", 1, 1 << 22);
        int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(fv))));
        if (n * n != fv) o.fail("faces_per_layer", "a perfect square (n x n faces per layer)");
        cell_w = static_cast<double>(scene.width) / n;
        cell_h = static_cast<double>(scene.height) / n;
    } else {
        cell_w = cell_h = o.number_in("cell", 1, 1 << 16);
    }
    if (cell_w <= gap || cell_h <= gap)
        o.fail("gap", fmt::format("less than the cell size ({} x {} px)", cell_w, cell_h));
    return generate_ideal(scene.width, scene.height, layers, cell_w, cell_h, gap);
}

bool boolean_or(const JsonFields& o, const char* key, bool fallback) {
    if (!o.has(key)) return fallback;
    if (!o.node().at(key).is_boolean()) o.fail(key, "true or false");
    return o.node().at(key).get<bool>();
}

// [lo, hi] with lo <= hi, both within [min, max].
std::pair<double, double> range_or(const JsonFields& o, const char* key, double fallback,
                                   double min, double max) {
    if (!o.has(key)) return {fallback, fallback};
    const auto& a = o.node().at(key);
    std::string expected = fmt::format("[lo, hi] with {} <= lo <= hi <= {}", min, max);
    if (!a.is_array() || a.size() != 2 || !a[0].is_number() || !a[1].is_number())
        o.fail(key, expected);
    double lo = a[0].get<double>(), hi = a[1].get<double>();
    if (!(min <= lo && lo <= hi && hi <= max)) o.fail(key, expected);
    return {lo, hi};
}

// [nx, ny, nz]: integers in [1, 4096].
glm::ivec3 counts3(const JsonFields& o, const char* key) {
    const char* expected = "[nx, ny, nz], integers in [1, 4096]";
    if (!o.has(key) || !o.node().at(key).is_array() || o.node().at(key).size() != 3)
        o.fail(key, expected);
    glm::ivec3 n;
    for (int i = 0; i < 3; ++i) {
        const auto& v = o.node().at(key)[static_cast<size_t>(i)];
        if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 4096)
            o.fail(key, expected);
        n[i] = v.get<int>();
    }
    return n;
}

GeneratedPolygons lathe_from_json(const JsonFields& o) {
    JsonFields list = o.child("profile");
    if (list.size() < 2) o.fail("profile", "[[r, y], ...] with 2 or more points");
    std::vector<glm::dvec2> profile;
    for (size_t i = 0; i < list.size(); ++i) {
        const auto& p = list.node()[i];
        bool ok = p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number();
        double r = ok ? p[0].get<double>() : 0, y = ok ? p[1].get<double>() : 0;
        if (!ok || !std::isfinite(r) || !std::isfinite(y) || r < 0)
            list.element(i).fail(nullptr, "[r, y]: finite numbers, r >= 0");
        if (!profile.empty() && profile.back() == glm::dvec2(r, y))
            list.element(i).fail(nullptr, "a point different from the one before");
        profile.emplace_back(r, y);
    }
    LatheCaps caps = LatheCaps::None;
    if (o.has("caps")) {
        const auto& c = o.node().at("caps");
        std::string name = c.is_boolean() ? (c.get<bool>() ? "both" : "none")
                                          : (c.is_string() ? c.get<std::string>() : "");
        if (name == "both")
            caps = LatheCaps::Both;
        else if (name == "first")
            caps = LatheCaps::First;
        else if (name == "last")
            caps = LatheCaps::Last;
        else if (name != "none")
            o.fail("caps", "true, false, \"first\", \"last\", \"both\" or \"none\"");
    }
    int segments = o.integer_in("segments", 3, 4096);
    if (static_cast<long long>(profile.size() - 1) * segments > kMaxGeneratedFaces)
        o.fail("segments", fmt::format("at most {} faces in all", kMaxGeneratedFaces));
    return generate_lathe(profile, segments, caps);
}

GeneratedPolygons shell_from_json(const JsonFields& o) {
    ShellOptions s;
    s.turns = o.integer_or("turns", s.turns, 1, 64);
    s.segments_per_turn = o.integer_or("segments_per_turn", s.segments_per_turn, 3, 4096);
    s.sides = o.integer_or("sides", s.sides, 3, 4096);
    s.growth = o.number_or("growth", s.growth, 1, 1e6);
    s.size = o.number_or("size", s.size, 1e-9, 1e9);
    s.tube = o.number_or("tube", s.tube, 1e-3, 0.999);
    s.translation = o.number_or("translation", s.translation, 0, 100);
    s.aspect = o.number_or("aspect", s.aspect, 0.05, 20);
    // the apex is the aperture scaled by 1 / growth^turns: keep it well above rounding
    if (std::pow(s.growth, s.turns) > 1e6)
        o.fail("growth", fmt::format("growth^turns at most 1e6 (here {:.3g}^{} = {:.3g})", s.growth,
                                     s.turns, std::pow(s.growth, s.turns)));
    if (static_cast<long long>(shell_face_count(s)) > kMaxGeneratedFaces)
        o.fail("sides", fmt::format("at most {} faces in all ({} here)", kMaxGeneratedFaces,
                                    shell_face_count(s)));
    return generate_shell(s);
}

// The parts of an `array` or `scatter`: generator objects, each with at most a colour.
GeneratedPolygons parts_from_json(const JsonFields& o, const Scene& scene) {
    JsonFields list = o.child("parts");
    if (list.size() == 0) o.fail("parts", "a non-empty array of generator objects");
    GeneratedPolygons out;
    for (size_t i = 0; i < list.size(); ++i) {
        JsonFields part = list.element(i);
        if (!part.node().is_object() || !part.has("generator"))
            part.fail(nullptr, "a generator object {\"generator\": ...}");
        if (part.has("transform"))
            part.fail("transform", "no transform: a part is placed by its own coordinates");
        std::optional<glm::dvec3> color;
        if (part.has("material")) {
            JsonFields m = part.child("material");
            m.only_keys("part material");
            color = m.color("color");
        }
        for (GeneratedPolygon& g : generate_from_json(part, scene)) {
            if (color) g.color = color;
            out.push_back(std::move(g));
        }
    }
    return out;
}

GeneratedPolygons copies_from_json(const JsonFields& o, const Scene& scene,
                                   const std::vector<Placement>& placements) {
    GeneratedPolygons parts = parts_from_json(o, scene);
    if (static_cast<long long>(parts.size()) * static_cast<long long>(placements.size()) >
        kMaxGeneratedFaces)
        o.fail("count", fmt::format("at most {} faces in all ({} copies of {} faces)",
                                    kMaxGeneratedFaces, placements.size(), parts.size()));
    return place_copies(parts, placements);
}

GeneratedPolygons array_from_json(const JsonFields& o, const Scene& scene) {
    glm::ivec3 n = o.has("count") ? counts3(o, "count") : glm::ivec3(1);
    if (static_cast<long long>(n.x) * n.y * n.z > 1'000'000)
        o.fail("count", "at most 1,000,000 copies in all");
    std::vector<Placement> placements =
        array_placements(n.x, n.y, n.z, o.vec3_or("step", glm::dvec3(0)));
    if (o.has("colors")) {  // cycled copy by copy
        JsonFields colors = o.child("colors");
        if (colors.size() == 0) o.fail("colors", "a non-empty array of colours");
        for (size_t k = 0; k < placements.size(); ++k) {
            JsonFields c = colors.element(k % colors.size());
            glm::dvec3 rgb = c.vec3_of_node();
            if (glm::any(glm::lessThan(rgb, glm::dvec3(0))) ||
                glm::any(glm::greaterThan(rgb, glm::dvec3(1))))
                c.fail(nullptr, "3 numbers in [0, 1]");
            placements[k].color = rgb;
        }
    }
    return copies_from_json(o, scene, placements);
}

GeneratedPolygons scatter_from_json(const JsonFields& o, const Scene& scene) {
    ScatterOptions s;
    s.count = o.integer_in("count", 1, 100'000);
    s.seed = static_cast<uint64_t>(o.integer_or("seed", 1, 0, 1 << 30));
    s.min = o.vec3("min");
    s.max = o.vec3("max");
    if (!glm::all(glm::lessThanEqual(s.min, s.max))) o.fail("max", "every coordinate >= min");
    s.min_distance = o.number_or("min_distance", 0, 0, 1e12);
    std::tie(s.scale_min, s.scale_max) = range_or(o, "scale", 1, 1e-6, 1e6);
    s.random_yaw = boolean_or(o, "random_yaw", false);
    s.color_jitter = o.number_or("color_jitter", 0, 0, 1);
    std::vector<Placement> placements = scatter_placements(s);
    if (static_cast<int>(placements.size()) < s.count)
        o.fail("count", fmt::format("copies that fit at min_distance {} (only {} did)",
                                    s.min_distance, placements.size()));
    return copies_from_json(o, scene, placements);
}

// [a, b]: two numbers in [min, max], integers when `integers`.
std::pair<double, double> pair_or(const JsonFields& o, const char* key,
                                  std::pair<double, double> fallback, double min, double max,
                                  bool integers) {
    if (!o.has(key)) return fallback;
    const auto& a = o.node().at(key);
    auto fits = [&](const nlohmann::json& v) {
        return (integers ? v.is_number_integer() : v.is_number()) && v.get<double>() >= min &&
               v.get<double>() <= max;
    };
    if (!a.is_array() || a.size() != 2 || !fits(a[0]) || !fits(a[1]))
        o.fail(key,
               fmt::format("[x, z], {} in [{}, {}]", integers ? "integers" : "numbers", min, max));
    return {a[0].get<double>(), a[1].get<double>()};
}

// {"cells": [nx, nz], "size": [sx, sz], "height": h, "octaves": n, "seed": s}
GeneratedPolygons terrain_from_json(const JsonFields& o) {
    TerrainOptions t;
    auto [nx, nz] = pair_or(o, "cells", {t.cells_x, t.cells_z}, 1, 4096, true);
    t.cells_x = static_cast<int>(nx);
    t.cells_z = static_cast<int>(nz);
    if (static_cast<long long>(terrain_face_count(t)) > kMaxGeneratedFaces)
        o.fail("cells", fmt::format("at most {} faces in all (2 per cell)", kMaxGeneratedFaces));
    std::tie(t.size_x, t.size_z) = pair_or(o, "size", {t.size_x, t.size_z}, 1e-9, 1e9, false);
    t.height = o.number_or("height", t.height, 0, 1e9);
    t.octaves = o.integer_or("octaves", t.octaves, 1, 16);
    t.seed = static_cast<uint64_t>(o.integer_or("seed", 1, 0, 1 << 30));
    return generate_terrain(t);
}

}  // namespace

GeneratedPolygons generate_box(const glm::dvec3& lo, const glm::dvec3& hi) {
    glm::dvec3 c[8];
    for (int i = 0; i < 8; ++i)
        c[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    GeneratedPolygons out;
    for (const auto& q : quads)
        out.push_back({{c[q[0]], c[q[1]], c[q[2]], c[q[3]]}, {}});
    return out;
}

GeneratedPolygons generate_quad(const glm::dvec3& origin, const glm::dvec3& u, const glm::dvec3& v,
                                int nu, int nv, bool triangles) {
    GeneratedPolygons out;
    auto at = [&](int i, int j) {
        return origin + u * (static_cast<double>(i) / nu) + v * (static_cast<double>(j) / nv);
    };
    for (int j = 0; j < nv; ++j) {
        for (int i = 0; i < nu; ++i) {
            glm::dvec3 a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (triangles) {
                out.push_back({{a, b, c}, {}});
                out.push_back({{a, c, d}, {}});
            } else {
                out.push_back({{a, b, c, d}, {}});
            }
        }
    }
    return out;
}

GeneratedPolygons generate_ideal(int width, int height, int layers, double cell_w, double cell_h,
                                 double gap) {
    int cols = static_cast<int>(std::floor(width / cell_w + 1e-9));
    int rows = static_cast<int>(std::floor(height / cell_h + 1e-9));
    GeneratedPolygons out;
    out.reserve(static_cast<size_t>(layers) * cols * rows);
    uint32_t k = 0;
    for (int layer = 0; layer < layers; ++layer) {
        double z = static_cast<double>(layer + 1) / (layers + 1);
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < cols; ++c, ++k) {
                double x0 = c * cell_w + gap, x1 = (c + 1) * cell_w;
                double y0 = r * cell_h + gap, y1 = (r + 1) * cell_h;
                out.push_back({{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}},
                               mosaic_color(k) * (1.0 - 0.5 * layer / layers)});
            }
        }
    }
    return out;
}

Scene ideal_scene(int width, int height, int layers, double cell_w, double cell_h, double gap) {
    Scene scene;
    scene.projection = Projection::Screen;
    scene.width = width;
    scene.height = height;
    for (auto& p : generate_ideal(width, height, layers, cell_w, cell_h, gap)) {
        Face f;
        f.vertices = std::move(p.vertices);
        f.id = scene.face_count++;
        scene.faces.push_back(std::move(f));
    }
    return scene;
}

GeneratedPolygons generate_random_triangles(int width, int height, int count, double area,
                                            uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto uniform = [&rng](double lo, double hi) {
        return lo + (hi - lo) * (static_cast<double>(rng() >> 11) * 0x1.0p-53);
    };
    GeneratedPolygons out;
    out.reserve(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
        double cx = uniform(0, width), cy = uniform(0, height);
        // three directions around the centre, then scaled to the wanted area
        double a0 = uniform(0, 2.0944), a1 = a0 + uniform(1.5, 2.6), a2 = a1 + uniform(1.5, 2.6);
        glm::dvec2 d[3] = {{std::cos(a0), std::sin(a0)},
                           {std::cos(a1), std::sin(a1)},
                           {std::cos(a2), std::sin(a2)}};
        double unit = 0.5 * std::abs((d[1].x - d[0].x) * (d[2].y - d[0].y) -
                                     (d[2].x - d[0].x) * (d[1].y - d[0].y));
        double r = std::sqrt(area / std::max(unit, 1e-3));
        GeneratedPolygon t;
        for (const auto& v : d)
            t.vertices.emplace_back(std::round((cx + r * v.x) * 256) / 256,
                                    std::round((cy + r * v.y) * 256) / 256, uniform(0, 1));
        t.color = mosaic_color(static_cast<uint32_t>(i));
        out.push_back(std::move(t));
    }
    return out;
}

GeneratedPolygons generate_from_json(const JsonFields& o, const Scene& scene) {
    std::string kind = o.string("generator");
    if (kind == "box") {
        o.only_keys("generator " + kind);
        glm::dvec3 lo = o.vec3("min"), hi = o.vec3("max");
        if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) o.fail("max", "every coordinate > min");
        return generate_box(lo, hi);
    }
    if (kind == "quad") {
        o.only_keys("generator " + kind);
        int nu = 1, nv = 1;
        if (o.has("divisions")) {
            JsonFields d = o.child("divisions");
            if (d.size() != 2) o.fail("divisions", "[nu, nv]");
            for (size_t i = 0; i < 2; ++i) {
                const auto& n = d.node()[i];
                if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 4096)
                    o.fail("divisions", "[nu, nv], integers in [1, 4096]");
            }
            nu = d.node()[0].get<int>();
            nv = d.node()[1].get<int>();
        }
        const bool triangles = boolean_or(o, "triangles", false);
        GeneratedPolygons quad =
            generate_quad(o.vec3("origin"), o.vec3("u"), o.vec3("v"), nu, nv, triangles);
        if (o.has("checker")) {  // two colours alternating cell by cell
            JsonFields checker = o.child("checker");
            if (checker.size() != 2) o.fail("checker", "two colours [[r, g, b], [r, g, b]]");
            glm::dvec3 colors[2] = {checker.element(0).vec3_of_node(),
                                    checker.element(1).vec3_of_node()};
            size_t per_cell = triangles ? 2 : 1;
            for (size_t k = 0; k < quad.size(); ++k) {
                size_t cell = k / per_cell;
                quad[k].color = colors[(cell % nu + cell / nu) % 2];
            }
        }
        return quad;
    }
    if (kind == "ideal") {
        o.only_keys("generator " + kind);
        return ideal_from_json(o, scene);
    }
    if (kind == "random_triangles") {
        o.only_keys("generator " + kind);
        if (scene.projection != Projection::Screen)
            throw SceneError(o.where("generator") +
                             ": random triangles are built in screen space; set "
                             "\"camera\": {\"projection\": \"screen\"}");
        return generate_random_triangles(
            scene.width, scene.height, o.integer_in("count", 1, 10'000'000),
            o.number_in("area", 0.01, 1e8),
            static_cast<uint64_t>(o.integer_or("seed", 1, 0, 1 << 30)));
    }
    if (kind == "lathe") {
        o.only_keys("generator " + kind);
        return lathe_from_json(o);
    }
    if (kind == "sphere") {
        o.only_keys("generator " + kind);
        glm::dvec3 center = o.vec3_or("center", glm::dvec3(0));
        double radius = o.number_in("radius", 1e-12, 1e12);
        int segments = o.integer_or("segments", 16, 3, 4096);
        int rings = o.integer_or("rings", 8, 2, 4096);
        if (static_cast<long long>(segments) * rings > kMaxGeneratedFaces)
            o.fail("rings", fmt::format("at most {} faces in all", kMaxGeneratedFaces));
        return generate_sphere(center, radius, segments, rings);
    }
    if (kind == "array") {
        o.only_keys("generator " + kind);
        return array_from_json(o, scene);
    }
    if (kind == "scatter") {
        o.only_keys("generator " + kind);
        return scatter_from_json(o, scene);
    }
    if (kind == "shell") {
        o.only_keys("generator " + kind);
        return shell_from_json(o);
    }
    if (kind == "terrain") {
        o.only_keys("generator " + kind);
        return terrain_from_json(o);
    }
    o.fail("generator",
           "one of \"box\", \"quad\", \"ideal\", \"random_triangles\", \"lathe\", "
           "\"sphere\", \"array\", \"scatter\", \"shell\", \"terrain\"");
}

}  // namespace fb89::host
