// The emulated TMS34010 (controller_sim/gsp_cpu.h) on small programs of its own, assembled
// by fb89's assembler: arithmetic and the status bits, 64-bit multiply and divide, fields,
// the graphics instructions with the window and the serial registers, and the states each
// instruction costs -- the data sheet's, the write queue's and the instruction cache's
// (TI's GSPSIM 1.04 for the cache: a miss 9 states a four-word sub-segment).
#include "controller_sim/gsp_cpu.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <fmt/format.h>

#include "controller_sim/gsp_assembler.h"

namespace fb89::controller::gsp {
namespace {

// Runs `source` from its first line until it reaches the label `done`; the CPU after.
struct Executed {
    Tms34010 cpu;
    Program program;
    explicit Executed(const std::string& source, GspTiming timing = {}) : cpu(timing) {
        program = assemble("test.asm", source);
        cpu.load_words(0, program.image());
        cpu.set_field(0, 16, false);
        cpu.set_field(1, 32, false);
        cpu.set_reg(0, 15, 0x100000);
        cpu.set_pc(0);
        const uint32_t done = program.labels.at("done");
        cpu.run([&] { return cpu.pc() == done; }, 100000);
    }
    uint32_t a(int n) const { return cpu.reg(0, n); }
};

constexpr uint32_t kN = 1u << 31, kC = 1u << 30, kZ = 1u << 29, kV = 1u << 28;

TEST(GspCpu, AddSubAndCompareSetTheStatusBitsAsTheDataSheetSays) {
    // 7FFFFFFFh + 1 overflows into the sign; 0 - 1 borrows
    const Executed add(
        "      MOVI 7FFFFFFFh,A0\n      ADDK 1,A0\n      GETST A1\ndone: JRUC done\n");
    EXPECT_EQ(add.a(0), 0x80000000u);
    EXPECT_EQ(add.a(1) & (kN | kC | kZ | kV), kN | kV);
    const Executed sub("      CLR A0\n      SUBK 1,A0\n      GETST A1\ndone: JRUC done\n");
    EXPECT_EQ(sub.a(0), 0xFFFFFFFFu);
    EXPECT_EQ(sub.a(1) & (kN | kC | kZ | kV), kN | kC);
    // CMP Rs,Rd is Rd - Rs: JRLO (C) unsigned below, JRLT signed below
    const Executed cmp(
        "      MOVK 5,A0\n      MOVI -3,A1\n      CLR A2\n      CLR A3\n"
        "      CMP A1,A0\n      JRLO lo\n      JRUC t2\nlo:   MOVK 1,A2\n"
        "t2:   CMP A1,A0\n      JRGT gt\n      JRUC done\ngt:   MOVK 1,A3\ndone: JRUC done\n");
    EXPECT_EQ(cmp.a(2), 1u);  // 5 is below FFFFFFFDh unsigned
    EXPECT_EQ(cmp.a(3), 1u);  // and above -3 signed
}

TEST(GspCpu, ImmediatesKeptAsTheirOnesComplementActOnTheirValue) {
    const Executed r(
        "      MOVI 1000,A0\n      SUBI 300,A0\n      MOVI 12345678h,A1\n      ANDI 0FF00h,A1\n"
        "      MOVI 100,A2\n      CMPI 100,A2\n      GETST A3\n      SUBI 70000h,A2\n"
        "done: JRUC done\n");
    EXPECT_EQ(r.a(0), 700u);
    EXPECT_EQ(r.a(1), 0x5600u);
    EXPECT_EQ(r.a(3) & kZ, kZ);
    EXPECT_EQ(r.a(2), static_cast<uint32_t>(100 - 0x70000));
}

TEST(GspCpu, SixtyFourBitMultiplyAndDivideUseAnEvenRegisterPair) {
    const Executed r(
        "      MOVI 40000000h,A4\n      MOVK 16,A3\n      MPYS A3,A4\n"  // 2^34: A4 high, A5 low
        "      MOVI -7,A6\n      MOVK 2,A9\n      MPYS A9,A6\n"          // -14, 64 bits
        "      MOVI -7,A11\n      MOVK 2,A10\n      DIVS A10,A11\n"      // odd: 32 bits, -3
        "      MOVK 1,A12\n      MOVI 1,A13\n      MOVK 3,A2\n      DIVS A2,A12\n"  // 2^32+1
        "      CLR A14\n      DIVS A14,A2\n      GETST A1\n"                        // by zero: V
        "done: JRUC done\n");
    EXPECT_EQ(r.a(4), 4u);
    EXPECT_EQ(r.a(5), 0u);
    EXPECT_EQ(r.a(6), 0xFFFFFFFFu);
    EXPECT_EQ(r.a(7), static_cast<uint32_t>(-14));
    EXPECT_EQ(r.a(11), static_cast<uint32_t>(-3));  // truncated toward zero
    EXPECT_EQ(r.a(12), 0x55555555u);                // (2^32 + 1) / 3
    EXPECT_EQ(r.a(13), 2u);                         // and its remainder
    EXPECT_EQ(r.a(2), 3u);                          // left as it was
    EXPECT_EQ(r.a(1) & kV, kV);
}

TEST(GspCpu, FieldsAreReadAtAnyBitAndExtendedAsSetf) {
    Executed r(
        "      MOVI 20000h,A0\n      MOVI 0ABCDh,A1\n      MOVE A1,*A0,0\n"  // 16 bits
        "      MOVI 20004h,A2\n      SETF 8,1,0\n      MOVE *A2,A3,0\n"      // 8 bits from bit 4
        "      SETF 8,0,0\n      MOVE *A2,A4,0\n      SETF 16,0,0\n"
        "      MOVE *A0+,A5,0\n      MOVE A0,A6\n"
        "done: JRUC done\n");
    EXPECT_EQ(r.a(3), 0xFFFFFFBCu);  // BCh sign-extended
    EXPECT_EQ(r.a(4), 0xBCu);
    EXPECT_EQ(r.a(5), 0xABCDu);
    EXPECT_EQ(r.a(6), 0x20010u);  // post-incremented by the field
    EXPECT_EQ(r.cpu.read_field(0x20000, 16), 0xABCDu);
}

TEST(GspCpu, FillXyIsClippedToTheWindowAndPixtWritesOnePixel) {
    // an 8-bit frame of 64 pixels a row at the VRAM's start, the window 10..19 x 5..6
    Executed r(
        "      MOVI 010000000h,A0\n      MOVE A0,OFFSET\n      MOVI 512,A0\n      MOVE A0,DPTCH\n"
        "      MOVI 5000Ah,A0\n      MOVE A0,WSTART\n      MOVI 60013h,A0\n      MOVE A0,WEND\n"
        "      MOVK 8,A0\n      MOVE A0,@0C0000150h,0\n"     // PSIZE 8
        "      MOVI 0C0h,A0\n      MOVE A0,@0C00000B0h,0\n"  // CONTROL: W = 3
        "      MOVI 7777h,A0\n      MOVE A0,COLOR1\n"
        "      MOVI 40000h,A0\n      MOVE A0,DADDR\n"  // from (0, 4)
        "      MOVI 40020h,A0\n      MOVE A0,DYDX\n"   // 32 x 4
        "      FILL XY\n"
        "      MOVI 010000000h,A1\n      MOVK 9,A2\n      PIXT A2,*A1\n"
        "done: JRUC done\n");
    const auto vram = r.cpu.vram();
    const auto at = [&](int x, int y) { return vram[static_cast<std::size_t>(y * 64 + x)]; };
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 32; ++x)
            EXPECT_EQ(at(x, y), (x >= 10 && x <= 19 && y >= 5 && y <= 6) ? 0x77 : (x + y ? 0 : 9))
                << x << "," << y;
    EXPECT_EQ(r.cpu.counters().pixels, 20u + 1u);
}

TEST(GspCpu, LineDrawsBresenhamsPixels) {
    // from (2, 1) to (8, 4): a = 6, b = 3, d = 2b - a = 0, seven pixels
    Executed r(
        "      MOVI 010000000h,A0\n      MOVE A0,OFFSET\n      MOVI 512,A0\n      MOVE A0,DPTCH\n"
        "      MOVK 8,A0\n      MOVE A0,@0C0000150h,0\n"
        "      MOVI 10002h,A0\n      MOVE A0,DADDR\n      MOVI 30006h,A0\n      MOVE A0,DYDX\n"
        "      MOVI 10001h,A0\n      MOVE A0,INC1\n      MOVK 1,A0\n      MOVE A0,INC2\n"
        "      CLR A0\n      MOVE A0,SADDR\n      MOVK 7,A0\n      MOVE A0,COUNT\n"
        "      MOVI 0505h,A0\n      MOVE A0,COLOR1\n      LINE 0\n"
        "done: JRUC done\n");
    const auto vram = r.cpu.vram();
    std::string rows;
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 10; ++x)
            rows += vram[static_cast<std::size_t>(y * 64 + x)] ? '#' : '.';
        rows += '\n';
    }
    EXPECT_EQ(rows,
              "..........\n"
              "..#.......\n"
              "...##.....\n"
              ".....##...\n"
              ".......##.\n"
              "..........\n");
}

