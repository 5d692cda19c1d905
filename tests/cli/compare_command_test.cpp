// `fb89 compare` as a user runs it: one row per method in the CSV and JSON, the contact
// sheet PNG at its layout's size, its title and captions read back whole from the pixels,
// the scene named as the console names it (a bundled scene by name, a file as given), no
// face id differing from the Z-buffer's for the exact raster methods, exit 2 for a bad
// scene, and the same on a 1989 host.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "controller_sim/png_io.h"
#include "experiments/compare.h"
#include "host/methods.h"
#include "tests/cli/bitmap_text.h"
#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;

using fb89::testing::CliRun;
using fb89::testing::slurp;
using fb89::testing::test_dir;

// Runs fb89 from the repository root, where scenes/A.json is.
CliRun fb89_from_root(const std::string& args) {
    return fb89::testing::run_fb89(
        args, "cd " + fs::path(FB89_SCENES_DIR).parent_path().string() + " && ");
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');)
        cells.push_back(cell);
    return cells;
}

// The CSV's rows as column -> value, one map per row.
std::vector<std::map<std::string, std::string>> parse_csv(const std::string& text) {
    std::stringstream in(text);
    std::string line;
    std::getline(in, line);
    const std::vector<std::string> header = split(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line);
        std::map<std::string, std::string> row;
        for (size_t i = 0; i < header.size() && i < cells.size(); ++i)
            row[header[i]] = cells[i];
        rows.push_back(row);
    }
    return rows;
}

TEST(CompareCommand, WritesTheSheetAndOneRowPerMethod) {
    const fs::path dir = test_dir();
    const fs::path sheet = dir / "sheet.png", csv = dir / "compare.csv",
                   json = dir / "compare.json";
    for (const fs::path& p : {sheet, csv, json})
        fs::remove(p);
    CliRun r =
        fb89_from_root("compare scenes/A.json --size 128x98 --repeat 1 --sheet " + sheet.string() +
                       " --csv " + csv.string() + " --json " + json.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("pixels_differing"), std::string::npos) << r.out;  // the text table

    ASSERT_TRUE(fs::exists(sheet));
    const fb89::controller::PngImage png = fb89::controller::read_png(sheet);
    const std::size_t methods = fb89::host::methods().size();
    const fb89::experiments::SheetLayout layout = fb89::experiments::sheet_layout(128, 98, methods);
    EXPECT_EQ(layout.columns * layout.rows >= methods, true);
    EXPECT_EQ(png.width, layout.width);
    EXPECT_EQ(png.height, layout.height);

    const std::string text = slurp(csv);
    EXPECT_EQ(text.rfind("scene,method,host,host_ms,commands,fills,spans,controller_ms,frame_ms,"
                         "bound_by,pixels_differing,px_coverage,px_other_face,pipeline_ms,"
                         "overlap,host_stalled_ms,host_util,controller_util,px_ties,depth_bits,"
                         "depth_spans,faces\n",
                         0),
              0u)
        << text;
    const auto rows = parse_csv(text);
    ASSERT_EQ(rows.size(), methods);
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("scene"), "A");  // a bundled scene, by its name
        EXPECT_EQ(row.at("host"), "native");
        const std::string& m = row.at("method");
        if (m == "zbuffer" || m == "scanline" || m == "warnock" || m == "hybrid") {
            EXPECT_EQ(row.at("pixels_differing"), "0") << m;  // the exact methods
        }
        // the pipeline in time: never faster than the larger side, never slower than both
        // in turn with the host's stalls
        const double pipeline = std::stod(row.at("pipeline_ms"));
        EXPECT_GE(pipeline + 1e-3, std::stod(row.at("frame_ms"))) << m;
        EXPECT_LE(pipeline, std::stod(row.at("host_ms")) + std::stod(row.at("controller_ms")) +
                                std::stod(row.at("host_stalled_ms")) + 1e-3)
            << m;
        // the two kinds of difference add up to all of them
        EXPECT_EQ(std::stoull(row.at("pixels_differing")),
                  std::stoull(row.at("px_coverage")) + std::stoull(row.at("px_other_face")))
            << m;
    }
    EXPECT_EQ(rows[0].at("method"), "zbuffer");

    const nlohmann::json j = nlohmann::json::parse(slurp(json));
    ASSERT_TRUE(j.is_array());
    ASSERT_EQ(j.size(), fb89::host::methods().size());
    EXPECT_EQ(j[0]["method"], "zbuffer");
    EXPECT_EQ(j[0]["pixels_differing"].get<uint64_t>(), 0u);
    EXPECT_GT(j[0]["commands"].get<uint64_t>(), 0u);
}

