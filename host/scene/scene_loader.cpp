#include "host/scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "host/scene/auto_camera.h"
#include "host/scene/generators.h"
#include "host/scene/json_fields.h"
#include "host/scene/obj_loader.h"
#include "host/scene/polygon.h"
#include "host/scene/scene_error.h"

namespace fb89::host {

namespace {

std::string read_file(const std::filesystem::path& file) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec))
        throw SceneError(fmt::format("{}: is a directory, not a scene file", file.string()));
    if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
        throw SceneError(
            fmt::format("{}: not a regular file (a device or a pipe could be "
                        "endless), not a scene file",
                        file.string()));
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SceneError(fmt::format("{}: cannot open the scene file", file.string()));
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// "line L, column C" of a byte offset, for JSON syntax errors.
std::string line_and_column(std::string_view text, size_t byte) {
    size_t line = 1, col = 1;
    for (size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return fmt::format("line {}, column {}", line, col);
}

void read_camera(const JsonFields& root, Scene& scene) {
    if (!root.has("camera")) root.fail("camera", "a camera object");
    JsonFields cam = root.child("camera");
    if (cam.has("projection")) {
        std::string p = cam.string("projection");
        if (p == "screen") {
            cam.only_keys("camera screen");
            scene.projection = Projection::Screen;
            return;
        }
        if (p != "perspective") cam.fail("projection", "\"perspective\" or \"screen\"");
    }
    cam.only_keys("camera");
    Camera& c = scene.camera;
    c.eye = cam.vec3("eye");
    c.look_at = cam.vec3("look_at");
    c.up = cam.vec3_or("up", {0, 1, 0});
    c.fovy_degrees = cam.number_in("fovy", 1e-3, 179.0);
    c.near = cam.number_in("near", 1e-9, 1e12);
    c.far = cam.number_in("far", 1e-9, 1e15);
    if (!(c.far > c.near)) cam.fail("far", fmt::format("a number greater than near ({})", c.near));
    glm::dvec3 view = c.look_at - c.eye;
    if (glm::length(view) == 0) cam.fail("look_at", "a point different from eye");
    if (glm::length(glm::cross(view, c.up)) == 0)
        cam.fail("up", "a vector not parallel to the view");
}

void read_globals(const JsonFields& root, Scene& scene) {
    root.only_keys("scene");
    read_camera(root, scene);
    if (root.has("image")) {
        JsonFields image = root.child("image");
        image.only_keys("image");
        scene.width = image.integer_or("width", 1024, 1, 16384);
        scene.height = image.integer_or("height", 780, 1, 16384);
    }
    if (root.has("background")) scene.background = root.color("background");
    if (root.has("light")) {
        JsonFields light = root.child("light");
        light.only_keys("light");
        scene.light.direction = light.vec3_or("direction", scene.light.direction);
        if (glm::length(scene.light.direction) == 0) light.fail("direction", "a non-zero vector");
        scene.light.direction = glm::normalize(scene.light.direction);
        scene.light.ambient = light.number_or("ambient", scene.light.ambient, 0, 1);
    }
}

Material read_material(const JsonFields& o, std::vector<size_t>& mirror_faces) {
    Material m;
    if (!o.has("material")) return m;
    JsonFields mat = o.child("material");
    mat.only_keys("material");
    if (mat.has("color")) m.color = mat.color("color");
    m.mirror = mat.number_or("mirror", 0, 0, 1);
    if (mat.has("emission")) {
        m.emission = mat.vec3("emission");
        if (m.emission.x < 0 || m.emission.y < 0 || m.emission.z < 0)
            mat.fail("emission", "3 numbers >= 0");
    }
    if (mat.has("mirror_faces")) {
        JsonFields list = mat.child("mirror_faces");
        for (size_t i = 0; i < list.size(); ++i) {
            const auto& v = list.node()[i];
            if (!v.is_number_unsigned()) mat.fail("mirror_faces", "an array of face indices >= 0");
            mirror_faces.push_back(v.get<size_t>());
        }
    }
    return m;
}

glm::dmat4 read_transform(const JsonFields& o) {
    glm::dmat4 t(1.0);
    if (!o.has("transform")) return t;
    JsonFields tr = o.child("transform");
    tr.only_keys("transform");
    glm::dvec3 scale(1.0);
    if (tr.has("scale")) {
        scale =
            tr.node().at("scale").is_number() ? glm::dvec3(tr.number("scale")) : tr.vec3("scale");
        if (scale.x == 0 || scale.y == 0 || scale.z == 0) tr.fail("scale", "non-zero factors");
    }
    glm::dmat4 rotation(1.0);
    if (tr.has("rotate")) {
        JsonFields rot = tr.child("rotate");
        rot.only_keys("rotate");
        glm::dvec3 axis = rot.vec3("axis");
        if (glm::length(axis) == 0) rot.fail("axis", "a non-zero vector");
        rotation =
            glm::rotate(glm::dmat4(1.0), glm::radians(rot.number("degrees")), glm::normalize(axis));
    }
    glm::dvec3 translate = tr.vec3_or("translate", glm::dvec3(0));
    // scale, then rotate, then translate
    return glm::translate(glm::dmat4(1.0), translate) * rotation *
           glm::scale(glm::dmat4(1.0), scale);
}

GeneratedPolygons read_geometry(const JsonFields& o, Scene& scene,
                                const std::filesystem::path& base_dir) {
    if (o.has("polygon") || o.has("polygons")) {
        o.only_keys("object polygons");
        GeneratedPolygons out;
        auto read_one = [&](const JsonFields& poly) {
            GeneratedPolygon g;
            for (size_t i = 0; i < poly.size(); ++i)
                g.vertices.push_back(poly.element(i).vec3_of_node());
            if (g.vertices.size() < 3) poly.fail(nullptr, "a polygon of 3 or more vertices");
            out.push_back(std::move(g));
        };
        if (o.has("polygon")) read_one(o.child("polygon"));
        if (o.has("polygons")) {
            JsonFields list = o.child("polygons");
            for (size_t i = 0; i < list.size(); ++i)
                read_one(list.element(i));
        }
        return out;
    }
    if (o.has("obj")) {
        o.only_keys("object obj");
        try {
            return load_obj(base_dir / o.string("obj"), &scene.notes);
        } catch (const SceneError& e) {
            const bool relative = std::filesystem::path(o.string("obj")).is_relative();
            throw SceneError(fmt::format("{}: {}{}", o.where("obj"), e.what(),
                                         relative ? " (a relative \"obj\" is read from the "
                                                    "scene file's folder)"
                                                  : ""));
        }
    }
    if (o.has("generator")) return generate_from_json(o, scene);
    o.fail(nullptr, "an object with \"polygon\", \"polygons\", \"obj\" or \"generator\"");
}

// What faces take from the object they come from.
struct FaceSource {
    Material material;
    bool has_color = false;  // the material's colour replaces the polygons' own
    std::vector<size_t> mirror_faces;
    glm::dmat4 transform{1.0};
    std::string where;  // names the object in messages: "scene.json: objects[2]"
    uint32_t object = 0;
};

// Appends an object's polygons as faces: transform, check, triangulate if needed, number.
// A face's id is its index in the input (objects in file order, faces in each object's
// order), whatever is dropped or split: a dropped face leaves its id unused, the pieces of
// a triangulated one share its id.
void add_faces(Scene& scene, const GeneratedPolygons& polys, const FaceSource& source) {
    for (size_t i = 0; i < polys.size(); ++i) {
        std::vector<glm::dvec3> v;
        v.reserve(polys[i].vertices.size());
        for (const auto& p : polys[i].vertices)
            v.push_back(glm::dvec3(source.transform * glm::dvec4(p, 1.0)));
        PolygonResult prepared = prepare_polygon(v);
        std::string where = fmt::format("{}: face {}", source.where, i);
        if (prepared.verdict == PolygonVerdict::NotFinite)
            throw SceneError(fmt::format("{}: {}", where, prepared.reason));
        if (prepared.verdict == PolygonVerdict::Degenerate) {
            // dropped, its id left unused: every later face keeps its index in the input
            ++scene.dropped;
            scene.notes.push_back(fmt::format("{}: dropped ({}); id {} unused", where,
                                              prepared.reason, scene.face_count));
            ++scene.face_count;
            continue;
        }
        if (prepared.verdict == PolygonVerdict::Triangulated) {
            ++scene.triangulated;
            scene.notes.push_back(fmt::format("{}: triangulated into {} triangles ({})", where,
                                              prepared.pieces.size(), prepared.reason));
        }
        Material m = source.material;
        if (polys[i].color && !source.has_color) m.color = *polys[i].color;
        const auto& mirrors = source.mirror_faces;
        if (!mirrors.empty())
            m.mirror = std::find(mirrors.begin(), mirrors.end(), i) != mirrors.end()
                           ? source.material.mirror
                           : 0.0;
        for (auto& piece : prepared.pieces)
            scene.faces.push_back({std::move(piece), m, scene.face_count, source.object});
        ++scene.face_count;
    }
}

void add_object(Scene& scene, const JsonFields& o, uint32_t object_index,
                const std::filesystem::path& base_dir) {
    FaceSource source;
    source.material = read_material(o, source.mirror_faces);
    source.has_color = o.has("material") && o.child("material").has("color");
    source.transform = read_transform(o);
    source.where = o.where();
    source.object = object_index;
    GeneratedPolygons polys = read_geometry(o, scene, base_dir);
    for (size_t f : source.mirror_faces)
        if (f >= polys.size())
            o.fail("material",
                   fmt::format("mirror_faces indices below the object's {} faces", polys.size()));
    add_faces(scene, polys, source);
}

// A bare OBJ model as a scene: its faces as they are, framed by the automatic camera.
Scene load_obj_scene(const std::filesystem::path& file) {
    Scene scene;
    scene.source = file.string();
    const GeneratedPolygons polys = load_obj(file, &scene.notes);
    FaceSource source;
    source.where = file.string();
    add_faces(scene, polys, source);
    if (scene.faces.empty())
        throw SceneError(fmt::format("{}: nothing to draw: all {} faces have zero area",
                                     file.string(), polys.size()));
    scene.notes.push_back(file.string() + ": " + frame_automatically(scene));
    return scene;
}

}  // namespace

