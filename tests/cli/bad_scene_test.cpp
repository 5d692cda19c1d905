// Bad scenes, as a user would feed them to fb89 (docs/RELIABILITY.md, "Bad input"):
// overflowing numbers, wrong types, huge sizes, enormous or degenerate faces, broken OBJ
// files; missing, empty, directory and device files. Each must end with exit 2 and a
// message naming the file and what was wrong where (or, for input that is valid however
// odd, exit 0 with the right answer), never a crash, a hang or a half-written output.
#include <gtest/gtest.h>

#include <climits>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "controller_sim/png_io.h"
#include "protocol/stream_writer.h"
#include "tests/cli/bad_input.h"

namespace {

namespace fs = std::filesystem;
namespace pr = fb89::protocol;

using fb89::testing::CliRun;
using fb89::testing::test_dir;
using fb89::testing::bad_input::expect_refused;
using fb89::testing::bad_input::put_u16;
using fb89::testing::bad_input::put_u32;
using fb89::testing::bad_input::run_with_timeout;
using fb89::testing::bad_input::scratch;
using fb89::testing::bad_input::write_bytes;
using fb89::testing::bad_input::write_file;

const char* const kCamera =
    R"("camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 20})";

std::string scene_with(const std::string& rest) {
    return std::string("{") + kCamera + ", " + rest + "}";
}

const char* const kTriangle = R"({"polygon": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]})";

struct SceneCase {
    const char* name;
    std::string json;
    std::string says;
};

// Renders each case with --png, --ids, --stream and --stats: exit 2 naming the file and
// what was wrong, and none of the outputs written.
void expect_scenes_refused(const std::vector<SceneCase>& cases, const std::string& method) {
    for (const SceneCase& c : cases) {
        SCOPED_TRACE(std::string(c.name) + " (" + method + ")");
        const std::string path = write_file("bad.json", c.json);
        const std::string png = scratch("o.png"), ids = scratch("o_ids.png"),
                          stream = scratch("o.fb89"), stats = scratch("o.json");
        CliRun r = run_with_timeout("render " + path + " -m " + method + " --png " + png +
                                    " --ids " + ids + " --stream " + stream + " --stats " + stats);
        expect_refused(r, "bad.json", {c.says});
        for (const auto& out : {png, ids, stream, stats})
            EXPECT_FALSE(fs::exists(out)) << out << " must not be written";
    }
}

TEST(BadInputScene, OverflowingNumbersAreRefusedNamingTheField) {
    std::vector<SceneCase> cases = {
        {"1e999 in a vertex",
         scene_with(R"("objects": [{"polygon": [[0, 0, 0], [1e999, 0, 0], [0, 1, 0]]}])"),
         "number overflow"},
        {"-1e999 in the eye",
         R"({"camera": {"eye": [0, 0, -1e999], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 20}, "objects": []})",
         "number overflow"},
        {"NaN literal",
         scene_with(R"("objects": [{"polygon": [[NaN, 0, 0], [1, 0, 0], [0, 1, 0]]}])"),
         "invalid JSON"},
        {"Infinity literal", scene_with(R"("background": [Infinity, 0, 0], "objects": [])"),
         "invalid JSON"},
        {"scale overflowing to inf",
         scene_with(std::string(
             R"("objects": [{"polygon": [[1e300, 0, 0], [0, 1e300, 0], [0, 0, 0]], "transform": {"scale": 1e300}}])")),
         "objects[0]: face 0"},
        {"1e999 in the fov",
         R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fovy": 1e999, "near": 1, "far": 20}, "objects": []})",
         "number overflow"},
    };
    expect_scenes_refused(cases, "zbuffer");
}

TEST(BadInputScene, WrongTypesNameTheFieldAndWhatWasExpected) {
    std::vector<SceneCase> cases = {
        {"objects an object", scene_with(R"("objects": {"polygon": []})"), "objects"},
        {"camera an array", R"({"camera": [0, 0, 5], "objects": []})", "camera"},
        {"width a string", scene_with(R"("image": {"width": "big", "height": 10}, "objects": [])"),
         "image.width"},
        {"width a fraction", scene_with(R"("image": {"width": 10.5, "height": 10}, "objects": [])"),
         "image.width"},
        {"vertex a string", scene_with(R"("objects": [{"polygon": ["a", "b", "c"]}])"),
         "objects[0].polygon"},
        {"colour a name",
         scene_with(std::string(
             R"("objects": [{"polygon": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": {"color": "red"}}])")),
         "objects[0].material.color"},
        {"mirror a string",
         scene_with(std::string(
             R"("objects": [{"polygon": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": {"color": [1, 1, 1], "mirror": "yes"}}])")),
         "mirror"},
        {"root an array", "[1, 2, 3]", "bad.json"},
    };
    expect_scenes_refused(cases, "zbuffer");
}

