// Scene files: what loads, and that every malformed input gives an error naming the file,
// the field or line, and what was expected.
#include "host/scene/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "host/scene/scene_error.h"
#include "tests/scratch.h"

namespace fb89::host {
namespace {

const char* kLoaderCamera =
    R"("camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fovy": 45, "near": 0.1, "far": 100})";

Scene parse_body(const std::string& body) {
    return parse_scene_json("{" + std::string(kLoaderCamera) + ", " + body + "}", "s.json", ".");
}

// The error message of loading `body`, or "" when it loads.
std::string load_error_of(const std::string& json) {
    try {
        parse_scene_json(json, "bad.json", ".");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(SceneLoader, ReadsCameraImageLightAndDefaults) {
    Scene s =
        parse_body(R"("light": {"direction": [0, -2, 0], "ambient": 0.3}, "background": [0, 0.5, 1],
                       "objects": [{"polygon": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": {"color": [1, 0, 0]}}])");
    EXPECT_EQ(s.width, 1024);
    EXPECT_EQ(s.height, 780);
    EXPECT_DOUBLE_EQ(s.light.direction.y, -1.0);
    EXPECT_DOUBLE_EQ(s.light.ambient, 0.3);
    EXPECT_DOUBLE_EQ(s.background.b, 1.0);
    ASSERT_EQ(s.faces.size(), 1u);
    EXPECT_EQ(s.face_count, 1u);
    EXPECT_DOUBLE_EQ(s.faces[0].material.color.r, 1.0);
}

TEST(SceneLoader, AllowsComments) {
    Scene s = parse_scene_json(
        std::string("// a scene\n{") + kLoaderCamera + ", /* none */ \"objects\": []}", "c.json",
        ".");
    EXPECT_TRUE(s.faces.empty());
}

TEST(SceneLoader, NumbersFacesInLoadOrderAndPiecesKeepTheirId) {
    Scene s = parse_body(R"("objects": [
        {"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1]},
        {"polygon": [[0, 0, 0], [2, 0, 0], [1, 0.2, 0], [2, 2, 0], [0, 2, 0]]}])");
    EXPECT_EQ(s.face_count, 7u);
    EXPECT_EQ(s.triangulated, 1u);
    ASSERT_EQ(s.faces.size(), 6u + 3u);
    for (size_t i = 0; i < 6; ++i)
        EXPECT_EQ(s.faces[i].id, i);
    for (size_t i = 6; i < 9; ++i)
        EXPECT_EQ(s.faces[i].id, 6u);
    ASSERT_EQ(s.notes.size(), 1u);
    EXPECT_NE(s.notes[0].find("not convex"), std::string::npos) << s.notes[0];
}

TEST(SceneLoader, TriangulatesAndReportsNonPlanarPolygons) {
    Scene s =
        parse_body(R"("objects": [{"polygon": [[0, 0, 0], [1, 0, 0], [1, 1, 0.3], [0, 1, 0]]}])");
    EXPECT_EQ(s.triangulated, 1u);
    EXPECT_EQ(s.faces.size(), 2u);
    EXPECT_NE(s.notes.at(0).find("not planar"), std::string::npos);
}

TEST(SceneLoader, DropsAndReportsZeroAreaFacesLeavingTheirIdsUnused) {
    Scene s = parse_body(R"("objects": [{"polygon": [[0, 0, 0], [1, 1, 1], [2, 2, 2]]},
                                   {"polygon": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}])");
    EXPECT_EQ(s.dropped, 1u);
    ASSERT_EQ(s.faces.size(), 1u);
    EXPECT_EQ(s.faces[0].id, 1u);  // its index in the input, not moved by the drop
    EXPECT_EQ(s.face_count, 2u);
    EXPECT_NE(s.notes.at(0).find("objects[0]: face 0: dropped (zero area); id 0 unused"),
              std::string::npos)
        << s.notes[0];
}

TEST(SceneLoader, AppliesScaleThenRotateThenTranslate) {
    Scene s = parse_body(R"("objects": [{"polygon": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
        "transform": {"scale": 2, "rotate": {"axis": [0, 0, 1], "degrees": 90}, "translate": [10, 0, 0]}}])");
    const auto& v = s.faces.at(0).vertices.at(0);  // (1,0,0) -> (2,0,0) -> (0,2,0) -> (10,2,0)
    EXPECT_NEAR(v.x, 10, 1e-12);
    EXPECT_NEAR(v.y, 2, 1e-12);
}

TEST(SceneLoader, MirrorFacesSelectFacesOfAnObject) {
    Scene s = parse_body(R"("objects": [{"generator": "box", "min": [0, 0, 0], "max": [1, 1, 1],
        "material": {"mirror": 0.9, "mirror_faces": [2]}}])");
    for (const auto& f : s.faces)
        EXPECT_DOUBLE_EQ(f.material.mirror, f.id == 2 ? 0.9 : 0.0);
}

TEST(SceneLoader, IdealGeneratorBuildsRegisteredLayers) {
    Scene s = parse_scene_json(
        R"({"camera": {"projection": "screen"}, "image": {"width": 64, "height": 64},
        "objects": [{"generator": "ideal", "layers": 2, "faces_per_layer": 16}]})",
        "ideal.json", ".");
    ASSERT_EQ(s.faces.size(), 32u);
    // face 5: row 1, column 1 of 16-pixel cells: from (16.5, 16.5) to (32, 32)
    const auto& v = s.faces[5].vertices;
    EXPECT_DOUBLE_EQ(v[0].x, 16.5);
    EXPECT_DOUBLE_EQ(v[0].y, 16.5);
    EXPECT_DOUBLE_EQ(v[2].x, 32.0);
    EXPECT_DOUBLE_EQ(v[2].y, 32.0);
    EXPECT_LT(s.faces[5].vertices[0].z, s.faces[21].vertices[0].z);  // layer 0 is in front
}

