// The scene as rays and beams see it: faces in world space with their planes and both
// sides' flat colours, the camera's pixel rays, and the watertight ray-polygon test.
//
// Ray-polygon test: Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection" (JCGT
// 2013), extended from triangles to convex polygons. The vertices are moved into a space
// where the ray is the +z axis (a permutation and a shear); the ray hits the polygon when
// the 2D edge functions of its consecutive vertices around the origin all have one sign.
// An edge shared by two faces gives exactly negated values in both, so a ray through a
// shared edge or vertex hits at least one of them: no ray slips through a closed mesh. The
// hit distance comes from the face's plane. Differences from the paper: it only needs a
// ray tracer; ours must be watertight because beam corners lie on shared edges often.
//
// Shading (DESIGN.md "Scene model"): flat Lambertian with the scene's directional light plus
// ambient, on the side the ray arrives at (faces are two-sided); a mirror of reflectance r
// shows (1 − r) of its own colour plus r of what its reflection sees. No shadows.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "host/scene/scene.h"
#include "protocol/command.h"

namespace fb89::host {

struct Ray {
    glm::dvec3 origin;
    glm::dvec3 dir;  // need not be unit length; distances t are in multiples of it
};

// A face piece as traced: pieces of a triangulated polygon keep its id.
struct TraceFace {
    uint32_t first_vertex = 0;  // into TraceScene::vertices
    uint32_t vertex_count = 0;
    glm::dvec3 normal{0};  // unit, by Newell's method
    double plane = 0;      // dot(normal, p) for p on the face
    uint32_t id = 0;
    double mirror = 0;                       // reflectance in [0, 1]
    std::array<glm::dvec3, 2> local_color;   // seen from the normal's side [0], the other [1]
    std::array<protocol::Rgb, 2> end_color;  // path_color() of a path that ends here at once
};

inline constexpr uint32_t kNoFace = UINT32_MAX;

// A piece's bounding box: its vertices' least and greatest coordinates.
struct PieceBox {
    glm::dvec3 lo, hi;
};

// The closest hit along a ray; piece == kNoFace when nothing is hit.
struct Hit {
    double t = 0;
    uint32_t piece = kNoFace;
};

// A ray prepared for the watertight test: the axis it runs along most (kz), the other two,
// the shear that makes it the +z axis, and its origin's coordinates in that order.
struct RaySpace {
    int kx = 0, ky = 1, kz = 2;
    double sx = 0, sy = 0;
    double ox = 0, oy = 0, oz = 0;
    explicit RaySpace(const Ray& ray);
    // The axes for a ray along `d`: kz the one it runs along most, kx and ky keeping the
    // winding (the packets of rays, ray_packet.h, group rays by them).
    static void axes(const glm::dvec3& d, int& kx, int& ky, int& kz);
};

class TraceScene {
  public:
    // `id_colors`: every face's colour is its id + 1 (the face-id pass), unshaded.
    TraceScene(const Scene& scene, bool id_colors, int max_reflections);

