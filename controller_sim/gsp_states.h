// The TMS34010's minimum states of each instruction form the executive uses, from the data
// sheet's tables (SPVS002C pp. 11-14; an instruction from the cache, no wait states), in
// one place: the emulated GSP (gsp_cpu.cpp) charges them as it executes, and the path pricer
// (gsp_listing.cpp) counts the same forms from the listing's text. A memory operand adds its
// memory cycles (p. 19) to these; docs/COST_MODEL.md, "The GSP as code".
#pragma once

#include <cstdint>

namespace fb89::controller::gsp::states {

inline constexpr uint32_t kRegister = 1;        // p. 12-14: MOVE Rs,Rd, ADD, SLL K, MOVK...
inline constexpr uint32_t kImmediateWord = 2;   // p. 13: MOVI/ADDI/SUBI/CMPI IW,Rd
inline constexpr uint32_t kImmediateLong = 3;   // p. 13: their IL forms, ANDI/ORI/XORI
inline constexpr uint32_t kCmpxy = 3;           // p. 11
inline constexpr uint32_t kCvxyl = 3;           // p. 11
inline constexpr uint32_t kMemoryIssue = 1;     // a memory MOVE's own state [EST, band 1-2]
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
inline constexpr uint32_t kJump = 2;            // p. 14: JUMP Rs
inline constexpr uint32_t kCall = 6;            // p. 14: CALL Rs, CALLA
inline constexpr uint32_t kCallr = 5;           // p. 14
inline constexpr uint32_t kRets = 7;            // p. 14
inline constexpr uint32_t kMpyFixed = 5;        // p. 13: MPYS/MPYU 5 + FS1/2 (FS1 = 32: 21)
inline constexpr uint32_t kDivs = 40;           // p. 13: DIVS Rs,Rd
inline constexpr uint32_t kDivu = 37;           // p. 13: DIVU Rs,Rd
inline constexpr uint32_t kPixtReadFixed = 2;   // p. 11: PIXT *Rs,Rd 4 = 2 + its read cycle
inline constexpr uint32_t kPixtWriteIssue = 1;  // PIXT Rs,*Rd [EST, band 1-2] + its write
inline constexpr uint32_t kFillXy = 8;          // FILL XY's own set-up [EMU] (MAME: 4+2+2)
inline constexpr uint32_t kFillL = 6;           // FILL L's [EMU] (MAME: 4+2)
inline constexpr uint32_t kLine = 4;            // LINE's own set-up [EST, band 2-8]
inline constexpr uint32_t kSetf = 1;            // p. 12
inline constexpr uint32_t kMmFixedTm = 2;       // MMTM: 2 + 4n [UG]
inline constexpr uint32_t kMmFixedFm = 3;       // MMFM: 3 + 4n [UG]

}  // namespace fb89::controller::gsp::states