TEST(GspCpu, SerialRegisterTransfersCopyWholeVramRows) {
    // row 0 filled, read into the serial registers (SRT), written to rows 1 and 2
    Executed r(
        "      MOVK 16,A0\n      MOVE A0,@0C0000150h,0\n"
        "      MOVI 4000h,A0\n      MOVE A0,DPTCH\n"
        "      MOVI 010000000h,A0\n      MOVE A0,DADDR\n      MOVI 10400h,A0\n      MOVE A0,DYDX\n"
        "      MOVI 0ABCDABCDh,A0\n      MOVE A0,COLOR1\n      FILL L\n"
        "      MOVI 0800h,A0\n      MOVE A0,@0C0000080h,0\n"  // SRT
        "      MOVI 010000000h,A1\n      PIXT *A1,A2\n"
        "      MOVI 010004000h,A0\n      MOVE A0,DADDR\n      MOVI 20001h,A0\n      MOVE A0,DYDX\n"
        "      FILL L\n"
        "done: JRUC done\n");
    const auto vram = r.cpu.vram();
    for (std::size_t row = 0; row < 3; ++row)
        for (std::size_t byte : {0u, 1u, 1000u, 2047u})
            EXPECT_EQ(vram[row * 2048 + byte], byte % 2 ? 0xAB : 0xCD) << row << " " << byte;
    EXPECT_EQ(vram[3 * 2048], 0);
}