TEST(CompareCommand, NothingIsWrittenUnaskedAndTheSheetWhereAsked) {
    const fs::path dir = test_dir() / "work";  // test_dir() holds the runner's own "out"
    fs::remove_all(dir);
    fs::create_directories(dir);
    CliRun r = fb89::testing::run_fb89("compare A --size 64x49 --repeat 1 -q",
                                       "cd " + dir.string() + " && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    EXPECT_TRUE(fs::is_empty(dir)) << "compare wrote a file it was not asked for";
    r = fb89::testing::run_fb89("compare A --size 64x49 --repeat 1 -q --sheet out/sheet.png",
                                "cd " + dir.string() + " && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "out" / "sheet.png"));
}

// The sheet's title band and each tile's caption, read back from the pixels.
struct SheetText {
    std::vector<std::string> title;
    std::vector<std::vector<std::string>> captions;  // the grey lines under each frame
};

SheetText read_sheet(const fb89::controller::PngImage& png,
                     const fb89::experiments::SheetLayout& l) {
    using fb89::testing::PixelArea;
    SheetText t;
    t.title = fb89::testing::read_bitmap_text(png, PixelArea{0, 0, png.width, l.title_height},
                                              {255, 255, 255}, 1);
    for (uint32_t i = 0; i < l.columns * l.rows; ++i) {
        const uint32_t x = l.gap + (i % l.columns) * (l.thumb_width + l.gap);
        const uint32_t y = l.title_height +
                           (i / l.columns) * (l.thumb_height + l.caption_height + l.gap) +
                           l.thumb_height;
        t.captions.push_back(fb89::testing::read_bitmap_text(
            png, PixelArea{x, y, l.thumb_width, l.caption_height}, {200, 200, 200}, 1));
    }
    return t;
}

std::string trimmed(const std::string& row) {
    return row.substr(std::min(row.find_first_not_of(' '), row.size()));
}

// Given by name, the bundled scene is named so on the sheet, in the CSV and in the JSON -- not
// by the path it was found at -- and the title and captions read whole inside the sheet.
TEST(CompareCommand, ABundledSceneIsNamedByItsNameOnTheSheetAndInTheTables) {
    const fs::path dir = test_dir();
    const fs::path sheet = dir / "sheet.png", csv = dir / "compare.csv",
                   json = dir / "compare.json";
    CliRun r =
        fb89::testing::run_fb89("compare A --size 128x98 --repeat 1 -q --sheet " + sheet.string() +
                                    " --csv " + csv.string() + " --json " + json.string(),
                                "cd " + dir.string() + " && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string title = "A  128x98  host native  controller tms34010-50mhz";
    const fb89::controller::PngImage png = fb89::controller::read_png(sheet);
    const SheetText text = read_sheet(
        png, fb89::experiments::sheet_layout(128, 98, fb89::host::methods().size(), title));
    ASSERT_EQ(text.title.size(), 1u) << ::testing::PrintToString(text.title);
    EXPECT_EQ(trimmed(text.title[0]), title);
    ASSERT_GE(text.captions.size(), fb89::host::methods().size());
    for (std::size_t i = 0; i < fb89::host::methods().size(); ++i) {  // (then empty tiles)
        const auto& caption = text.captions[i];
        ASSERT_EQ(caption.size(), 6u) << ::testing::PrintToString(caption);
        EXPECT_NE(caption[4].find(" spans"), std::string::npos) << caption[4];
    }
    for (const auto& row : parse_csv(slurp(csv)))
        EXPECT_EQ(row.at("scene"), "A");
    for (const auto& row : nlohmann::json::parse(slurp(json)))
        EXPECT_EQ(row["scene"], "A");
}

// A scene file of the user's is named by the path as given (relative, not made absolute); a
// title longer than the sheet is wide wraps onto more rows, all of it inside the sheet.
TEST(CompareCommand, AFileIsNamedAsGivenAndALongTitleWrapsInsideTheSheet) {
    const fs::path dir = test_dir();
    const std::string given =
        "scenes_of_my_own_in_a_folder_with_a_long_name/and_another_folder_inside_it/"
        "the_scene_A_copied_here.json";
    fs::create_directories((dir / given).parent_path());
    fs::copy_file(fs::path(FB89_SCENES_DIR) / "A.json", dir / given,
                  fs::copy_options::overwrite_existing);
    const fs::path sheet = dir / "sheet.png";
    CliRun r = fb89::testing::run_fb89(
        "compare " + given + " --size 64x49 --repeat 1 --sheet " + sheet.string() + " --json -",
        "cd " + dir.string() + " && ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const auto& row : nlohmann::json::parse(r.out))
        EXPECT_EQ(row["scene"], given);

    const std::string title = given + "  64x49  host native  controller tms34010-50mhz";
    const fb89::experiments::SheetLayout layout =
        fb89::experiments::sheet_layout(64, 49, fb89::host::methods().size(), title);
    const fb89::controller::PngImage png = fb89::controller::read_png(sheet);
    EXPECT_EQ(png.height, layout.height);
    const SheetText text = read_sheet(png, layout);
    EXPECT_GE(text.title.size(), 2u) << ::testing::PrintToString(text.title);
    EXPECT_EQ(fb89::testing::ink_of(text.title), fb89::testing::ink_of({title}))
        << ::testing::PrintToString(text.title);
    const auto extent = fb89::testing::ink_extent(
        png, fb89::testing::PixelArea{0, 0, png.width, layout.title_height}, {255, 255, 255});
    ASSERT_TRUE(extent.has_value());
    EXPECT_LT(extent->x + extent->width, png.width) << "the title reaches the sheet's edge";
}

// The figure after "<label> " in `text` (digits and the thousands' commas), as a number.
uint64_t count_after(const std::string& text, const std::string& label) {
    const size_t at = text.find(label);
    if (at == std::string::npos) return ~uint64_t{0};
    std::string digits;
    for (size_t i = at + label.size(); i < text.size() && (std::isdigit(text[i]) || text[i] == ',');
         ++i)
        if (text[i] != ',') digits += text[i];
    return digits.empty() ? ~uint64_t{0} : std::stoull(digits);
}

// The depth-command methods' frames as the default profile draws them (a 16-bit depth word):
// compare counts the ties `render --ids` counts, pixel for pixel, and none wrong.
TEST(CompareCommand, TheDepthCommandsDifferAsTheProfilesDepthWordDrawsThem) {
    const CliRun c = fb89_from_root("compare demo --repeat 1 -q --csv -");
    ASSERT_EQ(c.exit_code, 0) << c.err;
    std::map<std::string, std::map<std::string, std::string>> by_method;
    for (const auto& row : parse_csv(c.out))
        by_method[row.at("method")] = row;
    for (const char* method : {"zspans", "faces"}) {
        const auto& row = by_method.at(method);
        const fs::path ids = test_dir() / fmt::format("{}.ids.png", method);
        const CliRun r =
            fb89_from_root(fmt::format("render demo --method {} --ids {}", method, ids.string()));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const uint64_t differ = count_after(r.out, "(16-bit depth word): ");
        EXPECT_EQ(row.at("depth_bits"), "16") << method;
        EXPECT_EQ(std::stoull(row.at("pixels_differing")), differ) << method << "\n" << r.out;
        EXPECT_EQ(std::stoull(row.at("px_ties")), count_after(r.out, "pixels differ: ")) << method;
        EXPECT_GT(std::stoull(row.at("px_ties")), 1000u) << method;
        EXPECT_EQ(row.at("px_coverage"), "0") << method;
        EXPECT_GT(std::stoull(row.at(std::string(method) == "faces" ? "faces" : "depth_spans")),
                  0u);
    }
    EXPECT_EQ(by_method.at("zbuffer").at("px_ties"), "");
}

TEST(CompareCommand, BadInputExitsTwo) {
    CliRun missing = fb89_from_root("compare nowhere.json --repeat 1 --sheet " +
                                    (test_dir() / "sheet.png").string());
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("nowhere.json"), std::string::npos) << missing.err;
    EXPECT_EQ(fb89_from_root("compare scenes/A.json --threshold lots").exit_code, 2);
    EXPECT_EQ(fb89_from_root("compare scenes/A.json --threshold -1").exit_code, 2);
    EXPECT_EQ(fb89_from_root("compare").exit_code, 2);
}

TEST(PeriodCompare, TimesEveryMethodOnA1989Host) {
    const fs::path sheet = test_dir() / "sheet.png";
    CliRun r = fb89_from_root("compare scenes/A.json --size 32x24 --host sun3-60 -q --sheet " +
                              sheet.string() + " --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = parse_csv(r.out);
    ASSERT_EQ(rows.size(), fb89::host::methods().size()) << r.out;
    for (const auto& row : rows) {
        EXPECT_EQ(row.at("host"), "sun3-60");
        EXPECT_GT(std::stod(row.at("host_ms")), 0.0) << row.at("method");
    }
    EXPECT_TRUE(fs::exists(sheet));
}

}  // namespace
