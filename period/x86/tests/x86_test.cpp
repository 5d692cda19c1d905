// The 386 + 387 PC's own tests (period/x86/, found by tests/CMakeLists.txt): its classifier's
// keys on the validation kernels under qemu-i386, and its profile pricing them by the rules
// docs/HOST_COST_MODEL.md ("The 386 PC") gives. (ctest label `period`: these run the emulator.)
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "period/emulator.h"
#include "period/host_cost.h"
#include "period/host_profile.h"
#include "period/isa.h"
#include "period/phases.h"
#include "period/validation.h"

namespace fb89::period {
namespace {

const PhaseCounts& timed_counts(const std::string& kernel) {
    static std::map<std::string, KernelRun> runs;
    if (!runs.contains(kernel)) {
        static const ValidationData data = builtin_validation();
        runs.emplace(kernel, run_validation_kernel(find_emulator_parts(instruction_set("x86")),
                                                   data.kernel(kernel)));
    }
    const PhaseCounts* p = runs.at(kernel).counts.phase(static_cast<int>(Phase::HiddenSurface));
    if (!p) throw std::runtime_error(kernel + ": no timed phase");
    return *p;
}

uint64_t count(const PhaseCounts& c, const std::string& key) {
    const auto it = c.classes.find(key);
    return it == c.classes.end() ? 0 : it->second;
}

// vmpup's loop: 50,000 iterations of 18 register adds, each one `addl %reg,%reg`
// (period/x86/register_add.h), then the loop's own decrement and branch.
TEST(PeriodX86, IntloopIsItsRegisterAddsAndTheLoop) {
    const PhaseCounts& t = timed_counts("intloop");
    EXPECT_EQ(count(t, "addl reg,reg"), 900000u);
    EXPECT_LT(t.instructions, 900000u + 3 * 50000u + 100);
}

// FFBENCH's transform on the 387: doubles loaded and stored through indexed addresses, the
// arithmetic on the register stack, and the 82385's read misses on its 1 MB array.
TEST(PeriodX86, FftKeysThe387sStackAndIndexedOperands) {
    const PhaseCounts& t = timed_counts("fft2d");
    EXPECT_GT(count(t, "fldl memi"), 1000000u);
    EXPECT_GT(count(t, "fstpl memi"), 1000000u);
    EXPECT_GT(count(t, "fmul sti"), 1000000u);
    EXPECT_GT(count(t, "fxch sti"), 0u);
    // the array is 32 times the cache: a column pass misses on nearly every double
    EXPECT_GT(count(t, "@dcache_32k_4b_wt_read_miss"), 1000000u);
    for (const auto& [key, n] : t.classes)
        EXPECT_EQ(key.find("st("), std::string::npos) << key << " is a register, not memory";
}

TEST(HostCostX86, TheProfilePricesItsKeysByTheirRules) {
    const HostProfile p = load_host_profile("pc-386-25");
    EXPECT_EQ(p.isa, "x86");
    const auto cpu = [&](const std::string& key) { return price_key(p, key).cpu; };
    const auto fpu = [&](const std::string& key) { return price_key(p, key).fpu; };
    // I386: a load 4, a store 2, register ALU 2, load-op 6, read-modify-write 7
    EXPECT_EQ(cpu("movl mem,reg"), 4);
    EXPECT_EQ(cpu("movl reg,mem"), 2);
    EXPECT_EQ(cpu("addl reg,reg"), 2);
    EXPECT_EQ(cpu("addl mem,reg"), 6);
    EXPECT_EQ(cpu("addl reg,mem"), 7);
    // an indexed address adds a clock
    EXPECT_EQ(cpu("movl memi,reg"), 5);
    // I387 fld m64 25 and fmul at extended precision 57; the 386's protocol 3 + 5 a doubleword
    EXPECT_EQ(fpu("fldl memi"), 25);
    EXPECT_EQ(cpu("fldl mem"), 3 + 2 * 5);
    EXPECT_EQ(fpu("fmul sti"), 57);
    EXPECT_EQ(cpu("fmul sti"), 3);
    // a P6 instruction from Debian's library is a stand-in
    ASSERT_NE(price_key(p, "cmovel reg,reg").rule, nullptr);
    EXPECT_TRUE(price_key(p, "cmovel reg,reg").rule->stand_in);
    // the PC's own cache, and no other machine's
    EXPECT_EQ(cpu("@dcache_32k_4b_wt_read_miss"), 2);
    EXPECT_EQ(cpu("@dcache_128k_16b_wb_read_miss"), 0);
}

}  // namespace
}  // namespace fb89::period
