// A 1989 host as data: the instruction set it runs, the clocks, memory wait states and
// cycle tables that price the instructions the counting plugin saw
// (docs/HOST_COST_MODEL.md). period/<isa>/profiles/*.json are embedded at build time,
// beside the controller's profiles.
#pragma once

#include <filesystem>
#include <map>
#include <regex>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fb89::period {

// One row of the cycle table: instructions whose mnemonic matches `mnemonic` and whose
// operand classes match `operands` cost `cpu` MPU clocks (plus the EA terms and wait
// states) and `fpu` FPU clocks.
struct CostRule {
    std::string mnemonic_text;
    std::regex mnemonic;
    bool any_operands = true;                        // no "operands" field
    std::vector<std::vector<std::string>> operands;  // per operand: the classes allowed
    double cpu = 0, fpu = 0;
    std::vector<int> fetch, calc;  // operands whose fetch-EA / calculate-EA time is added
    int accesses = -1;             // data bus accesses; -1: one per memory operand
    // an instruction the machine does not have (a V8/V9 form in Debian's SPARC libraries),
    // priced as the sequence of its own that would stand in for it; reported apart
    bool stand_in = false;
    std::string source;
};

// Names a rule's operand pattern may use for several classes ("reg": "dreg", "areg").
using OperandGroups = std::map<std::string, std::vector<std::string>>;

struct HostProfile {
    std::string name, description;
    std::string isa = "m68k";  // the instruction set whose guest it prices (period/isa.h)
    std::string cpu, fpu;      // the chips, for `fb89 list hosts` ("" if not given)
    double cpu_clock_mhz = 0, fpu_clock_mhz = 0;
    double memory_wait_states = 0;
    std::map<std::string, double> ea_fetch, ea_calc;
    // The instruction set's operand classes, as its classifier names them: those that are a
    // data access in memory, and the groups a rule may name. A profile without them has the
    // MC68020's (period/m68k/classify.c).
    std::vector<std::string> memory_classes = {"ind",   "postinc", "predec", "disp",
                                               "index", "abs",     "pcrel"};
    OperandGroups operand_groups = {
        {"reg", {"dreg", "areg"}},
        {"mem", {"ind", "postinc", "predec", "disp", "index", "abs", "pcrel"}}};
    std::vector<CostRule> rules;
    CostRule fallback;  // "default": what no rule matches
};

struct BuiltinProfile {
    std::string_view name;  // file stem, e.g. "sun3-60"
    std::string_view json;  // the file's text
};
std::span<const BuiltinProfile> builtin_profiles();  // defined in the generated file
std::vector<std::string> builtin_host_profile_names();

// A built-in name or a .json file. Throws std::runtime_error naming the profile and the
// field that is missing or wrong.
HostProfile load_host_profile(std::string_view name_or_path);
HostProfile parse_host_profile(std::string_view json, const std::string& origin);

}  // namespace fb89::period
