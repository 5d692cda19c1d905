// The shared option limits (frontend/option_limits.h): the words of a refusal, the CLI11 check
// built from an entry, and the requests of frontend/runs.h holding the same entries.
#include "frontend/option_limits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <CLI/CLI.hpp>

#include "frontend/common.h"
#include "frontend/runs.h"

namespace {

using fb89::frontend::check_limit;
using fb89::frontend::cli_check;
using fb89::frontend::limit_problem;
using fb89::frontend::Spelling;
using fb89::frontend::UsageError;
namespace limits = fb89::frontend::limits;

// What parsing `value` for an option checked by `limit` says: "" when it is accepted.
std::string cli_refusal(const fb89::frontend::OptionLimit& limit, const std::string& value) {
    CLI::App app;
    double parsed = 0;
    app.add_option(std::string(limit.option), parsed)->check(cli_check(limit));
    try {
        app.parse({value, std::string(limit.option)});  // CLI11 reads the vector back to front
    } catch (const CLI::ParseError& e) {
        return e.what();
    }
    return "";
}

std::string usage_error(const std::function<void()>& f) {
    try {
        f();
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(OptionLimits, AValueOutsideIsRefusedWithTheRangeInWholeNumbers) {
    EXPECT_EQ(limit_problem(limits::kRenderRepeat, 0), "0 is not in [1, 10000]");
    EXPECT_EQ(limit_problem(limits::kRenderRepeat, 10001), "10001 is not in [1, 10000]");
    EXPECT_EQ(limit_problem(limits::kRenderRepeat, -3), "-3 is not in [1, 10000]");
    EXPECT_EQ(limit_problem(limits::kApproxEps, 1.5), "1.5 is not in [0, 0.999]");
    EXPECT_EQ(limit_problem(limits::kBufferBytes, 0), "0 is not in [1, 1099511627776]");
    EXPECT_FALSE(limit_problem(limits::kRenderRepeat, 1));
    EXPECT_FALSE(limit_problem(limits::kRenderRepeat, 10000));
}

TEST(OptionLimits, AFractionIsNotAnIntegerAndNaNIsOutside) {
    EXPECT_EQ(limit_problem(limits::kRepeat, 2.5), "2.5 is not an integer");
    EXPECT_FALSE(limit_problem(limits::kTolerance, 2.5));
    EXPECT_EQ(limit_problem(limits::kTolerance, std::nan(""), "nan"), "nan is not in [0, 100]");
}

TEST(OptionLimits, TheErrorNamesTheOptionAsEachFrontEndSpellsIt) {
    EXPECT_EQ(usage_error([] { check_limit(limits::kReferenceRays, 1, Spelling::Option); }),
              "--reference-rays: 1 is not in [2, 16]");
    EXPECT_EQ(usage_error([] { check_limit(limits::kReferenceRays, 1, Spelling::Keyword); }),
              "reference_rays: 1 is not in [2, 16]");
}

TEST(OptionLimits, TheCommandLineCheckSaysTheSameWords) {
    EXPECT_EQ(cli_refusal(limits::kRenderRepeat, "0"), "--repeat: 0 is not in [1, 10000]");
    EXPECT_EQ(cli_refusal(limits::kRenderRepeat, "100000"),
              "--repeat: 100000 is not in [1, 10000]");
    EXPECT_EQ(cli_refusal(limits::kRenderRepeat, "1.5"), "--repeat: 1.5 is not an integer");
    EXPECT_EQ(cli_refusal(limits::kRenderRepeat, "99999999999999999999"),
              "--repeat: 99999999999999999999 is not in [1, 10000]");
    EXPECT_EQ(cli_refusal(limits::kTolerance, "lots"), "--tolerance: lots is not a number");
    EXPECT_EQ(cli_refusal(limits::kRenderRepeat, "10000"), "");
    EXPECT_EQ(cli_refusal(limits::kTolerance, "0.5"), "");
}

// What CLI11 says of these arguments to a command with options of each kind, in fb89's words.
std::string said_of(std::vector<std::string> args) {
    CLI::App app;
    double scale = 1, start = 0;
    std::string ff = "flux", method = "zbuffer", csv, png;
    bool json = false;
    app.add_option("--scale", scale)->check(CLI::Range(0.125, 8.0));
    app.add_option("--patches", start)->check(CLI::Range(1, 8192));
    app.add_option("--start", start)->check(CLI::NonNegativeNumber);
    app.add_option("--ff", ff)->check(CLI::IsMember({"flux", "hybrid", "hierarchical"}));
    app.add_option("--method", method);
    app.add_option("--png", png);
    CLI::Option* j = app.add_flag("--json", json);
    app.add_option("--csv", csv)->excludes(j);
    std::reverse(args.begin(), args.end());  // CLI11 reads the vector back to front
    try {
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        return fb89::frontend::usage_words(e.what());
    }
    return "";
}

TEST(OptionLimits, CLI11sProblemsAreSaidInTheProjectsWords) {
    EXPECT_EQ(said_of({"--scale", "9"}), "--scale: 9 is not in [0.125, 8]");
    EXPECT_EQ(said_of({"--patches", "0"}), "--patches: 0 is not in [1, 8192]");
    EXPECT_EQ(said_of({"--start=-1"}), "--start: -1 is not 0 or more");
    EXPECT_EQ(said_of({"--ff", "hirarchical"}),
              "--ff: unknown choice 'hirarchical'; did you mean 'hierarchical'? (flux, hybrid "
              "or hierarchical)");
    EXPECT_EQ(said_of({"--ff", "painter"}),
              "--ff: unknown choice 'painter' (flux, hybrid or hierarchical)");
    EXPECT_EQ(said_of({"--method", "zbuffer", "--method", "hybrid"}),
              "--method: given 2 times; give it once");
    EXPECT_EQ(said_of({"--csv", "a.csv", "--json"}),
              "--json and --csv exclude each other: give one of them");
    EXPECT_EQ(said_of({"--png"}), "--png: needs a value after it");
    EXPECT_EQ(said_of({"--scale", "2"}), "");
    // words that are not CLI11's pass as they are
    EXPECT_EQ(fb89::frontend::usage_words("--repeat: 0 is not in [1, 10000]"),
              "--repeat: 0 is not in [1, 10000]");
    EXPECT_EQ(fb89::frontend::usage_words("--method: unknown method 'x' (a or b)"),
              "--method: unknown method 'x' (a or b)");
}

TEST(OptionLimits, TheRequestsHoldTheSameLimitsInTheCallersSpelling) {
    fb89::frontend::SweepRequest r;
    r.scenes = {"A"};
    r.steps = 201;
    EXPECT_EQ(usage_error([&] { fb89::frontend::run_threshold_sweep(r); }),
              "--steps: 201 is not in [1, 200]");
    r.spelling = Spelling::Keyword;
    EXPECT_EQ(usage_error([&] { fb89::frontend::run_threshold_sweep(r); }),
              "steps: 201 is not in [1, 200]");
    r.steps = 3;
    r.repeat = 0;
    EXPECT_EQ(usage_error([&] { fb89::frontend::run_threshold_sweep(r); }),
              "repeat: 0 is not in [1, 1000]");
}

TEST(OptionLimits, ASizeSideIsHeldToTheSameEntry) {
    EXPECT_EQ(usage_error([] { fb89::frontend::parse_size("0x48", Spelling::Keyword); }),
              "size: width and height must be in [1, 16384], got '0x48'");
    EXPECT_EQ(fb89::frontend::parse_size("16384x1").width, 16384);
}

}  // namespace
