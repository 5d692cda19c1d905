// The scene format as written down: scenes/README.md documents, section by section, exactly
// the keys the loader accepts (every JsonFields::only_keys call names a section of
// scene_keys.h); its example scenes load; the OBJ example brings in its mesh and colours.
#include "host/scene/scene_keys.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "host/scene/scene_error.h"
#include "host/scene/scene_loader.h"

namespace fb89::host {
namespace {

namespace fs = std::filesystem;

std::string readme() {
    std::ifstream in(fs::path(FB89_SCENES_DIR) / "README.md");
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Section name -> the keys in the first column of the table after its marker
// `<!-- keys NAME -->`; a section marked twice is listed with a "#twice" key.
std::map<std::string, std::set<std::string>> documented_keys(const std::string& text) {
    std::map<std::string, std::set<std::string>> out;
    const std::regex marker(R"(<!-- keys ([a-z_ ]+) -->)");
    const std::regex row(R"(^\| `([a-z_]+)` \|)");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), marker);
         it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[1];
        if (out.count(name)) out[name].insert("#twice");
        std::set<std::string>& keys = out[name];
        std::istringstream lines(text.substr(static_cast<size_t>(it->position() + it->length())));
        std::string line;
        bool in_table = false;
        while (std::getline(lines, line)) {
            if (line.rfind("|", 0) != 0) {
                if (in_table) break;  // the table has ended
                continue;
            }
            in_table = true;
            std::smatch m;
            if (std::regex_search(line, m, row)) keys.insert(m[1]);
        }
    }
    return out;
}

TEST(SceneFormat, TheReadmeDocumentsExactlyTheKeysTheLoaderAccepts) {
    const auto documented = documented_keys(readme());
    for (const KeySection& section : scene_key_sections()) {
        SCOPED_TRACE(std::string(section.name));
        auto found = documented.find(std::string(section.name));
        ASSERT_NE(found, documented.end())
            << "no table marked <!-- keys " << section.name << " -->";
        std::set<std::string> accepted(section.keys.begin(), section.keys.end());
        EXPECT_EQ(found->second, accepted);
    }
    for (const auto& [name, keys] : documented) {
        bool known = false;
        for (const KeySection& section : scene_key_sections())
            known = known || section.name == name;
        EXPECT_TRUE(known) << "README documents a section the loader does not have: " << name;
    }
}

TEST(SceneFormat, TheTableAfterAMarkerIsReadToItsEndAndAMissingKeyIsSeen) {
    const auto keys = documented_keys(
        "<!-- keys light -->\n| key | type |\n|---|---|\n| `direction` | v |\n\ntext\n"
        "| `ambient` | not this table |\n<!-- keys light -->\n");
    ASSERT_EQ(keys.count("light"), 1u);
    EXPECT_EQ(keys.at("light"), (std::set<std::string>{"direction", "#twice"}));
    const auto& accepted = scene_keys("light");
    EXPECT_NE(keys.at("light"), std::set<std::string>(accepted.begin(), accepted.end()));
}

TEST(SceneFormat, AnUnknownKeyIsRefusedWithTheSectionsKeys) {
    try {
        parse_scene_json(R"({"camera": {"projection": "screen"}, "objects": [],
                             "light": {"direction": [0, 0, -1], "colour": [1, 1, 1]}})",
                         "s.json", ".");
        FAIL() << "loaded";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown field 'colour' (expected one of: direction, "
                                             "ambient)"),
                  std::string::npos)
            << e.what();
    }
}

TEST(SceneFormat, TheReadmesMinimalSceneLoads) {
    const std::string text = readme();
    const auto begin = text.find("```json\n");
    ASSERT_NE(begin, std::string::npos);
    const auto end = text.find("```", begin + 8);
    const Scene scene =
        parse_scene_json(text.substr(begin + 8, end - begin - 8), "README.md", FB89_SCENES_DIR);
    EXPECT_EQ(scene.face_count, 6u);  // one box
}

TEST(SceneFormat, TheObjExampleBringsInItsMeshTransformsAndColours) {
    const Scene scene = load_scene(fs::path(FB89_SCENES_DIR) / "obj_example.json");
    // 8 x 8 floor tiles, a wall, three icosahedra of 20 faces
    ASSERT_EQ(scene.face_count, 64u + 1 + 3 * 20);
    EXPECT_EQ(scene.dropped, 0u);
    EXPECT_EQ(scene.triangulated, 0u);
    std::map<uint32_t, std::map<std::string, int>> colours;  // object -> colour -> faces
    for (const Face& f : scene.faces)
        ++colours[f.object][fmt::format("{:.2f} {:.2f} {:.2f}", f.material.color.r,
                                        f.material.color.g, f.material.color.b)];
    // the first copy takes the file's two materials (icosahedron.mtl's Kd)
    EXPECT_EQ(colours[2],
              (std::map<std::string, int>{{"0.85 0.62 0.18", 8}, {"0.20 0.45 0.75", 12}}));
    // the second's material colour replaces them
    EXPECT_EQ(colours[3], (std::map<std::string, int>{{"0.80 0.25 0.20", 20}}));
    // transforms: the stretched copy is 0.9 high per unit of radius, centred at y = 0.78
    double lo = 1e9, hi = -1e9;
    for (const Face& f : scene.faces)
        if (f.object == 3)
            for (const auto& v : f.vertices) {
                lo = std::min(lo, v.y);
                hi = std::max(hi, v.y);
            }
    EXPECT_NEAR(hi - lo, 2 * 0.9 * 0.850651, 1e-5);
    EXPECT_NEAR((hi + lo) / 2, 0.78, 1e-9);
    EXPECT_GT(lo, 0.0);  // it stands above the floor, not in it
}

}  // namespace
}  // namespace fb89::host
