// frontend/calibration.h: a threshold asked for as "calibrated" without its calibration says
// what is missing -- the method and the host -- and the exact command that makes it; the
// calibration of one method or host is never taken for another's. The file lives in a
// scratch folder ($FB89_CALIBRATION), never the user's.
#include "frontend/calibration.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <string>

#include "tests/scratch.h"

namespace {

namespace fe = fb89::frontend;
namespace fs = std::filesystem;

// $FB89_CALIBRATION aimed at an empty scratch file for the test, and back after it.
class Calibration : public ::testing::Test {
  protected:
    void SetUp() override {
        const char* was = std::getenv("FB89_CALIBRATION");
        m_was = was ? was : "";
        m_had = was != nullptr;
        m_file = fb89::testing::scratch_path("calibration-hint") / "calibration.json";
        fs::create_directories(m_file.parent_path());
        fs::remove(m_file);
        ::setenv("FB89_CALIBRATION", m_file.c_str(), 1);
    }
    void TearDown() override {
        if (m_had)
            ::setenv("FB89_CALIBRATION", m_was.c_str(), 1);
        else
            ::unsetenv("FB89_CALIBRATION");
    }
    fs::path m_file;

  private:
    std::string m_was;
    bool m_had = false;
};

std::string source_of_hybrid(const std::string& host) {
    std::string source;
    fe::resolve_threshold("calibrated", &source, host);
    return source;
}

std::string source_of_beam(const std::string& host) {
    std::string source;
    fe::resolve_beam_threshold("calibrated", &source, host);
    return source;
}

TEST_F(Calibration, AMissingOneNamesTheMethodTheHostAndTheCommandThatMakesIt) {
    EXPECT_EQ(source_of_hybrid("native"),
              "the paper's: not calibrated yet for method hybrid on host native: `fb89 "
              "calibrate` makes it");
    EXPECT_EQ(source_of_beam("native"),
              "the built-in one: not calibrated yet for method beam on host native: `fb89 "
              "calibrate --method beam` makes it");
    EXPECT_EQ(source_of_hybrid("sun3-60"),
              "the paper's: not calibrated yet for method hybrid on host sun3-60: `fb89 "
              "calibrate --host sun3-60` makes it");
    EXPECT_EQ(source_of_beam("sun4-260"),
              "the built-in one: not calibrated yet for method beam on host sun4-260: `fb89 "
              "calibrate --method beam --host sun4-260` makes it");
    EXPECT_FALSE(fs::exists(m_file)) << "asking writes nothing";
}

TEST_F(Calibration, OneMethodsOrHostsCalibrationIsNotAnothers) {
    fe::save_calibration(0.01, "{}");
    EXPECT_EQ(source_of_hybrid("native"), "calibrated here");
    EXPECT_NE(source_of_beam("native").find("`fb89 calibrate --method beam`"), std::string::npos);
    EXPECT_NE(source_of_hybrid("sun3-60").find("`fb89 calibrate --host sun3-60`"),
              std::string::npos);
    fe::save_beam_calibration(2, "{}", "sun3-60");
    EXPECT_EQ(source_of_beam("sun3-60"), "calibrated here");
    EXPECT_NE(source_of_beam("native").find("`fb89 calibrate --method beam`"), std::string::npos);
    EXPECT_NE(source_of_hybrid("sun3-60").find("`fb89 calibrate --host sun3-60`"),
              std::string::npos);
}

TEST(CalibrationCommand, NamesOnlyWhatDiffersFromTheDefaults) {
    EXPECT_EQ(fe::calibrate_command("hybrid"), "fb89 calibrate");
    EXPECT_EQ(fe::calibrate_command("beam"), "fb89 calibrate --method beam");
    EXPECT_EQ(fe::calibrate_command("hybrid", "pc-386-25"), "fb89 calibrate --host pc-386-25");
}

}  // namespace
