// The uniform grid: cell sizing, where pieces are listed, and the 3D-DDA walk.
#include "host/trace/grid.h"

#include <algorithm>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "tests/host/trace/trace_test_util.h"

namespace fb89::host {
namespace {

using testing::add_face;
using testing::add_square;
using testing::world_scene;

TEST(UniformGrid, HasAboutDensityCellsPerPieceAndNeverAFlatBox) {
    Scene s = world_scene(8, 8);
    for (int i = 0; i < 64; ++i)
        add_square(s, (i % 8) - 3.5, (i / 8) - 3.5, 0, 0.4, {1, 1, 1});  // all in one plane
    TraceScene trace(s, true, 0);
    UniformGrid grid(trace, 2.0);
    EXPECT_GT(grid.hi().z - grid.lo().z, 0.0);
    EXPECT_EQ(grid.resolution().z, 1);
    EXPECT_GE(grid.cell_count(), 64u);
    EXPECT_LE(grid.cell_count(), 4u * 128u);
}

TEST(UniformGrid, ListsAPieceInEveryCellItPassesThrough) {
    Scene s = world_scene(8, 8);
    add_square(s, 0, 0, 0, 2, {1, 1, 1});
    add_square(s, 0, 0, 0.9, 0.1, {1, 1, 1});
    TraceScene trace(s, true, 0);
    UniformGrid grid(trace, 50.0);
    // sample points of the big square: the cell holding each lists piece 0
    for (double y = -1.99; y < 2; y += 0.17)
        for (double x = -1.99; x < 2; x += 0.13) {
            glm::ivec3 first, last;
            ASSERT_TRUE(grid.cell_range({x, y, 0}, {x, y, 0}, first, last));
            auto cell = grid.cell(grid.index(first.x, first.y, first.z));
            EXPECT_NE(std::find(cell.begin(), cell.end(), 0u), cell.end()) << x << "," << y;
        }
    EXPECT_LT(grid.entries(), grid.cell_count()) << "a plane is listed only where it passes";
}

TEST(UniformGrid, WalksCellsInOrderAndStopsAtTheBox) {
    Scene s = world_scene(8, 8);
    add_face(s, {{0, 0, 0}, {4, 0, 0}, {4, 4, 4}}, {1, 1, 1});
    TraceScene trace(s, true, 0);
    UniformGrid grid(trace, 8.0);
    // along x at zero y and z direction components: every cell of one row, in order
    const Ray ray{{-1, 0.5, 0.5}, {1, 0, 0}};
    std::vector<double> exits;
    const uint64_t cells = grid.walk(ray, 0, INFINITY, [&](uint32_t, double t_exit) {
        exits.push_back(t_exit);
        return false;
    });
    EXPECT_EQ(cells, static_cast<uint64_t>(grid.resolution().x));
    EXPECT_TRUE(std::is_sorted(exits.begin(), exits.end()));
    EXPECT_NEAR(exits.back(), 1 + grid.hi().x, 1e-9);
    // a ray that misses the box walks nothing
    EXPECT_EQ(
        grid.walk({{-1, 9, 0.5}, {1, 0, 0}}, 0, INFINITY, [](uint32_t, double) { return false; }),
        0u);
    // a visitor that stops ends the walk at once
    EXPECT_EQ(grid.walk(ray, 0, INFINITY, [](uint32_t, double) { return true; }), 1u);
}

TEST(UniformGrid, WalksACrowdedCellThroughItsOwnGridAndNotItsList) {
    Scene s = world_scene(8, 8);
    add_square(s, 0, 0, 0, 4, {1, 1, 1});  // a floor
    for (int i = 0; i < 12; ++i)           // a stack of small squares over its middle
        add_square(s, 0, 0, 1 + 0.01 * i, 0.1, {1, 1, 1});
    TraceScene trace(s, true, 0);
    UniformGrid grid(trace);
    const Ray ray{{0.05, 0.05, 5}, {0, 0, -1}};  // down through the stack
    uint32_t crowded = 0;
    ASSERT_EQ(grid.walk(ray, 0, INFINITY,
                        [&](uint32_t cell, double) {
                            crowded = cell;
                            return false;
                        }),
              1u);
    ASSERT_NE(grid.sub(crowded), nullptr);

    std::vector<uint32_t> tested;
    uint64_t lists = 0;
    const auto walked = grid.walk_levels(
        ray, 0, INFINITY,
        [&](std::span<const uint32_t> pieces) {
            ++lists;
            tested.insert(tested.end(), pieces.begin(), pieces.end());
        },
        [](double) { return false; });
    EXPECT_EQ(walked.cells, 1u);
    EXPECT_GT(walked.sub_cells, 1u);
    EXPECT_EQ(lists, walked.sub_cells) << "the crowded cell's own list is not tested";
    std::sort(tested.begin(), tested.end());
    tested.erase(std::unique(tested.begin(), tested.end()), tested.end());
    EXPECT_EQ(tested.size(), 13u) << "every piece along the ray, through the finer cells";

    // done() after the first finer cell ends both walks
    const auto first = grid.walk_levels(
        ray, 0, INFINITY, [](std::span<const uint32_t>) {}, [](double) { return true; });
    EXPECT_EQ(first.cells, 1u);
    EXPECT_EQ(first.sub_cells, 1u);
}

}  // namespace
}  // namespace fb89::host
