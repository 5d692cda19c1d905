// OBJ files as users bring them: garbage, other formats and empty models are errors naming
// the file (and the first line that is not OBJ); every bad face or vertex names its line; a
// missing material library or material is a warning naming it and its line, and the faces
// load grey.
#include "host/scene/obj_loader.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "host/scene/scene_error.h"
#include "tests/scratch.h"

namespace fb89::host {
namespace {

namespace fs = std::filesystem;

fs::path write(const std::string& name, const std::string& text) {
    const fs::path dir = fb89::testing::scratch_path("obj_loader");
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary) << text;
    return dir / name;
}

// The error message of loading `text` as `name`, or "" when it loads.
std::string obj_error_of(const std::string& name, const std::string& text) {
    try {
        load_obj(write(name, text));
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

void expect_has(const std::string& text, const std::string& part) {
    EXPECT_NE(text.find(part), std::string::npos) << "expected '" << part << "' in:\n" << text;
}

// The notes of loading `text` as `name` (which must load).
std::string notes_of(const std::string& name, const std::string& text,
                     GeneratedPolygons* polys = nullptr) {
    std::vector<std::string> notes;
    GeneratedPolygons p = load_obj(write(name, text), &notes);
    if (polys) *polys = p;
    std::string all;
    for (const auto& n : notes)
        all += n + "\n";
    return all;
}

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ObjLoader, BinaryGarbageIsAnErrorNamingTheFileAndTheLineThatIsNotText) {
    std::string bytes;
    uint32_t x = 12345;
    for (int i = 0; i < 4096; ++i) {
        x = x * 1664525u + 1013904223u;
        bytes += static_cast<char>(x >> 24);
    }
    const std::string e = obj_error_of("garbage.obj", bytes);
    expect_has(e, "garbage.obj: line ");
    expect_has(e, "not text (byte 0x");
    // a PNG's signature: line 1 is "\x89PNG\r", line 2 begins with the byte 0x1a
    const std::string png =
        obj_error_of("png.obj", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
    expect_has(png, "png.obj: line 2: not text (byte 0x1a in column 1)");
    expect_has(png, "line 1, '\\x89PNG', is no OBJ statement either");
}

TEST(ObjLoader, TextWithNoFacesIsAnErrorNamingTheFirstLineThatIsNotObj) {
    EXPECT_EQ(obj_error_of("readme.obj", "hello world\nthis is not a model\n# a comment\n"),
              write("readme.obj", "").string() +
                  ": no faces (an OBJ model needs at least one \"f\" line; read 0 vertices, 0 "
                  "faces from 3 lines; line 1, 'hello world', is not an OBJ statement)");
    const std::string json = obj_error_of("scene.obj", "{\"camera\": {}, \"objects\": []}\n");
    expect_has(json, "scene.obj: no faces");
    expect_has(json, "line 1, '{\"camera\": {}, \"objects\": []}', is not an OBJ statement");
}

TEST(ObjLoader, AModelWithNoFacesIsAnError) {
    expect_has(obj_error_of("empty.obj", ""),
               "empty.obj: no faces (an OBJ model needs at least one \"f\" line; read 0 "
               "vertices, 0 faces from 0 lines: the file is empty)");
    expect_has(obj_error_of("comments.obj", "# only\n\n# comments\n"),
               "comments.obj: no faces (an OBJ model needs at least one \"f\" line; read 0 "
               "vertices, 0 faces from 3 lines)");
    expect_has(obj_error_of("points.obj", kTriangle + "l 1 2\np 3\n"),
               "points.obj: no faces (an OBJ model needs at least one \"f\" line; read 3 "
               "vertices, 0 faces from 5 lines; 1 line and 1 point element(s), which fb89 "
               "does not draw)");
}

TEST(ObjLoader, EveryBadFaceOrVertexNamesItsLine) {
    struct Case {
        std::string text, says;
    };
    const Case cases[] = {
        {kTriangle + "f 1 2 3\nf 1 2 99\n", "bad.obj: line 5: face refers to vertex 99 of 3"},
        {kTriangle + "f 1 2 0\n",
         "bad.obj: line 4: face vertex 3: index 0; OBJ indices start at 1"},
        {kTriangle + "f -1 -2 -4\n",
         "bad.obj: line 4: face vertex 3: index -4 counts back past the first vertex (3 "
         "vertices before this line)"},
        {kTriangle + "f 1 two 3\n",
         "bad.obj: line 4: face vertex 2: expected a vertex index (a whole number), got 'two'"},
        {kTriangle + "f 1/1 2x/1 3\n", "line 4: face vertex 2: expected a vertex index"},
        {kTriangle + "f 1 2\n", "bad.obj: line 4: a face of 2 vertices; a face needs 3 or more"},
        {kTriangle + "f\n", "bad.obj: line 4: a face of 0 vertices"},
        {"v 0 0 0\nv 1 zero 0\nv 0 1 0\nf 1 2 3\n",
         "bad.obj: line 2: vertex coordinate 2: expected a finite number, got 'zero'"},
        {"v 0 0 0\nv 1 0 0\nv 0 1e999 0\nf 1 2 3\n",
         "bad.obj: line 3: vertex coordinate 2: expected a finite number, got '1e999'"},
        {"v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n",
         "bad.obj: line 2: vertex coordinate 3: expected a finite number, got ''"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.text);
        expect_has(obj_error_of("bad.obj", c.text), c.says);
    }
}

TEST(ObjLoader, IndicesMayCountBackOrReferToVerticesListedLater) {
    GeneratedPolygons polys;
    notes_of("order.obj", "f 1 2 3\n" + kTriangle + "f -3 -2 -1\nf 1/1/1 2//2 3/3\n", &polys);
    ASSERT_EQ(polys.size(), 3u);
    for (const auto& p : polys)
        EXPECT_EQ(p.vertices, (std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
}

TEST(ObjLoader, AMissingMaterialLibraryIsAWarningNamingItAndTheFacesLoadGrey) {
    GeneratedPolygons polys;
    const fs::path file = write("model.obj", "");
    const std::string notes = notes_of(
        "model.obj",
        "# a model\nv 0 0 0\nmtllib model.mtl\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n", &polys);
    expect_has(notes, file.string() + ": line 3: material library 'model.mtl' not found (in " +
                          file.parent_path().string() + "): faces are grey");
    EXPECT_EQ(notes.find("usemtl"), std::string::npos) << "the library's note says it:\n" << notes;
    ASSERT_EQ(polys.size(), 1u);
    EXPECT_FALSE(polys[0].color);
}

TEST(ObjLoader, AnUndefinedMaterialIsAWarningNamingItsFirstLine) {
    write("colours.mtl", "newmtl red\nKd 1 0 0\n");
    GeneratedPolygons polys;
    const std::string notes = notes_of(
        "colours.obj",
        "mtllib colours.mtl\n" + kTriangle +
            "usemtl red\nf 1 2 3\nusemtl blue\nf 1 2 3\nusemtl red\nusemtl blue\nf 3 2 1\n",
        &polys);
    expect_has(notes,
               "colours.obj: line 7: material 'blue' is in no material library of the "
               "file: its faces are grey");
    EXPECT_EQ(notes.find("line 10"), notes.npos) << "once per material:\n" << notes;
    ASSERT_EQ(polys.size(), 3u);
    EXPECT_EQ(polys[0].color, glm::dvec3(1, 0, 0));
    EXPECT_FALSE(polys[1].color);
    const std::string bare = notes_of("bare.obj", kTriangle + "usemtl skin\nf 1 2 3\n");
    expect_has(bare,
               "bare.obj: line 4: usemtl 'skin', but the file names no material library "
               "(mtllib): its faces are grey");
}

TEST(ObjLoader, LinesThatAreNotObjStatementsAreIgnoredWithANote) {
    GeneratedPolygons polys;
    const std::string notes =
        notes_of("extra.obj", kTriangle + "frobnicate 3\nf 1 2 3\nxyz\nqq\n", &polys);
    expect_has(notes,
               "extra.obj: line 4: 'frobnicate 3' is not an OBJ statement: ignored (and 2 "
               "more such lines)");
    EXPECT_EQ(polys.size(), 1u);
    // statements fb89 does not draw or need are OBJ all the same
    EXPECT_EQ(notes_of("known.obj", "o thing\ng part\ns 1\nvn 0 0 1\nvt 0 0\n" + kTriangle +
                                        "f 1//1 2//1 3//1\n"),
              "");
}

}  // namespace
}  // namespace fb89::host
