// Generators: lathe and sphere (face counts, planar convex faces, closed oriented surfaces),
// copies of parts, regular (`array`) and seeded random (`scatter`), and the seeded `terrain`
// of the growth benchmark's ladder, from C++ and from scene files.
#include "host/scene/generators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>

#include <glm/geometric.hpp>

#include "host/scene/copies.h"
#include "host/scene/lathe.h"
#include "host/scene/polygon.h"
#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

using Key = std::tuple<double, double, double>;

Key key_of(const glm::dvec3& v) {
    return {v.x + 0.0, v.y + 0.0, v.z + 0.0};  // + 0.0 folds -0 into 0
}

// Every directed edge used once, and its reverse once: a closed, consistently wound surface.
bool is_closed_and_oriented(const GeneratedPolygons& faces) {
    std::map<std::pair<Key, Key>, int> edges;
    for (const auto& f : faces)
        for (size_t i = 0; i < f.vertices.size(); ++i)
            ++edges[{key_of(f.vertices[i]), key_of(f.vertices[(i + 1) % f.vertices.size()])}];
    for (const auto& [edge, uses] : edges) {
        auto reverse = edges.find({edge.second, edge.first});
        if (uses != 1 || reverse == edges.end() || reverse->second != 1) return false;
    }
    return true;
}

size_t faces_not_planar_convex(const GeneratedPolygons& faces) {
    size_t bad = 0;
    for (const auto& f : faces)
        bad += prepare_polygon(f.vertices).verdict != PolygonVerdict::Ok;
    return bad;
}

const std::vector<glm::dvec2> kGoblet = {{0.07, 0},     {0.07, 0.01},  {0.012, 0.025}, {0.01, 0.12},
                                         {0.03, 0.145}, {0.062, 0.19}, {0.074, 0.25},  {0.07, 0.3}};

TEST(Lathe, FaceCountIsProfileSegmentsTimesStepsPlusCaps) {
    EXPECT_EQ(generate_lathe(kGoblet, 12, LatheCaps::None).size(), 7u * 12);
    EXPECT_EQ(generate_lathe(kGoblet, 12, LatheCaps::First).size(), 7u * 12 + 1);
    EXPECT_EQ(generate_lathe(kGoblet, 12, LatheCaps::Last).size(), 7u * 12 + 1);
    EXPECT_EQ(generate_lathe(kGoblet, 12, LatheCaps::Both).size(), 7u * 12 + 2);
}

TEST(Lathe, EveryFaceIsPlanarAndConvex) {
    EXPECT_EQ(faces_not_planar_convex(generate_lathe(kGoblet, 24, LatheCaps::Both)), 0u);
    std::vector<glm::dvec2> steep = {{0, -3}, {2.5, -2}, {0.1, 7}, {4, 7.5}, {0, 9}};
    EXPECT_EQ(faces_not_planar_convex(generate_lathe(steep, 7, LatheCaps::None)), 0u);
}

TEST(Lathe, QuadsBetweenRingsAndTrianglesAtTheAxis) {
    GeneratedPolygons faces = generate_lathe({{0, 0}, {1, 1}, {1, 2}, {0, 3}}, 8, LatheCaps::Both);
    ASSERT_EQ(faces.size(), 24u);  // caps: none, both ends are on the axis
    for (size_t i = 0; i < 24; ++i)
        EXPECT_EQ(faces[i].vertices.size(), (i < 8 || i >= 16) ? 3u : 4u) << "face " << i;
}

TEST(Lathe, ProfileSegmentOnTheAxisMakesNoFace) {
    EXPECT_EQ(generate_lathe({{0, 0}, {0, 1}, {1, 2}}, 6, LatheCaps::None).size(), 6u);
}

TEST(Lathe, CapIsARegularPolygonOfSegmentsVertices) {
    GeneratedPolygons faces = generate_lathe({{2, 0}, {2, 1}}, 10, LatheCaps::First);
    ASSERT_EQ(faces.size(), 11u);
    const auto& cap = faces[0].vertices;
    ASSERT_EQ(cap.size(), 10u);
    for (const auto& v : cap) {
        EXPECT_DOUBLE_EQ(v.y, 0);
        EXPECT_NEAR(std::hypot(v.x, v.z), 2, 1e-12);
    }
}

