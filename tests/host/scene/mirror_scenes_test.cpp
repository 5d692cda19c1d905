// The mirror scenes for the beam-ray tracing experiment (§4; scenes/README.md): the face
// counts of the paper's images G, H and I, mirrors where the experiment needs them, and
// faces that load as written (planar convex, nothing triangulated or dropped) and lie in
// front of the camera.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "host/scene/polygon.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

Scene load(const std::string& name) {
    return load_scene(std::filesystem::path(FB89_SCENES_DIR) / (name + ".json"));
}

size_t mirror_faces(const Scene& s) {
    return static_cast<size_t>(std::count_if(s.faces.begin(), s.faces.end(),
                                             [](const Face& f) { return f.material.mirror > 0; }));
}

// Vertices at or behind the near plane, which the camera would clip.
size_t vertices_not_in_front(const Scene& s) {
    glm::dvec3 forward = glm::normalize(s.camera.look_at - s.camera.eye);
    size_t bad = 0;
    for (const Face& f : s.faces)
        for (const auto& v : f.vertices)
            bad += glm::dot(v - s.camera.eye, forward) <= s.camera.near;
    return bad;
}

void expect_perspective_1024x780(const Scene& s) {
    EXPECT_EQ(s.projection, Projection::Perspective);
    EXPECT_EQ(s.width, 1024);
    EXPECT_EQ(s.height, 780);
    EXPECT_EQ(vertices_not_in_front(s), 0u);
}

TEST(MirrorScenes, GIsConcentricCubesWith18FacesAndALargeMirror) {
    Scene s = load("G");
    expect_perspective_1024x780(s);
    EXPECT_EQ(s.face_count, 18u);
    EXPECT_EQ(s.triangulated, 0u);
    EXPECT_EQ(s.dropped, 0u);
    ASSERT_GE(mirror_faces(s), 1u);
    double largest = 0;  // the mirror is large: a few square metres
    for (const Face& f : s.faces)
        if (f.material.mirror > 0)
            largest = std::max(largest, 0.5 * glm::length(newell_normal(f.vertices)));
    EXPECT_GT(largest, 4.0);
}

TEST(MirrorScenes, HIsTwoGobletsWithAbout950FacesAndAMirror) {
    Scene s = load("H");
    expect_perspective_1024x780(s);
    EXPECT_GE(s.face_count, 900u);
    EXPECT_LE(s.face_count, 1000u);
    EXPECT_EQ(s.triangulated, 0u);
    EXPECT_EQ(s.dropped, 0u);
    EXPECT_GE(mirror_faces(s), 1u);
}

TEST(MirrorScenes, IIsASeaShellWithAbout2000FacesAndTwoMirrors) {
    Scene s = load("I");
    expect_perspective_1024x780(s);
    EXPECT_GE(s.face_count, 1800u);
    EXPECT_LE(s.face_count, 2200u);
    EXPECT_EQ(s.triangulated, 0u);
    EXPECT_EQ(s.dropped, 0u);
    EXPECT_GE(mirror_faces(s), 2u);
}

TEST(MirrorScenes, IHasMirrorsFacingEachOther) {
    // a mirror seen in a mirror: some vertex of each mirror lies in front of the other
    Scene s = load("I");
    std::vector<const Face*> mirrors;
    for (const Face& f : s.faces)
        if (f.material.mirror > 0) mirrors.push_back(&f);
    ASSERT_GE(mirrors.size(), 2u);
    auto in_front = [](const Face& mirror, const Face& other, const glm::dvec3& eye) {
        glm::dvec3 n = newell_normal(mirror.vertices);
        if (glm::dot(n, eye - mirror.vertices[0]) < 0) n = -n;  // the side the camera sees
        for (const auto& v : other.vertices)
            if (glm::dot(n, v - mirror.vertices[0]) > 1e-6) return true;
        return false;
    };
    bool facing = false;
    for (const Face* a : mirrors)
        for (const Face* b : mirrors)
            facing = facing ||
                     (a != b && in_front(*a, *b, s.camera.eye) && in_front(*b, *a, s.camera.eye));
    EXPECT_TRUE(facing);
}

TEST(MirrorScenes, CornellMirrorIsTheCornellBoxWithAMirrorWall) {
    Scene box = load("cornell_box"), s = load("cornell_mirror");
    expect_perspective_1024x780(s);
    EXPECT_EQ(s.face_count, box.face_count);
    EXPECT_EQ(mirror_faces(box), 0u);
    ASSERT_EQ(mirror_faces(s), 1u);
    // the data's red wall (not quite planar) is the only polygon triangulated, as in
    // cornell_box.json; the mirror is a whole planar face
    EXPECT_EQ(s.triangulated, 1u);
    EXPECT_EQ(box.triangulated, 1u);
    EXPECT_EQ(s.dropped, 0u);
    for (size_t i = 0; i < s.faces.size(); ++i) {
        EXPECT_EQ(s.faces[i].vertices, box.faces[i].vertices) << "face " << i;
        if (s.faces[i].material.mirror > 0) {
            EXPECT_NEAR(s.faces[i].material.mirror, 0.9, 1e-12);
        }
    }
}

}  // namespace
}  // namespace fb89::host
