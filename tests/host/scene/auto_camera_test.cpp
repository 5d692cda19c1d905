// The automatic camera of a bare OBJ model: every vertex of the model projects inside the
// image with a margin and between near and far, whatever the model's shape and the image's
// proportions; the light comes from the camera's side; the scene's notes say so.
#include "host/scene/auto_camera.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "host/scene/scene_loader.h"
#include "tests/scratch.h"

namespace fb89::host {
namespace {

namespace fs = std::filesystem;

// Projects every vertex as the camera does (gluLookAt + gluPerspective) and checks that it
// lies inside the image, `margin` pixels or more from its borders, and inside (0, 1) in depth.
void expect_every_vertex_on_screen(const Scene& s, double margin) {
    const Camera& c = s.camera;
    const glm::dmat4 m =
        glm::perspective(glm::radians(c.fovy_degrees), double(s.width) / s.height, c.near, c.far) *
        glm::lookAt(c.eye, c.look_at, c.up);
    ASSERT_GT(c.near, 0);
    for (const Face& f : s.faces)
        for (const glm::dvec3& v : f.vertices) {
            const glm::dvec4 clip = m * glm::dvec4(v, 1.0);
            ASSERT_GT(clip.w, 0);
            const double x = (clip.x / clip.w + 1) / 2 * s.width;
            const double y = (1 - clip.y / clip.w) / 2 * s.height;
            const double z = (clip.z / clip.w + 1) / 2;
            EXPECT_GE(x, margin);
            EXPECT_LE(x, s.width - margin);
            EXPECT_GE(y, margin);
            EXPECT_LE(y, s.height - margin);
            EXPECT_GT(z, 0);
            EXPECT_LT(z, 1);
        }
}

fs::path write_scratch(const std::string& name, const std::string& text) {
    const fs::path dir = fb89::testing::scratch_path("auto_camera");
    fs::create_directories(dir);
    std::ofstream(dir / name) << text;
    return dir / name;
}

TEST(AutoCamera, TheBundledIcosahedronLoadsFramedWithEveryVertexOnScreen) {
    const fs::path file = fs::path(FB89_SCENES_DIR) / "models" / "icosahedron.obj";
    const Scene s = load_scene(file);
    EXPECT_EQ(s.faces.size(), 20u);
    EXPECT_EQ(s.face_count, 20u);
    EXPECT_EQ(s.width, 1024);
    EXPECT_EQ(s.height, 780);
    EXPECT_DOUBLE_EQ(s.camera.fovy_degrees, 45);
    EXPECT_NEAR(glm::length(s.camera.look_at), 0, 1e-6);  // the model's centre
    EXPECT_DOUBLE_EQ(s.light.ambient, 0.3);
    // the light travels away from the camera's side, onto the faces the camera sees
    EXPECT_LT(glm::dot(s.light.direction, s.camera.eye - s.camera.look_at), 0);
    EXPECT_NEAR(s.faces[0].material.color.r, 0.85, 1e-6) << "colours from its .mtl";
    EXPECT_NEAR(s.faces[0].material.color.b, 0.18, 1e-6);
    ASSERT_FALSE(s.notes.empty());
    const std::string& note = s.notes.back();
    EXPECT_EQ(
        note.rfind(file.string() + ": a bare OBJ model: camera framed automatically (eye (", 0), 0u)
        << note;
    EXPECT_NE(note.find("fovy 45, near "), std::string::npos) << note;
    EXPECT_NE(note.find("), light from ("), std::string::npos) << note;
    // the bounding sphere fills 1 / 1.1 of the half-height: 780 / 2 * (1 - 1 / 1.1) > 35 px
    expect_every_vertex_on_screen(s, 30);
}

TEST(AutoCamera, LongFlatAndOffCentreModelsFitTallAndWideImages) {
    const fs::path rod = write_scratch("rod.obj",
                                       "v 100 5 5\nv 140 5 5\nv 140 6 5\nv 100 6 5\nf 1 2 3 4\n"
                                       "v 100 5 -2\nv 100 6 -2\nv 100 6 5\nv 100 5 5\nf 5 6 7 8\n");
    for (const auto& [w, h] : {std::pair{1024, 780}, std::pair{100, 900}, std::pair{900, 50}}) {
        SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
        Scene s = load_scene(rod);
        s.width = w, s.height = h;
        frame_automatically(s);
        expect_every_vertex_on_screen(s, 1);
        EXPECT_NEAR(s.camera.look_at.x, 120, 1e-9);
    }
}

}  // namespace
}  // namespace fb89::host
