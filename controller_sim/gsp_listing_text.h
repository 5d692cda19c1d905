// Reading the GSP's listing (controller_sim/gsp/*.asm) as text: its instructions with their
// labels, operands and comments, its .equ symbols and its ";@path" lines. What an
// instruction costs is gsp_listing.cpp's (the data sheet's tables); this file knows only
// TI's assembler syntax as the listing uses it. Internal to the controller library.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "controller_sim/gsp_listing.h"

namespace fb89::controller::listing_text {

// The B file's names in TI's documents (SADDR = B0 ... PATTRN = B13).
inline constexpr std::string_view kBFileNames[] = {"SADDR",  "SPTCH", "DADDR", "DPTCH",  "OFFSET",
                                                   "WSTART", "WEND",  "DYDX",  "COLOR0", "COLOR1",
                                                   "COUNT",  "INC1",  "INC2",  "PATTRN"};
// The condition codes of JRcc.
inline constexpr std::string_view kConditions[] = {"UC", "EQ", "NE", "LO", "HS", "LT", "GE", "LE",
                                                   "GT", "C",  "NC", "Z",  "NZ", "P",  "N",  "NN",
                                                   "V",  "NV", "HI", "LS", "MI", "PL"};

std::string upper(std::string_view s);
std::string_view trim(std::string_view s);
// A0-A14, B0-B14, SP or a B-file name.
bool is_register(std::string_view s);
// A number as the TI assembler writes it: decimal, or hexadecimal with a trailing h.
std::optional<uint64_t> parse_number(std::string_view s);

struct Instruction {
    int line = 0;
    std::string label;  // "" when the line has none
    std::string mnemonic;
    std::vector<std::string> operands;
    std::string comment;
    std::string text;  // mnemonic and operands as written
};

struct PathSpec {
    std::string name, start;
    std::string end;                  // "" : to a dispatch or a jump back to COMMON's label
    std::vector<std::string> taken;   // "take LABEL": jumps to these are taken on this path
    std::vector<std::string> fallen;  // "fall LABEL": and these not (a loop's last time)
};

struct Parsed {
    std::vector<Instruction> code;              // in listing order
    std::map<std::string, std::size_t> labels;  // label -> index into code
    std::map<std::string, uint64_t> symbols;    // .equ
    std::vector<PathSpec> paths;
};

// The listing's instructions, labels, symbols and paths; throws std::runtime_error naming
// the listing and line for a line it cannot read.
Parsed parse(const Listing& listing);

}  // namespace fb89::controller::listing_text