TEST(Lathe, VerticesLieOnTheirProfileCircles) {
    for (const auto& f : generate_lathe(kGoblet, 16, LatheCaps::Both)) {
        for (const auto& v : f.vertices) {
            bool on_profile = false;
            for (const auto& p : kGoblet)
                on_profile =
                    on_profile || (v.y == p.y && std::abs(std::hypot(v.x, v.z) - p.x) < 1e-12);
            EXPECT_TRUE(on_profile) << v.x << " " << v.y << " " << v.z;
        }
    }
}

TEST(Lathe, CappedOrAxisClosedProfilesAreClosedOrientedSurfaces) {
    EXPECT_TRUE(is_closed_and_oriented(generate_lathe(kGoblet, 16, LatheCaps::Both)));
    EXPECT_TRUE(
        is_closed_and_oriented(generate_lathe({{0, 0}, {1, 1}, {0.5, 2}}, 9, LatheCaps::Last)));
    EXPECT_FALSE(is_closed_and_oriented(generate_lathe(kGoblet, 16, LatheCaps::First)));
}

TEST(Sphere, HasSegmentsTimesRingsFacesOnTheSphereAndIsClosed) {
    glm::dvec3 c{1, -2, 3};
    GeneratedPolygons faces = generate_sphere(c, 0.5, 14, 8);
    EXPECT_EQ(faces.size(), 14u * 8);
    EXPECT_EQ(faces_not_planar_convex(faces), 0u);
    EXPECT_TRUE(is_closed_and_oriented(faces));
    for (const auto& f : faces)
        for (const auto& v : f.vertices)
            EXPECT_NEAR(glm::length(v - c), 0.5, 1e-12);
}

TEST(Copies, ArrayPlacesCopiesXFastestAndKeepsPartColours) {
    GeneratedPolygons part = generate_box({0, 0, 0}, {1, 1, 1});
    part[0].color = glm::dvec3(0.5, 0.25, 1);
    GeneratedPolygons faces = place_copies(part, array_placements(3, 2, 1, {10, 20, 30}));
    ASSERT_EQ(faces.size(), 6u * 6);
    EXPECT_EQ(faces[6 * 1].vertices[0], part[0].vertices[0] + glm::dvec3(10, 0, 0));
    EXPECT_EQ(faces[6 * 3].vertices[0], part[0].vertices[0] + glm::dvec3(0, 20, 0));
    EXPECT_EQ(faces[6 * 5].vertices[0], part[0].vertices[0] + glm::dvec3(20, 20, 0));
    EXPECT_EQ(faces[6 * 4].color, part[0].color);
    EXPECT_FALSE(faces[6 * 4 + 1].color.has_value());
}

TEST(Copies, PlacementScalesThenTurnsAboutYThenMoves) {
    GeneratedPolygons part = {{{{1, 2, 0}, {0, 0, 0}, {0, 0, 1}}, {}}};
    Placement p;
    p.scale = 2;
    p.yaw_degrees = 90;
    p.offset = {5, 0, 0};
    GeneratedPolygons faces = place_copies(part, {p});
    // (1, 2, 0) -> (2, 4, 0) -> turned 90 degrees about +y: (0, 4, -2) -> (5, 4, -2)
    EXPECT_NEAR(faces[0].vertices[0].x, 5, 1e-12);
    EXPECT_NEAR(faces[0].vertices[0].y, 4, 1e-12);
    EXPECT_NEAR(faces[0].vertices[0].z, -2, 1e-12);
}

ScatterOptions forest(uint64_t seed) {
    ScatterOptions o;
    o.count = 200;
    o.min = {-5, 0, -5};
    o.max = {5, 0, 5};
    o.min_distance = 0.5;
    o.scale_min = 0.5;
    o.scale_max = 1.5;
    o.random_yaw = true;
    o.color_jitter = 0.2;
    o.seed = seed;
    return o;
}

TEST(Copies, ScatterIsTheSameForTheSameSeed) {
    std::vector<Placement> a = scatter_placements(forest(7)), b = scatter_placements(forest(7));
    ASSERT_EQ(a.size(), 200u);
    ASSERT_EQ(b.size(), 200u);
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].offset, b[i].offset);
        EXPECT_EQ(a[i].scale, b[i].scale);
        EXPECT_EQ(a[i].yaw_degrees, b[i].yaw_degrees);
        EXPECT_EQ(a[i].shade, b[i].shade);
    }
    EXPECT_NE(scatter_placements(forest(8))[0].offset, a[0].offset);
}