    const std::vector<TraceFace>& faces() const { return m_faces; }
    const std::vector<glm::dvec3>& vertices() const { return m_vertices; }
    const glm::dvec3* vertices_of(const TraceFace& f) const { return &m_vertices[f.first_vertex]; }
    // Worked out once, for the grid, the BVH and the volume queries' first test.
    const PieceBox& box(uint32_t piece) const { return m_boxes[piece]; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    bool id_colors() const { return m_id_colors; }
    int max_reflections() const { return m_max_reflections; }
    const glm::dvec3& background() const { return m_background; }
    uint32_t face_count() const { return m_face_count; }  // distinct ids

    // The ray through the centre of pixel (x, y), under gluLookAt + gluPerspective: it
    // starts on the near plane, and its parameter t grows by one per unit of depth, so it
    // leaves the view volume at t = primary_length() (the far plane), as the raster methods
    // clip. A scene given in screen space is seen along +z, unclipped.
    Ray pixel_ray(int x, int y) const;
    double primary_length() const { return m_primary_length; }
    // The t at which every pixel ray reaches the depth of point p (pixel rays' t is depth
    // from the near plane): no pixel ray meets p's depth before it.
    double ray_depth(const glm::dvec3& p) const {
        return m_orthographic ? p.z + 1.0 : glm::dot(p - m_eye, m_forward) - m_near;
    }
    bool orthographic() const { return m_orthographic; }

    // The watertight test of one piece: true with t when the ray hits it at tmin < t. A hit
    // beyond `wanted` may be reported as none (the caller has a nearer one): the plane is
    // checked against both ends first, without a division.
    bool intersect(const Ray& ray, const RaySpace& space, uint32_t piece, double tmin, double& t,
                   double wanted = INFINITY) const;

    // Lengths below this are "touching" for beam queries (a billionth of the scene's size).
    double tolerance() const { return m_tolerance; }

  private:
    std::vector<TraceFace> m_faces;
    std::vector<glm::dvec3> m_vertices;
    std::vector<PieceBox> m_boxes;  // per piece
    int m_width = 0, m_height = 0;
    bool m_id_colors = false;
    int m_max_reflections = 0;
    glm::dvec3 m_background{0};
    uint32_t m_face_count = 0;
    bool m_orthographic = false;
    glm::dvec3 m_eye{0}, m_forward{0}, m_right{0}, m_up{0};  // pixel ray frame
    double m_near = 0;
    // pixel_ray's terms worked out once: column_ndc(x) and forward + column_ndc(x) * right
    // per column, row_ndc(y) per row (the same sums in the same order, so the same rays)
    std::vector<glm::dvec3> m_column_dir;
    std::vector<double> m_row_ndc;
    double column_ndc(int x) const { return 2.0 * (x + 0.5) / m_width - 1.0; }
    double row_ndc(int y) const { return 1.0 - 2.0 * (y + 0.5) / m_height; }
    double m_primary_length = INFINITY;
    double m_tolerance = 0;
};

// The colour a path shows: hits[0] seen first; each mirror mixes in what follows it, and a
// path that leaves through a mirror (or stops at the reflection limit) ends on the
// background. In id mode the colour is the id + 1 of the face finally seen.
struct PathHit {
    uint32_t piece = kNoFace;
    bool back = false;  // arrived from the side opposite the normal
    bool operator==(const PathHit&) const = default;
};

protocol::Rgb path_color(const TraceScene& scene, const PathHit* hits, int count);
// The same, a path of one face taken from the colour worked out for it in advance.
inline protocol::Rgb traced_color(const TraceScene& scene, const PathHit* hits, int count) {
    return count == 1 ? scene.faces()[hits[0].piece].end_color[hits[0].back ? 1 : 0]
                      : path_color(scene, hits, count);
}

// Inline, as the ray tracer calls them once per ray or test.
inline void RaySpace::axes(const glm::dvec3& d, int& kx, int& ky, int& kz) {
    const glm::dvec3 a = glm::abs(d);
    kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);  // keep the winding
}

inline RaySpace::RaySpace(const Ray& ray) {
    const glm::dvec3& d = ray.dir;
    axes(d, kx, ky, kz);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    ox = ray.origin[kx];
    oy = ray.origin[ky];
    oz = ray.origin[kz];
}

inline Ray TraceScene::pixel_ray(int x, int y) const {
    if (m_orthographic) return {{x + 0.5, y + 0.5, -1.0}, {0, 0, 1}};
    const bool inside = x >= 0 && x < m_width && y >= 0 && y < m_height;
    const glm::dvec3 column = inside ? m_column_dir[x] : m_forward + column_ndc(x) * m_right;
    const glm::dvec3 dir = column + (inside ? m_row_ndc[y] : row_ndc(y)) * m_up;
    return {m_eye + m_near * dir, dir};  // dir's depth component is 1: t is depth
}

inline bool TraceScene::intersect(const Ray& ray, const RaySpace& s, uint32_t piece, double tmin,
                                  double& t, double wanted) const {
    const TraceFace& f = m_faces[piece];
    // plane first: most faces behind the best hit so far stop here. Without dividing: the
    // plane's distance is num / denom; with both made positive-denominator, a face is
    // dropped only when it is clearly outside (tmin, wanted], by a margin far above the
    // rounding of the products, so the exact test below decides every face near either end.
    const double denom = glm::dot(f.normal, ray.dir);
    if (denom == 0) return false;
    const double num = f.plane - glm::dot(f.normal, ray.origin);
    const double a = denom > 0 ? num : -num, b = denom > 0 ? denom : -denom;
    constexpr double kMargin = 1e-14;
    if (a <= tmin * b * (1 - kMargin) || a > wanted * b * (1 + kMargin)) return false;

    // watertight inside test in ray space
    const glm::dvec3* v = vertices_of(f);
    auto sheared = [&](const glm::dvec3& p, double& x, double& y) {
        const double* c = &p.x;  // x, y, z side by side, as glm::value_ptr has them
        const double z = c[s.kz] - s.oz;
        x = (c[s.kx] - s.ox) - s.sx * z;
        y = (c[s.ky] - s.oy) - s.sy * z;
    };
    double x0, y0, px, py;
    sheared(v[0], x0, y0);
    px = x0;
    py = y0;
    bool negative = false, positive = false;
    double det = 0;
    for (uint32_t i = 1; i <= f.vertex_count; ++i) {
        double qx = x0, qy = y0;
        if (i < f.vertex_count) sheared(v[i], qx, qy);
        const double e = qx * py - qy * px;  // edge (p, q) around the origin
        negative |= e < 0;
        positive |= e > 0;
        if (negative && positive) return false;
        det += e;
        px = qx;
        py = qy;
    }
    if (det == 0) return false;  // edge-on
    t = num / denom;
    return t > tmin;
}

}  // namespace fb89::host
