// The growth benchmark (bench/growth): the log-log slope it fits, and a smoke run of
// fb89_growth on a ladder of tiny rungs, checked by counts only (rows, faces, files), never
// by times.
#include "bench/growth/loglog_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/cli_runner.h"

namespace fb89::growth {
namespace {

TEST(GrowthFit, SlopeOfAPowerLawIsItsExponent) {
    std::vector<double> x{1e3, 4e3, 16e3, 64e3}, square, root;
    for (double v : x) {
        square.push_back(3 * v * v);
        root.push_back(0.5 * std::sqrt(v));
    }
    EXPECT_NEAR(loglog_slope(x, square), 2.0, 1e-12);
    EXPECT_NEAR(loglog_slope(x, root), 0.5, 1e-12);
}

TEST(GrowthFit, FewerThanTwoPositivePointsGiveNoSlope) {
    EXPECT_TRUE(std::isnan(loglog_slope({1e3}, {5})));
    EXPECT_TRUE(std::isnan(loglog_slope({1e3, 4e3}, {5, 0})));
    EXPECT_TRUE(std::isnan(loglog_slope({1e3, 1e3}, {5, 6})));
}

#ifdef FB89_GROWTH_PATH

// The rows of a CSV file as maps from column name to text (no quoted commas here).
std::vector<std::map<std::string, std::string>> read_csv(const std::filesystem::path& file) {
    std::istringstream text(testing::slurp(file));
    std::string line;
    auto split = [](const std::string& l) {
        std::vector<std::string> cells;
        std::istringstream in(l);
        for (std::string cell; std::getline(in, cell, ',');)
            cells.push_back(cell);
        return cells;
    };
    std::getline(text, line);
    const std::vector<std::string> header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(text, line)) {
        const std::vector<std::string> cells = split(line);
        auto& row = rows.emplace_back();
        for (size_t i = 0; i < header.size() && i < cells.size(); ++i)
            row[header[i]] = cells[i];
    }
    return rows;
}

int run_growth(const std::string& args) {
    const std::filesystem::path dir = testing::test_dir();
    const std::string cmd = std::string(FB89_GROWTH_PATH) + " --out " + dir.string() + " " + args +
                            " >" + (dir / "stdout").string() + " 2>" + (dir / "stderr").string();
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(GrowthHarness, TinyLadderRunsEveryMethodOnEveryRungAndTheObjRung) {
    ASSERT_EQ(run_growth("--min-faces 16 --max-faces 256 --repeat 1 --quiet"), 0)
        << testing::slurp(testing::test_dir() / "stderr");
    const std::filesystem::path dir = testing::test_dir();
    const auto rows = read_csv(dir / "growth.csv");
    // 3 rungs x 4 methods from the generator, then the top rung from its OBJ file
    ASSERT_EQ(rows.size(), 3u * 4 + 4);
    std::map<std::string, int> per_faces;
    for (const auto& r : rows) {
        EXPECT_EQ(r.at("ok"), "1");
        EXPECT_EQ(r.at("loaded_faces"), r.at("faces"));
        EXPECT_NE(r.at("peak_rss_bytes"), "0");
        ++per_faces[r.at("source") + " " + r.at("faces")];
    }
    EXPECT_EQ(per_faces,
              (std::map<std::string, int>{
                  {"generator 16", 4}, {"generator 64", 4}, {"generator 256", 4}, {"obj 256", 4}}));
    // six quantities for each method's generator series; none for the single OBJ rung
    EXPECT_EQ(read_csv(dir / "growth_slopes.csv").size(), 4u * 6);
    EXPECT_TRUE(std::filesystem::exists(dir / "growth.md"));
    for (const char* scene :
         {"terrain_16.json", "terrain_64.json", "terrain_256.json", "terrain_256_obj.json"})
        EXPECT_TRUE(std::filesystem::exists(dir / "scenes" / scene)) << scene;
    EXPECT_FALSE(std::filesystem::exists(dir / "scenes" / "terrain_256.obj"));  // removed
}

TEST(GrowthHarness, KeptObjFileHoldsEachGridPointOnceAndEveryFace) {
    ASSERT_EQ(run_growth("--min-faces 256 --max-faces 256 --methods zbuffer --repeat 1 "
                         "--keep-obj --quiet"),
              0);
    std::istringstream obj(testing::slurp(testing::test_dir() / "scenes" / "terrain_256.obj"));
    size_t v = 0, f = 0;
    for (std::string line; std::getline(obj, line);) {
        v += line.rfind("v ", 0) == 0;
        f += line.rfind("f ", 0) == 0;
    }
    EXPECT_EQ(v, 17u * 9);  // rung n = 8: 16 x 8 cells
    EXPECT_EQ(f, 256u);
}

#endif  // FB89_GROWTH_PATH

}  // namespace
}  // namespace fb89::growth