// The first draws of seed 7 (std::mt19937_64 is fully specified by the standard, and so is
// our mapping to [lo, hi)), so that a change of generator or mapping shows up here before it
// silently moves every tree of scene F.
TEST(Copies, ScatterDrawsAreFixedAcrossMachines) {
    std::vector<Placement> a = scatter_placements(forest(7));
    EXPECT_EQ(a[0].offset, glm::dvec3(2.5438530415285801, 0, -3.8258571896548199));
    EXPECT_EQ(a[0].scale, 1.3919131767124764);
}

TEST(Copies, ScatterKeepsItsDistanceRangesAndBox) {
    ScatterOptions o = forest(3);
    std::vector<Placement> a = scatter_placements(o);
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_GE(a[i].scale, o.scale_min);
        EXPECT_LE(a[i].scale, o.scale_max);
        EXPECT_GE(a[i].shade, 0.8);
        EXPECT_LE(a[i].shade, 1.2);
        EXPECT_GE(a[i].offset.x, -5);
        EXPECT_LE(a[i].offset.z, 5);
        for (size_t j = 0; j < i; ++j)
            EXPECT_GE(glm::length(a[i].offset - a[j].offset), o.min_distance);
    }
}

TEST(Copies, ScatterReturnsFewerWhenTheyDoNotFit) {
    ScatterOptions o = forest(1);
    o.count = 1000;  // at most ~(10 / 0.5)^2 discs fit
    EXPECT_LT(scatter_placements(o).size(), 1000u);
}

// ---- terrain ----

TerrainOptions terrain(int cells_x, int cells_z, uint64_t seed) {
    TerrainOptions o;
    o.cells_x = cells_x;
    o.cells_z = cells_z;
    o.seed = seed;
    return o;
}

TEST(Terrain, FaceCountIsTwoPerCell) {
    for (auto [nx, nz] : {std::pair{1, 1}, {2, 1}, {16, 8}, {64, 32}, {7, 13}}) {
        const TerrainOptions o = terrain(nx, nz, 1);
        EXPECT_EQ(generate_terrain(o).size(), 2u * nx * nz);
        EXPECT_EQ(terrain_face_count(o), 2u * nx * nz);
    }
    // the growth ladder's top rung: 1024 x 512 cells
    EXPECT_EQ(terrain_face_count(terrain(1024, 512, 1989)), 1'048'576u);
}

TEST(Terrain, TheSameSeedGivesTheSameFacesAndAnotherSeedOthers) {
    const GeneratedPolygons a = generate_terrain(terrain(24, 12, 7));
    const GeneratedPolygons b = generate_terrain(terrain(24, 12, 7));
    const GeneratedPolygons c = generate_terrain(terrain(24, 12, 8));
    ASSERT_EQ(a.size(), b.size());
    size_t differ = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].vertices, b[i].vertices);
        EXPECT_EQ(a[i].color, b[i].color);
        differ += a[i].vertices != c[i].vertices;
    }
    EXPECT_EQ(differ, a.size());
}

TEST(Terrain, FacesArePlanarConvexUpwardAndWithinTheHeight) {
    TerrainOptions o = terrain(20, 10, 3);
    o.height = 0.8;
    const GeneratedPolygons faces = generate_terrain(o);
    EXPECT_EQ(faces_not_planar_convex(faces), 0u);
    for (const auto& f : faces) {
        EXPECT_GT(newell_normal(f.vertices).y, 0);
        for (const auto& v : f.vertices) {
            EXPECT_LE(std::abs(v.y), 0.4);
            EXPECT_LE(std::abs(v.x), o.size_x / 2);
            EXPECT_LE(std::abs(v.z), o.size_z / 2);
        }
    }
}

TEST(Terrain, InteriorEdgesAreSharedExactlyInOppositeDirections) {
    const int nx = 6, nz = 4;
    std::map<std::pair<Key, Key>, int> edges;
    for (const auto& f : generate_terrain(terrain(nx, nz, 5)))
        for (size_t i = 0; i < 3; ++i)
            ++edges[{key_of(f.vertices[i]), key_of(f.vertices[(i + 1) % 3])}];
    size_t shared = 0;
    for (const auto& [edge, uses] : edges) {
        EXPECT_EQ(uses, 1);
        shared += edges.count({edge.second, edge.first});
    }
    // per cell: one diagonal; between cells: (nx - 1) nz + nx (nz - 1) edges, each both ways
    EXPECT_EQ(shared, 2u * (nx * nz + (nx - 1) * nz + nx * (nz - 1)));
}

// ---- from scene files ----

const char* kCamera =
    R"("camera": {"eye": [0, 3, 9], "look_at": [0, 0, 0], "fovy": 45, "near": 0.1, "far": 100})";

