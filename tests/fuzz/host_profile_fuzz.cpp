// Fuzz target: the 1989 host profile JSON (period::parse_host_profile, what
// load_host_profile uses for `--host FILE.json`; comments allowed). Bad input must throw
// std::runtime_error naming the file; nothing else may escape. A profile that loads must
// hold the ranges host_profile.cpp checks, and pricing a fixed set of instruction class
// keys with it (price_key, then price over a small set of counts) must give clocks and
// times that are >= 0 (never NaN) and rules that belong to the profile.
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "period/host_cost.h"
#include "period/host_profile.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using fb89::fuzz::finding;
namespace period = fb89::period;

// Keys as the counting plugin writes them, and a few it never would.
constexpr std::string_view kKeys[] = {"movel disp,dreg",
                                      "moveq imm,dreg",
                                      "fmoved disp,fpreg",
                                      "rts",
                                      "addl dreg,dreg",
                                      "movel dreg,ind",
                                      "leal disp,areg",
                                      "bnes target",
                                      "moveml reglist,predec",
                                      "fmulx fpreg,fpreg",
                                      "bfextu dreg,imm,imm,dreg",
                                      "movel index,dreg",
                                      "addil imm,abs",
                                      ".short",
                                      "movel dreg,dreg,dreg",
                                      "rts dreg",
                                      "",
                                      " ",
                                      "x ,,",
                                      "movel imm"};

void check_rule(const period::CostRule& r) {
    if (!(r.cpu >= 0) || !(r.fpu >= 0)) finding("a rule with negative or NaN clocks");
    for (int i : r.fetch)
        if (i < 0 || i > 7) finding("a fetch operand index outside 0..7");
    for (int i : r.calc)
        if (i < 0 || i > 7) finding("a calc operand index outside 0..7");
    if (r.accesses < -1) finding("accesses below -1");
    if (r.any_operands && !r.operands.empty())
        finding("a rule for any operands with an operand pattern");
}

void check(const period::HostProfile& p) {
    if (!(p.cpu_clock_mhz > 0) || !(p.fpu_clock_mhz > 0)) finding("a clock not > 0");
    if (!(p.memory_wait_states >= 0)) finding("negative wait states");
    if (p.rules.empty()) finding("no rules");
    for (const auto* table : {&p.ea_fetch, &p.ea_calc})
        for (const auto& [cls, v] : *table)
            if (!(v >= 0)) finding("a negative EA entry");
    for (const period::CostRule& r : p.rules)
        check_rule(r);
    check_rule(p.fallback);

    period::GuestCounts counts;
    period::PhaseCounts phase;
    phase.phase = static_cast<int>(period::Phase::HiddenSurface);
    for (std::string_view key : kKeys) {
        const period::KeyPrice k = period::price_key(p, key);
        if (!(k.cpu >= 0) || !(k.fpu >= 0)) finding("a key priced at negative or NaN clocks");
        if (k.rule && (k.rule < p.rules.data() || k.rule >= p.rules.data() + p.rules.size()))
            finding("a key priced by a rule not in the profile");
        phase.classes[std::string(key)] = 3;
        phase.instructions += 3;
    }
    counts.instructions = phase.instructions;
    counts.phases.push_back(phase);
    const period::HostCost cost = period::price(counts, p);
    for (const period::PhaseCost& c : cost.phases)
        if (!(c.ms >= 0) || !(c.cpu_cycles >= 0) || !(c.fpu_cycles >= 0))
            finding("a phase priced at a negative or NaN time");
    if (!(cost.end_to_end_ms() >= 0)) finding("a negative or NaN end-to-end time");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    static const std::string kOrigin = "fuzz.json";
    try {
        check(period::parse_host_profile(text, kOrigin));
    } catch (const std::runtime_error& e) {
        if (std::string_view(e.what()).find(kOrigin) == std::string_view::npos)
            finding("an error that does not name the file");
    }
    return 0;
}