TEST(BadInputScene, HugeImageSizesAreRefused) {
    std::vector<SceneCase> cases = {
        {"width 16385",
         scene_with(std::string(R"("image": {"width": 16385, "height": 10}, "objects": [)") +
                    kTriangle + "]"),
         "image.width: expected an integer in [1, 16384]"},
        {"height 1e9",
         scene_with(std::string(R"("image": {"width": 10, "height": 1000000000}, "objects": [)") +
                    kTriangle + "]"),
         "image.height"},
        {"height 1e30",
         scene_with(std::string(R"("image": {"width": 10, "height": 1e30}, "objects": [)") +
                    kTriangle + "]"),
         "image.height"},
        {"negative width",
         scene_with(std::string(R"("image": {"width": -4, "height": 10}, "objects": [)") +
                    kTriangle + "]"),
         "image.width"},
    };
    expect_scenes_refused(cases, "zbuffer");
    const std::string ok =
        write_file("ok.json", scene_with(std::string(R"("objects": [)") + kTriangle + "]"));
    for (const char* size : {"99999x10", "0x10", "16385x1", "10x-1"}) {
        SCOPED_TRACE(size);
        const std::string png = scratch("o.png");
        CliRun r = run_with_timeout("render " + ok + " --size " + size + " --png " + png);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("--size"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(png));
    }
}

// A triangle of 1e30 extent is refused (clipping it in double precision would lose it);
// one of 1e12, the largest allowed, covers every pixel around a small one, in every method.
TEST(BadInputScene, AFaceOf1e30ExtentIsRefusedAndOneOf1e12CoversTheScreen) {
    expect_scenes_refused(
        {{"1e30 extent",
          scene_with(
              R"("objects": [{"polygon": [[-1e30, -1e30, 0], [1e30, -1e30, 0], [0, 1e30, 0]]}])"),
          "objects[0]: face 0: a vertex coordinate is beyond ±1e12"}},
        "zbuffer");
    const std::string path = write_file(
        "vast.json",
        scene_with(
            R"("image": {"width": 64, "height": 48}, "objects": [{"polygon": [[-1e12, -1e12, 0], [1e12, -1e12, 0], [0, 1e12, 0]]}, {"polygon": [[-1, -1, 1], [1, -1, 1], [0, 1, 1]]}])"));
    for (const char* method : {"zbuffer", "warnock", "scanline", "hybrid", "raytrace", "beam"}) {
        SCOPED_TRACE(method);
        const std::string ids = scratch(std::string(method) + "_ids.png");
        CliRun r = run_with_timeout("render " + path + " -q -m " + method + " --ids " + ids);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto image = fb89::controller::read_png(ids);
        size_t vast = 0, small = 0;
        for (size_t p = 0; p < image.pixels.size() / 3; ++p) {
            const uint8_t id = image.pixels[3 * p + 2];  // id + 1, low byte
            EXPECT_TRUE(id == 1 || id == 2) << "pixel " << p << " holds " << int(id);
            vast += id == 1, small += id == 2;
            if (id != 1 && id != 2) break;
        }
        EXPECT_GT(small, 0u);
        EXPECT_EQ(vast + small, 64u * 48u);
    }
}

TEST(BadInputScene, DegenerateFacesAreDroppedAndReportedNeverDrawn) {
    const std::string path =
        write_file("flat.json", scene_with(
                                    R"("image": {"width": 32, "height": 24}, "objects": [
                {"polygon": [[0, 0, 0], [1, 1, 0], [2, 2, 0]]},
                {"polygon": [[0, 0, 0], [0, 0, 0], [0, 0, 0]]},
                {"polygon": [[0, 0, 0], [1, 0, 0], [1, 0, 0], [0, 0, 0]]},
                {"polygon": [[0, 0, 0], [1e-300, 0, 0], [0, 1e-300, 0]]},
                {"polygon": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]}])"));
    for (const char* method : {"zbuffer", "warnock", "scanline", "raytrace", "beam"}) {
        SCOPED_TRACE(method);
        const std::string ids = scratch("flat_ids.png");
        CliRun r = run_with_timeout("render " + path + " -m " + method + " --ids " + ids);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        for (const char* where : {"objects[0]: face 0: dropped", "objects[1]: face 0: dropped",
                                  "objects[2]: face 0: dropped", "objects[3]: face 0: dropped"})
            EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
        const auto image = fb89::controller::read_png(ids);
        for (size_t p = 0; p < image.pixels.size() / 3; ++p) {
            const uint8_t id = image.pixels[3 * p + 2];
            ASSERT_TRUE(id == 0 || id == 5)
                << "only the whole triangle (id 4, its index in the file) is drawn, pixel " << p
                << " holds id + 1 = " << int(id);
        }
    }
}

