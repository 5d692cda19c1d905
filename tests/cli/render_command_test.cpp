// `fb89 render` as a user runs it: outputs, exit codes and messages.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "controller_sim/png_io.h"
#include "tests/cli/cli_runner.h"
#include "tests/scenes_dir.h"

namespace {

namespace fs = std::filesystem;

using fb89::testing::CliRun;
using fb89::testing::run_fb89;
using fb89::testing::slurp;
using fb89::testing::test_dir;
using fb89::testing::test_file;

using fb89::testing::kScenes;

TEST(RenderCommand, WritesImageIdsStreamAndStats) {
    fs::path png = test_file("demo.png"), ids = test_file("demo.ids.png"),
             stream = test_file("demo.fb89"), stats = test_file("demo.json");
    CliRun r =
        run_fb89("render " + kScenes + "/demo.json --png " + png.string() + " --ids " +
                 ids.string() + " --stream " + stream.string() + " --stats " + stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("hidden-surface"), std::string::npos);
    EXPECT_NE(r.out.find("DRAW_SPAN"), std::string::npos);
    auto image = fb89::controller::read_png(png);
    EXPECT_EQ(image.width, 1024u);
    EXPECT_EQ(image.height, 780u);
    EXPECT_GT(fs::file_size(stream), 1000u);
    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["method"], "zbuffer");
    EXPECT_GT(j["host"]["counters"]["depth_tests"].get<uint64_t>(), 0u);
    EXPECT_TRUE(j["host"]["times"]["hidden_surface"].contains("cpu_ms"));
    EXPECT_TRUE(j["controller"].is_object());
}

// The pipeline in time: the profile's buffer (unbounded), or --buffer's; a buffer too small for
// a command, or not a number, is a usage error naming --buffer.
TEST(RenderCommand, TheBufferBoundsThePipelineInTime) {
    const fs::path stats = test_file("buffer.json");
    CliRun r = run_fb89("render " + kScenes + "/A.json --size 128x98 --stats " + stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("pipeline (send times measured, buffer unbounded): frame "),
              std::string::npos)
        << r.out;
    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["pipeline"]["buffer_bytes"], "unbounded");
    const uint64_t unbounded_high = j["pipeline"]["buffer_high_water_bytes"].get<uint64_t>();
    r = run_fb89("render " + kScenes + "/A.json --size 128x98 --buffer 64 --stats " +
                 stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("buffer 64 bytes"), std::string::npos) << r.out;
    j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["pipeline"]["buffer_bytes"], 64);
    EXPECT_LE(j["pipeline"]["buffer_high_water_bytes"].get<uint64_t>(), 64u);
    EXPECT_GT(unbounded_high, 64u);  // the host sends faster than the controller draws
    EXPECT_GT(j["pipeline"]["host_stalls"].get<uint64_t>(), 0u);
    for (const char* bad : {"5", "lots", "0"}) {
        r = run_fb89("render " + kScenes + "/A.json --size 128x98 --buffer " + std::string(bad));
        EXPECT_EQ(r.exit_code, 2) << bad;
        EXPECT_NE(r.err.find("--buffer"), std::string::npos) << r.err;
    }
}

// --timeline writes the frame through the pipeline as trace-event JSON beside the other
// outputs; a path that cannot be written is an error naming it, exit 2, nothing written.
TEST(RenderCommand, TheTimelineIsWrittenWholeOrNotAtAll) {
    const fs::path timeline = test_file("timeline.json");
    const fs::path png = test_file("timeline.png");
    CliRun r = run_fb89("render " + kScenes + "/A.json --size 128x98 -q --buffer 256 --timeline " +
                        timeline.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(timeline));
    EXPECT_EQ(j.at("otherData").at("buffer_bytes"), 256);
    EXPECT_NE(j.at("otherData").at("title").get<std::string>().find("zbuffer"), std::string::npos);
    EXPECT_GT(j.at("traceEvents").size(), 100u);
    // into a folder that is a file: refused, and the PNG of the same command not written
    const fs::path blocked = test_file("a-file");
    { std::ofstream(blocked) << "x"; }
    fs::remove(png);
    r = run_fb89("render " + kScenes + "/A.json --size 128x98 -q --png " + png.string() +
                 " --timeline " + (blocked / "t.json").string());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("a-file"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(png));
}

