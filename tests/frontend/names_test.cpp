// frontend/names.cpp: every registered name passes its check, a near miss is answered with
// the nearest known name, a far one with none, and paths pass where the loaders read files.
#include "frontend/names.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "frontend/common.h"
#include "tests/cli/help_text.h"

namespace {

namespace fe = fb89::frontend;

// What a check says of `name`: "" when it passes, else its UsageError's message.
std::string said(const std::function<void(const std::string&)>& check, const std::string& name) {
    try {
        check(name);
    } catch (const fe::UsageError& e) {
        return e.what();
    }
    return "";
}

void check_method(const std::string& name) {
    fe::find_method(name);
}

TEST(Names, EveryRegisteredNamePassesItsCheck) {
    for (const std::string& m : fb89::testing::registered_methods())
        EXPECT_EQ(said(check_method, m), "") << m;
    for (const std::string& p : fb89::testing::registered_profiles())
        EXPECT_EQ(said(fe::check_profile_name, p), "") << p;
    for (const std::string& h : fb89::testing::registered_hosts())
        EXPECT_EQ(said(fe::check_host_name, h), "") << h;
    for (const std::string& h : fb89::testing::registered_host_profiles())
        EXPECT_EQ(said(fe::check_host_profile_name, h), "") << h;
    EXPECT_EQ(fe::scene_names(), fb89::testing::bundled_scenes());
}

TEST(Names, ANearMissIsAnsweredWithTheNearestKnownName) {
    EXPECT_EQ(said(check_method, "zbufer"),
              "unknown method 'zbufer'; did you mean 'zbuffer'? (zbuffer, scanline, warnock, "
              "hybrid, raytrace, beam, zspans, faces, hzb or mlrta; fb89 list methods)");
    const std::string profile = said(fe::check_profile_name, "tms34020-40mz");
    EXPECT_EQ(profile.rfind("unknown profile 'tms34020-40mz'; did you mean 'tms34020-40mhz'? (", 0),
              0u)
        << profile;
    EXPECT_NE(profile.find("or a .json profile; fb89 list profiles)"), std::string::npos);
    const std::string host = said(fe::check_host_name, "sun4-26");
    EXPECT_EQ(host.rfind("unknown host 'sun4-26'; did you mean 'sun4-260'? (native, ", 0), 0u)
        << host;
    EXPECT_NE(host.find("or a .json host profile; fb89 list hosts)"), std::string::npos) << host;
    const std::string period = said(fe::check_host_profile_name, "pc-386-2");
    EXPECT_EQ(period.rfind("unknown host profile 'pc-386-2'; did you mean 'pc-386-25'? (", 0), 0u)
        << period;
    EXPECT_EQ(period.find("native"), std::string::npos) << "host-validate has no native";
}

TEST(Names, AFarNameGetsNoGuessButTheWholeList) {
    const std::string far = said(check_method, "painter");
    EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
    for (const std::string& m : fb89::testing::registered_methods())
        EXPECT_TRUE(fb89::testing::names(far, m)) << m << ": " << far;
    EXPECT_EQ(said(fe::check_host_name, "vax-11-780").find("did you mean"), std::string::npos);
}

TEST(Names, ANameCutShortIsAnsweredWithTheNamesItOpens) {
    const std::string profile = said(fe::check_profile_name, "tms34020");
    EXPECT_EQ(profile.rfind("unknown profile 'tms34020'; did you mean 'tms34020-40mhz'? (", 0), 0u)
        << profile;
    EXPECT_EQ(fe::nearest_hint("tms34010", fe::profile_names()),
              "; did you mean 'tms34010-50mhz', 'tms34010-isa' or 'tms34010-mame'?");
    EXPECT_EQ(fe::nearest_hint("sparc", fe::host_names()),
              "; did you mean 'sparcstation-1' or 'sparcstation-2'?");
    // a name two edits away is still the one guess
    EXPECT_EQ(fe::nearest_hint("tms34020-40", fe::profile_names()),
              "; did you mean 'tms34020-40mhz'?");
    // one letter is too little to guess from; more than three names are no guess either
    EXPECT_EQ(fe::nearest_hint("t", {"tms34010-50mhz"}), "");
    EXPECT_EQ(fe::nearest_hint("zz", {"zzaaa", "zzbbb", "zzccc", "zzddd"}), "");
}

TEST(Names, AMessageListingTheNamesItExpectedGetsTheNearest) {
    EXPECT_EQ(fe::with_nearest_name("--calls: call set '/spna': at character 2: unknown filter "
                                    "'/spna'; expected a step or one of /fill /span /draw"),
              "--calls: call set '/spna': at character 2: unknown filter '/spna'; expected a step "
              "or one of /fill /span /draw; did you mean '/span'?");
    EXPECT_EQ(fe::with_nearest_name("--isa: expected baseline, v3 or v4, got 'baselin'"),
              "--isa: expected baseline, v3 or v4, got 'baselin'; did you mean 'baseline'?");
    EXPECT_EQ(fe::with_nearest_name("--isa: expected baseline, v3 or v4, got 'sse'"),
              "--isa: expected baseline, v3 or v4, got 'sse'");
    const std::string guessed = "unknown method 'zbufer'; did you mean 'zbuffer'? (a or b)";
    EXPECT_EQ(fe::with_nearest_name(guessed), guessed);
    EXPECT_EQ(fe::with_nearest_name("cannot open x"), "cannot open x");
}

TEST(Names, PathsPassWhereTheLoadersReadFiles) {
    EXPECT_EQ(said(fe::check_profile_name, "boards/mine.json"), "");
    EXPECT_EQ(said(fe::check_profile_name, "mine.json"), "");
    EXPECT_EQ(said(fe::check_host_name, "hosts/mine.json"), "");
    EXPECT_EQ(said(fe::check_host_profile_name, "mine.json"), "");
    // the host loader reads only .json files; "native" is no host profile
    EXPECT_NE(said(fe::check_host_name, "hosts/mine"), "");
    EXPECT_NE(said(fe::check_host_profile_name, "native"), "");
}

TEST(Names, ValidatorsGiveTheChecksMessage) {
    std::string good = "beam", bad = "bem";
    EXPECT_EQ(fe::method_validator()(good), "");
    EXPECT_NE(fe::method_validator()(bad).find("did you mean 'beam'?"), std::string::npos);
    std::string calibrated = "hybird";
    EXPECT_EQ(fe::one_of_validator("method", {"hybrid", "beam"})(calibrated),
              "unknown method 'hybird'; did you mean 'hybrid'? (hybrid or beam)");
}

TEST(Names, NameListJoinsTheLastTwoWithTheWordGiven) {
    EXPECT_EQ(fe::name_list({"a", "b", "c"}), "a, b or c");
    EXPECT_EQ(fe::name_list({"a", "b"}, "and"), "a and b");
    EXPECT_EQ(fe::name_list({"a"}), "a");
    EXPECT_EQ(fe::name_list({}), "");
}

}  // namespace
