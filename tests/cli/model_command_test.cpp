// `fb89 model` as a user runs it: the analytic model's tables (Marks et al. 1990,
// Eqs. 2.1-2.7, Expr. 3.1) as text, JSON and CSV, and its exit codes.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_runner.h"

namespace {

namespace fs = std::filesystem;

using fb89::testing::CliRun;
using fb89::testing::run_fb89;

std::vector<std::string> text_lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        out.push_back(line);
    return out;
}

TEST(ModelCommand, TablePrintsThe1685SamplesOfEs64Fv16) {
    CliRun r = run_fb89("model --es 64 --fv 16");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("Eqs. 2.1-2.4"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("S(F_v) 2.4"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(" 1685 "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ideal scene (exact)"), std::string::npos) << r.out;
}

TEST(ModelCommand, JsonGivesTheThreeSanityValues) {
    CliRun r = run_fb89("model --es 64,128 --fv 16 --fv 1024,16384 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["samples"].size(), 6u);
    auto s = [&](double e_s, double f_v) {
        for (const auto& row : j["samples"])
            if (row["e_s"] == e_s && row["f_v"] == f_v) return row;
        return nlohmann::json();
    };
    EXPECT_EQ(s(64, 16)["s_2_4"], 1685.0);
    EXPECT_EQ(s(128, 1024)["s_2_4"], 17749.0);
    EXPECT_EQ(s(128, 16384)["s_2_4"], 21845.0);
    EXPECT_EQ(s(128, 16384)["e_f"], 1.0);
    EXPECT_EQ(s(64, 16384)["valid"], false);  // F_v > E_s^2
    EXPECT_NE(s(64, 16384)["note"].get<std::string>().find("E_f < 1"), std::string::npos);
    EXPECT_EQ(s(64, 16)["ideal"], true);
}

TEST(ModelCommand, CsvTabulatesAGeometricGridWithOneHeaderRow) {
    CliRun r = run_fb89("model --es 16..1024*2 --fv 1..1048576*4 --d 2 --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto rows = text_lines(r.out);
    ASSERT_EQ(rows.size(), 1u + 7 * 11);
    EXPECT_EQ(rows[0], "e_s,f_v,d,e_f,s_sort_2_1,s_split_2_3,s_2_4,f,c_sort,valid,ideal,note");
    EXPECT_NE(r.out.find("\n128,16384,2,1,5461,1,21845,32768,229376,true,true,\n"),
              std::string::npos)
        << r.out;
}

TEST(ModelCommand, LinearRangesAndNonIntegerValuesAreAccepted) {
    CliRun r = run_fb89("model --es 780 --fv 1..2+0.5 --csv -");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    auto rows = text_lines(r.out);
    ASSERT_EQ(rows.size(), 4u);
    EXPECT_EQ(rows[2].substr(0, 8), "780,1.5,");
    EXPECT_NE(rows[2].find(",true,false,"), std::string::npos) << rows[2];  // valid, not ideal
}

TEST(ModelCommand, WindowCostsGiveExpr31AndExpr27) {
    CliRun r = run_fb89("model --fw 64 --ew 32 --d 4 --faces 1000 --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    nlohmann::json j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["window_costs"].size(), 1u);
    const auto& w = j["window_costs"][0];
    EXPECT_EQ(w["expr_3_1"], 0.1875);
    EXPECT_EQ(w["expr_2_6"], 0.75);
    EXPECT_DOUBLE_EQ(w["expr_2_5"].get<double>(), 0.75);
    EXPECT_DOUBLE_EQ(w["expr_2_7"].get<double>(), 1000.0 * (16 * 64 - 4) / (32 * 32 * 4));
    EXPECT_EQ(w["valid"], true);
    EXPECT_FALSE(j.contains("samples"));
}

TEST(ModelCommand, WindowTableOmitsExpr27WithoutFaces) {
    CliRun r = run_fb89("model --fw 64 --ew 32 --d 4");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("3.1"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0.1875"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("2.7  "), std::string::npos) << r.out;
}

TEST(ModelCommand, OutOfDomainRowsAreReportedNotRefused) {
    CliRun r = run_fb89("model --es 64 --fv 0.5");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("F_v < 1"), std::string::npos) << r.out;
    CliRun w = run_fb89("model --fw 2 --ew 32 --d 4");
    ASSERT_EQ(w.exit_code, 0) << w.err;
    EXPECT_NE(w.out.find("F_w < D"), std::string::npos) << w.out;
}

TEST(ModelCommand, HelpDescribesEveryEquationByNumber) {
    CliRun r = run_fb89("model --help");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* eq :
         {"Eq. 2.1", "Eqs. 2.2-2.3", "Eq. 2.4", "Expr. 2.5", "Expr. 2.6", "Expr. 2.7", "Expr. 3.1",
          "--es", "--fv", "--d", "--fw", "--ew", "--faces", "--json", "--csv"})
        EXPECT_NE(r.out.find(eq), std::string::npos) << eq << "\n" << r.out;
}

TEST(ModelCommand, BadValuesExitTwoNamingTheOption) {
    struct Case {
        const char* args;
        const char* option;
    };
    for (const Case& c :
         {Case{"--es -1 --fv 16", "--es"}, Case{"--es=-1 --fv 16", "--es"},
          Case{"--es 64 --fv 0", "--fv"}, Case{"--es 64 --fv abc", "--fv"},
          Case{"--es 64 --fv 16 --d 0", "--d"}, Case{"--es 64x --fv 16", "--es"},
          Case{"--es 64, --fv 16", "--es"}, Case{"--es 64 --fv nan", "--fv"},
          Case{"--fw 64 --ew -2", "--ew"}, Case{"--fw 64 --ew 8 --faces 0", "--faces"},
          Case{"--es 64..16 --fv 16", "--es"}, Case{"--es 1..64*1 --fv 16", "--es"},
          Case{"--es 1..1e9 --fv 16", "--es"}, Case{"--es 64", "--fv"}, Case{"--fw 64", "--ew"}}) {
        CliRun r = run_fb89(std::string("model ") + c.args);
        EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.out;
        EXPECT_NE(r.err.find(c.option), std::string::npos) << c.args << "\n" << r.err;
    }
}

TEST(ModelCommand, MissingOrConflictingRequestsExitTwo) {
    EXPECT_EQ(run_fb89("model").exit_code, 2);
    EXPECT_EQ(run_fb89("model --es 64 --fv 16 --json --csv -").exit_code, 2);
    CliRun both = run_fb89("model --es 64 --fv 16 --fw 64 --ew 32 --csv -");
    EXPECT_EQ(both.exit_code, 2);
    EXPECT_NE(both.err.find("--csv"), std::string::npos) << both.err;
}

}  // namespace
