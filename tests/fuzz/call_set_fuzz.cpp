// Fuzz target: protocol::CallSet::parse. Bad text must throw CallSetError; a set that parses
// must print as canonical text that parses back to the same set, and its first()/last()
// must bound every number it contains. `@file` items resolve in a scratch directory that
// holds one small call-set file, "calls.txt".
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <string_view>

#include "protocol/call_set.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using fb89::fuzz::finding;
using fb89::protocol::CallSet;
using fb89::protocol::CallSetError;
using fb89::protocol::kNoLastCall;
using fb89::protocol::Opcode;

void enter_scratch_dir() {
    static const bool entered = [] {
        const std::string_view calls = "0-3\n# a comment\nframe/2\n";
        fb89::fuzz::write_scratch("calls.txt", reinterpret_cast<const uint8_t*>(calls.data()),
                                  calls.size());
        if (::chdir(fb89::fuzz::scratch_dir().c_str()) != 0) finding("chdir to scratch failed");
        return true;
    }();
    (void)entered;
}

void check_bounds(const CallSet& set) {
    const uint64_t first = set.first(), last = set.last();
    const uint64_t probes[] = {
        0,         1,    2,        3,         7,        100,         first,
        first + 1, last, last - 1, first - 1, last + 1, kNoLastCall, kNoLastCall - 1};
    for (uint64_t n : probes)
        for (int op = 0; op <= 0x0B; ++op) {  // every command's opcode, and bytes that are none
            const bool in = set.contains(n, static_cast<Opcode>(op));
            if (in && !fb89::protocol::command_row(static_cast<uint8_t>(op)))
                finding("contains() a byte that is no command's opcode");
            if (in && !set.contains_number(n)) finding("contains() without contains_number()");
            if (in && (n < first || n > last)) finding("a contained number outside first..last");
        }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    enter_scratch_dir();
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    CallSet set;
    try {
        set = CallSet::parse(text);
    } catch (const CallSetError&) {
        return 0;
    }
    check_bounds(set);
    (void)set.has_opcode_filter();
    const std::string canonical = set.to_string();
    if (set.empty()) return 0;
    CallSet again;
    try {
        again = CallSet::parse(canonical);
    } catch (const CallSetError& e) {
        finding(std::string("canonical text does not parse: '") + canonical + "': " + e.what());
    }
    if (again.to_string() != canonical || again.ranges() != set.ranges())
        finding("canonical text parses to another set: '" + canonical + "'");
    return 0;
}
