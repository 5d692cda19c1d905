// Bad input, as a user would feed it to fb89 (docs/RELIABILITY.md, "Bad input"): command
// streams cut short, corrupt, of a newer version or claiming gigabytes; scenes with
// overflowing numbers, wrong types, huge sizes, enormous or degenerate faces; missing,
// empty and directory files. Every run has a generous time-out; each must end with exit 2
// and a message naming the file and what was wrong where (or, for input that is valid
// however odd, exit 0 with the right answer), never a crash, a hang or a half-written
// output that looks valid.
#include <gtest/gtest.h>

#include <climits>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "controller_sim/png_io.h"
#include "protocol/stream_writer.h"
#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
namespace pr = fb89::protocol;

using fb89::testing::CliRun;
using fb89::testing::test_dir;

// A crash shows as 128 + signal, a hang as timeout's 124.
CliRun fb89(const std::string& args) {
    return fb89::testing::run_fb89(args, "timeout -s KILL 120 ");
}

std::string scratch(const std::string& name) {
    return (test_dir() / name).string();
}

std::string write_file(const std::string& name, const std::string& text) {
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

std::string write_bytes(const std::string& name, const std::vector<uint8_t>& bytes) {
    const std::string path = scratch(name);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
    return path;
}

void put_u16(std::vector<uint8_t>& b, size_t at, uint16_t v) {
    b[at] = static_cast<uint8_t>(v), b[at + 1] = static_cast<uint8_t>(v >> 8);
}

void put_u32(std::vector<uint8_t>& b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i)
        b[at + i] = static_cast<uint8_t>(v >> (8 * i));
}