Scene parse(const std::string& objects) {
    return parse_scene_json("{" + std::string(kCamera) + R"(, "objects": [)" + objects + "]}",
                            "g.json", ".");
}

std::string error_of(const std::string& objects) {
    try {
        parse(objects);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(GeneratorsJson, LatheAndSphereLoadAsPlanarConvexFaces) {
    Scene s = parse(R"({"generator": "lathe", "segments": 16, "caps": "first",
                        "profile": [[0.07, 0], [0.012, 0.025], [0.01, 0.12], [0.074, 0.25]]},
                       {"generator": "lathe", "segments": 5, "caps": true, "profile": [[1, 0], [1, 1]]},
                       {"generator": "sphere", "center": [1, 1, 1], "radius": 2})");
    EXPECT_EQ(s.face_count, 3u * 16 + 1 + 5 + 2 + 16u * 8);
    EXPECT_EQ(s.triangulated, 0u);
    EXPECT_EQ(s.dropped, 0u);
}

TEST(GeneratorsJson, ArrayAndScatterCopyTheirPartsWithTheirColours) {
    Scene s = parse(R"({"generator": "array", "count": [2, 1, 3], "step": [1, 0, 1],
                        "colors": [[1, 0, 0], [0, 0, 1]],
                        "parts": [{"generator": "box", "min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}]},
                       {"generator": "scatter", "count": 4, "seed": 9, "min": [-2, 0, -2],
                        "max": [2, 0, 2], "min_distance": 0.5,
                        "parts": [{"generator": "sphere", "radius": 0.2, "segments": 6, "rings": 3,
                                   "material": {"color": [0, 1, 0]}},
                                  {"generator": "box", "min": [0, 0, 0], "max": [0.1, 1, 0.1]}]},
                       {"generator": "array",
                        "parts": [{"generator": "array", "count": [2, 1, 1], "step": [1, 0, 0],
                                   "parts": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]}]}],
                        "material": {"color": [0.2, 0.2, 0.2]}})");
    EXPECT_EQ(s.face_count, 6u * 6 + 4 * (18 + 6) + 12);
    EXPECT_EQ(s.faces[0].material.color, glm::dvec3(1, 0, 0));
    EXPECT_EQ(s.faces[6].material.color, glm::dvec3(0, 0, 1));
    EXPECT_EQ(s.faces[36].material.color, glm::dvec3(0, 1, 0));
    EXPECT_EQ(s.faces[36 + 18].material.color, glm::dvec3(0.8, 0.8, 0.8));  // the default
    EXPECT_EQ(s.faces.back().material.color, glm::dvec3(0.2, 0.2, 0.2));
}

TEST(GeneratorsJson, ScatterWithTheSameSeedLoadsTheSameFaces) {
    const char* forest = R"({"generator": "scatter", "count": 30, "seed": 5, "min": [-3, 0, -3],
        "max": [3, 0, 3], "min_distance": 0.4, "scale": [0.5, 1], "random_yaw": true,
        "color_jitter": 0.3,
        "parts": [{"generator": "lathe", "segments": 7, "profile": [[0.3, 0], [0, 1]],
                   "material": {"color": [0.2, 0.5, 0.2]}}]})";
    Scene a = parse(forest), b = parse(forest);
    ASSERT_EQ(a.faces.size(), 30u * 7);
    ASSERT_EQ(b.faces.size(), a.faces.size());
    for (size_t i = 0; i < a.faces.size(); ++i) {
        EXPECT_EQ(a.faces[i].vertices, b.faces[i].vertices);
        EXPECT_EQ(a.faces[i].material.color, b.faces[i].material.color);
    }
}

TEST(GeneratorsJson, TerrainLoadsItsCellsAsTrianglesSeeded) {
    const char* hills = R"({"generator": "terrain", "cells": [8, 4], "size": [2, 1],
                            "height": 0.3, "seed": 11})";
    Scene a = parse(hills), b = parse(hills);
    EXPECT_EQ(a.face_count, 64u);
    EXPECT_EQ(a.triangulated, 0u);
    EXPECT_EQ(a.dropped, 0u);
    ASSERT_EQ(b.faces.size(), a.faces.size());
    for (size_t i = 0; i < a.faces.size(); ++i)
        EXPECT_EQ(a.faces[i].vertices, b.faces[i].vertices);
    TerrainOptions o = terrain(8, 4, 11);
    o.size_x = 2;
    o.size_z = 1;
    o.height = 0.3;
    EXPECT_EQ(a.faces[5].vertices, generate_terrain(o)[5].vertices);
}