struct BadCase {
    const char* json;
    const char* expected;  // a fragment the message must contain
};

class SceneLoaderErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneLoaderErrors, NameTheFieldAndWhatWasExpected) {
    std::string message = load_error_of(GetParam().json);
    EXPECT_NE(message.find(GetParam().expected), std::string::npos)
        << "message: " << message << "\nexpected to contain: " << GetParam().expected;
    EXPECT_EQ(message.rfind("bad.json", 0), 0u) << "message must start with the file: " << message;
}

INSTANTIATE_TEST_SUITE_P(
    Malformed, SceneLoaderErrors,
    ::testing::Values(
        BadCase{R"({"objects": []})", "camera: expected a camera object, but it is missing"},
        BadCase{
            R"({"camera": {"eye": [0, 0], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "objects": []})",
            "camera.eye: expected an array of 3 finite numbers"},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 0.5}, "objects": []})",
            "camera.far: expected a number greater than near"},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": "wide", "near": 1, "far": 2}, "objects": []})",
            "camera.fovy: expected a number, got \"wide\""},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "objects": [{"polygon": [[0, 0, 0], [1, 0, 0], [0, 1e999, 0]]}]})",
            "invalid JSON (number overflow parsing '1e999')"},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "objects": [{"polygon": [[0, 0, 0], [1, 0, 0]]}]})",
            "objects[0].polygon: expected a polygon of 3 or more vertices"},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "objects": [{"polygon": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": {"color": [2, 0, 0]}}]})",
            "objects[0].material.color: expected 3 numbers in [0, 1]"},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "objects": [{"polgon": []}]})",
            "objects[0]: expected an object with \"polygon\""},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "objects": [{"generator": "cone"}]})",
            "objects[0].generator: expected one of \"box\", \"quad\", \"ideal\", "
            "\"random_triangles\""},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "objects": [{"obj": "missing.obj"}]})",
            "missing.obj: cannot open the OBJ file"},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "image": {"width": 0}, "objects": []})",
            "image.width: expected an integer in [1, 16384]"},
        BadCase{
            R"({"camera": {"eye": [0, 0, 1], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 2}, "colour": [1, 1, 1], "objects": []})",
            "unknown field 'colour'"},
        BadCase{"{\n  \"camera\": {\n    \"eye\": [0, 0, 1],,\n", "line 3"},
        BadCase{
            R"({"camera": {"projection": "screen"}, "objects": [{"generator": "ideal", "layers": 1, "faces_per_layer": 15}]})",
            "objects[0].faces_per_layer: expected a perfect square"}));

TEST(SceneLoader, ReadsTriFiles) {
    Scene s = parse_tri("16 8 2\n0 1 1 0.5 5 1 0.5 1 5 0.5\n0 5 1 0.5 5 5 0.5 1 5 0.5\n", "t.tri");
    EXPECT_EQ(s.projection, Projection::Screen);
    EXPECT_EQ(s.width, 16);
    EXPECT_EQ(s.faces.size(), 2u);
    EXPECT_EQ(s.face_count, 1u);
}

TEST(SceneLoader, TriErrorsNameTheLine) {
    auto message = [](const char* text) {
        try {
            parse_tri(text, "t.tri");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message("16 8 2\n0 1 1 0.5 5 1 0.5 1 5 0.5\n")
                  .find("t.tri: line 2: expected 2 triangles, found 1"),
              std::string::npos);
    EXPECT_NE(message("16 8 1\n0 1 1 0.5 5 x 0.5 1 5 0.5\n")
                  .find("t.tri: line 2: y is not a valid number: 'x'"),
              std::string::npos);
    EXPECT_NE(
        message("16 8 1\n0 1 1 0.5 5 1 nan 1 5 0.5\n").find("line 2: a vertex coordinate is NaN"),
        std::string::npos);
}

TEST(SceneLoader, LoadsObjMeshesRelativeToTheSceneFile) {
    auto dir = fb89::testing::scratch_path("obj_test");
    std::filesystem::create_directories(dir / "meshes");
    std::ofstream(dir / "meshes" / "quad.obj")
        << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 1 2 9\n";
    std::ofstream(dir / "ok.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    std::ofstream(dir / "scene.json")
        << "{" << kLoaderCamera << R"(, "objects": [{"obj": "ok.obj"}]})";
    Scene s = load_scene(dir / "scene.json");
    ASSERT_EQ(s.faces.size(), 1u);
    EXPECT_EQ(s.faces[0].vertices.size(), 4u);  // kept whole, not triangulated
    std::ofstream(dir / "bad.json")
        << "{" << kLoaderCamera << R"(, "objects": [{"obj": "meshes/quad.obj"}]})";
    try {
        load_scene(dir / "bad.json");
        FAIL() << "an OBJ face referring to a missing vertex must be an error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("quad.obj"), std::string::npos) << e.what();
    }
}

TEST(SceneLoader, MissingFileIsAnError) {
    EXPECT_THROW(load_scene("/nonexistent/scene.json"), SceneError);
}

}  // namespace
}  // namespace fb89::host
