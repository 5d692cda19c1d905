// Pricing counted instructions with a host profile: rule order, operand patterns, EA
// tables, immediates by size, wait states per data access, and the phases' times.
#include "period/host_cost.h"
#include "period/isa.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

#include <stdexcept>
#include <string>

namespace fb89::period {
namespace {

const char* const kProfile = R"({
  "schema": 1, "name": "test", "cpu_clock_mhz": 20, "fpu_clock_mhz": 10,
  "memory_wait_states": 1,
  "ea": {"fetch": {"ind": 4, "disp": 5, "imm.w": 2, "imm.l": 4, "imm.d": 12},
         "calc": {"disp": 2}},
  "rules": [
    {"mnemonic": "^move[bwl]$", "operands": "reg,reg", "cpu": 2},
    {"mnemonic": "^move[bwl]$", "operands": "mem,reg", "cpu": 2, "fetch": [0]},
    {"mnemonic": "^addl$", "operands": "dreg,mem", "cpu": 4, "fetch": [1], "accesses": 2},
    {"mnemonic": "^lea$", "cpu": 2, "calc": [0], "accesses": 0},
    {"mnemonic": "^(add|sub)[wl]$", "operands": "imm|dreg,dreg", "cpu": 2, "fetch": [0]},
    {"mnemonic": "^fmuld$", "operands": "*,fpreg", "cpu": 10, "fpu": 50, "fetch": [0]},
    {"mnemonic": "^rts$", "operands": "", "cpu": 10, "accesses": 1}
  ],
  "default": {"cpu": 7}
})";

HostProfile profile() {
    return parse_host_profile(kProfile, "test");
}

TEST(HostCost, TheFirstMatchingRulePricesAKey) {
    const HostProfile p = profile();
    EXPECT_EQ(price_key(p, "movel dreg,areg").cpu, 2);
    // fetch-EA 5 and one data access with one wait state
    EXPECT_EQ(price_key(p, "movel disp,dreg").cpu, 2 + 5 + 1);
    // read and written: two accesses
    EXPECT_EQ(price_key(p, "addl dreg,ind").cpu, 4 + 4 + 2);
    // calculate-EA only, no access
    EXPECT_EQ(price_key(p, "lea disp,areg").cpu, 2 + 2);
    EXPECT_EQ(price_key(p, "rts").cpu, 10 + 1);
}

TEST(HostCost, ImmediatesArePricedByTheMnemonicsSize) {
    const HostProfile p = profile();
    EXPECT_EQ(price_key(p, "addw imm,dreg").cpu, 2 + 2);
    EXPECT_EQ(price_key(p, "addl imm,dreg").cpu, 2 + 4);
    const KeyPrice f = price_key(p, "fmuld imm,fpreg");
    EXPECT_EQ(f.cpu, 10 + 12);
    EXPECT_EQ(f.fpu, 50);
}

TEST(HostCost, AKeyNoRuleMatchesTakesTheDefaultAndIsReported) {
    const HostProfile p = profile();
    const KeyPrice k = price_key(p, "divsll dreg,dreg");
    EXPECT_EQ(k.rule, nullptr);
    EXPECT_EQ(k.cpu, 7);
    EXPECT_EQ(price_key(p, "movel dreg,dreg,dreg").rule, nullptr) << "operand count differs";
    EXPECT_EQ(price_key(p, "rts dreg").rule, nullptr) << "\"\" matches no operands only";
}

TEST(HostCost, PhasesAddCpuClocksAtTheCpuClockAndFpuClocksAtTheFpus) {
    const GuestCounts counts = parse_guest_counts(
        R"({"tool":"fb89_count","version":1,"guest_instructions":1003,
            "phases":[{"phase":3,"entered":1,"instructions":1003,
                       "classes":{"movel dreg,dreg":1000,"fmuld fpreg,fpreg":2,"swap dreg":1}}]})",
        "counts");
    const HostCost c = price(counts, profile());
    const PhaseCost& hs = c.phases[static_cast<int>(Phase::HiddenSurface)];
    EXPECT_EQ(hs.instructions, 1003u);
    EXPECT_EQ(hs.cpu_cycles, 1000 * 2 + 2 * 10 + 7);
    EXPECT_EQ(hs.fpu_cycles, 2 * 50);
    EXPECT_EQ(hs.unpriced, 1u);
    EXPECT_EQ(c.unpriced_keys.at("swap dreg"), 1u);
    // 2027 clocks at 20 MHz and 100 at 10 MHz
    EXPECT_DOUBLE_EQ(hs.ms, 2027 / 20e3 + 100 / 10e3);
    EXPECT_DOUBLE_EQ(c.end_to_end_ms(), hs.ms);
}

