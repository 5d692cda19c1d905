// Tests of controller_sim/gsp_assembler: the forms TI's listings in tests/golden/gsp/ do not
// reach (long jumps, the errors), each word worked out from the instruction set's encodings.
#include "controller_sim/gsp_assembler.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fb89::controller::gsp {
namespace {

// The message assemble throws for `text`, or "" when it assembles.
std::string error_of(const std::string& text) {
    try {
        assemble("x.asm", text);
    } catch (const AssemblyError& e) {
        return e.what();
    }
    return "";
}

std::vector<uint16_t> words_of(const std::string& text) {
    return assemble("x.asm", text).image();
}

TEST(GspAssembler, ErrorsNameTheFileAndTheLine) {
    EXPECT_EQ(error_of("        NOP\n        FOO A1\n"),
              "x.asm line 2: 'FOO' is not an instruction");
    EXPECT_EQ(error_of("  ADD A1,B2\n"), "x.asm line 1: ADD: registers in opposite files");
    EXPECT_EQ(error_of("  JRUC nowhere\n"), "x.asm line 1: 'nowhere' is not defined");
    EXPECT_EQ(error_of("  MOVE *A0,A1,2\n"), "x.asm line 1: MOVE: the field is 0 or 1");
    EXPECT_EQ(error_of("  ADD A1\n"), "x.asm line 1: ADD takes 2 operands, not 1");
    EXPECT_EQ(error_of("a: NOP\na: NOP\n"), "x.asm line 2: a defined twice");
    EXPECT_EQ(error_of("  MOVK 33,A1\n"), "x.asm line 1: MOVK: '33' is not 1-32");
    EXPECT_EQ(error_of("  MOVI [12],A1\n"), "x.asm line 1: '[12]' is not an XY pair [y,x]");
    EXPECT_EQ(error_of("  PIXT A1,A2\n"), "x.asm line 1: PIXT A1,A2: not an operand pair of PIXT");
    std::string nops;
    for (int i = 0; i < 40; ++i)
        nops += "  NOP\n";
    EXPECT_EQ(error_of("  DSJS A1,far\n" + nops + "far: NOP\n"),
              "x.asm line 1: DSJS: the label is beyond 31 words");
}

TEST(GspAssembler, AJumpOutOfShortReachTakesTheLongForm) {
    std::string nops;
    for (int i = 0; i < 200; ++i)
        nops += "  NOP\n";
    // JRNE over 200 words: the long form, its displacement from the word after it
    std::vector<uint16_t> w = words_of("  JRNE on\n" + nops + "on: NOP\n");
    ASSERT_EQ(w.size(), 203u);
    EXPECT_EQ(w[0], 0xCB00);
    EXPECT_EQ(w[1], 200);
    // back over 200: negative; within 127 words: the short form's 8 bits
    w = words_of("back: NOP\n" + nops + "  JRUC back\n  JRUC back2\nback2: NOP\n");
    EXPECT_EQ(w[201], 0xC000);
    EXPECT_EQ(static_cast<int16_t>(w[202]), -203);
    EXPECT_EQ(w[203], 0x0300);  // to the next instruction: a NOP, as GSPA writes it
    // DSJ within 31 words is DSJS, beyond it the long form (0D80h + the register)
    w = words_of("loop: NOP\n  DSJ A3,loop\n");
    EXPECT_EQ(w[1], 0x3C43);  // backward (bit 10), 2 words back, A3
    w = words_of("loop: NOP\n" + nops + "  DSJ B3,loop\n");
    EXPECT_EQ(w[201], 0x0D93);
    EXPECT_EQ(static_cast<int16_t>(w[202]), -203);
}

TEST(GspAssembler, ImmediatesAndAddressesTakeTheirWordsLowFirst) {
    // a value that fits 16 bits: the short form; a label's address: always 32 bits
    EXPECT_EQ(words_of("  MOVI 100,A1\n"), (std::vector<uint16_t>{0x09C1, 100}));
    EXPECT_EQ(words_of("  MOVI 12345678h,B1\n"), (std::vector<uint16_t>{0x09F1, 0x5678, 0x1234}));
    EXPECT_EQ(words_of("here: MOVI here,A2\n"), (std::vector<uint16_t>{0x09E2, 0, 0}));
    // CMPI and SUBI keep the value's ones' complement
    EXPECT_EQ(words_of("  CMPI 1,A0\n"), (std::vector<uint16_t>{0x0B40, 0xFFFE}));
    // an XY pair [y,x] and the B file's names
    EXPECT_EQ(words_of("  MOVI [2,3],DYDX\n"), (std::vector<uint16_t>{0x09F7, 3, 2}));
    EXPECT_EQ(words_of("V .equ 0C0000150h\n  MOVE A1,@V,1\n"),
              (std::vector<uint16_t>{0x0781, 0x0150, 0xC000}));
}

TEST(GspAssembler, TheListingGivesEachLineItsAddressAndWords) {
    const Program p = assemble("x.asm", "start: MOVK 8,A0\n  MOVI 12345678h,A1\n  .long start\n");
    const std::string text = listing(p);
    EXPECT_NE(text.find("    1 00000000 1900"), std::string::npos) << text;
    EXPECT_NE(text.find("    2 00000010 09E1 5678 1234"), std::string::npos) << text;
    EXPECT_NE(text.find("    3 00000040 0000 0000"), std::string::npos) << text;
    EXPECT_EQ(p.text_bits, 0x60u);
}

}  // namespace
}  // namespace fb89::controller::gsp
