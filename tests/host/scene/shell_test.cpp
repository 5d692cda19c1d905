// The `shell` generator: face count, planar convex faces with area, a consistently wound
// surface open only at the aperture, the shape its parameters promise, and scene-file errors
// that name the field.
#include "host/scene/shell.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <glm/geometric.hpp>

#include "host/scene/polygon.h"
#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

using VertexKey = std::tuple<double, double, double>;

VertexKey vertex_key(const glm::dvec3& v) {
    return {v.x + 0.0, v.y + 0.0, v.z + 0.0};  // + 0.0 folds -0 into 0
}

// Directed edges used once with no reverse: the surface's boundary.
std::vector<std::pair<VertexKey, VertexKey>> boundary_edges(const GeneratedPolygons& faces) {
    std::map<std::pair<VertexKey, VertexKey>, int> edges;
    for (const auto& f : faces)
        for (size_t i = 0; i < f.vertices.size(); ++i)
            ++edges[{vertex_key(f.vertices[i]),
                     vertex_key(f.vertices[(i + 1) % f.vertices.size()])}];
    std::vector<std::pair<VertexKey, VertexKey>> out;
    for (const auto& [edge, uses] : edges) {
        EXPECT_EQ(uses, 1) << "an edge used twice the same way: faces wound inconsistently";
        if (!edges.contains({edge.second, edge.first})) out.push_back(edge);
    }
    return out;
}

ShellOptions small_shell() {
    ShellOptions o;
    o.turns = 3;
    o.segments_per_turn = 10;
    o.sides = 7;
    o.growth = 2.5;
    o.size = 2;
    o.tube = 0.6;
    o.translation = 1.2;
    o.aspect = 1.4;
    return o;
}

TEST(Shell, FaceCountIsTwiceTurnsTimesSegmentsTimesSidesPlusTheApexCap) {
    ShellOptions o = small_shell();
    EXPECT_EQ(generate_shell(o).size(), 2u * 3 * 10 * 7 + 1);
    EXPECT_EQ(shell_face_count(o), 2u * 3 * 10 * 7 + 1);
    o.turns = 1;
    o.segments_per_turn = 3;
    o.sides = 3;
    EXPECT_EQ(generate_shell(o).size(), 19u);
    EXPECT_EQ(generate_shell(ShellOptions{}).size(), 2u * 4 * 24 * 12 + 1);
}

TEST(Shell, EveryFaceIsPlanarConvexWithArea) {
    for (ShellOptions o : {small_shell(), ShellOptions{}}) {
        GeneratedPolygons faces = generate_shell(o);
        ASSERT_EQ(faces[0].vertices.size(), static_cast<size_t>(o.sides));
        for (size_t k = 0; k < faces.size(); ++k) {
            const auto& v = faces[k].vertices;
            EXPECT_EQ(v.size(), k == 0 ? static_cast<size_t>(o.sides) : 3u) << "face " << k;
            PolygonResult r = prepare_polygon(v);
            EXPECT_EQ(r.verdict, PolygonVerdict::Ok) << "face " << k << ": " << r.reason;
            EXPECT_GT(glm::length(newell_normal(v)), 0) << "face " << k;
        }
    }
}

TEST(Shell, ApexCapFacesBackAndCellsFaceOutOfTheTube) {
    ShellOptions o = small_shell();
    GeneratedPolygons faces = generate_shell(o);
    // the cap's normal points back along the spiral, away from the first cells
    glm::dvec3 cap_centre(0);
    for (const auto& v : faces[0].vertices)
        cap_centre += v / static_cast<double>(o.sides);
    glm::dvec3 next = faces[1].vertices[2];  // a vertex of the second ring
    EXPECT_LT(glm::dot(newell_normal(faces[0].vertices), next - cap_centre), 0);
    // a cell's normal points away from the axis at the tube's outer side (j = 0)
    size_t last_cell = faces.size() - 2 * static_cast<size_t>(o.sides);
    const auto& v = faces[last_cell].vertices;
    glm::dvec3 radial(v[0].x, 0, v[0].z);
    EXPECT_GT(glm::dot(newell_normal(v), radial), 0);
}

TEST(Shell, IsOneWoundSurfaceOpenOnlyAtTheAperture) {
    ShellOptions o = small_shell();
    GeneratedPolygons faces = generate_shell(o);
    std::vector<std::pair<VertexKey, VertexKey>> open = boundary_edges(faces);
    EXPECT_EQ(open.size(), static_cast<size_t>(o.sides));
    // the aperture: vertex d of each last cell's second triangle (a, c, d)
    std::set<VertexKey> aperture;
    for (size_t k = faces.size() - 2 * static_cast<size_t>(o.sides); k < faces.size(); k += 2)
        aperture.insert(vertex_key(faces[k + 1].vertices[2]));
    EXPECT_EQ(aperture.size(), static_cast<size_t>(o.sides));
    for (const auto& [a, b] : open) {
        EXPECT_TRUE(aperture.contains(a));
        EXPECT_TRUE(aperture.contains(b));
    }
}

TEST(Shell, ApertureIsTheOutermostRingAtSize) {
    ShellOptions o = small_shell();
    double outer = 0;
    for (const auto& f : generate_shell(o))
        for (const auto& p : f.vertices)
            outer = std::max(outer, std::hypot(p.x, p.z));
    EXPECT_NEAR(outer, o.size, 1e-12);
}

