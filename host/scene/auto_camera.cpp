// The automatic camera of a bare OBJ model: the bounding sphere of the faces' vertices
// (about their bounding box's centre) fitted in the view cone, the standard way to frame a
// model (gluLookAt + gluPerspective, as host/scene/projection.h projects every scene).
#include "host/scene/auto_camera.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace fb89::host {

namespace {

constexpr double kFovy = 45;
constexpr double kAmbient = 0.3;
const glm::dvec3 kDiagonal{1, 1, 1};  // from the centre towards the eye
const glm::dvec3 kBackground{0.12, 0.14, 0.18};

std::string point(const glm::dvec3& p) {
    return fmt::format("({:.4g}, {:.4g}, {:.4g})", p.x, p.y, p.z);
}

}  // namespace

std::string frame_automatically(Scene& scene) {
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (const Face& f : scene.faces)
        for (const glm::dvec3& v : f.vertices)
            lo = glm::min(lo, v), hi = glm::max(hi, v);
    const glm::dvec3 centre = (lo + hi) * 0.5;
    double radius = 0;
    for (const Face& f : scene.faces)
        for (const glm::dvec3& v : f.vertices)
            radius = std::max(radius, glm::length(v - centre));

    // the view cone's half-angle: the vertical one, or the horizontal one if the image is
    // taller than wide
    const double half_fovy = glm::radians(kFovy / 2);
    const double aspect = double(scene.width) / double(scene.height);
    const double half_angle = std::min(half_fovy, std::atan(std::tan(half_fovy) * aspect));
    const double distance = radius / std::sin(half_angle) * kFrameMargin;

    Camera& c = scene.camera;
    c.look_at = centre;
    c.eye = centre + glm::normalize(kDiagonal) * distance;
    c.up = {0, 1, 0};
    c.fovy_degrees = kFovy;
    // distance >= 2.87 radius, so near >= 1.8 radius > 0
    c.near = distance - 1.05 * radius;
    c.far = distance + 1.05 * radius;

    // from over the camera's left shoulder: behind it, up and to the left
    const glm::dvec3 back = glm::normalize(c.eye - c.look_at);
    const glm::dvec3 right = glm::normalize(glm::cross(-back, c.up));
    const glm::dvec3 up = glm::cross(right, -back);
    const glm::dvec3 from = glm::normalize(back + 0.6 * up - 0.4 * right);
    scene.light.direction = -from;
    scene.light.ambient = kAmbient;
    scene.background = kBackground;

    return fmt::format(
        "a bare OBJ model: camera framed automatically (eye {}, look at {}, fovy "
        "{:g}, near {:.4g}, far {:.4g}), light from {}, ambient {:g}; to choose "
        "them, write a JSON scene with an \"obj\" object (scenes/README.md, \"A bare "
        "OBJ model\")",
        point(c.eye), point(c.look_at), kFovy, c.near, c.far, point(from), kAmbient);
}

}  // namespace fb89::host