TEST(BadInputScene, MissingEmptyAndDirectoryFilesNameThePath) {
    const std::string dir = scratch("dir.json");
    fs::create_directories(dir);
    fs::create_directories(scratch("meshdir.obj"));
    std::vector<SceneCase> cases = {
        {"empty scene", "", "invalid JSON"},
        {"only a comment", "// nothing\n", "invalid JSON"},
        {"cut in the middle", std::string("{") + kCamera + R"(, "objects": [{"polygon": [[0, 0)",
         "line 1"},
        {"missing OBJ", scene_with(R"("objects": [{"obj": "nowhere.obj"}])"),
         "nowhere.obj: cannot open the OBJ file"},
        {"OBJ a directory", scene_with(R"("objects": [{"obj": "meshdir.obj"}])"),
         "meshdir.obj: is a directory, not an OBJ file"},
    };
    expect_scenes_refused(cases, "zbuffer");
    CliRun missing = run_with_timeout("render /nonexistent/scene.json");
    expect_refused(missing, "/nonexistent/scene.json", {"cannot open"});
    expect_refused(run_with_timeout("render " + dir), "dir.json", {"is a directory"});
    expect_refused(run_with_timeout("render " + write_file("scene.yaml", "camera: {}")),
                   "scene.yaml", {"unknown scene format"});
    expect_refused(run_with_timeout("radiosity " + write_file("empty.json", "")), "empty.json", {});
}

TEST(BadInputScene, BrokenObjFilesNameTheFile) {
    struct Obj {
        const char* name;
        const char* text;
        const char* says;
    };
    const Obj objs[] = {
        {"bad index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n",
         "mesh.obj: line 4: face refers to vertex 99 of 3"},
        {"zero index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 0 2\n",
         "mesh.obj: line 4: face vertex 2: index 0"},
        {"binary",
         "v 0 0 0\n\x7f"
         "ELF\x02\x01\n",
         "mesh.obj: line 2: not text (byte 0x7f"},
        {"plain text", "Dear reader,\nno model here.\n",
         "mesh.obj: no faces (an OBJ model needs at least one \"f\" line; read 0 vertices, 0 "
         "faces from 2 lines; line 1, 'Dear reader,', is not an OBJ statement)"},
        {"empty", "", "mesh.obj: no faces"},
        {"nan vertex", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
         "mesh.obj: line 1: vertex coordinate 1: expected a finite number, got 'nan'"},
        {"inf vertex", "v 1 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n",
         "mesh.obj: line 2: vertex coordinate 1: expected a finite number, got '1e999'"},
        {"word vertex", "v 0 0 0\nv 1 0 0\nv 0 abc 0\nf 1 2 3\n",
         "line 3: vertex coordinate 2: expected a finite number, got 'abc'"},
        {"missing coordinate", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n",
         "line 2: vertex coordinate 3: expected a finite number, got ''"},
        {"two-vertex face", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n",
         "mesh.obj: line 5: a face of 2 vertices; a face needs 3 or more"},
        {"one-vertex face", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 3 # one\nf 1 2 3\n",
         "mesh.obj: line 4: a face of 1 vertex; a face needs 3 or more"},
    };
    std::vector<SceneCase> cases;
    for (const Obj& o : objs) {
        write_file("mesh.obj", o.text);
        cases = {{o.name, scene_with(R"("objects": [{"obj": "mesh.obj"}])"), o.says}};
        expect_scenes_refused(cases, "zbuffer");
    }
}