// The kernels' instruction set: --isa and $FB89_ISA force one, --stats says which ran, every
// one this machine runs counts the same; a name it does not know is a usage error naming it.
TEST(RenderCommand, TheKernelsInstructionSetIsChosenReportedAndChecked) {
    const std::string render = "render G --size 96x73 -q --stats - -m beam";
    const CliRun best = run_fb89(render);
    ASSERT_EQ(best.exit_code, 0) << best.err;
    const nlohmann::json best_stats = nlohmann::json::parse(best.out);
    EXPECT_EQ(best_stats.at("accel"), "bvh");
    const CliRun baseline = run_fb89(render + " --isa baseline");
    ASSERT_EQ(baseline.exit_code, 0) << baseline.err;
    const nlohmann::json stats = nlohmann::json::parse(baseline.out);
    EXPECT_EQ(stats.at("kernels"), "baseline");
    EXPECT_EQ(stats.at("host").at("counters"), best_stats.at("host").at("counters"));
    const CliRun from_env = fb89::testing::run_fb89(render, "FB89_ISA=baseline ");
    ASSERT_EQ(from_env.exit_code, 0) << from_env.err;
    EXPECT_EQ(nlohmann::json::parse(from_env.out).at("kernels"), "baseline");

    const CliRun bad = run_fb89(render + " --isa v9");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("v9"), std::string::npos) << bad.err;
    const CliRun bad_env = fb89::testing::run_fb89(render, "FB89_ISA=v9 ");
    EXPECT_EQ(bad_env.exit_code, 2);
    EXPECT_NE(bad_env.err.find("$FB89_ISA: expected baseline, v3 or v4, got 'v9'"),
              std::string::npos)
        << bad_env.err;
    const CliRun bad_accel = run_fb89(render + " --accel octree");
    EXPECT_EQ(bad_accel.exit_code, 2);
    EXPECT_NE(bad_accel.err.find("octree"), std::string::npos) << bad_accel.err;
}

TEST(RenderCommand, SizeOverridesTheScene) {
    fs::path png = test_file("small.png");
    CliRun r =
        run_fb89("render " + kScenes + "/cornell_box.json --size 256x195 -q --png " + png.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "");
    auto image = fb89::controller::read_png(png);
    EXPECT_EQ(image.width, 256u);
    EXPECT_EQ(image.height, 195u);
}

TEST(RenderCommand, ASizeOutOfRangeSaysTheRange) {
    for (const char* size : {"100000x100000", "0x10", "99999999999x2"}) {
        const CliRun r = run_fb89(std::string("render A --size ") + size);
        EXPECT_EQ(r.exit_code, 2) << size;
        EXPECT_NE(r.err.find("width and height must be in [1, 16384]"), std::string::npos) << r.err;
    }
    const CliRun shape = run_fb89("render A --size big");
    EXPECT_EQ(shape.exit_code, 2);
    EXPECT_NE(shape.err.find("expected WxH such as 1024x780, width and height in [1, 16384]"),
              std::string::npos)
        << shape.err;
}

