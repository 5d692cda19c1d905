// Tests of experiments successors and successors-rays (experiments/successor_experiments.cpp):
// three rows a scene, the hierarchical Z-buffer never testing more than the Z-buffer and, on
// the ideal scene from depth complexity 16, a quarter of its tests or fewer, with the same
// commands; four rows a scene and size, multi-level ray tracing sending the ray tracer's
// commands, every method's frame the ray tracer's, beams saving the rays of empty tiles.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "experiments/experiments.h"

namespace fb89::experiments {
namespace {

std::size_t column(const Table& table, const char* name) {
    const auto& cols = table.columns();
    for (std::size_t i = 0; i < cols.size(); ++i)
        if (cols[i] == name) return i;
    ADD_FAILURE() << "no column " << name;
    return 0;
}

TEST(SuccessorsExperiment, TheHierarchicalZBufferCullsWhereDepthComplexityIsHigh) {
    ExperimentSettings s;
    s.scenes = {FB89_SCENES_DIR "/A.json"};
    s.size = {128, 98};
    s.repeat = 1;
    const Table table = experiment_successors(s);
    const auto col = [&](const char* name) { return column(table, name); };
    ASSERT_EQ(table.rows().size(), 3u * (1 + 7));  // A and the ideal ladder 1 .. 64
    // by scene: each method's depth tests and commands
    std::map<std::string, std::map<std::string, std::vector<std::string>>> by;
    for (const auto& row : table.rows())
        by[row[col("scene")]][row[col("method")]] = row;
    for (const auto& [scene, methods] : by) {
        SCOPED_TRACE(scene);
        ASSERT_EQ(methods.size(), 3u);
        const auto& z = methods.at("zbuffer");
        const auto& h = methods.at("hzb");
        EXPECT_EQ(z[col("speedup")], "1.000");
        EXPECT_EQ(h[col("commands")], z[col("commands")]);
        const uint64_t zt = std::stoull(z[col("depth_tests")]);
        const uint64_t ht = std::stoull(h[col("depth_tests")]);
        EXPECT_LE(ht, zt);
        EXPECT_TRUE(z[col("nodes_culled")].empty());  // the Z-buffer keeps no such count
        EXPECT_FALSE(h[col("pyramid_tests")].empty());
        if (scene == "ideal-16" || scene == "ideal-32" || scene == "ideal-64") {
            EXPECT_LE(ht * 4, zt);
            EXPECT_GT(std::stoull(h[col("nodes_culled")]) + std::stoull(h[col("faces_culled")]),
                      0u);
        }
    }
}

TEST(SuccessorsExperiment, MultiLevelRayTracingShowsTheRayTracersFrameAtEverySize) {
    ExperimentSettings s;
    s.scenes = {FB89_SCENES_DIR "/cornell_box.json", FB89_SCENES_DIR "/G.json"};
    s.repeat = 1;
    const Table table = experiment_successors_rays(s, {{64, 48}, {128, 96}}, INFINITY);
    const auto col = [&](const char* name) { return column(table, name); };
    ASSERT_EQ(table.rows().size(), 5u * 2 * 2);
    std::map<std::string, std::map<std::string, std::vector<std::string>>> by;
    for (const auto& row : table.rows())
        by[row[col("scene")] + " " + row[col("width")]][row[col("method")]] = row;
    ASSERT_EQ(by.size(), 4u);
    for (const auto& [where, methods] : by) {
        SCOPED_TRACE(where);
        ASSERT_EQ(methods.size(), 5u);
        for (const auto& [method, row] : methods)
            EXPECT_EQ(row[col("same_frame")], "yes") << method;
        const auto& rays = methods.at("raytrace");
        const auto& kd = methods.at("raytrace-kd");
        const auto& ml = methods.at("mlrta");
        const auto& scalar = methods.at("mlrta-scalar");
        EXPECT_EQ(rays[col("speedup")], "1.000");
        // its rays one by one: the same rays, beams and commands
        for (const char* same : {"rays", "pixels_by_beams", "beams", "entry_points", "commands"})
            EXPECT_EQ(scalar[col(same)], ml[col(same)]) << same;
        EXPECT_EQ(ml[col("commands")], rays[col("commands")]);
        EXPECT_EQ(kd[col("commands")], rays[col("commands")]);
        EXPECT_EQ(kd[col("rays")], rays[col("rays")]);
        // every ray the ray tracer casts, mlrta casts, but one a pixel its beams decided
        EXPECT_EQ(std::stoull(ml[col("rays")]) + std::stoull(ml[col("pixels_by_beams")]),
                  std::stoull(rays[col("rays")]));
        EXPECT_GT(std::stoull(ml[col("entry_points")]), 0u);
        EXPECT_FALSE(ml[col("mean_entry_depth")].empty());
        EXPECT_TRUE(rays[col("mean_entry_depth")].empty());
    }
}

}  // namespace
}  // namespace fb89::experiments