// Zero-area OBJ faces at the start, in the middle and at the end are dropped and reported,
// and every other face keeps its index in the file as its id, in the id buffer of every
// method: a dropped face leaves its id unused. Lines and points are counted, not drawn.
TEST(BadInputScene, DroppedObjFacesLeaveTheirIdsUnusedAndTheRestKeepTheirIndex) {
    // four quads side by side across the view, with a flat face before, between and after
    write_file("strip.obj",
               "v -2 -0.5 0\nv -1 -0.5 0\nv -1 0.5 0\nv -2 0.5 0\n"  // 1-4: quad A
               "v -1 -0.5 0\nv 0 -0.5 0\nv 0 0.5 0\nv -1 0.5 0\n"    // 5-8: quad B
               "v 0 -0.5 0\nv 1 -0.5 0\nv 1 0.5 0\nv 0 0.5 0\n"      // 9-12: quad C
               "v 1 -0.5 0\nv 2 -0.5 0\nv 2 0.5 0\nv 1 0.5 0\n"      // 13-16: quad D
               "f 1 2 1\n"                                           // 0: flat (start)
               "f 1 2 3 4\nf 5 6 7 8\n"                              // 1, 2
               "f 5 5 5\n"                                           // 3: flat (middle)
               "f 9 10 11 12\nf 13 14 15 16\n"                       // 4, 5
               "l 1 2\np 3\n"                                        // not faces
               "f 16 15 16\n");                                      // 6: flat (end)
    const std::string scene = write_file(
        "strip.json",
        R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fovy": 60, "near": 0.1, "far": 100},
            "image": {"width": 64, "height": 16},
            "objects": [{"polygon": [[-9, -9, -5], [9, -9, -5], [9, 9, -5]]},
                        {"obj": "strip.obj"}]})");
    for (const char* method : {"zbuffer", "warnock", "scanline", "hybrid", "raytrace", "beam"}) {
        SCOPED_TRACE(method);
        const std::string ids = scratch("strip_ids.png");
        CliRun r = run_with_timeout("render " + scene + " -m " + method + " --ids " + ids);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        // ids count across objects: the big triangle is 0, the OBJ's faces 1 to 7
        for (const char* note :
             {"objects[1]: face 0: dropped (fewer than 3 distinct vertices); id 1 unused",
              "objects[1]: face 3: dropped (fewer than 3 distinct vertices); id 4 unused",
              "objects[1]: face 6: dropped (fewer than 3 distinct vertices); id 7 unused",
              "1 line and 1 point element(s) skipped"})
            EXPECT_NE(r.err.find(note), std::string::npos) << note << "\n" << r.err;
        const auto image = fb89::controller::read_png(ids);
        // along the middle row, left to right: quads A, B, C, D have ids 2, 3, 5, 6
        std::vector<int> seen;
        const size_t row = 8;
        for (size_t x = 0; x < image.width; ++x) {
            const int id_plus_1 = image.pixels[3 * (row * image.width + x) + 2];
            if (id_plus_1 >= 2 && (seen.empty() || seen.back() != id_plus_1 - 1))
                seen.push_back(id_plus_1 - 1);
        }
        EXPECT_EQ(seen, (std::vector<int>{2, 3, 5, 6}));
    }
}

TEST(BadInputScene, RadiosityWithoutAnEmitterOrFacesIsAnError) {
    const std::string dark =
        write_file("dark.json", scene_with(std::string(R"("objects": [)") + kTriangle + "]"));
    const std::string png = scratch("r.png");
    CliRun r = run_with_timeout("radiosity " + dark + " --png " + png);
    expect_refused(r, "dark.json", {"emi"});
    EXPECT_FALSE(fs::exists(png));
    const std::string none = write_file("none.json", scene_with(R"("objects": [])"));
    EXPECT_EQ(run_with_timeout("radiosity " + none + " --png " + png).exit_code, 2);
    EXPECT_FALSE(fs::exists(png));
}

}  // namespace

namespace {

TEST(BadInputDevice, ADeviceGivenAsAFileIsRefusedNotReadForever) {
    // /dev/zero would never end; a scene, an OBJ and a call-set file must be regular files
    fb89::testing::CliRun scene = fb89::testing::run_fb89("render /dev/zero -q");
    EXPECT_EQ(scene.exit_code, 2);
    EXPECT_NE(scene.err.find("not a regular file"), std::string::npos) << scene.err;
    const auto dir = fb89::testing::test_dir();
    std::ofstream(dir / "obj_device.json")
        << R"({ "camera": {"eye": [0,0,5], "look_at": [0,0,0], "up": [0,1,0], "fovy": 45,
               "near": 0.1, "far": 100},
               "objects": [ { "obj": "/dev/zero", "material": {"color": [1,1,1]} } ] })";
    fb89::testing::CliRun obj =
        fb89::testing::run_fb89("render " + (dir / "obj_device.json").string() + " -q");
    EXPECT_EQ(obj.exit_code, 2);
    EXPECT_NE(obj.err.find("not a regular file"), std::string::npos) << obj.err;
}

}  // namespace