// A bundled scene by name, from any folder; a name that is nowhere lists the bundled ones.
TEST(RenderCommand, BundledScenesAreFoundByNameFromAnyFolder) {
    const fs::path png = test_file("by_name.png");
    const CliRun r = fb89::testing::run_fb89("render demo -q --png " + png.string(), "cd / && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(png));
    const CliRun missing =
        fb89::testing::run_fb89("render nosuch --png " + png.string(), "cd / && ");
    EXPECT_EQ(missing.exit_code, 2);
    for (const std::string& said :
         std::vector<std::string>{"nosuch: cannot open the scene file: no bundled scene of that "
                                  "name, nor a file in the current folder",
                                  "(the bundled scenes: A, B, C", "; fb89 list scenes)"})
        EXPECT_NE(missing.err.find(said), std::string::npos) << said << "\n" << missing.err;
    // the table names it as the user did, or by its bundled name; never an absolute path
    const CliRun shown =
        fb89::testing::run_fb89("render " + kScenes + "/A.json --size 32x24 --png " + png.string());
    EXPECT_EQ(shown.out.rfind("scene A: 24 faces", 0), 0u) << shown.out;
}

// A relative path is read from the current folder, and only there: the source tree's
// scenes/demo.json is not found from another folder, and the error says to give its name.
TEST(RenderCommand, ARelativeScenePathIsReadFromTheCurrentFolderOnly) {
    const fs::path dir = fb89::testing::test_dir();
    fs::create_directories(dir / "mine");
    fs::copy_file(kScenes + "/A.json", dir / "mine" / "A.json",
                  fs::copy_options::overwrite_existing);
    const std::string in_dir = "cd " + dir.string() + " && ";
    const fs::path png = dir / "a.png";
    const CliRun here =
        fb89::testing::run_fb89("render mine/A.json --size 32x24 -q --png " + png.string(), in_dir);
    EXPECT_EQ(here.exit_code, 0) << here.err;
    EXPECT_TRUE(fs::exists(png));
    const CliRun elsewhere = fb89::testing::run_fb89(
        "render scenes/demo.json --size 32x24 -q --png " + (dir / "demo.png").string(), in_dir);
    EXPECT_EQ(elsewhere.exit_code, 2);
    EXPECT_EQ(elsewhere.err,
              "fb89: error: scenes/demo.json: cannot open the scene file: no such "
              "file (a relative path is read from the current folder, " +
                  fs::canonical(dir).string() +
                  "); demo is a bundled scene: give its name alone, demo\n");
    EXPECT_FALSE(fs::exists(dir / "demo.png"));
}

// Counter names of any length keep the values in one column.
TEST(RenderCommand, CountedOperationsLineUp) {
    const CliRun r = run_fb89("render F --size 128x98 --png " + test_file("f.png").string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const size_t begin = r.out.find("host counted operations:\n");
    ASSERT_NE(begin, std::string::npos) << r.out;
    std::istringstream lines(r.out.substr(begin));
    std::string line;
    std::getline(lines, line);
    size_t end_column = 0;
    int counted = 0;
    while (std::getline(lines, line) && line.rfind("  ", 0) == 0) {
        if (end_column == 0) end_column = line.size();
        EXPECT_EQ(line.size(), end_column) << line;
        ++counted;
    }
    EXPECT_GE(counted, 5);
    EXPECT_NE(r.out.find("faces_split_after_snapping"), std::string::npos);
}

TEST(RenderCommand, ReportsTriangulatedPolygons) {
    CliRun r = run_fb89("render " + kScenes + "/cornell_box.json --size 64x48");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("triangulated"), std::string::npos) << r.err;
}

TEST(RenderCommand, VersionAndHelpExitZero) {
    EXPECT_EQ(run_fb89("--version").exit_code, 0);
    CliRun help = run_fb89("render --help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.out.find("--ids"), std::string::npos);
}

TEST(RenderCommand, UsageErrorsExitTwo) {
    EXPECT_EQ(run_fb89("").exit_code, 2);
    EXPECT_EQ(run_fb89("render").exit_code, 2);
    EXPECT_EQ(run_fb89("frobnicate").exit_code, 2);
    CliRun method = run_fb89("render " + kScenes + "/demo.json --method painter");
    EXPECT_EQ(method.exit_code, 2);
    EXPECT_NE(method.err.find("unknown method 'painter'"), std::string::npos) << method.err;
    CliRun size = run_fb89("render " + kScenes + "/demo.json --size 12by7");
    EXPECT_EQ(size.exit_code, 2);
    EXPECT_NE(size.err.find("--size"), std::string::npos) << size.err;
}

TEST(RenderCommand, BadInputExitsTwoNamingTheFile) {
    CliRun missing = run_fb89("render /nonexistent/scene.json");
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("/nonexistent/scene.json"), std::string::npos) << missing.err;

    fs::path bad = test_file("bad.json");
    std::ofstream(bad)
        << "{ \"camera\": { \"eye\": [0, 0, 1], \"look_at\": [0, 0, 0], \"fovy\": 45,\n"
           "  \"near\": 1, \"far\": 10 }, \"objects\": [ { \"polygon\": 3 } ] }\n";
    CliRun r = run_fb89("render " + bad.string());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("bad.json: objects[0].polygon: expected an array"), std::string::npos)
        << r.err;

    CliRun profile = run_fb89("render " + kScenes + "/demo.json --profile no-such-profile");
    EXPECT_EQ(profile.exit_code, 2);
    EXPECT_NE(profile.err.find("no-such-profile"), std::string::npos) << profile.err;
}

