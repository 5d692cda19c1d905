// A bare OBJ model given where a scene is expected (`fb89 render model.obj`), as a user
// would: it renders framed by the automatic camera and says so; garbage, other text and
// empty models end with exit 2 naming the file; a missing material library is a warning
// naming it; a bad vertex index names its line (scenes/README.md, "A bare OBJ model").
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <glm/geometric.hpp>

#include "controller_sim/png_io.h"
#include "host/scene/scene_loader.h"
#include "tests/cli/bad_input.h"

namespace {

namespace fs = std::filesystem;

using fb89::testing::CliRun;
using fb89::testing::bad_input::expect_refused;
using fb89::testing::bad_input::run_with_timeout;
using fb89::testing::bad_input::scratch;
using fb89::testing::bad_input::write_file;

const std::string kIcosahedron = std::string(FB89_SCENES_DIR) + "/models/icosahedron.obj";

// The faces of a convex model about its look-at point that turn towards the eye: whose
// outward normal (away from that point, whatever the winding) points to the eye side.
std::set<uint32_t> front_faces(const fb89::host::Scene& s) {
    std::set<uint32_t> front;
    for (const auto& f : s.faces) {
        const auto& v = f.vertices;
        glm::dvec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
        if (glm::dot(normal, v[0] - s.camera.look_at) < 0) normal = -normal;
        if (glm::dot(normal, s.camera.eye - v[0]) > 0) front.insert(f.id);
    }
    return front;
}

TEST(ObjScene, ABareObjModelRendersFramedAutomaticallyWithEveryFrontFaceVisible) {
    const std::string ids = scratch("ico_ids.png"), png = scratch("ico.png");
    CliRun r = run_with_timeout("render " + kIcosahedron + " --ids " + ids + " --png " + png);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(": 20 faces (20 pieces on screen), 1024x780"), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("icosahedron.obj: a bare OBJ model: camera framed automatically (eye ("),
              std::string::npos)
        << r.err;
    const auto image = fb89::controller::read_png(ids);
    ASSERT_EQ(image.width, 1024u);
    ASSERT_EQ(image.height, 780u);
    std::map<uint32_t, size_t> pixels;  // of each id seen
    for (size_t p = 0; p < image.pixels.size() / 3; ++p) {
        const uint32_t id_plus_1 = uint32_t(image.pixels[3 * p]) << 16 |
                                   uint32_t(image.pixels[3 * p + 1]) << 8 | image.pixels[3 * p + 2];
        if (id_plus_1) ++pixels[id_plus_1 - 1];
        // the model stays clear of the borders: the framing holds all of it
        const size_t x = p % image.width, y = p / image.width;
        if (x == 0 || y == 0 || x + 1 == image.width || y + 1 == image.height) {
            EXPECT_EQ(id_plus_1, 0u) << "a face reaches the border at " << x << ", " << y;
        }
    }
    // every face that turns towards the camera shows (the grazing ones as slivers of some
    // 4,000 pixels); a face turned away may win a pixel or so of a silhouette edge it shares
    // with one that turns towards it, where their depths tie, and no more
    const std::set<uint32_t> front = front_faces(fb89::host::load_scene(kIcosahedron));
    EXPECT_GE(front.size(), 8u);
    for (uint32_t id = 0; id < 20; ++id)
        if (front.count(id))
            EXPECT_GE(pixels[id], 1000u) << "face " << id << " turns towards the camera";
        else
            EXPECT_LE(pixels[id], 16u) << "face " << id << " turns away";
}

TEST(ObjScene, GarbagePlainTextAndEmptyModelsAreRefusedNamingTheFile) {
    std::string bytes;
    uint32_t x = 1;
    for (int i = 0; i < 2000; ++i) {
        x = x * 1103515245u + 12345u;
        bytes += static_cast<char>(x >> 16);
    }
    expect_refused(run_with_timeout("render " + write_file("noise.obj", bytes)), "noise.obj",
                   {"line ", "not text"});
    expect_refused(run_with_timeout("render " + write_file("notes.obj", "shopping list\neggs\n")),
                   "notes.obj", {"no faces", "line 1, 'shopping list', is not an OBJ statement"});
    expect_refused(run_with_timeout("render " + write_file("empty.obj", "")), "empty.obj",
                   {"no faces", "the file is empty"});
    expect_refused(
        run_with_timeout("render " + write_file("cloud.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")),
        "cloud.obj", {"no faces", "read 3 vertices, 0 faces from 3 lines"});
}

TEST(ObjScene, AMissingMaterialLibraryIsAWarningNamingItAndTheModelRenders) {
    const std::string obj = write_file(
        "grey.obj", "mtllib grey.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl stone\nf 1 2 3\n");
    CliRun r = run_with_timeout("render " + obj);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("grey.obj: line 1: material library 'grey.mtl' not found"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("faces are grey"), std::string::npos) << r.err;
}

TEST(ObjScene, ABadVertexIndexNamesItsLine) {
    const std::string obj = write_file("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 7\n");
    expect_refused(run_with_timeout("render " + obj), "bad.obj",
                   {"line 5: face refers to vertex 7 of 3"});
    const std::string zero = write_file("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    expect_refused(run_with_timeout("render " + zero), "zero.obj",
                   {"line 4: face vertex 1: index 0"});
}

TEST(ObjScene, CompareTakesABareObjModelToo) {
    const std::string sheet = scratch("sheet.png");
    CliRun r = run_with_timeout("compare " + kIcosahedron +
                                " --size 128x98 --repeat 1 -q --sheet " + sheet);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_TRUE(fs::exists(sheet));
}

}  // namespace
