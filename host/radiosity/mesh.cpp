#include "host/radiosity/mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "host/scene/polygon.h"

namespace fb89::host {

namespace {

double triangle_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return 0.5 * glm::length(glm::cross(b - a, c - a));
}

int divisions(double length, const MeshOptions& o) {
    return std::clamp(static_cast<int>(std::lround(length / o.patch_size)), 1, o.max_per_side);
}

// Cuts one element into its grid of patches.
void add_patches(Mesh& mesh, Element& e, uint32_t element_index) {
    e.first_patch = static_cast<uint32_t>(mesh.patches.size());
    for (int j = 0; j < e.nv; ++j)
        for (int i = 0; i < e.nu; ++i) {
            Patch p;
            p.element = element_index;
            p.i = i;
            p.j = j;
            p.corners = region_corners(e, i, i + 1, j, j + 1);
            set_shape(p);
            mesh.patches.push_back(p);
        }
}

void add_element(Mesh& mesh, const Face& face, uint32_t piece, const glm::dvec3& normal,
                 std::array<glm::dvec3, 4> corners, const MeshOptions& o) {
    Element e;
    e.piece = piece;
    e.face_id = face.id;
    e.corners = corners;
    e.normal = normal;
    e.reflectance = face.material.color;
    e.emission = face.material.emission;
    const double along_s =
        std::max(glm::length(corners[1] - corners[0]), glm::length(corners[2] - corners[3]));
    const double along_t =
        std::max(glm::length(corners[3] - corners[0]), glm::length(corners[2] - corners[1]));
    e.nu = divisions(along_s, o);
    e.nv = divisions(along_t, o);
    const auto index = static_cast<uint32_t>(mesh.elements.size());
    add_patches(mesh, e, index);
    mesh.elements.push_back(e);
}

// A piece of `parent`: patches [i0, i1) x [j0, j1) of its grid, cut `split` x `split` finer.
void add_sub_element(Mesh& mesh, const Element& parent, int i0, int i1, int j0, int j1, int split) {
    Element e = parent;
    e.corners = region_corners(parent, i0, i1, j0, j1);
    e.nu = (i1 - i0) * split;
    e.nv = (j1 - j0) * split;
    const auto index = static_cast<uint32_t>(mesh.elements.size());
    add_patches(mesh, e, index);
    mesh.elements.push_back(e);
}

// The quadtree over one element's patch grid: a region with no patch to split stays one
// element with its patches as they were; a single patch to split becomes a 2 x 2 element.
void refine_region(Mesh& out, const Element& e, const std::vector<bool>& split, int i0, int i1,
                   int j0, int j1) {
    bool any = false;
    for (int j = j0; j < j1 && !any; ++j)
        for (int i = i0; i < i1 && !any; ++i)
            any = split[e.patch(i, j)];
    if (!any || (i1 - i0 == 1 && j1 - j0 == 1)) {
        add_sub_element(out, e, i0, i1, j0, j1, any ? 2 : 1);
        return;
    }
    const int im = i1 - i0 > 1 ? i0 + (i1 - i0) / 2 : i1;
    const int jm = j1 - j0 > 1 ? j0 + (j1 - j0) / 2 : j1;
    refine_region(out, e, split, i0, im, j0, jm);
    if (im < i1) refine_region(out, e, split, im, i1, j0, jm);
    if (jm < j1) refine_region(out, e, split, i0, im, jm, j1);
    if (im < i1 && jm < j1) refine_region(out, e, split, im, i1, jm, j1);
}

double largest(const glm::dvec3& v) {
    return std::max({v.x, v.y, v.z});
}

struct MeshBox {
    glm::dvec3 lo{INFINITY}, hi{-INFINITY};
    void add(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    bool touches(const MeshBox& o, double margin) const {
        for (int a = 0; a < 3; ++a)
            if (o.lo[a] > hi[a] + margin || lo[a] > o.hi[a] + margin) return false;
        return true;
    }
};

double longest_side(const Patch& p) {
    double side = 0;
    for (int k = 0; k < p.corner_count; ++k)
        side = std::max(side, glm::length(p.corners[(k + 1) % p.corner_count] - p.corners[k]));
    return side;
}

}  // namespace

void set_shape(Patch& p) {
    p.corner_count = p.corners[2] == p.corners[3] ? 3 : 4;
    const double a1 = triangle_area(p.corners[0], p.corners[1], p.corners[2]);
    const double a2 =
        p.corner_count == 4 ? triangle_area(p.corners[0], p.corners[2], p.corners[3]) : 0.0;
    p.area = a1 + a2;
    const glm::dvec3 c1 = (p.corners[0] + p.corners[1] + p.corners[2]) / 3.0;
    const glm::dvec3 c2 = (p.corners[0] + p.corners[2] + p.corners[3]) / 3.0;
    p.centre = p.area > 0 ? (a1 * c1 + a2 * c2) / p.area : c1;
}

std::array<glm::dvec3, 4> region_corners(const Element& e, double s0, double s1, double t0,
                                         double t1) {
    std::array<glm::dvec3, 4> c = {e.point(s0, t0), e.point(s1, t0), e.point(s1, t1),
                                   e.point(s0, t1)};
    if (t1 == 1 && e.corners[2] == e.corners[3]) c[2] = c[3] = e.corners[2];  // the apex, exactly
    return c;
}

uint32_t add_region_element(Mesh& mesh, const Element& parent, double s0, double s1, double t0,
                            double t1) {
    Element e = parent;
    e.corners = region_corners(parent, s0, s1, t0, t1);
    e.nu = e.nv = 1;
    const auto index = static_cast<uint32_t>(mesh.elements.size());
    add_patches(mesh, e, index);
    mesh.elements.push_back(e);
    return index;
}

glm::dvec3 Element::point(double s, double t) const {
    return (1 - s) * (1 - t) * corners[0] + s * (1 - t) * corners[1] + s * t * corners[2] +
           (1 - s) * t * corners[3];
}

std::array<glm::dvec3, 4> region_corners(const Element& e, int i0, int i1, int j0, int j1) {
    return region_corners(e, static_cast<double>(i0) / e.nu, static_cast<double>(i1) / e.nu,
                          static_cast<double>(j0) / e.nv, static_cast<double>(j1) / e.nv);
}

Mesh mesh_scene(const Scene& scene, const MeshOptions& options) {
    Mesh mesh;
    for (uint32_t piece = 0; piece < scene.faces.size(); ++piece) {
        const Face& face = scene.faces[piece];
        const auto& v = face.vertices;
        const glm::dvec3 n = newell_normal(v);
        if (!(glm::length(n) > 0)) continue;
        const glm::dvec3 normal = glm::normalize(n);
        if (v.size() == 3)
            add_element(mesh, face, piece, normal, {v[0], v[1], v[2], v[2]}, options);
        else if (v.size() == 4)
            add_element(mesh, face, piece, normal, {v[0], v[1], v[2], v[3]}, options);
        else
            for (size_t k = 1; k + 1 < v.size(); ++k)  // a fan of triangles
                add_element(mesh, face, piece, normal, {v[0], v[k], v[k + 1], v[k + 1]}, options);
    }
    return mesh;
}

double patch_size_for(const Scene& scene, int target) {
    double area = 0;
    for (const Face& f : scene.faces)
        area += 0.5 * glm::length(newell_normal(f.vertices));
    return std::sqrt(area / std::max(target, 1));
}

std::vector<bool> patches_to_split(const Mesh& mesh, const std::vector<glm::dvec3>& radiosity,
                                   double threshold, double min_patch_size) {
    const size_t n = mesh.patches.size();
    std::vector<bool> split(n, false);
    // the floor below which differences do not count: the brightest non-emitting patch
    double brightest = 0;
    for (size_t p = 0; p < n; ++p)
        if (largest(mesh.elements[mesh.patches[p].element].emission) == 0)
            brightest = std::max(brightest, largest(radiosity[p]));
    const double floor = 1e-3 * brightest;
    auto differ = [&](size_t a, size_t b) {
        const double scale = std::max(largest(radiosity[a]), largest(radiosity[b]));
        if (!(scale > floor)) return false;
        return largest(glm::abs(radiosity[a] - radiosity[b])) > threshold * scale;
    };

    // neighbours: patches of one piece whose bounding boxes touch
    std::vector<MeshBox> boxes(n);
    MeshBox all;
    std::vector<std::vector<uint32_t>> by_piece;
    for (size_t p = 0; p < n; ++p) {
        const Patch& patch = mesh.patches[p];
        for (int k = 0; k < patch.corner_count; ++k) {
            boxes[p].add(patch.corners[k]);
            all.add(patch.corners[k]);
        }
        const uint32_t piece = mesh.elements[patch.element].piece;
        if (piece >= by_piece.size()) by_piece.resize(piece + 1);
        by_piece[piece].push_back(static_cast<uint32_t>(p));
    }
    const double margin = 1e-9 * glm::length(all.hi - all.lo);
    for (std::vector<uint32_t>& group : by_piece) {
        // sweep along x: only boxes that overlap in x are compared
        std::sort(group.begin(), group.end(),
                  [&](uint32_t a, uint32_t b) { return boxes[a].lo.x < boxes[b].lo.x; });
        for (size_t a = 0; a < group.size(); ++a)
            for (size_t b = a + 1; b < group.size(); ++b) {
                const MeshBox& A = boxes[group[a]];
                const MeshBox& B = boxes[group[b]];
                if (B.lo.x > A.hi.x + margin) break;
                if (A.touches(B, margin) && differ(group[a], group[b]))
                    split[group[a]] = split[group[b]] = true;
            }
    }
    for (size_t p = 0; p < n; ++p)
        if (split[p] && longest_side(mesh.patches[p]) <= min_patch_size) split[p] = false;
    return split;
}

Mesh refine(const Mesh& mesh, const std::vector<glm::dvec3>& radiosity, double threshold,
            double min_patch_size) {
    const std::vector<bool> split = patches_to_split(mesh, radiosity, threshold, min_patch_size);
    Mesh out;
    for (const Element& e : mesh.elements) {
        bool any = false;
        for (int k = 0; k < e.nu * e.nv && !any; ++k)
            any = split[e.first_patch + static_cast<uint32_t>(k)];
        if (!any) {  // as it was, exactly
            Element copy = e;
            const auto index = static_cast<uint32_t>(out.elements.size());
            add_patches(out, copy, index);
            out.elements.push_back(copy);
        } else {
            refine_region(out, e, split, 0, e.nu, 0, e.nv);
        }
    }
    return out;
}

}  // namespace fb89::host