TEST(GspCpu, StatesAreTheDataSheetsAndAQueuedWriteRunsBesideRegisterWork) {
    GspTiming warm;
    warm.cache = false;
    // MOVE Rs,*Rd issues in 1 and queues its 2; a NOP runs beside the queue; the read's first
    // state runs beside what is left, and it takes its 4: TI's simulator's "write 16, NOP,
    // read 16" in 6
    Executed r(
        "      MOVI 20000h,A0\nm0:   MOVE A1,*A0,0\n      NOP\n      MOVE *A0,A2,0\n"
        "done: JRUC done\n",
        warm);
    EXPECT_EQ(r.cpu.counters().states, 3u + 1u + 1u + 4u);  // MOVI IL 3 first
    // DSJS: 2 taken, 3 not (SPVS002C p. 14; GSPSIM 1.04: a loop of 100 in 99 x 2 + 3 after
    // its MOVI IW's 2)
    Executed loop("      MOVI 100,A1\nl:    DSJS A1,l\ndone: JRUC done\n", warm);
    EXPECT_EQ(loop.cpu.counters().states, 2u + 99u * 2u + 3u);
}

// Each memory MOVE and PIXT form the executive runs, alone, after a queued write and before a
// read: the warm states TI's simulator GSPSIM 1.04 gives for each block of
// tests/ti-gsp/moves.asm (its second pass), in the same order. The blocks are written here
// as the file writes them; the emulator must take the same states for each.
TEST(GspCpu, MemoryAccessesTakeTheStatesOfTisSimulator) {
    const std::vector<std::string> reads = {
        "*A1,A2,0",    "*A1,A2,1",     "*A1+,A2,0",       "*A1+,A2,1",     "-*A1,A2,0",
        "-*A1,A2,1",   "*A1(32),A2,0", "*A1(32),A2,1",    "@100040h,A2,0", "@100040h,A2,1",
        "*A1(8),A2,0", "*A1(8),A2,1",  "@0C0000150h,A2,0"};
    const std::vector<std::string> writes = {"A2,*A1,0",      "A2,*A1,1",        "A2,*A1+,0",
                                             "A2,*A1+,1",     "A2,-*A1,0",       "A2,-*A1,1",
                                             "A2,*A1(32),0",  "A2,*A1(32),1",    "A2,@100080h,0",
                                             "A2,@100080h,1", "A2,@0C0000150h,0"};
    const std::string nops6 = "NOP\nNOP\nNOP\nNOP\nNOP\nNOP\n";
    std::vector<std::string> blocks;
    for (const auto& f : reads)
        blocks.push_back("MOVE " + f + "\nNOP\n");
    for (const auto& f : reads)
        blocks.push_back("MOVE A4,*A5,0\nMOVE " + f + "\nNOP\n");
    for (std::size_t i = 0; i < 4; ++i)
        blocks.push_back("MOVE A4,*A5,1\nMOVE " + reads[i] + "\nNOP\n");
    for (const auto& f : writes)
        blocks.push_back("MOVE " + f + "\n" + nops6);
    for (const auto& f : writes)
        blocks.push_back("MOVE " + f + "\nMOVE *A5,A4,0\nNOP\n");
    for (const auto& f : writes)
        blocks.push_back("MOVE A4,*A5,0\nMOVE " + f + "\nMOVE *A5,A4,0\nNOP\n");
    const std::vector<std::string> pixt = {"PIXT A2,*A1\n" + nops6,
                                           "PIXT A2,*A1\nMOVE *A5,A4,0\nNOP\n",
                                           "MOVE A4,*A5,0\nPIXT A2,*A1\nMOVE *A5,A4,0\nNOP\n",
                                           "PIXT *A1,A2\nNOP\n",
                                           "MOVE A4,*A5,0\nPIXT *A1,A2\nNOP\n",
                                           "PIXT *A1,A2\nPIXT A2,*A1\n" + nops6};
    const std::size_t moves = blocks.size();
    blocks.insert(blocks.end(), pixt.begin(), pixt.end());  // at 8 bits a pixel
    blocks.insert(blocks.end(), pixt.begin(), pixt.end());  // at 16
    // GSPSIM 1.04, tests/ti-gsp/moves.asm, each block's second pass
    const std::vector<uint64_t> gspsim = {
        5,  7,  6,  8,  4, 6,  6, 8,  7,  9,  8,  10, 7,  // reads alone (and a NOP)
        7,  9,  8,  10, 7, 9,  7, 9,  8,  10, 9,  11, 8,  // after a 16-bit write
        9,  11, 10, 12,                                   // after a 32-bit write
        7,  7,  7,  7,  7, 7,  9, 9,  9,  9,  9,          // writes alone (and six NOPs)
        7,  9,  7,  9,  7, 9,  8, 10, 9,  11, 9,          // writes, then a read
        10, 12, 10, 12, 9, 11, 9, 11, 10, 12, 10,         // after a 16-bit write, then a read
        8,  9,  11, 5,  7, 12,                            // PIXT at 8 bits a pixel
        8,  7,  9,  5,  7, 12};                           // and at 16
    ASSERT_EQ(blocks.size(), gspsim.size());
    GspTiming warm;
    warm.cache = false;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const bool wide = i >= moves + pixt.size();
        GspTiming timing = warm;
        timing.pixel_write_states =
            wide ? 2 : 4;  // a whole word at 16 bits; a read and a write at 8
        // the set-up (PSIZE, A2 the pixel size as PSIZE may be written with it, the pointers)
        // is taken off by running it alone
        const std::string setup = fmt::format(
            "      MOVK {},A0\n      MOVE A0,@0C0000150h,0\n      MOVE A0,A2\n      MOVI "
            "100000h,A5\n"
            "      MOVI 100000h,A1\n",
            wide ? 16 : 8);
        const Executed alone(setup + "done: JRUC done\n", timing);
        std::string block;  // each instruction indented, as the assembler reads it
        for (std::size_t at = 0, end; (end = blocks[i].find('\n', at)) != std::string::npos;
             at = end + 1)
            block += "      " + blocks[i].substr(at, end + 1 - at);
        const Executed with(setup + block + "done: JRUC done\n", timing);
        EXPECT_EQ(with.cpu.counters().states - alone.cpu.counters().states, gspsim[i])
            << "block " << i << ":\n"
            << blocks[i];
    }
}

