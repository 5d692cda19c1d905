// The scene model: no more than a scene needs (DESIGN.md "Scene model").
//
// A camera, an image size, a background, one directional light plus ambient, and faces.
// A face is a planar convex polygon with a colour, an optional mirror reflectance and an
// optional emission. A face's id is its index in the input (objects in file order, faces in
// each object's order, from 0): the pieces of a polygon that had to be triangulated on load
// keep its id, so several Face entries may share an id, and a face dropped on load (zero
// area) leaves its id unused, so no later face's id moves (docs/PROTOCOL.md, "Face ids").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace fb89::host {

// How scene coordinates reach the screen.
enum class Projection {
    Perspective,  // world space, seen by the camera (gluLookAt + gluPerspective)
    Screen,       // already in screen space: x right, y down in pixels, z in [0,1] (nearer smaller)
};

struct Camera {
    glm::dvec3 eye{0, 0, 5};
    glm::dvec3 look_at{0, 0, 0};
    glm::dvec3 up{0, 1, 0};
    double fovy_degrees = 45;
    double near = 0.1;
    double far = 100;
};

struct Light {
    glm::dvec3 direction{0, 0, -1};  // the way the light travels, from the light into the scene
    double ambient = 0.2;
};

struct Material {
    glm::dvec3 color{0.8, 0.8, 0.8};
    double mirror = 0;  // specular reflectance in [0,1]
    glm::dvec3 emission{0, 0, 0};
};

struct Face {
    std::vector<glm::dvec3> vertices;  // planar, convex, 3 or more
    Material material;
    uint32_t id = 0;
    uint32_t object = 0;  // index of the scene-file object it came from
};

struct Scene {
    std::string source;  // file it was loaded from, for messages
    Projection projection = Projection::Perspective;
    Camera camera;
    int width = 1024;
    int height = 780;
    glm::dvec3 background{0, 0, 0};
    Light light;
    std::vector<Face> faces;
    // faces in the input, dropped ones included: every id is below it (for a .tri file,
    // whose ids are given, the distinct ids)
    uint32_t face_count = 0;

    // What loading changed and why: triangulated polygons, dropped degenerate faces.
    std::vector<std::string> notes;
    uint32_t triangulated = 0;
    uint32_t dropped = 0;
};

}  // namespace fb89::host