struct BadGenerator {
    const char* object;
    const char* expected;  // a fragment the message must contain
};

class GeneratorsJsonErrors : public ::testing::TestWithParam<BadGenerator> {};

TEST_P(GeneratorsJsonErrors, NameTheFieldAndWhatWasExpected) {
    std::string message = error_of(GetParam().object);
    EXPECT_NE(message.find(GetParam().expected), std::string::npos)
        << "message: " << message << "\nexpected to contain: " << GetParam().expected;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, GeneratorsJsonErrors,
    ::testing::Values(
        BadGenerator{R"({"generator": "lathe", "segments": 8, "profile": [[1, 0]]})",
                     "objects[0].profile: expected [[r, y], ...] with 2 or more points"},
        BadGenerator{R"({"generator": "lathe", "segments": 8, "profile": [[1, 0], [-1, 1]]})",
                     "objects[0].profile[1]: expected [r, y]: finite numbers, r >= 0"},
        BadGenerator{R"({"generator": "lathe", "segments": 8, "profile": [[1, 0], [1, 0]]})",
                     "objects[0].profile[1]: expected a point different from the one before"},
        BadGenerator{R"({"generator": "lathe", "segments": 2, "profile": [[1, 0], [1, 1]]})",
                     "objects[0].segments: expected an integer in [3, 4096]"},
        BadGenerator{
            R"({"generator": "lathe", "segments": 8, "caps": "top", "profile": [[1, 0], [1, 1]]})",
            "objects[0].caps: expected true, false, \"first\", \"last\""},
        BadGenerator{R"({"generator": "sphere", "radius": 0})",
                     "objects[0].radius: expected a number in"},
        BadGenerator{R"({"generator": "array", "count": [2, 0, 1], "parts": []})",
                     "objects[0].count: expected [nx, ny, nz], integers in [1, 4096]"},
        BadGenerator{R"({"generator": "array", "parts": []})",
                     "objects[0].parts: expected a non-empty array of generator objects"},
        BadGenerator{R"({"generator": "array", "parts": [{"polygon": [[0, 0, 0]]}]})",
                     "objects[0].parts[0]: expected a generator object"},
        BadGenerator{
            R"({"generator": "array", "parts": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1], "transform": {}}]})",
            "objects[0].parts[0].transform: expected no transform"},
        BadGenerator{
            R"({"generator": "array", "parts": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1], "material": {"mirror": 1}}]})",
            "objects[0].parts[0].material: unknown field 'mirror'"},
        BadGenerator{
            R"({"generator": "scatter", "count": 50, "min": [0, 0, 0], "max": [1, 0, 1], "min_distance": 0.5, "parts": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]}]})",
            "objects[0].count: expected copies that fit at min_distance 0.5"},
        BadGenerator{
            R"({"generator": "scatter", "count": 5, "min": [0, 0, 0], "max": [1, 0, 1], "scale": [2, 1], "parts": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]}]})",
            "objects[0].scale: expected [lo, hi]"},
        BadGenerator{
            R"({"generator": "scatter", "count": 5, "min": [0, 0, 0], "max": [1, 0, 1], "random_yaw": 1, "parts": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]}]})",
            "objects[0].random_yaw: expected true or false"},
        BadGenerator{
            R"({"generator": "array", "count": [1000, 1000, 1], "parts": [{"generator": "sphere", "radius": 1}]})",
            "objects[0].count: expected at most 10000000 faces in all (1000000 copies of 128 "
            "faces)"},
        BadGenerator{R"({"generator": "sphere", "radius": 1, "segments": 4096, "rings": 4096})",
                     "objects[0].rings: expected at most 10000000 faces in all"},
        BadGenerator{R"({"generator": "terrain", "cells": [8, 0.5]})",
                     "objects[0].cells: expected [x, z], integers in [1, 4096]"},
        BadGenerator{R"({"generator": "terrain", "cells": [4096, 4096]})",
                     "objects[0].cells: expected at most 10000000 faces in all"},
        BadGenerator{R"({"generator": "terrain", "size": [1, -1]})",
                     "objects[0].size: expected [x, z], numbers in"},
        BadGenerator{R"({"generator": "terrain", "octaves": 0})",
                     "objects[0].octaves: expected an integer in [1, 16]"},
        BadGenerator{R"({"generator": "cone"})",
                     "\"lathe\", \"sphere\", \"array\", \"scatter\", \"shell\", \"terrain\""}));

}  // namespace
}  // namespace fb89::host
