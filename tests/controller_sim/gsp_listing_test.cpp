// Tests of controller_sim/gsp_listing: the command loop's paths priced instruction by
// instruction from the data sheet's tables (SPVS002C pp. 11-14) and memory cycles (p. 19),
// the write queue (p. 10), wait states, and the profile's derived figures held to the sums.
#include "controller_sim/gsp_listing.h"

#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "controller_sim/profile.h"

namespace fb89::controller {
namespace {

const Listing& tms34010_listing() {
    return builtin_listing("tms34010");
}

std::vector<uint32_t> cycles_of(const CountedPath& path) {
    std::vector<uint32_t> out;
    for (const CountedLine& l : path.lines)
        out.push_back(l.cycles);
    return out;
}

// The message count_paths throws for `text`, or "" when it counts.
std::string count_error(const std::string& text) {
    try {
        count_paths(Listing{"bad", text}, MemoryTiming{});
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

// The loop, by hand from the tables: CMP 1 (p. 13), JRNE short taken 2 (p. 14), CMP 1, JRLO
// taken 2, MOVE *A0+,A5 (16-bit read: GSPSIM's 1 + one 2-state cycle + 2), SLL 1, ADD 1,
// MOVE *A5,A5,1 (32-bit read: 1 + two cycles + 1), JUMP 2 (p. 14).
TEST(GspListing, TheLoopIsCountedInstructionByInstruction) {
    const auto paths = count_paths(tms34010_listing(), MemoryTiming{2, 2});
    const CountedPath& loop = paths.at("COMMON");
    EXPECT_EQ(cycles_of(loop), (std::vector<uint32_t>{1, 2, 1, 2, 5, 1, 1, 6, 2}));
    EXPECT_EQ(loop.cycles, 21u);
    EXPECT_EQ(loop.lines.front().text, "CMP    A1,A0");
    EXPECT_EQ(loop.lines.back().text, "JUMP   A5");
    EXPECT_NE(loop.lines[1].source.find("[DS] p. 14"), std::string::npos);
    EXPECT_NE(loop.lines[4].source.find("[SIM]"), std::string::npos);  // a memory MOVE
    EXPECT_EQ(loop.graphics, "");
}

TEST(GspListing, EachHandlerEndsWithItsJumpBackAndNamesItsGraphicsInstruction) {
    const auto paths = count_paths(tms34010_listing(), MemoryTiming{2, 2});
    for (const char* name : {"FRAME_BEGIN", "FRAME_BEGIN:fill", "FRAME_BEGIN:large", "FILL_RECT",
                             "DRAW_SPAN:line", "DRAW_SPAN:fill", "FRAME_END"})
        EXPECT_EQ(paths.at(name).lines.back().text, "JRUC   next") << name;
    EXPECT_EQ(paths.at("FILL_RECT").graphics, "FILL");
    EXPECT_EQ(paths.at("DRAW_SPAN:line").graphics, "LINE");
    EXPECT_EQ(paths.at("DRAW_SPAN:fill").graphics, "FILL");
    EXPECT_EQ(paths.at("FRAME_BEGIN").graphics, "FILL");
    EXPECT_EQ(paths.at("FRAME_END").graphics, "");
    // two 32-bit reads (*A0+: 7), each moved across to the B file (GSPA refuses *A0+,DADDR),
    // a 16-bit read (5), four register moves, FILL XY's 8 [EMU], JRUC 2
    EXPECT_EQ(cycles_of(paths.at("FILL_RECT")),
              (std::vector<uint32_t>{7, 1, 7, 1, 5, 1, 1, 1, 1, 8, 2}));
    EXPECT_EQ(paths.at("FILL_RECT").cycles, 35u);
    // TI's draw_line's way (DRAWLINE.ASM): y:x0 to DADDR, x1, MOVX, SUBXY, ADDI 010001h (a
    // long immediate, 3), the colour widened, FILL XY, and the jump back: beyond a short
    // jump's 127 words, GSPA's long JRUC, 3
    EXPECT_EQ(cycles_of(paths.at("DRAW_SPAN:fill")),
              (std::vector<uint32_t>{7, 1, 5, 1, 1, 1, 3, 1, 5, 1, 1, 1, 1, 8, 3}));
    EXPECT_EQ(paths.at("DRAW_SPAN:fill").cycles, 40u);
}

// The serial-register clear (TI's clear_page, CLEARPAG.ASM), instruction by instruction at
// M = 2: the three reads, the window set to the frame (SUBI IL 3), the colour widened, the
// VRAM rows from the height and FPSHIFT, the VRAM's 512 rows compared, the row fill's set-up
// (MOVI IL 3, MOVI IW 2, the pixel size read and kept, MOVK, the PSIZE write queued before
// FILL L's 6), DPYCTL read (an I/O cycle) and written with SRT, PIXT's read 4 (the
// memory-to-register cycle) after the last of that write's queue, the second row, DYDX =
// rows - 1 : 1, FILL L, the display, pitch and pixel size back.
TEST(GspListing, TheSerialRegisterClearIsCountedInstructionByInstruction) {
    const auto paths = count_paths(tms34010_listing(), MemoryTiming{2, 2});
    EXPECT_EQ(cycles_of(paths.at("FRAME_BEGIN")),
              (std::vector<uint32_t>{5, 3, 7 + 1, 1, 3, 1, 5, 1, 1, 1, 1, 1, 1,     6, 1, 2,
                                     1, 2, 1,     1, 1, 3, 1, 2, 1, 6, 1, 3, 6 + 2, 6, 1, 3,
                                     3, 3, 1,     4, 1, 2, 1, 1, 1, 1, 1, 6, 3,     1, 3, 2}));
    EXPECT_EQ(paths.at("FRAME_BEGIN").cycles, 116u);
    // the FILL clear (TI's clear_screen): the three reads, the window, the colour, DYDX,
    // DADDR, FILL XY
    EXPECT_EQ(paths.at("FRAME_BEGIN:fill").cycles, 42u);
    // a frame larger than the VRAM: the serial clear's first part, then the FILL clear's
    EXPECT_EQ(paths.at("FRAME_BEGIN:large").cycles, 58u);
}

// TIGA's call around a primitive (TIGA_CALL, the band's dear end): CALLA 6, MMTM of 2 and
// 7 registers (2 + 4n), four 32-bit pops (5 each: -*Rs), SLL and MOVY twice, two globals
// read (8 each: @a), JRNZ not taken 1, ADDXY twice, MMFM of 7 and 2 (3 + 4n), the stack
// pointer's read with a displacement 7, RETS 7: 145 states (TI's own mix: about 115 to 140).
TEST(GspListing, TigasCallAroundAPrimitiveIsCountedFromItsInstructionMix) {
    const auto paths = count_paths(tms34010_listing(), MemoryTiming{2, 2});
    EXPECT_EQ(
        cycles_of(paths.at("TIGA_CALL")),
        (std::vector<uint32_t>{6, 10, 30, 5, 5, 1, 1, 5, 5, 1, 1, 8, 1, 8, 1, 1, 31, 11, 7, 7}));
    EXPECT_EQ(paths.at("TIGA_CALL").cycles, 145u);
    // at the band's dear end (a wait state; LINE's set-up, not here, dearer too): 195
    EXPECT_EQ(
        count_paths(tms34010_listing(), MemoryTiming{3, 2}, TimingEnd::High).at("TIGA_CALL").cycles,
        195u);
}

// TI's assembler refuses a memory MOVE between an A-file pointer and a B-file register
// ("REGISTERS IN OPPOSITE FILES"): the chip has no such form, and neither does the pricer.
TEST(GspListing, APointerAndARegisterInOppositeFilesAreRefusedAsTisAssemblerRefusesThem) {
    const auto error = [](std::string_view text) -> std::string {
        try {
            (void)count_paths(Listing{"bad", text}, MemoryTiming{2, 2});
        } catch (const std::runtime_error& e) {
            return e.what();
        }
        return "";
    };
    const std::string header = ";@path COMMON next\n;@path X x\nnext:     JUMP   A5\n";
    for (const char* move : {"MOVE   *A0+,DADDR,1", "MOVE   *A0+,B5,1", "MOVE   DYDX,*A2,1",
                             "MOVE   *B0,A1,0", "PIXT   *DADDR,A5"}) {
        const std::string e = error(header + "x:        " + move + "\n          JRUC   next\n");
        EXPECT_NE(e.find("bad.asm line 4"), std::string::npos) << move << ": " << e;
        EXPECT_NE(e.find("opposite files"), std::string::npos) << move << ": " << e;
    }
    // the same file, and SP with either, are fine
    for (const char* move : {"MOVE   *A0+,A5,1", "MOVE   *B0+,DADDR,1", "MOVE   *SP(32),A14,1",
                             "MMTM   SP,B2,B7", "PIXT   *DADDR,B14"})
        EXPECT_EQ(error(header + "x:        " + move + "\n          JRUC   next\n"), "") << move;
    // MMTM's registers come from one file
    EXPECT_NE(
        error(header + "x:        MMTM   SP,A0,B7\n          JRUC   next\n").find("opposite files"),
        std::string::npos);
}

// FRAME_BEGIN writes the frame's number and reads the next word at once: the write is
// queued (p. 10), and the read, its first state beside the queue, waits 1 state more.
// FRAME_END's write to HSTCTL overlaps the jump back (a long one: `next` is beyond 127
// words).
TEST(GspListing, AQueuedWriteOverlapsRegisterInstructionsAndDelaysTheNextAccess) {
    const auto paths = count_paths(tms34010_listing(), MemoryTiming{2, 2});
    const auto begin = cycles_of(paths.at("FRAME_BEGIN"));
    ASSERT_GE(begin.size(), 3u);
    EXPECT_EQ(begin[1], 3u);       // MOVE A5,@FRAME_NO,0: issued in 3, its cycle queued
    EXPECT_EQ(begin[2], 7u + 1u);  // MOVE *A0+,A6,1 waits 1 state for it
    EXPECT_EQ(cycles_of(paths.at("FRAME_END")), (std::vector<uint32_t>{2, 3, 3}));
}

TEST(GspListing, WaitStatesLengthenMemoryReadsButNotAnIoWrite) {
    const auto slow = count_paths(tms34010_listing(), MemoryTiming{3, 2});
    EXPECT_EQ(slow.at("COMMON").cycles, 21u + 1u + 2u);  // one word read and two
    EXPECT_EQ(slow.at("FRAME_END").cycles, 8u);
}

TEST(GspListing, TheBandsEndsMoveEveryEstimatedTimingAndNothingElse) {
    const auto low = count_paths(tms34010_listing(), MemoryTiming{2, 2}, TimingEnd::Low);
    const auto high = count_paths(tms34010_listing(), MemoryTiming{2, 2}, TimingEnd::High);
    // the cheap end: each memory MOVE a state to issue and its cycles (2 states less for a
    // *A0+ read, 1 for the loop's *A5); the dear end GSPSIM's, as the estimate
    EXPECT_EQ(low.at("COMMON").cycles, 21u - 2u - 1u);
    EXPECT_EQ(high.at("COMMON").cycles, 21u);
    EXPECT_EQ(low.at("DRAW_SPAN:line").cycles, 39u - 3u * 2u - 2u);  // three *A0+ reads; LINE 2
    EXPECT_EQ(high.at("DRAW_SPAN:line").cycles, 39u + 4u);           // LINE 8
}

TEST(GspListing, TheProfilesFiguresAreTheListingsSums) {
    for (const char* name : {"tms34010-50mhz", "tms34010-isa", "tms34020-40mhz"}) {
        const CostProfile p = load_profile(name);
        const auto paths = count_paths(builtin_listing(p.gsp), memory_timing(p));
        const auto sum = [](const CountedPath& path) {
            return std::accumulate(path.lines.begin(), path.lines.end(), uint64_t{0},
                                   [](uint64_t s, const CountedLine& l) { return s + l.cycles; });
        };
        EXPECT_EQ(p.c_cmd, sum(paths.at("COMMON"))) << name;
        EXPECT_EQ(p.c_frame_begin_srt_setup, sum(paths.at("FRAME_BEGIN"))) << name;
        EXPECT_EQ(p.c_frame_begin_setup, sum(paths.at("FRAME_BEGIN:fill"))) << name;
        EXPECT_EQ(p.c_frame_begin_large_setup, sum(paths.at("FRAME_BEGIN:large"))) << name;
        EXPECT_EQ(p.c_tiga_call, sum(paths.at("TIGA_CALL"))) << name;
        EXPECT_EQ(p.c_setup, sum(paths.at("FILL_RECT"))) << name;
        EXPECT_EQ(p.c_line_setup, sum(paths.at("DRAW_SPAN:line"))) << name;
        EXPECT_EQ(p.c_span_fill_setup, sum(paths.at("DRAW_SPAN:fill"))) << name;
        EXPECT_EQ(p.c_frame_end_setup, sum(paths.at("FRAME_END"))) << name;
        for (const auto& [path_name, path] : paths)
            EXPECT_EQ(path.cycles, sum(path)) << name << " " << path_name;
    }
}

// The TMS34020's timings on the same listing, by hand from its User's Guide ([UG20]): the
// loop's reads are 3 states each whatever the field (a 32-bit bus cycle), its register
// instructions and jumps as the 34010's: CMP 1, JRNE 2, CMP 1, JRLO 2, MOVE *A0+,A5,0 3,
// SLL 1, ADD 1, MOVE *A5,A5,1 3, JUMP 2.
TEST(GspListing, TheTms34020PricesTheSameListingByItsOwnTables) {
    const MemoryTiming c20{2, 2, 1, Chip::Tms34020};
    const auto paths = count_paths(tms34010_listing(), c20);
    EXPECT_EQ(cycles_of(paths.at("COMMON")), (std::vector<uint32_t>{1, 2, 1, 2, 3, 1, 1, 3, 2}));
    EXPECT_EQ(paths.at("COMMON").lines[4].source.substr(0, 6), "[UG20]");
    // two 32-bit reads and a 16-bit one, 3 each; six register moves; FILL XY's 8 [EMU]; JRUC 2
    EXPECT_EQ(cycles_of(paths.at("FILL_RECT")),
              (std::vector<uint32_t>{3, 1, 3, 1, 3, 1, 1, 1, 1, 8, 2}));
    // the 16-bit depth loop, a nearer pixel: the read 3, MOVE, SRL, CMP, JRHS not taken 1
    // each, the depth written 1 (+1 hidden), PIXT 2 [EMU] after the hidden state, its own
    // write hidden behind ADDK; DSJS taken 2 [EMU]
    EXPECT_EQ(cycles_of(paths.at("ZPIXEL16:nearer")),
              (std::vector<uint32_t>{3, 1, 1, 1, 1, 1, 3, 1, 1, 1, 2}));
    EXPECT_EQ(paths.at("ZPIXEL16:farther").cycles, 3u + 1 + 1 + 1 + 2 + 1 + 1 + 1 + 2);
    // a wait state lengthens each memory cycle by a state: two reads on the loop
    const auto slow = count_paths(tms34010_listing(), MemoryTiming{3, 2, 2, Chip::Tms34020});
    EXPECT_EQ(slow.at("COMMON").cycles, paths.at("COMMON").cycles + 2u);
    // at the band's dear end a 32-bit field through a register crosses a long word (case 3)
    const auto high = count_paths(tms34010_listing(), c20, TimingEnd::High);
    EXPECT_EQ(high.at("COMMON").cycles, paths.at("COMMON").cycles + 1u);
    EXPECT_EQ(high.at("FILL_RECT").cycles, paths.at("FILL_RECT").cycles + 2u);
}

// A long immediate costs the 34020 2 states when its long word is aligned and 3 when not,
// from the instructions' own layout (the listing loaded at a long word).
TEST(GspListing, TheTms34020PricesALongImmediateByItsAlignment) {
    const std::string text =
        ";@path COMMON next\n"
        "next: MOVI 12345678h,A1\n"  // words 0-2: its long word at word 1, not aligned
        "      MOVI 12345678h,A2\n"  // words 3-5: at word 4, aligned
        "      MOVK 1,A3\n"          // word 6
        "      MOVI 12345678h,A4\n"  // words 7-9: at word 8, aligned
        "      JUMP A5\n";
    const auto paths = count_paths(Listing{"imm", text}, MemoryTiming{2, 2, 1, Chip::Tms34020});
    EXPECT_EQ(cycles_of(paths.at("COMMON")), (std::vector<uint32_t>{3, 2, 1, 2, 2}));
    EXPECT_NE(paths.at("COMMON").lines[0].source.find("not aligned"), std::string::npos);
    const auto c10 = count_paths(Listing{"imm", text}, MemoryTiming{2, 2});
    EXPECT_EQ(cycles_of(c10.at("COMMON")), (std::vector<uint32_t>{3, 3, 1, 3, 2}));
}

TEST(GspListing, TheTms34020ProfileIsPricedByItsChip) {
    const CostProfile c20 = load_profile("tms34020-40mhz");
    EXPECT_EQ(c20.gsp_chip, Chip::Tms34020);
    EXPECT_EQ(memory_timing(c20).chip, Chip::Tms34020);
    EXPECT_EQ(memory_timing(c20).pixel_write_states, 1u);  // byte strobes, 8 bpp: case 1
    EXPECT_EQ(c20.c_cmd, count_paths(tms34010_listing(), memory_timing(c20)).at("COMMON").cycles);
    EXPECT_EQ(load_profile("tms34010-50mhz").gsp_chip, Chip::Tms34010);
    EXPECT_EQ(chip_named("tms34020"), Chip::Tms34020);
    EXPECT_EQ(chip_named("tms34030"), std::nullopt);
    EXPECT_EQ(chip_name(Chip::Tms34020), "tms34020");
}

TEST(GspListing, EachCommandsRepeatedWorkFitsTheInstructionCache) {
    // 256 bytes, 128 words (SPVS002C p. 2): what a tiling command repeats, and what a depth
    // command repeats a span or a row at a time, run from the cache at minimum cycles (a
    // frame's FRAME_BEGIN and FRAME_END and a FACE's set-up do not: docs/COST_MODEL.md, "Depth
    // commands"; the emulated GSP counts what its misses cost, "The GSP as code")
    const auto paths = count_paths(tms34010_listing(), MemoryTiming{});
    ASSERT_EQ(cached_work().size(), 3u);
    for (const CachedWork& w : cached_work()) {
        EXPECT_LE(working_set_words(paths, w.paths), 128u) << w.what;
        // and in at most four of its 32-word segments, where the assembler puts them
        EXPECT_LE(working_set_segments(tms34010_listing(), paths, w.paths),
                  kInstructionCacheSegments)
            << w.what;
    }
    // the FACE's row loop across segments: more than it fits in words alone
    EXPECT_GE(working_set_segments(tms34010_listing(), paths, cached_work()[2].paths), 3u);
    // the tiling commands' dispatch and handlers
    EXPECT_GE(working_set_words(paths, cached_work()[0].paths), 30u);
    EXPECT_GE(listing_words(tms34010_listing()),
              60u);  // every instruction counted, not just a path
}

TEST(GspListing, TheAnnotatedListingMarksEachCountedInstruction) {
    const std::string text = annotated_listing(tms34010_listing(), MemoryTiming{2, 2});
    // the line holding `what`: its cycles, address and words (gsp_assembler.h) before it
    auto line_with = [&](std::string_view what) {
        const std::size_t at = text.find(what);
        if (at == std::string::npos) return std::string("(none)");
        const std::size_t begin = text.rfind('\n', at) + 1;
        return text.substr(begin, text.find('\n', at) - begin);
    };
    EXPECT_EQ(line_with("fetch:    MOVE   *A0+,A5,0").rfind("   5  00000090 9405 ", 0), 0u) << text;
    EXPECT_NE(text.find("COMMON            21 cycles"), std::string::npos) << text;
    // data: words, no cycles
    EXPECT_EQ(line_with("table:").rfind("      000021C0 0000 0000 00E0 ", 0), 0u) << text;
    EXPECT_NE(text.find("the instruction cache holds 256 bytes, so the executive does not fit"),
              std::string::npos)
        << text;
}

TEST(GspListing, RefusesWhatItCannotPriceNamingTheLine) {
    const std::string head = ";@path COMMON next\nnext: CMP A1,A0\n";
    EXPECT_NE(count_error(head + "      TRAP 3\n      JUMP A5\n")
                  .find("listing bad.asm line 3: TRAP 3: no timing"),
              std::string::npos);
    EXPECT_NE(count_error(head + "      JRNE next\n").find("says \"taken\" or \"not taken\""),
              std::string::npos);
    EXPECT_NE(count_error(head + "      JRUC elsewhere\n").find("no such label"),
              std::string::npos);
    EXPECT_NE(count_error(head).find("does not end"), std::string::npos);
    EXPECT_NE(count_error("next: CMP A1,A0\n").find("no @path COMMON"), std::string::npos);
    EXPECT_NE(count_error(head + "      ADD A1,B2\n      JUMP A5\n").find("A and B files"),
              std::string::npos);
    EXPECT_NE(count_error(head + "      MOVE *A0+,A5,2\n      JUMP A5\n").find("0 or 1"),
              std::string::npos);
    EXPECT_THROW(builtin_listing("tms9918"), std::runtime_error);
}

}  // namespace
}  // namespace fb89::controller
