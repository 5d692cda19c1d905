// Checking and repairing input polygons before they become faces.
//
// Faces must be planar and convex. A polygon that is not is triangulated (ear clipping in
// its best-fit plane) and that is reported; one with NaN/Inf coordinates is an error; one
// with zero area is dropped and reported. Nothing is changed silently.
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace fb89::host {

// Largest |coordinate| a face may have: far beyond it, clipping to the guard band in double
// precision loses the face (a face of 1e20 extent vanished; 1e15 still rendered exactly).
inline constexpr double kMaxCoordinate = 1e12;

enum class PolygonVerdict {
    Ok,            // planar and convex: use as is
    Triangulated,  // non-planar or non-convex: replaced by triangles
    Degenerate,    // fewer than 3 distinct vertices or zero area: dropped
    NotFinite,     // NaN, Inf or beyond kMaxCoordinate: an error for the caller to report
};

struct PolygonResult {
    PolygonVerdict verdict = PolygonVerdict::Ok;
    std::vector<std::vector<glm::dvec3>> pieces;  // the polygon, or its triangles
    std::string reason;                           // why it was triangulated or dropped
};

// Newell's normal: robust for any simple polygon; its length is twice the area.
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& vertices);

PolygonResult prepare_polygon(const std::vector<glm::dvec3>& vertices);

}  // namespace fb89::host