// Send marks: each priced as its phase is, cumulatively from the phase's start, so that the
// last one's time is the phase's up to it; a count of commands that goes back is refused.
TEST(HostCost, SendMarksArePricedFromTheirPhasesStart) {
    const std::string head =
        R"({"tool":"fb89_count","version":1,"guest_instructions":1003,
            "phases":[{"phase":3,"entered":1,"instructions":1003,
                       "classes":{"movel dreg,dreg":1000,"fmuld fpreg,fpreg":2,"swap dreg":1}}],)";
    const GuestCounts counts =
        parse_guest_counts(head + R"("sends":[{"phase":3,"commands":64,"instructions":500,
                            "classes":{"movel dreg,dreg":500}},
                           {"phase":3,"commands":70,"instructions":503,
                            "classes":{"movel dreg,dreg":500,"fmuld fpreg,fpreg":2,"swap dreg":1}}]})",
                           "counts");
    ASSERT_EQ(counts.sends.size(), 2u);
    const HostCost c = price(counts, profile());
    ASSERT_EQ(c.sends.size(), 2u);
    EXPECT_EQ(c.sends[0].commands, 64u);
    EXPECT_DOUBLE_EQ(c.sends[0].ms, 1000 / 20e3);  // 500 moves of 2 clocks at 20 MHz
    EXPECT_EQ(c.sends[1].commands, 70u);
    // everything the phase ran: its own time
    EXPECT_DOUBLE_EQ(c.sends[1].ms, c.phases[static_cast<int>(Phase::HiddenSurface)].ms);
    try {
        parse_guest_counts(
            head + R"("sends":[{"phase":3,"commands":64,"instructions":1,"classes":{}},
                                             {"phase":3,"commands":63,"instructions":1,"classes":{}}]})",
            "c.json");
        ADD_FAILURE() << "accepted commands that go back";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("c.json: send 1: 63 commands sent"), std::string::npos)
            << e.what();
    }
    // counts from before send marks: none, and no send times
    EXPECT_TRUE(price(parse_guest_counts(head.substr(0, head.size() - 1) + "}", "c"), profile())
                    .sends.empty());
}

TEST(HostCost, BadProfilesAndCountsAreRefusedNamingWhatIsWrong) {
    auto refused = [](const std::string& json, const std::string& says) {
        try {
            parse_host_profile(json, "p.json");
            ADD_FAILURE() << "accepted: " << json;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("p.json"), std::string::npos) << e.what();
        }
    };
    refused("{", "not valid JSON");
    refused(R"({"schema": 2})", "\"schema\" must be 1");
    std::string no_clock = kProfile;
    no_clock.replace(no_clock.find("\"cpu_clock_mhz\": 20"), 19, "\"cpu_clock_mhz\": \"x\"");
    refused(no_clock, "\"cpu_clock_mhz\" must be a number");
    std::string bad_regex = kProfile;
    bad_regex.replace(bad_regex.find("^lea$"), 5, "^le(a$");
    refused(bad_regex, "is not a regex");
    EXPECT_THROW(parse_guest_counts("{}", "c.json"), std::runtime_error);
    EXPECT_THROW(parse_guest_counts(R"({"tool":"fb89_count","version":1})", "c.json"),
                 std::runtime_error);
}

TEST(HostCost, EveryBuiltInProfileLoadsAndPricesTheCommonKeysOfItsInstructionSet) {
    ASSERT_FALSE(builtin_host_profile_names().empty());
    const std::map<std::string, std::vector<const char*>> common = {
        {"m68k",
         {"movel disp,dreg", "moveq imm,dreg", "fmoved disp,fpreg", "fmuld fpreg,fpreg",
          "beqw target", "lea disp,areg", "rts", "cmpl dreg,dreg", "faddd fpreg,fpreg", "jsr abs",
          "@dcache_64k_16b_wb_read_miss", "@dcache_64k_16b_wb_write_miss",
          "@dcache_64k_16b_wb_writeback"}},
        {"sparc",
         {"ld",
          "st",
          "ldd",
          "std",
          "add",
          "subcc",
          "sethi",
          "bicc",
          "bicc,a",
          "call",
          "jmpl",
          "save",
          "restore",
          "lddf",
          "faddd",
          "fmuld",
          "@load_use",
          "@annulled_slot",
          "@window_overflow",
          "@window_underflow",
          "@window_overflow_8w",
          "@window_underflow_8w",
          "@dcache_64k_16b_wt_read_miss",
          "@dcache_128k_16b_wb_read_miss",
          "@dcache_128k_16b_wb_writeback",
          "@dcache_64k_32b_wt_read_miss"}}};
    for (const std::string& name : builtin_host_profile_names()) {
        const HostProfile p = load_host_profile(name);
        EXPECT_EQ(p.name, name);
        EXPECT_NO_THROW(instruction_set(p.isa)) << name;
        EXPECT_FALSE(p.cpu.empty()) << name;
        // (an instruction set's own keys are checked here or in its folder, period/<isa>/tests)
        if (!common.contains(p.isa)) continue;
        for (const char* key : common.at(p.isa))
            EXPECT_NE(price_key(p, key).rule, nullptr) << name << ": " << key;
    }
    EXPECT_THROW(load_host_profile("sun3-61"), std::runtime_error);
}

TEST(HostCost, AProfileNamesAKnownInstructionSet) {
    const std::string text = R"({"schema": 1, "name": "x", "isa": "vax", "cpu_clock_mhz": 5,
        "fpu_clock_mhz": 5, "memory_wait_states": 0, "ea": {"fetch": {}, "calc": {}},
        "rules": [{"cpu": 1}], "default": {"cpu": 1}})";
    try {
        parse_host_profile(text, "x.json");
        ADD_FAILURE() << "took isa vax";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("unknown instruction set 'vax'"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace fb89::period