TEST(RenderCommand, UnwritableOutputExitsTwo) {
    CliRun r = run_fb89("render " + kScenes + "/demo.json -q --png /proc/no/such/dir/x.png");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("x.png"), std::string::npos) << r.err;
}

}  // namespace

namespace {

TEST(RenderCommand, BeamWritesItsMaskAndStatsAndEqualsTheRayTracer) {
    fs::path beam = test_file("g_beam.png"), rays = test_file("g_rays.png"),
             mask = test_file("g_mask.png"), stats = test_file("g_beam.json");
    CliRun b = run_fb89("render " + kScenes +
                        "/G.json --size 256x195 -q -m beam --beam-threshold 1 " + "--png " +
                        beam.string() + " --mask " + mask.string() + " --stats " + stats.string());
    ASSERT_EQ(b.exit_code, 0) << b.err;
    CliRun r = run_fb89("render " + kScenes + "/G.json --size 256x195 -q -m raytrace --png " +
                        rays.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurp(beam), slurp(rays));
    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["beam_threshold"].get<double>(), 1.0);
    EXPECT_EQ(j["reflections"].get<int>(), 8);
    const auto& c = j["host"]["counters"];
    EXPECT_EQ(c["pixels_by_beams"].get<uint64_t>() + c["pixels_by_rays"].get<uint64_t>(),
              256u * 195u);
    // the mask is the frame with every ray-traced pixel black: it differs from the frame
    auto masked = fb89::controller::read_png(mask);
    auto frame = fb89::controller::read_png(beam);
    ASSERT_EQ(masked.width, 256u);
    EXPECT_NE(masked.pixels, frame.pixels);
}

TEST(RenderCommand, BadBeamOptionsAreUsageErrors) {
    CliRun t = run_fb89("render " + kScenes + "/G.json -m beam --beam-threshold -3 -q");
    EXPECT_EQ(t.exit_code, 2);
    EXPECT_NE(t.err.find("--beam-threshold"), std::string::npos) << t.err;
    CliRun m = run_fb89("render " + kScenes + "/G.json -m zbuffer --mask x.png -q");
    EXPECT_EQ(m.exit_code, 2);
    EXPECT_NE(m.err.find("--mask"), std::string::npos) << m.err;
    CliRun r = run_fb89("render " + kScenes + "/G.json -m raytrace --reflections 99 -q");
    EXPECT_EQ(r.exit_code, 2);
}

TEST(RenderCommand, OptionsTheMethodDoesNotUseAreRefusedNotIgnored) {
    for (const char* args : {"-m zbuffer --threshold 0.1", "-m zbuffer --reflections 2",
                             "-m warnock --beam-threshold 5", "-m scanline --window-test centres",
                             "-m raytrace --depth-estimate scene", "-m hybrid --grid-density 2",
                             "-m raytrace --grid-density 2", "-m raytrace --packets off"}) {
        CliRun r = run_fb89("render " + kScenes + "/A.json --size 32x24 -q " + args);
        EXPECT_EQ(r.exit_code, 2) << args;
        EXPECT_NE(r.err.find("method does not use it"), std::string::npos) << args << r.err;
    }
    EXPECT_EQ(run_fb89("render " + kScenes +
                       "/A.json --size 32x24 -q -m hybrid --threshold 0.1 "
                       "--window-test centres")
                  .exit_code,
              0);
}

// The beams query the BVH unless the rays walk the grid: a grid density alone has no grid.
TEST(RenderCommand, AGridDensityNeedsTheGrid) {
    CliRun r = run_fb89("render " + kScenes + "/G.json --size 32x24 -q -m beam --grid-density 2");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--grid-density"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--accel grid"), std::string::npos) << r.err;
    EXPECT_EQ(run_fb89("render " + kScenes +
                       "/G.json --size 32x24 -q -m beam --grid-density 2 "
                       "--accel grid")
                  .exit_code,
              0);
}

}  // namespace

