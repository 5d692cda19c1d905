// The Sun-4 profiles' pricing (period/sparc/profiles, docs/HOST_COST_MODEL.md "SPARC"): each
// V8/V9 form Debian's V8plus libraries execute is priced as the V7 sequence that stands in
// for it, checked against the profile's own prices of those V7 instructions; every
// stand-in is marked and reported apart; every key the SPARC classifier can make is
// priced by a rule; the events (window traps, interlocks, annulled slots, cache misses)
// have prices of their own. No emulator: these are unit tests of the tables.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "period/host_cost.h"
#include "period/host_profile.h"

namespace fb89::period {
namespace {

double cycles(const HostProfile& p, const std::string& key) {
    const KeyPrice k = price_key(p, key);
    EXPECT_NE(k.rule, nullptr) << key << " has no rule in " << p.name;
    return k.cpu + k.fpu;
}

bool stand_in(const HostProfile& p, const std::string& key) {
    const KeyPrice k = price_key(p, key);
    return k.rule && k.rule->stand_in;
}

class SparcPricing : public ::testing::TestWithParam<std::string> {
  protected:
    HostProfile p = load_host_profile(GetParam());
};

TEST_P(SparcPricing, EachV8AndV9FormCostsTheV7SequenceStandingInForIt) {
    // a predicted branch is a branch; brz is a test and a branch; a conditional move a
    // branch over a move; V9 return a jmpl and a restore
    EXPECT_EQ(cycles(p, "bpcc"), cycles(p, "bicc"));
    EXPECT_EQ(cycles(p, "bpcc,a"), cycles(p, "bicc,a"));
    EXPECT_EQ(cycles(p, "fbpfcc"), cycles(p, "fbfcc"));
    EXPECT_EQ(cycles(p, "bpr"), cycles(p, "subcc") + cycles(p, "bicc"));
    EXPECT_EQ(cycles(p, "movcc"), cycles(p, "bicc") + cycles(p, "or"));
    EXPECT_EQ(cycles(p, "movr"), cycles(p, "bicc") + cycles(p, "or"));
    EXPECT_EQ(cycles(p, "return"), cycles(p, "jmpl") + cycles(p, "restore"));
    // 64-bit loads and stores are the V7 doubleword ones; ldsw is ld
    EXPECT_EQ(cycles(p, "ldx"), cycles(p, "ldd"));
    EXPECT_EQ(cycles(p, "stx"), cycles(p, "std"));
    EXPECT_EQ(cycles(p, "ldsw"), cycles(p, "ld"));
    // a 64-bit shift of a register pair: four single shifts and logic
    EXPECT_EQ(cycles(p, "sllx"), 4 * cycles(p, "sll"));
    // compare-and-swap in one thread: load, compare, branch, store
    EXPECT_EQ(cycles(p, "casa"),
              cycles(p, "ld") + cycles(p, "subcc") + cycles(p, "bicc") + cycles(p, "st"));
    // FP: a double move is two single ones; fsmuld two widenings and a multiply
    EXPECT_EQ(cycles(p, "fmovd"), 2 * cycles(p, "fmovs"));
    EXPECT_EQ(cycles(p, "impdep1"), 2 * cycles(p, "fmovs"));
    EXPECT_EQ(cycles(p, "fsmuld"), 2 * cycles(p, "fstod") + cycles(p, "fmuld"));
    // multiply and divide are calls of libgcc's V7 .umul and .udiv: a call and its slot,
    // and the routine (.umul: 23 instructions for small operands, 40 otherwise)
    EXPECT_EQ(cycles(p, "umul"), 2 + std::ceil((23 + 40) / 2.0));
    EXPECT_EQ(cycles(p, "smul"), cycles(p, "umul"));
    EXPECT_EQ(cycles(p, "mulx"), 3 * cycles(p, "umul") + 8);
    EXPECT_GT(cycles(p, "udiv"), 2 + 43.0);   // at least the shortest .udiv path
    EXPECT_LT(cycles(p, "udiv"), 2 + 131.0);  // at most a 6-digit quotient's
}

TEST_P(SparcPricing, EveryStandInIsMarkedAndNoV7InstructionIs) {
    for (const char* v8v9 :
         {"bpcc", "bpcc,a", "fbpfcc", "bpr",   "movcc",   "movr",   "fmovcc", "return", "umul",
          "smul", "umulcc", "udiv",   "sdiv",  "mulx",    "udivx",  "sdivx",  "sllx",   "srlx",
          "srax", "ldx",    "stx",    "ldsw",  "swap",    "casa",   "stbar",  "rdasr",  "flushw",
          "popc", "fmovd",  "fnegd",  "fabsd", "impdep1", "fsmuld", "fxtod",  "fsqrtd"})
        EXPECT_TRUE(stand_in(p, v8v9)) << v8v9;
    for (const char* v7 :
         {"ld",    "ldd",   "st",    "std",   "add",     "subcc",  "sethi", "bicc", "bicc,a",
          "ba",    "call",  "jmpl",  "save",  "restore", "mulscc", "rdy",   "wry",  "faddd",
          "fmuld", "fdivd", "fcmpd", "fitod", "fdtoi",   "lddf",   "stdf",  "ticc"})
        EXPECT_FALSE(stand_in(p, v7)) << v7;
}

TEST_P(SparcPricing, StandInsAreReportedApartPerPhase) {
    GuestCounts counts;
    PhaseCounts phase;
    phase.phase = static_cast<int>(Phase::HiddenSurface);
    phase.instructions = 300;
    phase.classes = {{"add", 100}, {"bpcc", 100}, {"umul", 100}, {"@window_overflow", 2}};
    counts.phases.push_back(phase);
    const PhaseCost c = price(counts, p).phases[static_cast<int>(Phase::HiddenSurface)];
    const double khz = p.cpu_clock_mhz * 1e3;
    EXPECT_EQ(c.stand_ins, 200u);
    EXPECT_DOUBLE_EQ(c.stand_in_ms, 100 * (cycles(p, "bpcc") + cycles(p, "umul")) / khz);
    EXPECT_EQ(c.events.at("@window_overflow"), 2u);
    EXPECT_EQ(c.unpriced, 0u);
}

TEST_P(SparcPricing, EventsHaveTheirOwnPrices) {
    EXPECT_EQ(cycles(p, "@load_use"), 1);
    EXPECT_EQ(cycles(p, "@annulled_slot"), 1);
    // SunOS's handlers: a trap, 47 and 50 instructions, 8 std or 8 ldd
    EXPECT_EQ(cycles(p, "@window_overflow"), 80);
    EXPECT_EQ(cycles(p, "@window_underflow"), 75);
    for (const char* miss : {"@dcache_64k_read_miss", "@dcache_64k_write_miss",
                             "@dcache_128k_read_miss", "@dcache_128k_write_miss"})
        EXPECT_NE(price_key(p, miss).rule, nullptr) << miss;
}

INSTANTIATE_TEST_SUITE_P(Sun4, SparcPricing, ::testing::Values("sun4-260", "sparcstation-1"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

}  // namespace
}  // namespace fb89::period
