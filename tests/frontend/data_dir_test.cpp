// frontend/data_dir.cpp's resolve_scene: a bundled scene by its name from any folder; a path
// (a '/', or .json, .obj, .tri) from the current folder only, never looked up in the source
// tree; errors naming the argument, saying when a bundled scene has that name, and the
// nearest bundled scene for a name that is none.
#include "frontend/data_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "host/scene/scene_error.h"
#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using fb89::frontend::resolve_scene;

// The current folder set to this test's own for the test's length.
class DataDir : public ::testing::Test {
  protected:
    void SetUp() override {
        m_old = fs::current_path();
        fs::current_path(fb89::testing::test_dir());
    }
    void TearDown() override { fs::current_path(m_old); }

  private:
    fs::path m_old;
};

// resolve_scene's error for `argument`, or "" when it resolves.
std::string error_of(const std::string& argument) {
    try {
        resolve_scene(argument);
    } catch (const fb89::host::SceneError& e) {
        return e.what();
    }
    return "";
}

TEST_F(DataDir, ABundledSceneIsFoundByItsNameFromAnyFolder) {
    EXPECT_EQ(fs::canonical(resolve_scene("demo")),
              fs::canonical(fs::path(FB89_SCENES_DIR) / "demo.json"));
    EXPECT_EQ(fs::canonical(resolve_scene("cornell_box")),
              fs::canonical(fs::path(FB89_SCENES_DIR) / "cornell_box.json"));
}

TEST_F(DataDir, ARelativePathIsReadFromTheCurrentFolderOnly) {
    // scenes/demo.json is in the source tree, not here
    const std::string here = fs::current_path().string();
    EXPECT_EQ(error_of("scenes/demo.json"),
              "scenes/demo.json: cannot open the scene file: no such file (a relative path is read "
              "from the current "
              "folder, " +
                  here + "); demo is a bundled scene: give its name alone, demo");
    // a bundled scene's file name is a path too
    EXPECT_NE(error_of("G.json").find("G is a bundled scene: give its name alone, G"),
              std::string::npos);
    // a path that is no bundled scene's gets no such note
    const std::string attic = error_of("rooms/attic.obj");
    EXPECT_EQ(attic.rfind("rooms/attic.obj: cannot open the scene file: no such file (", 0), 0u)
        << attic;
    EXPECT_EQ(attic.find("bundled"), std::string::npos) << attic;
    // a file that is here is read from here, as given
    fs::create_directories("scenes");
    std::ofstream("scenes/demo.json") << "{}";
    EXPECT_EQ(resolve_scene("scenes/demo.json"), "scenes/demo.json");
}

TEST_F(DataDir, AnAbsolutePathIsReadAsGiven) {
    const std::string demo = (fs::path(FB89_SCENES_DIR) / "demo.json").string();
    EXPECT_EQ(resolve_scene(demo), demo);
    const std::string missing = (fs::current_path() / "none.json").string();
    EXPECT_EQ(error_of(missing), missing + ": cannot open the scene file: no such file");
}

TEST_F(DataDir, AnUnknownNameGetsTheNearestBundledScene) {
    const std::string near = error_of("demoo");
    EXPECT_EQ(near.rfind("demoo: cannot open the scene file: no bundled scene of that name, nor a "
                         "file in the current folder; "
                         "did you mean 'demo'? (the bundled scenes: A, B, C",
                         0),
              0u)
        << near;
    EXPECT_NE(near.find("; fb89 list scenes)"), std::string::npos) << near;
    EXPECT_NE(error_of("garish_rom").find("did you mean 'garish_room'?"), std::string::npos);
    EXPECT_EQ(error_of("frobnicate").find("did you mean"), std::string::npos);
}

TEST_F(DataDir, AFolderNamedLikeABundledSceneIsNotTakenForIt) {
    fs::create_directories("demo");
    EXPECT_EQ(fs::canonical(resolve_scene("demo")),
              fs::canonical(fs::path(FB89_SCENES_DIR) / "demo.json"));
    std::ofstream("mine") << "{}";
    EXPECT_EQ(resolve_scene("mine"), "mine");
}

}  // namespace