namespace {

uint32_t rgb_at(const fb89::controller::PngImage& image, size_t pixel) {
    const uint8_t* p = image.pixels.data() + pixel * 3;
    return uint32_t{p[0]} << 16 | uint32_t{p[1]} << 8 | p[2];
}

TEST(RenderCommand, IdsViewGivesEachIdItsOwnColourBesideTheExactIds) {
    fs::path ids = test_file("A.ids.png"), view = test_file("A.view.png"),
             alone = test_file("A.view_alone.png");
    CliRun r = run_fb89("render " + kScenes + "/A.json --size 64x48 -q --ids " + ids.string() +
                        " --ids-view " + view.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto exact = fb89::controller::read_png(ids);
    auto colours = fb89::controller::read_png(view);
    EXPECT_EQ(colours.width, 64u);
    EXPECT_EQ(colours.height, 48u);
    ASSERT_EQ(colours.channels, 3u);
    ASSERT_EQ(colours.pixels.size(), exact.pixels.size());

    // pixel by pixel: the same id the same colour, different ids different colours, and
    // the background (0) black
    std::map<uint32_t, uint32_t> colour_of, id_of;
    for (size_t k = 0; k < size_t{64} * 48; ++k) {
        const uint32_t id = rgb_at(exact, k), colour = rgb_at(colours, k);
        if (id == 0) {
            EXPECT_EQ(colour, 0u) << "background pixel " << k;
            continue;
        }
        EXPECT_NE(colour, 0u) << "id " << id - 1 << " drawn black";
        EXPECT_EQ(colour_of.emplace(id, colour).first->second, colour)
            << "id " << id - 1 << " in two colours";
        EXPECT_EQ(id_of.emplace(colour, id).first->second, id)
            << "ids " << id_of[colour] - 1 << " and " << id - 1 << " share a colour";
    }
    EXPECT_GE(colour_of.size(), 2u) << "scene A shows fewer than two faces";

    // the two options are independent: --ids-view alone writes the same picture
    CliRun only =
        run_fb89("render " + kScenes + "/A.json --size 64x48 -q --ids-view " + alone.string());
    ASSERT_EQ(only.exit_code, 0) << only.err;
    EXPECT_EQ(slurp(alone), slurp(view));
    EXPECT_NE(run_fb89("render --help").out.find("--ids-view"), std::string::npos);
}

}  // namespace

namespace {

// Labels that read right without the docs (issue: "do no harm, round 2").
TEST(RenderCommand, ItsLinesSayWhatEachFigureIs) {
    const CliRun r = run_fb89("render " + kScenes + "/demo.json --size 128x98");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    // the controller's header once
    std::size_t headers = 0;
    for (std::size_t at = r.out.find("controller: tms34010-50mhz"); at != std::string::npos;
         at = r.out.find("controller: tms34010-50mhz", at + 1))
        ++headers;
    EXPECT_EQ(headers, 1u) << r.out;
    EXPECT_EQ(r.out.find("controller (tms34010-50mhz):"), std::string::npos) << r.out;
    // the split's host figure is this machine's CPU time; the controller's is modelled
    EXPECT_NE(r.out.find("split: host native "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" ms CPU | controller tms34010-50mhz "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" ms modelled | frame "), std::string::npos) << r.out;
    // with an unbounded buffer the host only ever waits for the bus
    EXPECT_NE(r.out.find("buffer unbounded): frame "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(", host waited for the bus "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("host stalled"), std::string::npos) << r.out;
    const CliRun bounded = run_fb89("render " + kScenes + "/demo.json --size 128x98 --buffer 64");
    ASSERT_EQ(bounded.exit_code, 0) << bounded.err;
    EXPECT_NE(bounded.out.find(" ms (bus or full buffer)"), std::string::npos) << bounded.out;
}

TEST(RenderCommand, SmallMistakesAreRefusedInWords) {
    const std::string demo = "render " + kScenes + "/demo.json --size 64x48 -q ";
    CliRun r = run_fb89(demo + "--repeat 1.5");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err,
              "fb89: usage: render: --repeat: 1.5 is not an integer (fb89 render --help says "
              "more)\n");
    r = run_fb89(demo + "--repeat many");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--repeat: many is not an integer"), std::string::npos) << r.err;
    const std::string same = test_file("same.png").string();
    fs::remove(same);
    r = run_fb89(demo + "--png " + same + " --ids " + same);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.err, "fb89: usage: --png and --ids both write to " + same +
                         "; give each a file of its own\n");
    EXPECT_FALSE(fs::exists(same));
    r = run_fb89(demo + "--untimed-stream");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--untimed-stream requires --stream"), std::string::npos) << r.err;
}

}  // namespace
