// The paper's §2 model is exact on its ideal scene (Fig. 2.3: D layers of F_v squares with
// half-pixel gaps, each face flush with the right and bottom of its cell) on square
// power-of-two screens: an instrumented Warnock with the area window test must take
// exactly Eq. 2.4's window samples, and its sorting-phase face computations (faces sorted
// whole into one sub-window) must equal F log4(F_v), F = D F_v (the sum behind C_sort).
#include <gtest/gtest.h>

#include <cmath>

#include "host/model/analytic_model.h"
#include "host/raster/screen_setup.h"
#include "host/raster/warnock.h"
#include "host/scene/generators.h"
#include "protocol/memory_buffer.h"

namespace fb89::host {
namespace {

Counters warnock_on_ideal(int e_s, int layers, uint64_t f_v, WindowTest test) {
    const double cell = e_s / std::sqrt(static_cast<double>(f_v));
    const Scene scene = ideal_scene(e_s, e_s, layers, cell, cell, 0.5);
    Counters setup;
    ScreenScene screen = project_scene(scene, ColorMode::FaceId, setup);
    Warnock warnock({test, {}});
    protocol::MemoryBuffer discard;
    HostStats stats;
    warnock.render(screen, discard, stats);
    return stats.counters;
}

void expect_exact(int e_s, int layers) {
    for (uint64_t f_v = 1; f_v <= static_cast<uint64_t>(e_s) * e_s; f_v *= 4) {
        Counters c = warnock_on_ideal(e_s, layers, f_v, WindowTest::Area);
        const uint64_t predicted = model::window_samples_recurrence(e_s, f_v);
        ASSERT_EQ(static_cast<double>(predicted),
                  model::window_samples(e_s, static_cast<double>(f_v)));
        EXPECT_EQ(c.get("window_samples"), predicted)
            << "E_s=" << e_s << " D=" << layers << " F_v=" << f_v;
        const double sorts = model::scene_sort_face_computations(static_cast<double>(f_v), layers);
        EXPECT_EQ(static_cast<double>(c.get("face_sorts")), sorts)
            << "E_s=" << e_s << " D=" << layers << " F_v=" << f_v;
    }
}

TEST(WarnockIdeal, AreaSamplesEqualEq24ForOneLayerOnScreensFrom16To256) {
    for (int e_s = 16; e_s <= 256; e_s *= 2)
        expect_exact(e_s, 1);
}

// The two largest screens hold 95% of the work (6.6 s against 0.37 s in Release): a heavy
// sweep, in the long label (Release only; under the sanitizers it repeats the code above).
TEST(WarnockIdealLong, AreaSamplesEqualEq24ForOneLayerOnScreensOf512And1024) {
    for (int e_s : {512, 1024})
        expect_exact(e_s, 1);
}

TEST(WarnockIdeal, AreaSamplesEqualEq24ForTwoAndFourLayersUpTo256) {
    for (int layers : {2, 4})
        for (int e_s = 16; e_s <= 256; e_s *= 2)
            expect_exact(e_s, layers);
}

TEST(WarnockIdeal, ReproducesTheReferenceCounts) {
    EXPECT_EQ(warnock_on_ideal(64, 1, 16, WindowTest::Area).get("window_samples"), 1685u);
    EXPECT_EQ(warnock_on_ideal(128, 1, 1024, WindowTest::Area).get("window_samples"), 17749u);
    EXPECT_EQ(warnock_on_ideal(128, 1, 16384, WindowTest::Area).get("window_samples"), 21845u);
}

TEST(WarnockIdeal, CentresTestSeesNoGapsAndSamplesEachCellOnce) {
    // the half-pixel gaps hold no pixel centre, so with the centres test each cell is one
    // surrounded window: (F_v - 1) / 3 sorting samples + F_v
    for (uint64_t f_v = 4; f_v <= 4096; f_v *= 4) {
        Counters c = warnock_on_ideal(256, 2, f_v, WindowTest::Centres);
        EXPECT_EQ(c.get("window_samples"), (f_v - 1) / 3 + f_v) << "F_v=" << f_v;
    }
}

}  // namespace
}  // namespace fb89::host