Scene parse_scene_json(std::string_view text, const std::string& name,
                       const std::filesystem::path& base_dir) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(text.begin(), text.end(), nullptr, true, true);
    } catch (const nlohmann::json::parse_error& e) {
        std::string what = e.what();
        auto colon = what.find("syntax error");
        throw SceneError(fmt::format("{}: {}: invalid JSON ({})", name,
                                     line_and_column(text, e.byte > 0 ? e.byte - 1 : 0),
                                     colon == std::string::npos ? what : what.substr(colon)));
    } catch (const nlohmann::json::exception& e) {  // e.g. a number too large for a double
        std::string what = e.what();
        auto bracket = what.find("] ");
        throw SceneError(
            fmt::format("{}: invalid JSON ({})", name,
                        bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
    Scene scene;
    scene.source = name;
    JsonFields fields(root, name, "");
    read_globals(fields, scene);
    if (!fields.has("objects")) fields.fail("objects", "an array of objects");
    JsonFields objects = fields.child("objects");
    for (size_t i = 0; i < objects.size(); ++i)
        add_object(scene, objects.element(i), static_cast<uint32_t>(i), base_dir);
    return scene;
}

Scene load_scene(const std::filesystem::path& file) {
    if (file.extension() == ".obj") return load_obj_scene(file);
    std::string text = read_file(file);
    std::string ext = file.extension().string();
    if (ext == ".tri") return parse_tri(text, file.string());
    if (ext == ".json") return parse_scene_json(text, file.string(), file.parent_path());
    throw SceneError(fmt::format("{}: unknown scene format '{}' (expected .json, .obj or .tri)",
                                 file.string(), ext));
}

}  // namespace fb89::host
