// Meshing faces into patches, and adaptive refinement where radiosity changes fast.
#include "host/radiosity/mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include <glm/geometric.hpp>

#include "host/radiosity/visibility.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

Scene one_face(std::vector<glm::dvec3> v) {
    Scene s;
    Face f;
    f.vertices = std::move(v);
    f.material.color = {0.5, 0.6, 0.7};
    f.id = 7;
    s.faces.push_back(f);
    return s;
}

// The unit square in z = 0 as 4 x 4 patches; patch (i, j) is index j * 4 + i.
Mesh unit_square_4x4() {
    MeshOptions o;
    o.patch_size = 0.25;
    return mesh_scene(one_face({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}), o);
}

double total_area(const Mesh& m) {
    double a = 0;
    for (const Patch& p : m.patches)
        a += p.area;
    return a;
}

TEST(Mesh, SquareIsAGridOfEqualPatches) {
    Mesh m = unit_square_4x4();
    ASSERT_EQ(m.elements.size(), 1u);
    ASSERT_EQ(m.patches.size(), 16u);
    EXPECT_NEAR(total_area(m), 1.0, 1e-12);
    EXPECT_NEAR(m.patches[5].centre.x, 0.375, 1e-12);
    EXPECT_NEAR(m.patches[5].centre.y, 0.375, 1e-12);
}

TEST(Mesh, PatchSizeForHitsTheTarget) {
    Scene s = one_face({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}});
    MeshOptions o;
    o.patch_size = patch_size_for(s, 100);
    EXPECT_EQ(mesh_scene(s, o).patches.size(), 100u);
}

TEST(Mesh, UniformRadiosityIsNotRefined) {
    Mesh m = unit_square_4x4();
    std::vector<glm::dvec3> B(m.patches.size(), glm::dvec3(0.4, 0.2, 0.1));
    const std::vector<bool> split = patches_to_split(m, B, 0.05);
    EXPECT_EQ(std::count(split.begin(), split.end(), true), 0);
    Mesh r = refine(m, B, 0.05);
    ASSERT_EQ(r.patches.size(), m.patches.size());
    ASSERT_EQ(r.elements.size(), 1u);
    for (size_t p = 0; p < m.patches.size(); ++p)
        EXPECT_EQ(r.patches[p].centre, m.patches[p].centre);
}

TEST(Mesh, GentleGradientBelowTheThresholdIsNotRefined) {
    Mesh m = unit_square_4x4();
    std::vector<glm::dvec3> B;
    for (const Patch& p : m.patches)
        B.push_back(glm::dvec3(1.0 - 0.04 * p.i));  // 4% steps
    EXPECT_EQ(refine(m, B, 0.05).patches.size(), 16u);
    EXPECT_GT(refine(m, B, 0.03).patches.size(), 16u);
}

// A shadow edge between columns 1 and 2: those two columns split, the others stay.
TEST(Mesh, SharpChangeIsRefinedThereOnly) {
    Mesh m = unit_square_4x4();
    std::vector<glm::dvec3> B;
    for (const Patch& p : m.patches)
        B.push_back(p.i < 2 ? glm::dvec3(1.0) : glm::dvec3(0.1));
    std::vector<bool> split = patches_to_split(m, B, 0.2);
    for (const Patch& p : m.patches)
        EXPECT_EQ(split[p.j * 4 + p.i], p.i == 1 || p.i == 2) << p.i << "," << p.j;

    Mesh r = refine(m, B, 0.2);
    EXPECT_EQ(r.patches.size(), 8u + 8u * 4u);
    EXPECT_NEAR(total_area(r), 1.0, 1e-12);
    int small = 0, kept = 0;
    for (const Patch& p : r.patches) {
        if (std::abs(p.area - 1.0 / 64) < 1e-12) {
            ++small;
            EXPECT_GT(p.centre.x, 0.25);
            EXPECT_LT(p.centre.x, 0.75);
        } else {
            EXPECT_NEAR(p.area, 1.0 / 16, 1e-12);
            ++kept;
        }
    }
    EXPECT_EQ(small, 32);
    EXPECT_EQ(kept, 8);
    // every sub-element carries its face and material
    for (const Element& e : r.elements) {
        EXPECT_EQ(e.face_id, 7u);
        EXPECT_EQ(e.piece, 0u);
        EXPECT_EQ(e.reflectance, glm::dvec3(0.5, 0.6, 0.7));
        EXPECT_NEAR(e.normal.z, 1.0, 1e-12);
    }
    // patches index their elements consistently
    for (size_t k = 0; k < r.patches.size(); ++k) {
        const Patch& p = r.patches[k];
        EXPECT_EQ(r.elements[p.element].patch(p.i, p.j), k);
    }
}

