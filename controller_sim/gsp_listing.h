// The GSP's command executive as counted code: a TMS34010 assembly listing
// (controller_sim/gsp/*.asm, embedded at build time) whose paths are priced instruction by
// instruction from the data sheet's minimum-cycle tables (SPVS002C pp. 11-14) and the memory
// cycles each field needs (p. 19). The controller's per-command cycles (C_cmd and each
// opcode's set-up) are these sums, never typed in: docs/COST_MODEL.md, "The command loop".
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fb89::controller {

// What the memory costs an instruction of the listing: the states of one local-memory cycle
// with its wait states (a 16-bit word read or written), and of an I/O register's cycle
// (which ignores LRDY: no wait states, SPVS002C p. 20).
// The processor whose instruction timings price the listing: the TMS34010's data sheet
// (SPVS002C pp. 11-14), or the TMS34020's User's Guide (SPVU019 ch. 13 and 15, the cycle
// counts of a cached instruction with no wait states; docs/COST_MODEL.md, "The TMS34020's
// own timings"). The 34020 runs the 34010's object code (SPVS004D p. 1): the same listing.
enum class Chip { Tms34010, Tms34020 };

struct MemoryTiming {
    uint32_t cycle_states = 2;
    uint32_t io_cycle_states = 2;
    // One pixel written alone (PIXT): a write cycle when the pixel fills its word or byte
    // strobes take it alone, else a read and a write (the 34020: its hidden write states).
    uint32_t pixel_write_states = 4;
    Chip chip = Chip::Tms34010;
};

// "tms34010" or "tms34020"; std::nullopt for any other name.
std::optional<Chip> chip_named(std::string_view name);
std::string_view chip_name(Chip chip);

// Which end of an estimated instruction timing a count takes: the estimate itself, or the
// low or high end of its band.
enum class TimingEnd { Estimate, Low, High };

// One instruction on a counted path, with its price.
struct CountedLine {
    int line = 0;         // 1-based, in the listing
    std::string text;     // the instruction as written (label and comment dropped)
    uint32_t cycles = 0;  // what it adds to the path, queued writes included
    uint32_t words = 0;   // its length in 16-bit instruction words
    std::string source;   // "[DS] p. 13", "[DS] p. 12 + p. 19 (...)", "[EMU] ..."
};

struct CountedPath {
    std::string name;  // COMMON, FRAME_BEGIN, FILL_RECT, DRAW_SPAN:line, ...
    std::vector<CountedLine> lines;
    uint64_t cycles = 0;  // the sum of lines[].cycles
    // The graphics instruction the path runs ("FILL" or "LINE"; "" for none): its fixed part
    // is in `cycles`, its pixels are the cost model's.
    std::string graphics;
};

struct Listing {
    std::string_view name;  // the file stem, e.g. "tms34010"
    std::string_view text;
};
std::span<const Listing> builtin_listings();  // defined in the generated file

// The listing by name; throws std::runtime_error naming the known ones.
const Listing& builtin_listing(std::string_view name);

// Counts every ";@path NAME START [END] [take LABEL | fall LABEL]..." of `listing`: from
// START to a dispatch, a taken jump back to COMMON's label, or (with END) the point where it
// reaches END (by a jump or by running into it). A "take LABEL" makes every conditional jump
// to LABEL on the path taken, whatever its comment says (a loop's other way); a "fall LABEL"
// makes it not taken (a loop's last time round). Throws
// std::runtime_error naming the listing and line for an instruction it cannot price, an
// unknown label, or a path that does not end.
std::map<std::string, CountedPath> count_paths(const Listing& listing, const MemoryTiming& memory,
                                               TimingEnd end = TimingEnd::Estimate);

// The TMS34010's instruction cache (SPVS002C p. 2): 256 bytes, four segments of 64.
inline constexpr uint32_t kInstructionCacheBytes = 256;

// The listing's length in 16-bit words, instructions only (what the 256-byte instruction
// cache must hold for the minimum cycles to apply, SPVS002C p. 2).
uint32_t listing_words(const Listing& listing);

// The 16-bit words of the instructions on the named paths, each instruction once: what must
// sit in the instruction cache for those paths to run at their minimum cycles.
uint32_t working_set_words(const std::map<std::string, CountedPath>& paths,
                           std::span<const std::string_view> names);
// The instruction cache's segments those instructions lie in, as the assembler places the
// listing: 32-word blocks aligned to 64 bytes, four of which the cache holds (SPVS002C p. 2;
// least recently used replacement, the User's Guide 5-3). A working set of at most 128 words
// that spans five or more still misses on every pass.
inline constexpr uint32_t kInstructionCacheSegments = 4;
uint32_t working_set_segments(const Listing& listing,
                              const std::map<std::string, CountedPath>& paths,
                              std::span<const std::string_view> names);
// The paths each command repeats, whose working set the cache must hold: a FILL_RECT's and a
// DRAW_SPAN's with the loop's dispatch, a DEPTH_SPAN with its pixel loop, and a FACE's row
// loop. FRAME_BEGIN and FRAME_END, once a frame, and a FACE's set-up, once a face, run
// through the cache (docs/COST_MODEL.md, "Depth commands"; the emulated GSP counts their
// misses, "The GSP as code").
struct CachedWork {
    std::string_view what;
    std::vector<std::string_view> paths;
};
std::span<const CachedWork> cached_work();

// The listing's text, each instruction of a counted path marked with its cycles and source.
std::string annotated_listing(const Listing& listing, const MemoryTiming& memory);

}  // namespace fb89::controller
