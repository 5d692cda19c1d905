// `fb89 radiosity` as a user runs it: outputs, counters, exit codes and messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>

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
const std::string kGarish = kScenes + "/garish_room.json";
// a small run: a coarse mesh and a small image
const std::string kSmall = " --patches 120 --size 256x195 ";

void expect_usage_error(const std::string& args, const std::string& names) {
    CliRun r = run_fb89(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << args << "\n" << r.err;
}

TEST(RadiosityCommand, BadOptionsExitTwoNamingTheOption) {
    expect_usage_error("radiosity " + kGarish + " --ff beams", "--ff");
    expect_usage_error("radiosity " + kGarish + " --patches 0", "--patches");
    expect_usage_error("radiosity " + kGarish + " --patches 100000", "--patches");
    expect_usage_error("radiosity " + kGarish + " --solver jacobi", "--solver");
    expect_usage_error("radiosity " + kGarish + " --size 12", "--size");
    expect_usage_error("radiosity " + kGarish + " --hemicube-res 64", "--hemicube-res");
    expect_usage_error("radiosity " + kGarish + " --adaptive-passes 2", "--adaptive-passes");
    expect_usage_error("radiosity " + kGarish + " --adaptive -1", "--adaptive");
    EXPECT_EQ(run_fb89("radiosity").exit_code, 2);
    EXPECT_EQ(run_fb89("radiosity " + kScenes + "/no_such_scene.json").exit_code, 2);
    // the hierarchy's options need it, and it takes no other solver or re-meshing
    expect_usage_error("radiosity " + kGarish + " --epsilon 0.1", "--epsilon");
    expect_usage_error("radiosity " + kGarish + " --link-rays 2", "--link-rays");
    expect_usage_error("radiosity " + kGarish + " --ff hierarchical --link-rays 0", "--link-rays");
    expect_usage_error("radiosity " + kGarish + " --ff hierarchical --epsilon -1", "--epsilon");
    expect_usage_error("radiosity " + kGarish + " --ff hierarchical --solver progressive",
                       "--solver");
    expect_usage_error("radiosity " + kGarish + " --ff hierarchical --adaptive 0.2", "--adaptive");
    expect_usage_error("radiosity " + kGarish + " --shaft-culling", "--shaft-culling");
}

TEST(RadiosityCommand, HierarchicalRendersTheRoomAndReportsItsLinks) {
    fs::path png = test_file("room_hr.png"), stats = test_file("room_hr.json");
    CliRun r =
        run_fb89("radiosity " + kGarish + kSmall + "-q --ff hierarchical --epsilon 0.05 --png " +
                 png.string() + " --stats " + stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(slurp(stats));
    const auto& h = j["radiosity"]["hierarchical"];
    EXPECT_EQ(h["roots"], 29);
    EXPECT_GT(h["links"].get<int>(), 0);
    EXPECT_EQ(h["leaves"], j["radiosity"]["patches"]);
    // 4 rays for each link factor found nonzero, none for the rest
    EXPECT_EQ(h["rays"].get<int>() % 4, 0);
    EXPECT_LE(h["rays"].get<int>(), 4 * h["link_form_factors"].get<int>());
    EXPECT_GE(h["rays"].get<int>(), 4 * h["links"].get<int>());
    EXPECT_EQ(j["radiosity"]["solver"], "push-pull");
    EXPECT_TRUE(j["radiosity"]["converged"].get<bool>());
    EXPECT_TRUE(fs::exists(png));
    // a budget reached is said, and the run still renders
    CliRun budget = run_fb89("radiosity " + kGarish + kSmall +
                             "--ff hierarchical --epsilon 0 --max-links 500 --png " + png.string());
    ASSERT_EQ(budget.exit_code, 0) << budget.err;
    EXPECT_NE(budget.out.find("budget reached"), std::string::npos) << budget.out;
    EXPECT_NE((budget.err + budget.out).find("reached its budget"), std::string::npos);
}

// --shaft-culling: the same room, image and links, fewer rays; the shafts counted.
TEST(RadiosityCommand, ShaftCullingRendersTheSameRoomWithFewerRays) {
    fs::path plain_png = test_file("plain.png"), culled_png = test_file("culled.png");
    fs::path plain_stats = test_file("plain.json"), culled_stats = test_file("culled.json");
    const std::string run =
        "radiosity " + kGarish + kSmall + "-q --ff hierarchical --epsilon 0.05 ";
    ASSERT_EQ(run_fb89(run + "--png " + plain_png.string() + " --stats " + plain_stats.string())
                  .exit_code,
              0);
    CliRun r = run_fb89(run + "--shaft-culling --png " + culled_png.string() + " --stats " +
                        culled_stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto plain = nlohmann::json::parse(slurp(plain_stats))["radiosity"]["hierarchical"];
    const auto culled = nlohmann::json::parse(slurp(culled_stats))["radiosity"]["hierarchical"];
    EXPECT_FALSE(plain["shaft_culling"].get<bool>());
    EXPECT_TRUE(culled["shaft_culling"].get<bool>());
    EXPECT_EQ(culled["links"], plain["links"]);
    EXPECT_EQ(culled["leaves"], plain["leaves"]);
    EXPECT_EQ(plain["shafts"], 0);
    EXPECT_LE(culled["shafts"].get<int>(), culled["link_form_factors"].get<int>());
    EXPECT_GT(culled["shafts_clear"].get<int>(), 0);
    EXPECT_EQ(culled["rays"].get<int>(),
              4 * (culled["shafts"].get<int>() - culled["shafts_clear"].get<int>()));
    EXPECT_LT(culled["rays"].get<int>(), plain["rays"].get<int>());
    EXPECT_EQ(slurp(culled_png), slurp(plain_png));
}

TEST(RadiosityCommand, SceneWithoutEmitterIsAnError) {
    CliRun r = run_fb89("radiosity " + kScenes + "/A.json" + kSmall);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("emits"), std::string::npos) << r.err;
}

TEST(RadiosityCommand, WritesImageStreamAndStatsWithTheCounters) {
    fs::path png = test_file("room.png"), stats = test_file("room.json"),
             stream = test_file("room.fb89"), replayed = test_file("replayed.png");
    CliRun r = run_fb89("radiosity " + kGarish + kSmall + "--png " + png.string() + " --stats " +
                        stats.string() + " --stream " + stream.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* word : {"patches", "visibility", "form factors", "solving", "rendering",
                             "flux_rays", "DRAW_SPAN"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word << "\n" << r.out;

    auto image = fb89::controller::read_png(png);
    EXPECT_EQ(image.width, 256u);
    EXPECT_EQ(image.height, 195u);

    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    EXPECT_EQ(j["scene"]["faces"], 29);
    EXPECT_EQ(j["radiosity"]["ff"], "flux");
    EXPECT_TRUE(j["radiosity"]["converged"].get<bool>());
    EXPECT_GT(j["radiosity"]["patches"].get<int>(), 29);
    const auto& counters = j["host"]["counters"];
    EXPECT_GT(counters["flux_rays"].get<uint64_t>(), 0u);
    EXPECT_EQ(counters["flux_rays"], counters["radiosity_facing_pairs"]);
    for (const char* stage :
         {"load", "meshing", "visibility", "form_factors", "solving", "rendering", "end_to_end"})
        EXPECT_TRUE(j["host"]["times"][stage].contains("cpu_ms")) << stage;
    EXPECT_GT(j["render"]["counters"]["spans"].get<uint64_t>(), 0u);
    EXPECT_TRUE(j["controller"].is_object());

    // the stream replays to the same picture
    CliRun replay = run_fb89("replay " + stream.string() + " -q --png " + replayed.string());
    ASSERT_EQ(replay.exit_code, 0) << replay.err;
    EXPECT_EQ(slurp(replayed), slurp(png));
}

TEST(RadiosityCommand, FluxAndHybridGiveTheSameImage) {
    fs::path flux = test_file("flux.png"), hybrid = test_file("hybrid.png"),
             stats = test_file("hybrid.json");
    ASSERT_EQ(run_fb89("radiosity " + kGarish + kSmall + "-q --png " + flux.string()).exit_code, 0);
    CliRun r = run_fb89("radiosity " + kGarish + kSmall + "-q --ff hybrid --png " +
                        hybrid.string() + " --stats " + stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(slurp(flux), slurp(hybrid));
    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    const auto& counters = j["host"]["counters"];
    EXPECT_GT(counters["volume_queries"].get<uint64_t>(), 0u);
    EXPECT_LE(counters["flux_rays"].get<uint64_t>(),
              counters["radiosity_facing_pairs"].get<uint64_t>());
}

TEST(RadiosityCommand, BothSolversGiveTheSamePicture) {
    fs::path gs = test_file("gs.png"), pr = test_file("pr.png");
    ASSERT_EQ(run_fb89("radiosity " + kGarish + kSmall + "-q --tolerance 1e-6 --png " + gs.string())
                  .exit_code,
              0);
    ASSERT_EQ(run_fb89("radiosity " + kGarish + kSmall +
                       "-q --tolerance 1e-6 --solver progressive --png " + pr.string())
                  .exit_code,
              0);
    auto a = fb89::controller::read_png(gs);
    auto b = fb89::controller::read_png(pr);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    int worst = 0;
    for (size_t k = 0; k < a.pixels.size(); ++k)
        worst = std::max(worst, std::abs(int(a.pixels[k]) - int(b.pixels[k])));
    EXPECT_LE(worst, 1);
}

TEST(RadiosityCommand, AdaptiveRefinementAddsPatches) {
    fs::path stats = test_file("adaptive.json");
    CliRun r = run_fb89("radiosity " + kGarish + kSmall + "-q --adaptive 0.3 --adaptive-passes 2 " +
                        "--stats " + stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(slurp(stats));
    const auto& passes = j["radiosity"]["adaptive"]["patches_per_pass"];
    ASSERT_GE(passes.size(), 2u);
    EXPECT_GT(passes[1].get<int>(), passes[0].get<int>());
    EXPECT_EQ(passes.back(), j["radiosity"]["patches"]);
}

TEST(RadiosityCommand, IdsWritesThePatchSceneFaceIdBufferAndIdsViewItsColours) {
    fs::path ids = test_file("room.ids.png"), view = test_file("room.view.png"),
             stats = test_file("room.json");
    fs::remove(ids);
    fs::remove(view);
    CliRun r = run_fb89("radiosity " + kGarish + kSmall + "-q --ids " + ids.string() +
                        " --ids-view " + view.string() + " --stats " + stats.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(fs::exists(ids));
    ASSERT_TRUE(fs::exists(view));
    auto image = fb89::controller::read_png(ids);
    EXPECT_EQ(image.width, 256u);
    EXPECT_EQ(image.height, 195u);
    ASSERT_EQ(image.channels, 3u);

    // ids are the patch scene's faces: one per patch, so more of them than the scene's faces
    const uint64_t patches =
        nlohmann::json::parse(slurp(stats))["radiosity"]["patches"].get<uint64_t>();
    std::set<uint32_t> seen;
    for (size_t k = 0; k < image.pixels.size(); k += 3) {
        const uint32_t v = uint32_t{image.pixels[k]} << 16 | uint32_t{image.pixels[k + 1]} << 8 |
                           image.pixels[k + 2];
        if (v == 0) continue;
        EXPECT_LE(v, patches) << "id " << v - 1 << " is not a patch";
        seen.insert(v - 1);
    }
    EXPECT_GT(seen.size(), 29u) << "fewer ids than the scene has faces";

    // the view: the same size, the same id the same colour wherever it is
    auto colours = fb89::controller::read_png(view);
    ASSERT_EQ(colours.width, image.width);
    ASSERT_EQ(colours.height, image.height);
    std::map<uint32_t, uint32_t> colour_of;
    for (size_t k = 0; k < image.pixels.size(); k += 3) {
        const uint32_t v = uint32_t{image.pixels[k]} << 16 | uint32_t{image.pixels[k + 1]} << 8 |
                           image.pixels[k + 2];
        const uint32_t c = uint32_t{colours.pixels[k]} << 16 |
                           uint32_t{colours.pixels[k + 1]} << 8 | colours.pixels[k + 2];
        EXPECT_EQ(colour_of.emplace(v, c).first->second, c) << "id " << v << " in two colours";
    }
}

// The hierarchy's leaves differ in size where they meet (T-junctions); the room is closed
// to the camera, so every pixel of its id buffer is some patch's, as with a uniform mesh.
TEST(RadiosityCommand, HierarchicalPatchesCoverEveryPixelOfTheClosedRoom) {
    for (const std::string ff : {"hierarchical", "hybrid"}) {
        const fs::path ids = test_file("covered." + ff + ".png");
        CliRun r = run_fb89("radiosity " + kGarish + " -q --ff " + ff + " --ids " + ids.string());
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto image = fb89::controller::read_png(ids);
        ASSERT_EQ(image.channels, 3u);
        int background = 0;
        for (size_t k = 0; k < image.pixels.size(); k += 3)
            background +=
                image.pixels[k] == 0 && image.pixels[k + 1] == 0 && image.pixels[k + 2] == 0;
        EXPECT_EQ(background, 0) << ff << ": pixels no patch covers";
    }
}

TEST(RadiosityCommand, OtherFormFactorsRunAndQuietPrintsNothing) {
    for (const std::string ff : {"disk", "exact", "hemicube --hemicube-res 16"}) {
        CliRun r = run_fb89("radiosity " + kScenes +
                            "/cornell_box.json --patches 60 --size 128x98 -q "
                            "--ff " +
                            ff);
        EXPECT_EQ(r.exit_code, 0) << ff << "\n" << r.err;
        EXPECT_EQ(r.out, "") << ff;
    }
}

// Rows of F above 1 are flagged on stdout, counted, located and explained for the form used.
TEST(RadiosityCommand, RowSumsAboveOneAreFlaggedAndExplained) {
    const std::string png = (fb89::testing::test_dir() / "room.png").string();
    CliRun point =
        run_fb89("radiosity cornell_box --patches 60 --size 128x98 --ff flux --png " + png);
    ASSERT_EQ(point.exit_code, 0) << point.err;
    EXPECT_NE(point.out.find("! 34 of 75 rows of F sum above 1, the largest by 26.7%"),
              std::string::npos)
        << point.out;
    EXPECT_NE(point.out.find("point form over-counts patches close to one another"),
              std::string::npos);
    CliRun exact =
        run_fb89("radiosity cornell_box --patches 60 --size 128x98 --ff exact --png " + png);
    ASSERT_EQ(exact.exit_code, 0) << exact.err;
    EXPECT_NE(exact.out.find("all or nothing"), std::string::npos) << exact.out;
    // the disk form keeps every row of this box below 1: nothing to flag
    CliRun disk =
        run_fb89("radiosity cornell_box --patches 60 --size 128x98 --ff disk --png " + png);
    ASSERT_EQ(disk.exit_code, 0) << disk.err;
    EXPECT_EQ(disk.out.find("rows of F sum above 1"), std::string::npos) << disk.out;
}

}  // namespace