// Exit 2, the file named in an "fb89: error" or "fb89: usage" line, and every `needle`.
void expect_refused(const CliRun& r, const std::string& file,
                    const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("fb89: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(file), std::string::npos) << "the message must name " << file << ":\n"
                                                   << r.err;
    for (const auto& n : needles)
        EXPECT_NE(r.err.find(n), std::string::npos) << "expected '" << n << "' in:\n" << r.err;
}

// Two 8x6 frames, no properties: FRAME_BEGIN @12, FILL_RECT @28, FRAME_END @48,
// FRAME_BEGIN @49, FILL_RECT @65, FRAME_END @85, frame index @86 .. 150.
constexpr size_t kFirstRecord = 12, kFrame0End = 49, kIndexAt = 86, kStreamSize = 151;

std::vector<uint8_t> two_frames() {
    return pr::encode_stream({pr::FrameBegin{0, 8, 6, pr::Rgb{0, 0, 0}},
                              pr::FillRect{0, 0, 4, 4, pr::Rgb{255, 0, 0}}, pr::FrameEnd{},
                              pr::FrameBegin{1, 8, 6, pr::Rgb{0, 0, 64}},
                              pr::FillRect{2, 2, 3, 3, pr::Rgb{9, 9, 9}}, pr::FrameEnd{}});
}

// Header of version 1 with no properties.
std::vector<uint8_t> bare_header() {
    std::vector<uint8_t> b = two_frames();
    b.resize(kFirstRecord);
    return b;
}

const char* const kCamera =
    R"("camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fovy": 45, "near": 1, "far": 20})";

std::string scene_with(const std::string& rest) {
    return std::string("{") + kCamera + ", " + rest + "}";
}

const char* const kTriangle = R"({"polygon": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]})";

// ---- command streams ----------------------------------------------------------------------

TEST(BadInputStream, NewerVersionsAreRefusedNamingBothVersions) {
    ASSERT_EQ(two_frames().size(), kStreamSize);
    for (const uint16_t version : {uint16_t{2}, uint16_t{7}, uint16_t{65535}}) {
        std::vector<uint8_t> b = two_frames();
        put_u16(b, 4, version);
        const std::string path = write_bytes("v.fb89", b);
        for (const char* tool : {"replay", "dump", "info", "trim"}) {
            SCOPED_TRACE(std::string(tool) + " version " + std::to_string(version));
            const std::string extra =
                std::string(tool) == "trim" ? " --calls 0- -o " + scratch("t.fb89") : "";
            expect_refused(fb89(std::string(tool) + " " + path + extra), "v.fb89",
                           {"version " + std::to_string(version), "up to 1"});
        }
    }
}

TEST(BadInputStream, TruncationKeepsCompleteFramesAndWritesNoPngWithoutOne) {
    struct Cut {
        size_t size;
        const char* says;  // in the message
        int frames;        // complete frames before the cut
    };
    const Cut cuts[] = {{0, "truncated", 0},     {3, "truncated", 0},
                        {7, "truncated", 0},     {10, "truncated", 0},
                        {20, "truncated", 0},    {40, "truncated", 0},
                        {70, "truncated", 1},    {kIndexAt + 3, "truncated", 2},
                        {kStreamSize - 1, "", 2}};
    for (const Cut& cut : cuts) {
        SCOPED_TRACE("cut to " + std::to_string(cut.size) + " bytes");
        std::vector<uint8_t> b = two_frames();
        b.resize(cut.size);
        const std::string path = write_bytes("cut.fb89", b), png = scratch("cut.png");
        fs::remove(png);
        CliRun r = fb89("replay " + path + " --png " + png);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_NE(r.err.find("fb89: error: " + path + ": " + cut.says), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("at byte"), std::string::npos) << r.err;
        if (cut.frames == 0) {
            EXPECT_FALSE(fs::exists(png)) << "no complete frame: nothing to write";
        } else {
            ASSERT_TRUE(fs::exists(png));
            const auto image = fb89::controller::read_png(png);
            EXPECT_EQ(image.pixels[2], cut.frames == 1 ? 0 : 64) << "the last complete frame";
        }
        for (const char* tool : {"dump", "info"})
            EXPECT_EQ(fb89(std::string(tool) + " " + path).exit_code, 2) << tool;
    }
    // a stream cut right after a complete record is a valid (cut) stream
    std::vector<uint8_t> b = two_frames();
    b.resize(kFrame0End);
    EXPECT_EQ(fb89("replay " + write_bytes("cut.fb89", b)).exit_code, 0);
}

TEST(BadInputStream, CorruptOpcodesNameTheOffsetAndCommand) {
    for (const int opcode : {0x00, 0x06, 0x42, 0xFD, 0xFF}) {
        SCOPED_TRACE("opcode " + std::to_string(opcode));
        std::vector<uint8_t> b = two_frames();
        b[kFrame0End] = static_cast<uint8_t>(opcode);  // command 3
        const std::string path = write_bytes("bad.fb89", b), png = scratch("bad.png");
        expect_refused(fb89("replay " + path + " --png " + png), "bad.fb89",
                       {"at byte 49", "command 3"});
        EXPECT_TRUE(fs::exists(png)) << "frame 0 stays usable";
    }
    // garbage from the first byte: not a stream at all
    const std::string text = write_file("text.fb89", "this is not an fb89 stream\n");
    expect_refused(fb89("info " + text), "text.fb89", {"magic"});
}

TEST(BadInputStream, SizesClaimingGigabytesAreRefusedBeforeAllocating) {
    struct Case {
        const char* name;
        std::vector<uint8_t> bytes;
        const char* says;
    };
    std::vector<Case> cases;
    {  // 4 G properties
        std::vector<uint8_t> b = bare_header();
        put_u32(b, 8, 0xFFFFFFFF);
        cases.push_back({"property count", b, "property count"});
    }
    {  // a 64 KiB key, a 4 GiB value
        std::vector<uint8_t> b = bare_header();
        put_u32(b, 8, 1);
        b.insert(b.end(), {0xFF, 0xFF, 'k'});
        cases.push_back({"key length", b, "key"});
        b = bare_header();
        put_u32(b, 8, 1);
        b.insert(b.end(), {1, 0, 'k', 0xFF, 0xFF, 0xFF, 0xFF, 'v'});
        cases.push_back({"value length", b, "value"});
    }
    {  // a 64 KiB marker
        std::vector<uint8_t> b = bare_header();
        b.insert(b.end(), {0x04, 0xFF, 0xFF, 'm', 'm'});
        cases.push_back({"marker length", b, "MARKER"});
    }
    {  // a frame 4 G pixels wide, one 16385 high
        std::vector<uint8_t> b = two_frames();
        put_u32(b, kFirstRecord + 5, 0xFFFFFFFF);
        cases.push_back({"frame width", b, "width"});
        b = two_frames();
        put_u32(b, kFirstRecord + 9, 16385);
        cases.push_back({"frame height", b, "height"});
    }
    {  // a frame index of 4 G entries (80 GB)
        std::vector<uint8_t> b = two_frames();
        put_u32(b, kIndexAt + 1, 0xFFFFFFFF);
        cases.push_back({"index entries", b, "index"});
    }
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = write_bytes("huge.fb89", c.bytes);
        for (const char* tool : {"replay", "dump", "info"})
            expect_refused(fb89(std::string(tool) + " " + path), "huge.fb89", {c.says, "byte"});
    }
}

