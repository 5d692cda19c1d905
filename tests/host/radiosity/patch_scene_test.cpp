// A radiosity solution as a scene: one face per patch, coloured by its radiosity, drawn
// unshaded by the raster pipeline.
#include "host/radiosity/patch_scene.h"

#include <gtest/gtest.h>

#include "host/raster/screen_setup.h"

namespace fb89::host {
namespace {

// A floor of 2 x 2 m in 4 x 4 patches and a small emitting panel above it.
Scene world() {
    Scene s;
    s.camera.eye = {1, 3, 4};
    s.camera.look_at = {1, 0, 1};
    s.width = 320;
    s.height = 240;
    s.background = {0.1, 0.2, 0.3};
    s.light.ambient = 0.2;
    Face floor;
    floor.vertices = {{0, 0, 0}, {0, 0, 2}, {2, 0, 2}, {2, 0, 0}};
    floor.material.color = {0.5, 0.5, 0.5};
    Face lamp;
    lamp.vertices = {{0.5, 1, 0.5}, {1, 1, 0.5}, {1, 1, 1}, {0.5, 1, 1}};
    lamp.material.emission = {4, 4, 4};
    lamp.id = 1;
    s.faces = {floor, lamp};
    s.face_count = 2;
    return s;
}

Mesh patch_mesh_of(const Scene& s) {
    MeshOptions o;
    o.patch_size = 0.5;
    return mesh_scene(s, o);
}

TEST(PatchScene, OneFacePerPatchWithTheWorldsCameraAndSize) {
    Scene w = world();
    Mesh m = patch_mesh_of(w);
    ASSERT_EQ(m.patches.size(), 17u);
    std::vector<glm::dvec3> B(m.patches.size(), glm::dvec3(0.25));
    Scene s = patch_scene(w, m, B);
    EXPECT_EQ(s.faces.size(), m.patches.size());
    EXPECT_EQ(s.face_count, m.patches.size());
    EXPECT_EQ(s.width, 320);
    EXPECT_EQ(s.height, 240);
    EXPECT_EQ(s.camera.eye, w.camera.eye);
    EXPECT_EQ(s.background, w.background);
    EXPECT_EQ(s.light.ambient, 1.0);
    for (size_t k = 0; k < s.faces.size(); ++k) {
        EXPECT_EQ(s.faces[k].id, k);
        EXPECT_EQ(s.faces[k].vertices.size(), 4u);
        EXPECT_EQ(s.faces[k].material.emission, glm::dvec3(0));
    }
}

TEST(PatchScene, BrightestLitLevelMapsToOne) {
    Scene w = world();
    Mesh m = patch_mesh_of(w);
    std::vector<glm::dvec3> B;
    for (size_t p = 0; p < m.patches.size(); ++p)
        B.push_back(m.elements[m.patches[p].element].emission.x > 0
                        ? glm::dvec3(4)
                        : glm::dvec3(0.1 * static_cast<double>(p + 1), 0.05, 0.0));
    EXPECT_NEAR(automatic_exposure(m, B), 1.0 / 1.6, 1e-12);
    Scene s = patch_scene(w, m, B);
    EXPECT_NEAR(s.faces[15].material.color.r, 1.0, 1e-12);  // the brightest floor patch
    EXPECT_NEAR(s.faces[0].material.color.r, 0.1 / 1.6, 1e-12);
    EXPECT_NEAR(s.faces[0].material.color.g, 0.05 / 1.6, 1e-12);
    EXPECT_EQ(s.faces[16].material.color, glm::dvec3(1));  // the lamp clips to white

    Scene fixed = patch_scene(w, m, B, 0.5);  // an exposure given
    EXPECT_NEAR(fixed.faces[0].material.color.r, 0.05, 1e-12);
}

// The brightest 1% of the lit area clips: a small hot patch does not darken the room.
TEST(PatchScene, SmallHotSpotDoesNotSetTheExposure) {
    Scene w = world();
    Face spot;  // 0.1 x 0.1 m, a quarter of 1% of the lit area
    spot.vertices = {{1.5, 0.5, 1.5}, {1.6, 0.5, 1.5}, {1.6, 0.5, 1.6}, {1.5, 0.5, 1.6}};
    spot.id = 2;
    w.faces.push_back(spot);
    Mesh m = patch_mesh_of(w);
    ASSERT_EQ(m.patches.size(), 18u);
    std::vector<glm::dvec3> B(m.patches.size(), glm::dvec3(0.5));
    B[16] = glm::dvec3(4);   // the lamp
    B[17] = glm::dvec3(50);  // the spot
    EXPECT_NEAR(automatic_exposure(m, B), 2.0, 1e-12);
    Scene s = patch_scene(w, m, B);
    EXPECT_NEAR(s.faces[0].material.color.r, 1.0, 1e-12);
    EXPECT_EQ(s.faces[17].material.color, glm::dvec3(1));
}

TEST(PatchScene, ProjectsUnshaded) {
    Scene w = world();
    Mesh m = patch_mesh_of(w);
    std::vector<glm::dvec3> B(m.patches.size(), glm::dvec3(0.2, 0.4, 0.8));
    Scene s = patch_scene(w, m, B, 1.0);
    Counters counters;
    ScreenScene screen = project_scene(s, ColorMode::Shaded, counters);
    ASSERT_FALSE(screen.faces.empty());
    for (const auto& f : screen.faces) {
        EXPECT_EQ(f.color.r, 51);
        EXPECT_EQ(f.color.g, 102);
        EXPECT_EQ(f.color.b, 204);
    }
}

TEST(PatchScene, BlackSolutionStaysBlack) {
    Scene w = world();
    Mesh m = patch_mesh_of(w);
    std::vector<glm::dvec3> B(m.patches.size(), glm::dvec3(0));
    EXPECT_EQ(automatic_exposure(m, B), 1.0);
    Scene s = patch_scene(w, m, B);
    for (const Face& f : s.faces)
        EXPECT_EQ(f.material.color, glm::dvec3(0));
}

}  // namespace
// A coarse square beside two squares half its height: the finer pair's shared corner lies
// inside the coarse square's edge, where the raster pipeline would round it apart.
TEST(PatchScene, TJunctionCornersAreAddedToTheCoarseEdge) {
    Face coarse, low, high;
    coarse.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    low.vertices = {{1, 0, 0}, {2, 0, 0}, {2, 0.5, 0}, {1, 0.5, 0}};
    high.vertices = {{1, 0.5, 0}, {2, 0.5, 0}, {2, 1, 0}, {1, 1, 0}};
    std::vector<Face> faces{coarse, low, high};
    close_t_junctions(faces);
    ASSERT_EQ(faces[0].vertices.size(), 5u);
    EXPECT_EQ(faces[0].vertices[2], glm::dvec3(1, 0.5, 0));  // between (1,0,0) and (1,1,0)
    EXPECT_EQ(faces[0].vertices[3], glm::dvec3(1, 1, 0));
    EXPECT_EQ(faces[1].vertices.size(), 4u);  // the finer ones have no corner inside an edge
    EXPECT_EQ(faces[2].vertices.size(), 4u);
}

TEST(PatchScene, FacesMeetingCornerToCornerAreLeftAsTheyAre) {
    Scene w = world();
    Mesh m = patch_mesh_of(w);
    std::vector<glm::dvec3> B(m.patches.size(), glm::dvec3(0.25));
    for (const Face& f : patch_scene(w, m, B).faces)
        EXPECT_EQ(f.vertices.size(), 4u);
}

}  // namespace fb89::host
