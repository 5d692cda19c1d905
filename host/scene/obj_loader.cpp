// OBJ meshes through tinyobjloader (Wavefront's "Object Files (.obj)", Appendix B1 of the
// Advanced Visualizer manual, for the statements and their indices). tinyobjloader reads the
// file; a scan of our own, line by line, says what it cannot: which line is at fault (it
// names none for a bad index), what it would drop or read wrongly without a word (a short
// face, an unparsable coordinate), whether the file is OBJ at all (it ignores any line it
// does not know, so any text loads as 0 faces), and which material library or material is
// missing (its warnings name no line).
#include "host/scene/obj_loader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <tiny_obj_loader.h>

#include "host/scene/scene_error.h"

namespace fb89::host {

namespace {

// A statement's line and its words after the tag (a material library's or material's name).
struct Statement {
    size_t line = 0;
    std::vector<std::string> names;
};

// What the scan found.
struct ObjScan {
    size_t lines = 0, vertices = 0, line_elements = 0, points = 0;
    std::vector<size_t> face_lines;  // the line of each `f`, in file order
    std::vector<Statement> mtllibs, usemtls;
    std::optional<Statement> first_unknown;  // the first line that is no OBJ statement
    size_t unknown = 0;
    std::vector<std::pair<size_t, long>> forward;  // (line, index) beyond the vertices so far
};

// Every statement of the OBJ format (Appendix B1) and tinyobjloader's two extensions (`t`,
// `vw`): a line of any other tag is not OBJ.
bool known_statement(const std::string& tag) {
    static const std::set<std::string> known = {
        "v",      "vt",     "vn",         "vp",        "f",      "l",      "p",
        "g",      "o",      "s",          "mg",        "usemtl", "mtllib", "usemap",
        "maplib", "cstype", "deg",        "bmat",      "step",   "curv",   "curv2",
        "surf",   "parm",   "trim",       "hole",      "scrv",   "sp",     "end",
        "con",    "bevel",  "c_interp",   "d_interp",  "lod",    "ctech",  "stech",
        "call",   "csh",    "shadow_obj", "trace_obj", "res",    "t",      "vw"};
    return known.count(tag) > 0;
}

// A word as a message can quote it: control and non-ASCII bytes as \xNN, cut at 40 bytes.
std::string shown(std::string_view word) {
    std::string out;
    for (size_t i = 0; i < word.size() && i < 40; ++i) {
        const auto c = static_cast<unsigned char>(word[i]);
        out += c < 0x20 || c >= 0x7f ? fmt::format("\\x{:02x}", c) : std::string(1, char(c));
    }
    return word.size() > 40 ? out + "..." : out;
}

// The column of the first byte that no text file holds (a control byte other than tab, CR,
// vertical tab and form feed), or 0.
size_t first_binary_byte(const std::string& line) {
    for (size_t i = 0; i < line.size(); ++i) {
        const auto c = static_cast<unsigned char>(line[i]);
        if ((c < 0x20 && c != '\t' && c != '\r' && c != '\v' && c != '\f') || c == 0x7f)
            return i + 1;
    }
    return 0;
}

SceneError line_error(const std::filesystem::path& file, size_t line, const std::string& what) {
    return SceneError(fmt::format("{}: line {}: {}", file.string(), line, what));
}

// An `f` line's vertex references ("f 1/1/1 -2//3 4" has 3): each vertex index a whole
// number, not 0, and a negative one no further back than the first vertex. An index beyond
// the vertices read so far is kept for the end, when all are known (a forward reference).
void check_face(const std::filesystem::path& file, size_t number, std::istringstream& words,
                ObjScan& scan) {
    size_t n = 0;
    for (std::string word; words >> word && word[0] != '#';) {
        ++n;
        const std::string index = word.substr(0, word.find('/'));
        char* end = nullptr;
        errno = 0;
        const long i = std::strtol(index.c_str(), &end, 10);
        if (index.empty() || *end != '\0' || errno == ERANGE)
            throw line_error(file, number,
                             fmt::format("face vertex {}: expected a vertex index (a whole "
                                         "number), got '{}'",
                                         n, shown(word)));
        if (i == 0)
            throw line_error(file, number,
                             fmt::format("face vertex {}: index 0; OBJ indices start at 1 "
                                         "(negative ones count back from the last vertex)",
                                         n));
        if (i < 0 && static_cast<size_t>(-i) > scan.vertices)
            throw line_error(file, number,
                             fmt::format("face vertex {}: index {} counts back past the first "
                                         "vertex ({} vertices before this line)",
                                         n, i, scan.vertices));
        if (i > 0 && static_cast<size_t>(i) > scan.vertices) scan.forward.emplace_back(number, i);
    }
    if (n < 3)
        throw line_error(file, number,
                         fmt::format("a face of {} {}; a face needs 3 or more", n,
                                     n == 1 ? "vertex" : "vertices"));
    scan.face_lines.push_back(number);
}

// A `v` line's x, y and z: finite numbers (tinyobjloader reads "abc" as 0 and 1e999 as inf).
void check_vertex(const std::filesystem::path& file, size_t number, std::istringstream& words) {
    for (int k = 0; k < 3; ++k) {
        std::string word;
        words >> word;
        char* end = nullptr;
        const double x = std::strtod(word.c_str(), &end);
        if (word.empty() || *end != '\0' || !std::isfinite(x))
            throw line_error(file, number,
                             fmt::format("vertex coordinate {}: expected a finite number, got "
                                         "'{}'",
                                         k + 1, shown(word)));
    }
}

// Reads the file line by line (see the file's header) and throws at the first line at fault.
ObjScan scan_lines(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    ObjScan scan;
    std::string line;
    for (size_t number = 1; std::getline(in, line); ++number) {
        scan.lines = number;
        std::istringstream words(line);
        std::string tag;
        if (!(words >> tag) || tag[0] == '#') continue;
        if (const size_t column = first_binary_byte(line))
            throw line_error(
                file, number,
                fmt::format(
                    "not text (byte 0x{:02x} in column {}): an OBJ file is lines of "
                    "text (v, f, ...){}",
                    static_cast<unsigned char>(line[column - 1]), column,
                    scan.first_unknown
                        ? fmt::format("; line {}, '{}', is no OBJ statement either",
                                      scan.first_unknown->line, shown(scan.first_unknown->names[0]))
                        : ""));
        if (!known_statement(tag)) {
            if (!scan.unknown++)
                scan.first_unknown =
                    Statement{number, {line.substr(0, line.find_last_not_of(" \t\r\v\f") + 1)}};
            continue;
        }
        if (tag == "v") check_vertex(file, number, words), ++scan.vertices;
        if (tag == "f") check_face(file, number, words, scan);
        if (tag == "l") ++scan.line_elements;
        if (tag == "p") ++scan.points;
        if (tag == "mtllib" || tag == "usemtl") {
            Statement s{number, {}};
            for (std::string name; words >> name && name[0] != '#';)
                s.names.push_back(name);
            (tag == "mtllib" ? scan.mtllibs : scan.usemtls).push_back(std::move(s));
        }
    }
    for (const auto& [number, index] : scan.forward)
        if (static_cast<size_t>(index) > scan.vertices)
            throw line_error(file, number,
                             fmt::format("face refers to vertex {} of {}", index, scan.vertices));
    return scan;
}

// A file with no face is no model: an error saying what was read, and naming the first line
// that is not OBJ when there is one (a text file that is something else).
void require_faces(const std::filesystem::path& file, const ObjScan& scan) {
    if (!scan.face_lines.empty()) return;
    std::string also;
    if (scan.lines == 0) also = ": the file is empty";
    if (scan.line_elements || scan.points)
        also = fmt::format("; {} line and {} point element(s), which fb89 does not draw",
                           scan.line_elements, scan.points);
    if (scan.first_unknown)
        also += fmt::format("; line {}, '{}', is not an OBJ statement", scan.first_unknown->line,
                            shown(scan.first_unknown->names[0]));
    throw SceneError(
        fmt::format("{}: no faces (an OBJ model needs at least one \"f\" line; read "
                    "{} vertices, 0 faces from {} lines{})",
                    file.string(), scan.vertices, scan.lines, also));
}

std::string name_list(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names)
        out += (out.empty() ? "'" : ", '") + shown(name) + "'";
    return out;
}

// Warnings (not errors: the faces load, grey): lines that are not OBJ statements, material
// libraries that do not exist, and materials that no library defines (once per name; not
// when a library is missing, which says it already).
void warn(const std::filesystem::path& file, const ObjScan& scan,
          const std::vector<tinyobj::material_t>& materials, std::vector<std::string>& notes) {
    const std::string f = file.string();
    if (scan.first_unknown)
        notes.push_back(fmt::format(
            "{}: line {}: '{}' is not an OBJ statement: ignored{}", f, scan.first_unknown->line,
            shown(scan.first_unknown->names[0]),
            scan.unknown > 1 ? fmt::format(" (and {} more such lines)", scan.unknown - 1) : ""));
    const std::filesystem::path dir = file.parent_path();
    bool missing = false;
    for (const Statement& lib : scan.mtllibs) {
        std::error_code ec;
        const bool found = std::any_of(lib.names.begin(), lib.names.end(), [&](const auto& n) {
            return std::filesystem::is_regular_file(dir / n, ec);
        });
        if (found || lib.names.empty()) continue;
        missing = true;
        notes.push_back(fmt::format(
            "{}: line {}: material library {} not found (in {}): faces "
            "are grey",
            f, lib.line, name_list(lib.names), dir.empty() ? "the current folder" : dir.string()));
    }
    if (missing) return;
    std::set<std::string> defined, told;
    for (const auto& m : materials)
        defined.insert(m.name);
    for (const Statement& use : scan.usemtls) {
        if (use.names.empty() || defined.count(use.names[0]) || !told.insert(use.names[0]).second)
            continue;
        notes.push_back(
            scan.mtllibs.empty()
                ? fmt::format("{}: line {}: usemtl '{}', but the file names no material library "
                              "(mtllib): its faces are grey",
                              f, use.line, shown(use.names[0]))
                : fmt::format("{}: line {}: material '{}' is in no material library of the file: "
                              "its faces are grey",
                              f, use.line, shown(use.names[0])));
    }
}

void require_regular_file(const std::filesystem::path& file) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec))
        throw SceneError(fmt::format("{}: is a directory, not an OBJ file", file.string()));
    if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
        throw SceneError(
            fmt::format("{}: not a regular file (a device or a pipe could be "
                        "endless), not an OBJ file",
                        file.string()));
    if (!std::ifstream(file).good())
        throw SceneError(fmt::format("{}: cannot open the OBJ file", file.string()));
}

}  // namespace