TEST(GspCpu, AnInstructionCacheMissCostsItsSubSegmentsFetch) {
    // the loop above, cold: its first fetch misses one sub-segment (4 words: the MOVI, the
    // DSJS and the JRUC in it), 9 states as GSPSIM charges a miss
    Executed loop("      MOVI 100,A1\nl:    DSJS A1,l\ndone: JRUC done\n");
    EXPECT_EQ(loop.cpu.counters().cache_misses, 1u);
    EXPECT_EQ(loop.cpu.counters().states, 2u + 99u * 2u + 3u + 9u);
    EXPECT_EQ(loop.cpu.counters().warm_states, 2u + 99u * 2u + 3u);
}

TEST(GspCpu, WhatTheBoardCannotDoIsAFaultNamingTheAddress) {
    const auto fault_of = [](const std::string& source) {
        try {
            Executed r(source);
        } catch (const GspFault& f) {
            return std::string(f.what());
        }
        return std::string("(none)");
    };
    EXPECT_NE(fault_of("      MOVI 30000000h,A0\n      MOVE *A0,A1,0\ndone: JRUC done\n")
                  .find("no memory there"),
              std::string::npos);
    EXPECT_NE(fault_of("      MOVI 0F0000000h,A0\n      JUMP A0\ndone: JRUC done\n")
                  .find("outside the code"),
              std::string::npos);
    EXPECT_NE(fault_of("l:    JRUC l\ndone: JRUC done\n").find("without finishing"),
              std::string::npos);
    EXPECT_NE(fault_of("      .word 0FFFFh\ndone: JRUC done\n").find("not an instruction"),
              std::string::npos);
}

}  // namespace
}  // namespace fb89::controller::gsp
