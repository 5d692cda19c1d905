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
          "popc", "fmovd",  "fnegd",  "fabsd", "impdep1", "fsmuld", "fxtod"})
        EXPECT_TRUE(stand_in(p, v8v9)) << v8v9;
    for (const char* v7 :
         {"ld",    "ldd",   "st",    "std",   "add",     "subcc",  "sethi", "bicc", "bicc,a",
          "ba",    "call",  "jmpl",  "save",  "restore", "mulscc", "rdy",   "wry",  "faddd",
          "fmuld", "fdivd", "fcmpd", "fitod", "fdtoi",   "lddf",   "stdf",  "ticc"})
        EXPECT_FALSE(stand_in(p, v7)) << v7;
}

// Each machine's own events: its register-window count's traps and its cache's misses (and a
// write-back cache's write-backs); the plugin follows every machine's beside it, and another
// machine's cost nothing here.
struct OwnEvents {
    std::string windows;  // "" for 7 windows, "_8w" for 8
    std::string cache;    // the plugin's key prefix, e.g. "128k_16b_wb"
};
OwnEvents own_events(const std::string& profile) {
    if (profile == "sun4-260") return {"", "128k_16b_wb"};
    if (profile == "sparcstation-1") return {"", "64k_16b_wt"};
    return {"_8w", "64k_32b_wt"};
}

TEST_P(SparcPricing, StandInsAreReportedApartPerPhase) {
    GuestCounts counts;
    PhaseCounts phase;
    phase.phase = static_cast<int>(Phase::HiddenSurface);
    phase.instructions = 300;
    const std::string overflow = "@window_overflow" + own_events(GetParam()).windows;
    phase.classes = {{"add", 100}, {"bpcc", 100}, {"umul", 100}, {overflow, 2}};
    counts.phases.push_back(phase);
    const PhaseCost c = price(counts, p).phases[static_cast<int>(Phase::HiddenSurface)];
    const double khz = p.cpu_clock_mhz * 1e3;
    EXPECT_EQ(c.stand_ins, 200u);
    EXPECT_DOUBLE_EQ(c.stand_in_ms, 100 * (cycles(p, "bpcc") + cycles(p, "umul")) / khz);
    EXPECT_EQ(c.events.at(overflow), 2u);
    EXPECT_EQ(c.unpriced, 0u);
}

TEST_P(SparcPricing, EventsHaveTheirOwnPrices) {
    EXPECT_EQ(cycles(p, "@load_use"), 1);
    EXPECT_EQ(cycles(p, "@annulled_slot"), 1);
    // SunOS's handlers: a trap, 47 and 50 instructions, 8 std or 8 ldd
    const OwnEvents own = own_events(GetParam());
    EXPECT_EQ(cycles(p, "@window_overflow" + own.windows), 80);
    EXPECT_EQ(cycles(p, "@window_underflow" + own.windows), 75);
    for (const char* windows : {"", "_8w"})
        if (windows != own.windows) {
            EXPECT_EQ(cycles(p, std::string("@window_overflow") + windows), 0) << windows;
            EXPECT_EQ(cycles(p, std::string("@window_underflow") + windows), 0) << windows;
        }
    for (const char* cache : {"64k_16b_wt", "128k_16b_wb", "64k_32b_wt"}) {
        const double read = cycles(p, std::string("@dcache_") + cache + "_read_miss");
        if (cache == own.cache)
            EXPECT_GT(read, 0) << cache;
        else
            EXPECT_EQ(read, 0) << cache;
    }
    // a write-back cache pays for the dirty line it writes back as for a fill; a write-through
    // one has nothing to write back and no store fills a line
    const double writeback = cycles(p, "@dcache_" + own.cache + "_writeback");
    if (own.cache.ends_with("_wb"))
        EXPECT_EQ(writeback, cycles(p, "@dcache_" + own.cache + "_read_miss"));
    else
        EXPECT_EQ(writeback + cycles(p, "@dcache_" + own.cache + "_write_miss"), 0);
}

// fsqrt: the Sun-4/260's Weitek parts have none, and the kernel emulates it (an unimplemented
// FPop: thousands of cycles); the SPARCstation 2's 602 executes it; the SPARCstation 1 is
// priced with the software sqrt of the period's libm, a stand-in.
TEST_P(SparcPricing, TheSquareRootIsWhatTheMachineDoesWithIt) {
    const double sqrt = cycles(p, "fsqrtd");
    if (GetParam() == "sun4-260") {
        EXPECT_GT(sqrt, 10 * cycles(p, "fdivd"));
        EXPECT_FALSE(stand_in(p, "fsqrtd"));
    } else if (GetParam() == "sparcstation-2") {
        EXPECT_LT(sqrt, 2 * cycles(p, "fdivd"));
        EXPECT_FALSE(stand_in(p, "fsqrtd"));
    } else {
        EXPECT_TRUE(stand_in(p, "fsqrtd"));
    }
}

// The variant docs/RESULTS.md prices the Sun-4/260 with (period/sparc/profiles/variants): the
// same machine in every rule but the square root, which is libm's software sqrt, a stand-in,
// instead of the kernel's emulation of the trapping fsqrt.
TEST(SparcPricingVariant, TheLibmSqrtSun4DiffersFromTheSun4OnlyInItsSquareRoot) {
    const std::string file = std::string(FB89_TEST_DATA_DIR) +
                             "/../period/sparc/profiles/variants/sun4-260-libm-sqrt.json";
    const HostProfile variant = load_host_profile(file), machine = load_host_profile("sun4-260");
    EXPECT_EQ(variant.isa, "sparc");
    EXPECT_EQ(variant.cpu_clock_mhz, machine.cpu_clock_mhz);
    EXPECT_EQ(cycles(variant, "fsqrtd"), 300);
    EXPECT_TRUE(stand_in(variant, "fsqrtd"));
    EXPECT_GT(cycles(machine, "fsqrtd"), 30 * cycles(variant, "fsqrtd"));
    for (const char* key : {"ld", "std", "faddd", "fmuld", "fdivd", "fcmpd", "umul", "@load_use",
                            "@window_overflow", "@dcache_128k_16b_wb_writeback"})
        EXPECT_EQ(cycles(variant, key), cycles(machine, key)) << key;
}

INSTANTIATE_TEST_SUITE_P(Sun4, SparcPricing,
                         ::testing::Values("sun4-260", "sparcstation-1", "sparcstation-2"),
                         [](const auto& param_info) {
                             std::string name = param_info.param;
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

}  // namespace
}  // namespace fb89::period