TEST(BadInputStream, FillsAndSpansReachingFarOutsideAreClippedNotRefused) {
    const std::string path = write_bytes(
        "far.fb89",
        pr::encode_stream({pr::FrameBegin{0, 16384, 16384, pr::Rgb{0, 0, 0}},
                           pr::FillRect{INT_MIN, INT_MIN, 0xFFFFFFFF, 0xFFFFFFFF, pr::Rgb{1, 2, 3}},
                           pr::DrawSpan{INT_MAX, INT_MIN, INT_MAX, pr::Rgb{4, 5, 6}},
                           pr::DrawSpan{5, INT_MIN, INT_MAX, pr::Rgb{7, 8, 9}},
                           pr::FillRect{INT_MAX, INT_MAX, 0xFFFFFFFF, 1, pr::Rgb{1, 1, 1}},
                           pr::FrameEnd{}}));
    const std::string stats = scratch("far.json");
    CliRun r = fb89("replay " + path + " -q --stats " + stats);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(fb89::testing::slurp(stats).find("\"frames_closed\": 1"), std::string::npos);
}

TEST(BadInputStream, MissingEmptyAndDirectoryStreamsNameThePath) {
    const std::string dir = scratch("dir.fb89");
    fs::create_directories(dir);
    const std::string empty = write_file("empty.fb89", "");
    for (const char* tool : {"replay", "dump", "info"}) {
        SCOPED_TRACE(tool);
        expect_refused(fb89(std::string(tool) + " /nonexistent/s.fb89"), "/nonexistent/s.fb89", {});
        expect_refused(fb89(std::string(tool) + " " + empty), "empty.fb89", {"truncated"});
        expect_refused(fb89(std::string(tool) + " " + dir), "dir.fb89", {});
    }
}

// ---- scenes -------------------------------------------------------------------------------

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
        CliRun r = fb89("render " + path + " -m " + method + " --png " + png + " --ids " + ids +
                        " --stream " + stream + " --stats " + stats);
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
        CliRun r = fb89("render " + ok + " --size " + size + " --png " + png);
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
        CliRun r = fb89("render " + path + " -q -m " + method + " --ids " + ids);
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
        CliRun r = fb89("render " + path + " -m " + method + " --ids " + ids);
        ASSERT_EQ(r.exit_code, 0) << r.err;
        for (const char* where : {"objects[0]: face 0: dropped", "objects[1]: face 0: dropped",
                                  "objects[2]: face 0: dropped", "objects[3]: face 0: dropped"})
            EXPECT_NE(r.err.find(where), std::string::npos) << r.err;
        const auto image = fb89::controller::read_png(ids);
        for (size_t p = 0; p < image.pixels.size() / 3; ++p) {
            const uint8_t id = image.pixels[3 * p + 2];
            ASSERT_TRUE(id == 0 || id == 1) << "only the whole triangle (id 0) is drawn, pixel "
                                            << p << " holds id + 1 = " << int(id);
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
    CliRun missing = fb89("render /nonexistent/scene.json");
    expect_refused(missing, "/nonexistent/scene.json", {"cannot open"});
    expect_refused(fb89("render " + dir), "dir.json", {"is a directory"});
    expect_refused(fb89("render " + write_file("scene.yaml", "camera: {}")), "scene.yaml",
                   {"unknown scene format"});
    expect_refused(fb89("radiosity " + write_file("empty.json", "")), "empty.json", {});
}

TEST(BadInputScene, BrokenObjFilesNameTheFile) {
    struct Obj {
        const char* name;
        const char* text;
        const char* says;
    };
    const Obj objs[] = {
        {"bad index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n", "refers to vertex 99 of 3"},
        {"nan vertex", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
         "mesh.obj: line 1: vertex coordinate 1: expected a finite number, got 'nan'"},
        {"inf vertex", "v 1 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n",
         "mesh.obj: line 2: vertex coordinate 1: expected a finite number, got '1e999'"},
        {"word vertex", "v 0 0 0\nv 1 0 0\nv 0 abc 0\nf 1 2 3\n",
         "line 3: vertex coordinate 2: expected a finite number, got 'abc'"},
        {"missing coordinate", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n",
         "line 2: vertex coordinate 3: expected a finite number, got ''"},
    };
    std::vector<SceneCase> cases;
    for (const Obj& o : objs) {
        write_file("mesh.obj", o.text);
        cases = {{o.name, scene_with(R"("objects": [{"obj": "mesh.obj"}])"), o.says}};
        expect_scenes_refused(cases, "zbuffer");
    }
}

TEST(BadInputScene, RadiosityWithoutAnEmitterOrFacesIsAnError) {
    const std::string dark =
        write_file("dark.json", scene_with(std::string(R"("objects": [)") + kTriangle + "]"));
    const std::string png = scratch("r.png");
    CliRun r = fb89("radiosity " + dark + " --png " + png);
    expect_refused(r, "dark.json", {"emi"});
    EXPECT_FALSE(fs::exists(png));
    const std::string none = write_file("none.json", scene_with(R"("objects": [])"));
    EXPECT_EQ(fb89("radiosity " + none + " --png " + png).exit_code, 2);
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