GeneratedPolygons load_obj(const std::filesystem::path& file, std::vector<std::string>* notes) {
    require_regular_file(file);
    const ObjScan scan = scan_lines(file);
    require_faces(file, scan);
    if (notes && (scan.line_elements || scan.points))
        notes->push_back(
            fmt::format("{}: {} line and {} point element(s) skipped: fb89 draws "
                        "faces only",
                        file.string(), scan.line_elements, scan.points));
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // faces stay whole convex polygons
    config.vertex_color = false;
    config.mtl_search_path = file.parent_path().string();
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), config)) {
        std::string why = reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == '\r'))
            why.pop_back();
        throw SceneError(fmt::format("{}: {}", file.string(), why.empty() ? "unreadable" : why));
    }
    const auto& attrib = reader.GetAttrib();
    const auto& materials = reader.GetMaterials();
    if (notes) warn(file, scan, materials, *notes);
    const size_t vertex_count = attrib.vertices.size() / 3;

    GeneratedPolygons out;
    for (const auto& shape : reader.GetShapes()) {
        size_t offset = 0;
        const auto& mesh = shape.mesh;
        for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
            // the scan saw every `f` line tinyobjloader did, in the same order
            const size_t line =
                out.size() < scan.face_lines.size() ? scan.face_lines[out.size()] : 0;
            size_t n = mesh.num_face_vertices[f];
            GeneratedPolygon poly;
            for (size_t k = 0; k < n; ++k) {
                int vi = mesh.indices[offset + k].vertex_index;
                if (vi < 0 || static_cast<size_t>(vi) >= vertex_count)
                    throw line_error(
                        file, line,
                        fmt::format("face refers to vertex {} of {}", vi + 1, vertex_count));
                const tinyobj::real_t* p = &attrib.vertices[3 * static_cast<size_t>(vi)];
                poly.vertices.emplace_back(p[0], p[1], p[2]);
            }
            int mat = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
            if (mat >= 0 && static_cast<size_t>(mat) < materials.size()) {
                const auto& kd = materials[static_cast<size_t>(mat)].diffuse;
                poly.color = glm::dvec3(kd[0], kd[1], kd[2]);
            }
            out.push_back(std::move(poly));
            offset += n;
        }
    }
    if (out.size() != scan.face_lines.size())
        throw SceneError(fmt::format("{}: {} faces read of the {} \"f\" lines", file.string(),
                                     out.size(), scan.face_lines.size()));
    return out;
}

}  // namespace fb89::host
