#include "host/methods.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace fb89::host {
namespace {

TEST(Methods, EveryMethodIsBuiltUnderItsOwnName) {
    std::set<std::string_view> seen;
    for (const MethodInfo& m : methods()) {
        EXPECT_TRUE(seen.insert(m.name).second) << m.name << " listed twice";
        EXPECT_EQ(method_named(m.name), m.method);
        EXPECT_EQ(make_renderer(m.method)->name(), m.name);
        EXPECT_FALSE(m.description.empty()) << m.name;
    }
    EXPECT_EQ(renderer_names().size(), methods().size());
}

TEST(Methods, AnUnknownNameIsRefusedNamingTheKnownOnes) {
    try {
        method_named("zbufer");
        FAIL() << "accepted";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("'zbufer'"), std::string::npos) << what;
        for (const MethodInfo& m : methods())
            EXPECT_NE(what.find(std::string(m.name)), std::string::npos) << what;
    }
}

TEST(Methods, EachMethodReadsOnlyItsOwnOptionGroups) {
    EXPECT_EQ(method_info(Method::ZBuffer).options, 0u);
    EXPECT_EQ(method_info(Method::ScanLine).options, 0u);
    EXPECT_TRUE(method_info(Method::Warnock).uses(kWindowOptions));
    EXPECT_FALSE(method_info(Method::Warnock).uses(kHybridOptions));
    EXPECT_TRUE(method_info(Method::Hybrid).uses(kHybridOptions));
    EXPECT_TRUE(method_info(Method::RayTrace).uses(kTraceOptions));
    EXPECT_FALSE(method_info(Method::RayTrace).uses(kBeamOptions));
    EXPECT_TRUE(method_info(Method::Beam).uses(kBeamOptions));
}

TEST(Methods, OutOfRangeOptionsAreRefusedOnlyWhereTheMethodReadsThem) {
    MethodOptions o(Method::Beam);
    o.beam.grid_density = 0;
    EXPECT_THROW(make_renderer(o), std::invalid_argument);
    o.beam.grid_density = kMaxGridDensity * 2;
    EXPECT_THROW(validate(o), std::invalid_argument);
    o.method = Method::RayTrace;  // rays use the BVH: the grid density is not theirs
    EXPECT_NO_THROW(validate(o));
    o.beam.grid_density = BeamOptions{}.grid_density;
    o.trace.max_reflections = kMaxReflections + 1;
    EXPECT_THROW(validate(o), std::invalid_argument);
    o.method = Method::ZBuffer;  // the Z-buffer reads no trace options
    EXPECT_NO_THROW(validate(o));

    MethodOptions h(Method::Hybrid);
    h.hybrid.threshold = -1;
    EXPECT_THROW(validate(h), std::invalid_argument);
    h.hybrid.threshold = INFINITY;
    h.warnock.approx = {4, 1.0};
    EXPECT_THROW(validate(h), std::invalid_argument);

    MethodOptions b(Method::Beam);
    b.beam.threshold = NAN;
    EXPECT_THROW(validate(b), std::invalid_argument);
}

TEST(Methods, DefaultsAreThePapersAndTheCalibratedOnes) {
    const MethodOptions o;
    EXPECT_EQ(o.method, Method::ZBuffer);
    EXPECT_EQ(o.hybrid.threshold, kPaperThreshold);
    EXPECT_EQ(o.beam.threshold, kDefaultBeamThreshold);
    EXPECT_EQ(o.warnock.window_test, WindowTest::Area);
    EXPECT_EQ(o.warnock.approx.min_side, 0);
}

}  // namespace
}  // namespace fb89::host
