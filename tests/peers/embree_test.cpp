// Peers: Embree 3 (bench/peers/embree_tracer.h), tracing exactly our pixel rays in float,
// sees what our ray tracer sees. In its robust (watertight) mode it agrees with our
// `raytrace` on at least 99.5% of the pixels, and every disagreement lies on an id boundary
// of ours, where single precision and a tie-break may pick the other face of an edge. Its
// 4x4 coherent packets give exactly the ids of its single rays.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/peers/embree_tracer.h"
#include "bench/peers/exactness.h"
#include "bench/peers/peer_scenes.h"
#include "bench/peers/ray_side_by_side.h"

namespace fb89::peers {
namespace {

constexpr int kWidth = 256, kHeight = 195;  // 195 rows: the last row of packets is partial

// Loads the scene at the test size; false when its file is not there yet.
bool load(const char* name, RayScene& scene) {
    const std::filesystem::path file = std::string(FB89_SCENES_DIR) + "/" + name + ".json";
    if (!std::filesystem::exists(file)) return false;
    scene = ray_file_scene(file, kWidth, kHeight);
    return true;
}

void expect_robust_agrees_with_raytrace(const char* name) {
    RayScene scene;
    if (!load(name, scene)) GTEST_SKIP() << name << ".json does not exist yet";
    EmbreeOptions options;
    options.robust = true;
    EmbreeTracer embree(*scene.world, options);
    std::vector<uint32_t> theirs;
    embree.trace_single(theirs);
    const std::vector<uint32_t> ours = our_ray_face_ids(scene, "raytrace");

    const IdAgreement a = compare_with_boundaries(kWidth, kHeight, ours, theirs);
    EXPECT_GE(a.agreement(), 0.995) << name << ": " << a.differ << " pixels differ";
    EXPECT_EQ(a.interior, 0u) << name << ": first interior disagreement " << a.first_interior;
    // not a vacuous agreement: the scene fills most of the image
    uint64_t covered = 0;
    for (uint32_t id : ours)
        covered += id != 0;
    EXPECT_GT(covered, ours.size() / 2) << name;
}

void expect_packets_equal_single_rays(const char* name) {
    RayScene scene;
    if (!load(name, scene)) GTEST_SKIP() << name << ".json does not exist yet";
    for (bool robust : {false, true}) {
        EmbreeOptions options;
        options.robust = robust;
        EmbreeTracer embree(*scene.world, options);
        std::vector<uint32_t> single, packets;
        embree.trace_single(single);
        embree.trace_packets(packets);
        ASSERT_EQ(single.size(), packets.size());
        uint64_t differ = 0;
        for (size_t i = 0; i < single.size(); ++i)
            differ += single[i] != packets[i];
        EXPECT_EQ(differ, 0u) << name << (robust ? ", robust" : ", default");
    }
}

TEST(EmbreePeer, RobustAgreesWithOurRayTracerOnTheCornellBox) {
    expect_robust_agrees_with_raytrace("cornell_box");
}

TEST(EmbreePeer, RobustAgreesWithOurRayTracerOnSceneG) {
    expect_robust_agrees_with_raytrace("G");
}

TEST(EmbreePeer, PacketsGiveTheIdsOfSingleRaysOnTheCornellBox) {
    expect_packets_equal_single_rays("cornell_box");
}

TEST(EmbreePeer, PacketsGiveTheIdsOfSingleRaysOnSceneG) {
    expect_packets_equal_single_rays("G");
}

TEST(EmbreePeer, SeesTheFacesOfEveryPieceUnderTheirIds) {
    // a fan-triangulated world scene: every id Embree reports is a face id + 1 of the scene
    RayScene scene = random_world_triangles(kWidth, kHeight, 200, 7);
    EmbreeTracer embree(*scene.world);
    EXPECT_EQ(embree.triangles(), 200u);
    std::vector<uint32_t> ids;
    embree.trace_single(ids);
    uint64_t hits = 0;
    for (uint32_t id : ids) {
        EXPECT_LE(id, scene.world->face_count);
        hits += id != 0;
    }
    EXPECT_GT(hits, 0u);
}

TEST(EmbreePeerHarness, TakesItsRatiosRoundByRound) {
    // Nine rounds; from the middle of the fifth, between Embree's frame and ours, the machine
    // runs at half speed. Round by round Embree takes 1.25x our time but in that one round;
    // the medians of each side's own times (10 and 16 ms) would give 0.625.
    RayRow row;
    const double embree[] = {10, 10, 10, 10, 10, 20, 20, 20, 20};
    const double ours[] = {8, 8, 8, 8, 16, 16, 16, 16, 16};
    for (int i = 0; i < 9; ++i)
        row.rounds.push_back({embree[i], ours[i], 1.0, 0.5 * (i + 1), 0.0, 0.25 * (i + 1)});
    using R = RayRow::Round;
    const RayRow::Spread rt = row.ratio(&R::embree_single, &R::raytrace);
    EXPECT_DOUBLE_EQ(rt.median, 1.25);
    EXPECT_DOUBLE_EQ(rt.low, 1.25);
    EXPECT_DOUBLE_EQ(rt.high, 1.25);
    // the packets over the beams: 1/0.5, 1/1, ..., 1/4.5; median the 5th, quartiles the 3rd
    // and 7th by nearest rank
    const RayRow::Spread bm = row.ratio(&R::embree_packets, &R::beam);
    EXPECT_DOUBLE_EQ(bm.median, 1 / 2.5);
    EXPECT_DOUBLE_EQ(bm.low, 1 / 3.5);
    EXPECT_DOUBLE_EQ(bm.high, 1 / 1.5);
    // Embree's packets over mlrta: 1/0.25, ..., 1/2.25
    EXPECT_DOUBLE_EQ(row.ratio(&R::embree_packets, &R::mlrta).median, 1 / 1.25);
    // a side that took no time has no ratio
    EXPECT_DOUBLE_EQ(row.ratio(&R::embree_single, &R::embree_robust).median, 0.0);
    // one line a round, and the header
    row.scene.assign(1, 's');
    row.isa = "v3";
    const std::string csv = ray_rounds_csv({row});
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 10);
    EXPECT_NE(csv.find("\n\"s\",v3,9,20.000,16.000,1.000,4.500,0.000,2.250,0.000\n"),
              std::string::npos)
        << csv;
}

TEST(EmbreePeerHarness, MeasuresAgainAWholeSceneTheRunsBestCanaryShowsSlow) {
    // a scene measured throughout a spell: its canary's median 3.6 ms, while the run's best
    // (found later, in calm) is 2.8 ms
    RayRow row;
    row.canary_ms = 3.6;
    EXPECT_TRUE(measured_in_a_spell(row, 2.8, 0.2));
    // within the tolerance: calm
    row.canary_ms = 3.3;
    EXPECT_FALSE(measured_in_a_spell(row, 2.8, 0.2));
    // a tolerance of 0 turns the check off, as it does the rounds' own
    row.canary_ms = 3.6;
    EXPECT_FALSE(measured_in_a_spell(row, 2.8, 0.0));
}

}  // namespace
}  // namespace fb89::peers
