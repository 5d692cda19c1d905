// The TMS34010's minimum states of each instruction form the executive uses, from the data
// sheet's tables (SPVS002C pp. 11-14; an instruction from the cache, no wait states), in
// one place: the emulated GSP (gsp_cpu.cpp) charges them as it executes, and the path pricer
// (gsp_listing.cpp) counts the same forms from the listing's text. A memory access adds its
// memory cycles (p. 19) to its form's states below (`Access`, TI's simulator's);
// docs/COST_MODEL.md, "The GSP as code".
#pragma once

#include <cstdint>

namespace fb89::controller::gsp::states {

inline constexpr uint32_t kRegister = 1;        // p. 12-14: MOVE Rs,Rd, ADD, SLL K, MOVK...
inline constexpr uint32_t kImmediateWord = 2;   // p. 13: MOVI/ADDI/SUBI/CMPI IW,Rd
inline constexpr uint32_t kImmediateLong = 3;   // p. 13: their IL forms, ANDI/ORI/XORI
inline constexpr uint32_t kCmpxy = 3;           // p. 11
inline constexpr uint32_t kCvxyl = 3;           // p. 11
inline constexpr uint32_t kJumpShortTaken = 2;  // p. 14: JRcc short
inline constexpr uint32_t kJumpShortNot = 1;
inline constexpr uint32_t kJumpLongTaken = 3;  // p. 14: JRcc long
inline constexpr uint32_t kJumpLongNot = 2;
inline constexpr uint32_t kJumpAbsTaken = 4;  // p. 14: JAcc (GSPSIM 1.04 the same)
inline constexpr uint32_t kJumpAbsNot = 3;
inline constexpr uint32_t kDsjTaken = 3;  // p. 14: DSJ Rd,Address
inline constexpr uint32_t kDsjNot = 2;
inline constexpr uint32_t kDsjsTaken = 2;  // p. 14: DSJS Rd,Address
inline constexpr uint32_t kDsjsNot = 3;
inline constexpr uint32_t kJump = 2;       // p. 14: JUMP Rs
inline constexpr uint32_t kCall = 6;       // p. 14: CALL Rs, CALLA
inline constexpr uint32_t kCallr = 5;      // p. 14
inline constexpr uint32_t kRets = 7;       // p. 14
inline constexpr uint32_t kMpyFixed = 5;   // p. 13: MPYS/MPYU 5 + FS1/2 (FS1 = 32: 21)
inline constexpr uint32_t kDivs = 40;      // p. 13: DIVS Rs,Rd
inline constexpr uint32_t kDivu = 37;      // p. 13: DIVU Rs,Rd
inline constexpr uint32_t kFillXy = 8;     // FILL XY's own set-up [EMU] (MAME: 4+2+2)
inline constexpr uint32_t kFillL = 6;      // FILL L's [EMU] (MAME: 4+2)
inline constexpr uint32_t kLine = 4;       // LINE's own set-up [EST, band 2-8]
inline constexpr uint32_t kSetf = 1;       // p. 12
inline constexpr uint32_t kMmFixedTm = 2;  // MMTM: 2 + 4n [UG]
inline constexpr uint32_t kMmFixedFm = 3;  // MMFM: 3 + 4n [UG]

// A memory access's own states around its memory cycles. The data sheet gives no figure for
// these forms (p. 12: "depends on field size and alignment"); these are TI's simulator's,
// GSPSIM 1.04, measured by tests/ti-gsp/moves.asm (docs/COST_MODEL.md, "Against TI's
// simulator"). An access spends `lead` states before its first memory cycle, the first
// `beside` of them beside a write still queued (the rest wait for it), and `tail` after its
// cycles; a write's cycles are queued, and its tail runs beside them. The 16- and 32-bit
// totals alone, at 2 states a cycle, aligned, cache warm:
struct Access {
    uint32_t lead = 0, beside = 0, tail = 0;
};
inline constexpr Access kReadIndirect{1, 1, 1};       // MOVE *Rs,Rd: 4 / 6
inline constexpr Access kReadPostIncrement{1, 1, 2};  // MOVE *Rs+,Rd: 5 / 7
inline constexpr Access kReadPreDecrement{0, 0, 1};   // MOVE -*Rs,Rd: 3 / 5
inline constexpr Access kReadDisplacement{2, 2, 1};   // MOVE *Rs(d),Rd: 5 / 7
inline constexpr Access kReadAbsolute{2, 2, 2};       // MOVE @a,Rd: 6 / 8
inline constexpr Access kWriteIndirect{1, 0, 0};      // MOVE Rs,*Rd and Rs,*Rd+: 1 + queued
inline constexpr Access kWritePreDecrement{1, 1, 0};  // MOVE Rs,-*Rd: 1 + queued
inline constexpr Access kWriteDisplacement{2, 2, 1};  // MOVE Rs,*Rd(d): 3 + queued less 1
inline constexpr Access kWriteAbsolute{3, 3, 0};      // MOVE Rs,@a: 3 + queued
inline constexpr Access kPixtRead{1, 1, 1};   // PIXT *Rs,Rd: 4 (also the data sheet's, p. 11)
inline constexpr Access kPixtWrite{1, 1, 1};  // PIXT Rs,*Rd: 2 + its pixel's write less 1

// The data sheet's reading the band's cheap end keeps: a state to issue, the cycles waited
// for whole (the figure fb89 followed before GSPSIM was measured).
inline constexpr Access kDataSheetMinimum{1, 0, 0};

}  // namespace fb89::controller::gsp::states