TEST(Mesh, MinimumPatchSizeStopsRefinement) {
    Mesh m = unit_square_4x4();
    std::vector<glm::dvec3> B;
    for (const Patch& p : m.patches)
        B.push_back(p.i < 2 ? glm::dvec3(1.0) : glm::dvec3(0.1));
    EXPECT_EQ(refine(m, B, 0.2, 0.3).patches.size(), 16u);
    EXPECT_EQ(refine(m, B, 0.2, 0.2).patches.size(), 40u);
}

TEST(Mesh, DarkPatchesAreNotRefined) {
    Mesh m = unit_square_4x4();
    std::vector<glm::dvec3> B;
    for (const Patch& p : m.patches)  // relative jumps, but all far below the brightest
        B.push_back(glm::dvec3(p.i == 0 && p.j == 0 ? 1.0 : (p.i % 2 ? 1e-6 : 1e-5)));
    std::vector<bool> split = patches_to_split(m, B, 0.5);
    EXPECT_TRUE(split[0]);    // beside the bright corner
    EXPECT_FALSE(split[15]);  // a dark jump
}

TEST(Mesh, RefinedTriangleKeepsItsApexAndArea) {
    MeshOptions o;
    o.patch_size = 0.25;
    Mesh m = mesh_scene(one_face({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}}), o);
    ASSERT_EQ(m.elements.size(), 1u);
    std::vector<glm::dvec3> B;
    for (const Patch& p : m.patches)
        B.push_back(glm::dvec3(p.j >= m.elements[0].nv - 1 ? 1.0 : 0.2));  // the apex row bright
    Mesh r = refine(m, B, 0.2);
    EXPECT_GT(r.patches.size(), m.patches.size());
    EXPECT_NEAR(total_area(r), total_area(m), 1e-12);
    int triangles = 0;
    for (const Patch& p : r.patches)
        if (p.corner_count == 3) {
            ++triangles;
            EXPECT_EQ(p.corners[2], glm::dvec3(0.5, 1, 0));
        }
    EXPECT_GT(triangles, 0);
}

TEST(Mesh, RepeatedRefinementGoesFiner) {
    Mesh m = unit_square_4x4();
    auto step = [](const Mesh& mesh) {
        std::vector<glm::dvec3> B;
        for (const Patch& p : mesh.patches)
            B.push_back(p.centre.x < 0.5 ? glm::dvec3(1.0) : glm::dvec3(0.1));
        return B;
    };
    Mesh once = refine(m, step(m), 0.2);
    Mesh twice = refine(once, step(once), 0.2);
    EXPECT_GT(twice.patches.size(), once.patches.size());
    EXPECT_NEAR(total_area(twice), 1.0, 1e-12);
}

// The radiosity scenes (scenes/README.md): the paper's patch counts at the documented
// --patches, room walls wound to face into the room, and no element that faces nothing
// (a face wound the wrong way round would).
struct RadiosityScene {
    std::string file;
    uint32_t faces;
    int patches_flag;
    size_t patches;
    uint32_t walls;  // the first faces, which bound the room
};

TEST(Mesh, RadiosityScenesMeshToThePapersCountsAndFaceIntoTheRoom) {
    for (const RadiosityScene& rs : {RadiosityScene{"garish_room.json", 29, 820, 786, 17},
                                     RadiosityScene{"programmers_cell.json", 324, 1070, 1344, 6},
                                     RadiosityScene{"cornell_box.json", 16, 800, 980, 6},
                                     RadiosityScene{"exhibition_hall.json", 111, 4700, 4475, 50}}) {
        Scene s = load_scene(std::filesystem::path(FB89_SCENES_DIR) / rs.file);
        EXPECT_EQ(s.face_count, rs.faces) << rs.file;
        MeshOptions o;
        o.patch_size = patch_size_for(s, rs.patches_flag);
        Mesh m = mesh_scene(s, o);
        EXPECT_EQ(m.patches.size(), rs.patches) << rs.file;

        glm::dvec3 lo(INFINITY), hi(-INFINITY);
        for (const Face& f : s.faces)
            for (const glm::dvec3& v : f.vertices) {
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
        const glm::dvec3 centre = 0.5 * (lo + hi);
        std::vector<bool> faces_something(m.elements.size(), false);
        for (uint32_t p = 0; p < m.patches.size(); ++p)
            for (uint32_t q = p + 1; q < m.patches.size(); ++q)
                if (facing(m, p, q))
                    faces_something[m.patches[p].element] = faces_something[m.patches[q].element] =
                        true;
        for (size_t k = 0; k < m.elements.size(); ++k) {
            const Element& e = m.elements[k];
            EXPECT_TRUE(faces_something[k]) << rs.file << ": face " << e.face_id;
            if (e.face_id < rs.walls) {
                EXPECT_GT(glm::dot(e.normal, centre - e.corners[0]), 0)
                    << rs.file << ": wall " << e.face_id << " faces out of the room";
            }
        }
    }
}

}  // namespace
}  // namespace fb89::host