TEST(Shell, GrowsByGrowthPerTurnAndDropsByTranslation) {
    ShellOptions o = small_shell();
    GeneratedPolygons faces = generate_shell(o);
    // vertex a of cell (i, 0) is the tube's outer point at step i: (1 + tube) times the tube
    // centre's distance from the axis, at the centre's height
    auto outer_point = [&](size_t i) {
        return faces[1 + 2 * i * static_cast<size_t>(o.sides)].vertices[0];
    };
    size_t per_turn = static_cast<size_t>(o.segments_per_turn);
    for (size_t i = 0; i + per_turn < 3 * per_turn; ++i) {
        glm::dvec3 p = outer_point(i), q = outer_point(i + per_turn);
        EXPECT_NEAR(std::hypot(q.x, q.z) / std::hypot(p.x, p.z), o.growth, 1e-9 * o.growth)
            << "step " << i;
        EXPECT_NEAR(q.y / p.y, o.growth, 1e-9 * o.growth) << "step " << i;
    }
    glm::dvec3 p = outer_point(0);
    double centre = std::hypot(p.x, p.z) / (1 + o.tube);
    EXPECT_NEAR(p.y, -o.translation * centre, 1e-12);
    EXPECT_NEAR(std::hypot(p.x, p.z), o.size / std::pow(o.growth, o.turns), 1e-12);
}

TEST(Shell, SameParametersGiveTheSameFaces) {
    GeneratedPolygons a = generate_shell(small_shell()), b = generate_shell(small_shell());
    ASSERT_EQ(a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k)
        EXPECT_EQ(a[k].vertices, b[k].vertices) << "face " << k;
}

const char* kShellCamera =
    R"("camera": {"eye": [0, 3, 9], "look_at": [0, 0, 0], "fovy": 45, "near": 0.1, "far": 100})";

Scene parse_shell(const std::string& objects) {
    return parse_scene_json("{" + std::string(kShellCamera) + R"(, "objects": [)" + objects + "]}",
                            "shell.json", ".");
}

std::string shell_error_of(const std::string& objects) {
    try {
        parse_shell(objects);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(ShellJson, LoadsAsPlanarConvexFacesWithNothingTriangulatedOrDropped) {
    Scene s = parse_shell(R"({"generator": "shell", "turns": 5, "segments_per_turn": 20, "sides": 9,
                        "growth": 1.8, "size": 0.3, "tube": 0.45, "translation": 2,
                        "aspect": 1.3, "material": {"color": [0.9, 0.7, 0.5]},
                        "transform": {"rotate": {"axis": [1, 0, 0], "degrees": 80}}},
                       {"generator": "shell"})");
    EXPECT_EQ(s.face_count, (2u * 5 * 20 * 9 + 1) + (2u * 4 * 24 * 12 + 1));
    EXPECT_EQ(s.faces.size(), s.face_count);
    EXPECT_EQ(s.triangulated, 0u);
    EXPECT_EQ(s.dropped, 0u);
}

struct BadShell {
    const char* object;
    const char* expected;  // a fragment the message must contain
};

class ShellJsonErrors : public ::testing::TestWithParam<BadShell> {};

TEST_P(ShellJsonErrors, NameTheFieldAndWhatWasExpected) {
    std::string message = shell_error_of(GetParam().object);
    EXPECT_NE(message.find(GetParam().expected), std::string::npos)
        << "message: " << message << "\nexpected to contain: " << GetParam().expected;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, ShellJsonErrors,
    ::testing::Values(
        BadShell{R"({"generator": "shell", "turns": 0})",
                 "shell.json: objects[0].turns: expected an integer in [1, 64]"},
        BadShell{R"({"generator": "shell", "turns": 2.5})", "objects[0].turns: expected"},
        BadShell{R"({"generator": "shell", "segments_per_turn": 2})",
                 "objects[0].segments_per_turn: expected an integer in [3, 4096]"},
        BadShell{R"({"generator": "shell", "sides": 4097})",
                 "objects[0].sides: expected an integer in [3, 4096]"},
        BadShell{R"({"generator": "shell", "growth": 0.5})", "objects[0].growth: expected"},
        BadShell{R"({"generator": "shell", "turns": 40, "growth": 3})",
                 "objects[0].growth: expected growth^turns at most 1e6"},
        BadShell{R"({"generator": "shell", "size": 0})", "objects[0].size: expected"},
        BadShell{R"({"generator": "shell", "tube": 1})", "objects[0].tube: expected"},
        BadShell{R"({"generator": "shell", "translation": -1})",
                 "objects[0].translation: expected"},
        BadShell{R"({"generator": "shell", "aspect": "tall"})", "objects[0].aspect: expected"},
        BadShell{R"({"generator": "shell", "turns": 64, "segments_per_turn": 4096,
                     "sides": 20, "growth": 1.1})",
                 "objects[0].sides: expected at most 10000000 faces in all"},
        BadShell{R"({"generator": "shell", "radius": 1})", "unknown field 'radius'"},
        BadShell{R"({"generator": "shel"})", "\"shell\""}));

}  // namespace
}  // namespace fb89::host
