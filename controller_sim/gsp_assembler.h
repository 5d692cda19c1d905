// TMS34010 assembly into the chip's instruction words, as TI's own assembler (GSPA 2.00, 1987)
// reads the syntax of TI's library sources: a label in column 1 (with or without ':'),
// ".equ" and ".set" (a number or a register), ".word" and ".long", ".text" and ".data",
// field-size operands ("MOVE *A0+,A5,1"), the B file's graphics names (SADDR = B0 ...
// PATTRN = B13, as TI's sources .set them) and the instruction set's encodings of the data
// sheet (SPVS002C) and the User's Guide's instruction pages. Like GSPA it takes the short form
// of a jump (JRcc with an 8-bit displacement, DSJ as DSJS) and of an immediate (a 16-bit
// word) wherever the operand fits, a label's address always as 32 bits. Addresses are bit
// addresses from 0: .text first, then .data. tests/golden/gsp/ holds TI's own words for the
// executive; docs/COST_MODEL.md, "The executive as words".
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fb89::controller::gsp {

// A line the assembler cannot read: "FILE line N: what".
class AssemblyError : public std::runtime_error {
  public:
    AssemblyError(const std::string& file, int line, const std::string& what);
    int line() const { return m_line; }

  private:
    int m_line;
};

struct AssembledLine {
    int line = 0;                 // 1-based in the source
    std::string text;             // the line as written
    uint32_t address = 0;         // the bit address of its first word
    std::vector<uint16_t> words;  // its code or data in memory order (none: no code)
    bool code = false;            // an instruction (not data)
};

struct Program {
    std::string name;
    std::vector<AssembledLine> lines;        // every line of the source, in order
    std::map<std::string, uint32_t> labels;  // bit addresses
    std::map<std::string, int64_t> symbols;  // .equ and .set numbers
    uint32_t text_bits = 0;                  // the .text section's length
    uint32_t data_bits = 0;                  // the .data section's, after it

    // The program's words from address 0, .text then .data.
    std::vector<uint16_t> image() const;
};

// Assembles `source` (named `file` in errors); throws AssemblyError for an unknown mnemonic,
// an operand the instruction does not take, an undefined or twice-defined name, a jump out
// of reach, or registers of both files where the chip takes one.
Program assemble(std::string_view file, std::string_view source);

// Words as GSPA lists them: four hexadecimal digits and a space each.
std::string hex_words(std::span<const uint16_t> words);

// The program as GSPA lists it: each line's number, address and words (32-bit data as two
// words, low first) beside its text; lines with more words than fit go on.
std::string listing(const Program& program);

}  // namespace fb89::controller::gsp
