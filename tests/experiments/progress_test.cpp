// Tests of experiments/progress: what the line says, when it estimates, that a line that is
// off says nothing, what an observer hears, and how work stops.
#include "experiments/progress.h"

#include <gtest/gtest.h>

#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include "experiments/measure.h"
#include "period/stop.h"

namespace fb89::experiments {
namespace {

// Captures std::cerr while alive.
struct CapturedCerr {
    std::ostringstream text;
    std::streambuf* old = std::cerr.rdbuf(text.rdbuf());
    ~CapturedCerr() { std::cerr.rdbuf(old); }
};

TEST(ProgressLine, CountsUnitsAndEstimatesOnlyOnceOneIsDone) {
    CapturedCerr err;
    {
        ProgressLine line(true);
        line.start("fig2.1");
        line.step(0, 4, "rounds");
        EXPECT_EQ(err.text.str().find("left"), std::string::npos) << err.text.str();
        line.step(1, 4, "rounds");
        line.step(4, 4, "rounds");
    }
    const std::string s = err.text.str();
    EXPECT_NE(s.find("\rfig2.1: 0/4 rounds"), std::string::npos) << s;
    EXPECT_NE(s.find("\rfig2.1: 1/4 rounds, about "), std::string::npos) << s;
    EXPECT_NE(s.find("s left"), std::string::npos) << s;
    // the last step has nothing left to estimate, and the line is wiped at the end
    const size_t last = s.find("\rfig2.1: 4/4 rounds");
    ASSERT_NE(last, std::string::npos) << s;
    EXPECT_EQ(s.find("left", last), std::string::npos) << s;
    EXPECT_EQ(s.back(), '\r');
}

TEST(ProgressLine, ManyUnitsAreShownAsAPercentageAtMostTenTimesASecond) {
    CapturedCerr err;
    ProgressLine line(true);
    line.start("form factors");
    for (uint64_t i = 0; i <= 100'000; ++i)
        line.step(i, 100'000);
    const std::string s = err.text.str();
    EXPECT_NE(s.find("form factors: 0%"), std::string::npos) << s;
    EXPECT_NE(s.find("form factors: 100%"), std::string::npos) << s;
    size_t shown = 0;
    for (size_t at = s.find('\r'); at != std::string::npos; at = s.find('\r', at + 1))
        ++shown;
    EXPECT_LT(shown, 100u) << "a hundred thousand steps drew " << shown << " lines";
}

TEST(ProgressLine, TickingShowsTheTimeSoFar) {
    CapturedCerr err;
    ProgressLine line(true);
    line.start("raytrace on the emulated sun3-60");
    const int answer = line.ticking([] {
        std::this_thread::sleep_for(std::chrono::milliseconds(1600));
        return 42;
    });
    EXPECT_EQ(answer, 42);
    // a tick a second; a busy machine may draw it late, so "1 s" or "2 s"
    const std::string s = err.text.str();
    EXPECT_TRUE(s.find("raytrace on the emulated sun3-60: 1 s") != std::string::npos ||
                s.find("raytrace on the emulated sun3-60: 2 s") != std::string::npos)
        << s;
}

TEST(ProgressLine, OffSaysNothing) {
    CapturedCerr err;
    {
        ProgressLine line(false);
        line.start("quiet");
        line.step(1, 2, "rounds");
        EXPECT_EQ(line.ticking([] { return 1; }), 1);
        line.clear();
    }
    EXPECT_EQ(err.text.str(), "");
}

TEST(ProgressLine, ALineWiderThanTheTerminalLosesItsStartNotItsCount) {
    const std::string text =
        "experiment split: programmers_cell.json (scene 14 of 14): "
        "3/6 emulated runs, about 12 s left";
    EXPECT_EQ(fit_to_width(text, 200), text);
    const std::string cut = fit_to_width(text, 40);
    EXPECT_EQ(cut.size(), 39u) << cut;  // one column spare: the cursor never wraps
    EXPECT_EQ(cut.rfind("...", 0), 0u) << cut;
    EXPECT_EQ(cut.substr(cut.size() - 20), text.substr(text.size() - 20));
    // counted in code points: a "§" is one column, never cut in half
    const std::string cut_utf8 = fit_to_width("§§§§§§§§§§ 3/4", 10);
    EXPECT_EQ(cut_utf8, "...§§ 3/4");
    EXPECT_EQ(fit_to_width("abc", 1), ".");
}

TEST(ProgressLine, AnObserverHearsEveryStartAndStepFromWhicheverThreadSteps) {
    std::vector<std::string> heard;
    std::mutex mutex;
    CapturedCerr err;
    {
        ObserveProgress observe(
            [&](const std::string& what, uint64_t done, uint64_t total, std::string_view unit) {
                std::lock_guard lock(mutex);
                heard.push_back(what + " " + std::to_string(done) + "/" + std::to_string(total) +
                                " " + std::string(unit));
            });
        ProgressLine line(false);  // not shown: the observer hears it all the same
        line.start("runs");
        std::thread([&] { line.step(1, 2, "emulated runs"); }).join();
        line.step(2, 2, "emulated runs");
    }
    ProgressLine after(false);  // the observer has gone with its scope
    after.start("unheard");
    EXPECT_EQ(heard, (std::vector<std::string>{"runs 0/0 ", "runs 1/2 emulated runs",
                                               "runs 2/2 emulated runs"}));
    EXPECT_EQ(err.text.str(), "");
}

TEST(ProgressLine, AnObserverThatThrowsStopsTheWork) {
    struct Enough {};
    ObserveProgress observe([](const std::string&, uint64_t done, uint64_t, std::string_view) {
        if (done == 2) throw Enough{};
    });
    int rounds = 0;
    EXPECT_THROW(interleave(1, 5, "timing", false, [&](size_t, bool) { ++rounds; }), Enough);
    EXPECT_EQ(rounds, 2);  // the warm-up and the first timed round
}

TEST(ProgressLine, AStopAskedForEndsInterleavedTimingBetweenRounds) {
    int rounds = 0;
    EXPECT_THROW(interleave(2, 5, "timing", false,
                            [&](size_t, bool) {
                                if (++rounds == 3) period::request_stop();
                            }),
                 period::Stopped);
    period::clear_stop();
    EXPECT_EQ(rounds, 4);  // the round under way ends; the next does not start
}

}  // namespace
}  // namespace fb89::experiments
