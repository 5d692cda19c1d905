// Tests of experiment successors (experiments/successor_experiments.cpp): three rows a scene,
// the hierarchical Z-buffer never testing more than the Z-buffer and, on the ideal scene from
// depth complexity 16, a quarter of its tests or fewer, with the same commands.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "experiments/experiments.h"

namespace fb89::experiments {
namespace {

TEST(SuccessorsExperiment, TheHierarchicalZBufferCullsWhereDepthComplexityIsHigh) {
    ExperimentSettings s;
    s.scenes = {FB89_SCENES_DIR "/A.json"};
    s.size = {128, 98};
    s.repeat = 1;
    const Table table = experiment_successors(s);
    const auto& cols = table.columns();
    const auto col = [&](const char* name) {
        for (std::size_t i = 0; i < cols.size(); ++i)
            if (cols[i] == name) return i;
        ADD_FAILURE() << "no column " << name;
        return std::size_t{0};
    };
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

}  // namespace
}  // namespace fb89::experiments
